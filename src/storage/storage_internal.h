/* Inside the storage module (docs/storage.md): the roll in storage, the elastic solve
 * every per-stage solver builds on, and the per-stage solvers the driver (storage.c)
 * calls: the temperature/humidity change (thermal.c) and the hold (creep.c).
 *
 * Geometry and sign conventions: turn k (k = 1..n) is the annulus [s[k-1], s[k]],
 * s[0] = r_c. Radial stress lives at the faces: sr[k] at s[k] (sr[0] on the core, sr[n] = 0
 * on the free outer face); the hoop stress of turn k is its mean over the turn,
 * st[k-1] = (s[k] sr[k] - s[k-1] sr[k-1]) / t (the turn's equilibrium, as the winding model
 * reports it). Tension positive. Layer j (0-based) of a reel result is turn j + 1. */
#ifndef RS_STORAGE_INTERNAL_H
#define RS_STORAGE_INTERNAL_H

#include "reelsim/problem.h"
#include "reelsim/reel.h"
#include "roll/roll.h" /* RS_ACCURACY_PER_RTOL */
#include "reelsim/status.h"

typedef struct rs_storage_roll {
  const rs_problem *problem;
  int n;               /* turns */
  double *s;           /* n + 1 face radii, m */
  double *sr;          /* n + 1 radial stresses at the faces, Pa */
  double *st;          /* n mean hoop stresses, Pa */
  double E_c_inv;      /* 1/Pa: 1 / E_c of the core (0: rigid) */
  double temperature;  /* C, the roll's current state */
  double humidity;     /* % RH */
  double hours;        /* h of storage so far */
  double *work;        /* 9 (n + 1) doubles for the solvers below */
  double *pbuf;        /* n + 1 doubles: the turns' pressures (rs_storage_turn_moduli) */
  long solves;         /* elastic solves so far */
  int max_substeps;    /* most sub-steps one change took */
} rs_storage_roll;

/* From a wound roll: the faces from the problem's core radius and the result's layer radii,
 * the stresses from the result (sr[0] = -core pressure). */
rs_status rs_storage_roll_init(rs_storage_roll *roll, const rs_problem *problem,
                               const rs_reel_result *wound);
void rs_storage_roll_free(rs_storage_roll *roll);

/* Tangent radial modulus of every turn, E_r[k-1] = E_r(P) of the stack law at the turn's
 * mean face pressure P = -(sr[k-1] + sr[k]) / 2 (+ the same of dsr when dsr is not NULL:
 * the pressure part-way through a change). */
void rs_storage_turn_moduli(const rs_storage_roll *roll, const double *dsr, double frac,
                            double *E_r);

/* Free-strain increments of one elastic solve. A NULL per-turn array counts as zeros; the
 * uniform parts are added to every turn. */
typedef struct rs_storage_load {
  const double *E_r;      /* n: the turns' tangent radial moduli (Pa); required */
  const double *E_theta;  /* n or NULL: the turns' hoop moduli (NULL: the material's) */
  const double *de_r;     /* n or NULL: free strain through each turn's thickness */
  const double *de_theta; /* n or NULL: free strain along the web */
  double de_r_all, de_theta_all; /* uniform parts */
  double de_core;         /* the core's free strain (u = r_c (sigma_r / E_c + de_core)) */
} rs_storage_load;

/* The stress change (dsr: n + 1, dst: n) of the roll from the free strains of `load`, every
 * turn an exact orthotropic annulus (Lekhnitskii's solution plus the eigenstrain's
 * particular solution), the faces' displacements continuous, the outer face free, the
 * core condition u(r_c) = r_c (sigma_r(r_c) / E_c + de_core): one tridiagonal solve, O(n).
 * Uses roll->work. RS_ERR_SOLVER when the system is singular (a turn's E_r <= 0). */
rs_status rs_storage_elastic(rs_storage_roll *roll, const rs_storage_load *load, double *dsr,
                             double *dst);

/* thermal.c: brings the roll from its current temperature and humidity to (T, H): the free
 * strains alpha dT + beta dH of web (r, theta) and core, applied in sub-steps with the
 * tangent moduli re-evaluated (midpoint rule), the number of sub-steps doubled until two
 * successive answers agree within rtol (RS_ACCURACY_PER_RTOL x numerics.rtol) of the largest
 * pressure. */
rs_status rs_storage_change(rs_storage_roll *roll, double T, double H, double rtol);
/* The same with a fixed number of sub-steps (the convergence test). */
rs_status rs_storage_change_steps(rs_storage_roll *roll, double T, double H, int steps);

/* creep.c: viscoelastic relaxation over a hold (the material's Prony series). create sets
 * *out = NULL when the material has no viscoelastic data: then hold is not called. */
typedef struct rs_storage_creep rs_storage_creep;
rs_status rs_storage_creep_create(const rs_storage_roll *roll, rs_storage_creep **out);
/* Holds the roll at its current temperature and humidity for `hours`, updating sr, st. */
rs_status rs_storage_creep_hold(rs_storage_creep *creep, rs_storage_roll *roll, double hours);
void rs_storage_creep_destroy(rs_storage_creep **creep);

#endif
