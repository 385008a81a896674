/* Creep and relaxation of a wound roll in storage: the web's Prony series on the hoop
 * direction and on the radial stack, integrated over a stage's hours with CVODE
 * (docs/storage.md, "Creep").
 *
 * Each turn j (faces s_{j-1}, s_j = r_c + j t) is a sheet of uniform stresses: its radial
 * stress the mean of its faces' R_j = (sigma_r(j-1) + sigma_r(j)) / 2, its hoop stress its
 * tension over t, H_j = (s_j sigma_r(j) - s_{j-1} sigma_r(j-1)) / t (the winding engine's
 * accounting: the turn's equilibrium). In each direction the sheet is a generalized
 * Maxwell body with the glassy (winding) modulus E (the stack's tangent E_r(P) at the turn's
 * pressure, E_theta along the web) and arms i of modulus w_i E and relaxation time tau_i:
 *     d sigma/dt = E da/dt - sum_i q_i / tau_i,     dq_i/dt = w_i E da/dt - q_i / tau_i,
 * a the direct strain of that direction; its relaxation modulus is exactly
 * E (1 - sum_i w_i (1 - exp(-t/tau_i))). The arms' relaxation is a creep strain rate
 * c' = sum_i q_i / (tau_i E) per turn and direction, an eigenstrain rate of the elastic roll
 * with the glassy moduli: the stress rates solve one linear boundary value problem (the
 * turns' compatibility at their faces, the core condition, a free outer face), tridiagonal
 * in the face stresses: O(N). CVODE (BDF) integrates the face stresses and the arm stresses
 * with a Krylov solver (SPGMR) preconditioned by the arms' own relaxation.
 *
 * The roll's stresses come in the winding engine's layout: the core pressure, sigma_r per
 * layer at its outer radius (the outermost 0: a free face), sigma_theta per layer (mean). */
#ifndef REELSIM_STORAGE_CREEP_H
#define REELSIM_STORAGE_CREEP_H

#include "reelsim/material.h"
#include "reelsim/status.h"

enum { RS_CREEP_MAX_TERMS = 16 };

typedef struct rs_creep_params {
  int n_layers;
  double core_radius;          /* m */
  double caliper;              /* m */
  double E_theta;              /* Pa, glassy hoop modulus */
  double nu_rtheta;            /* eps_theta = (sigma_theta - nu sigma_r) / E_theta; elastic */
  const rs_radial_law *radial; /* the stack law: tangent E_r(P), glassy (prepared) */
  double core_stiffness;       /* Pa, u(r_c) = r_c sigma_r(r_c) / E_c; INFINITY: rigid */
  int n_terms;                 /* Prony terms */
  double tau[RS_CREEP_MAX_TERMS];      /* h, > 0 */
  double w_theta[RS_CREEP_MAX_TERMS];  /* fraction of E_theta relaxing with tau_i, >= 0 */
  double w_radial[RS_CREEP_MAX_TERMS]; /* fraction of the stack modulus, >= 0 */
  double rtol;                 /* CVODE relative tolerance (RS_ACCURACY_PER_RTOL x numerics.rtol) */
  long max_steps;              /* CVODE steps per stage */
} rs_creep_params;

typedef struct rs_creep_stats {
  long steps, rhs, lin_iters, prec_solves, nonlin_iters, err_fails, conv_fails;
} rs_creep_stats;

typedef struct rs_creep rs_creep;

/* Checks the parameters (RS_ERR_INPUT naming the bad one) and sets up the solver. The arm
 * stresses start at zero: the first stage loads them with the wound stresses. */
rs_status rs_creep_create(const rs_creep_params *p, rs_creep **out);
void rs_creep_destroy(rs_creep **c);

/* Holds the roll for `hours` at constant temperature and humidity. In: the stresses now
 * (after any instantaneous change at the stage's start: the change since the last hold's
 * end loads the arms elastically, dq_i = w_i d sigma); out: the stresses after the hold.
 * core_pressure (Pa, compression positive), sigma_r[n], sigma_theta[n] (Pa). On failure
 * (RS_ERR_SOLVER, saying what was tried) the arrays are left as they were. */
rs_status rs_creep_hold(rs_creep *c, double hours, double *core_pressure, double *sigma_r,
                        double *sigma_theta);

void rs_creep_get_stats(const rs_creep *c, rs_creep_stats *stats);

/* The elastic problem one right-hand side solves (exposed for the tests): the face stress
 * rates ds[0..n) (face n is free: 0) of the roll whose turns have the creep strain rates
 * c_r[n], c_theta[n] and glassy stack moduli E_r[n] (per turn). Work array of n. */
void rs_creep_bvp(const rs_creep_params *p, const double *E_r, const double *c_r,
                  const double *c_theta, double *ds, double *work);

#endif
