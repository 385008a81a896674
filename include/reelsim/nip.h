/* The nip a problem is built of: the model, the drum or rider, the winder (rs_nip_spec),
 * and the contact model on its own at one reel state (rs_nip_contact, reelsim nip).
 *
 * A problem without a nip (RS_NIP_NONE) runs no nip code (T0 = web tension). How the reel
 * asks the model for T0 at each radius, the nip seam, is private (src/nip/nip_seam.h). */
#ifndef REELSIM_NIP_H
#define REELSIM_NIP_H

#include "reelsim/material.h"
#include "reelsim/recipe.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

typedef enum rs_nip_model_kind {
  RS_NIP_NONE,     /* no nip section: T0 = web tension, no nip code runs */
  RS_NIP_FRICTION, /* T0 = T + mu_roll * N (Good, Wu & Fikes 1994) */
  RS_NIP_CONTACT   /* the seed paper's contact model (nip issue) */
} rs_nip_model_kind;

typedef enum rs_winder_kind {
  RS_WINDER_CENTER,         /* center-driven roll, undriven rider: M2 = 0 */
  RS_WINDER_SURFACE,        /* drum driven, roll undriven: M1 = 0 */
  RS_WINDER_CENTER_SURFACE  /* a share of the torque on each */
} rs_winder_kind;

/* The drum (surface winder) or rider roll: a cylinder on a rigid core. */
typedef struct rs_drum {
  double radius;       /* m */
  double core_radius;  /* m, rigid core; a cover is radius - core_radius */
  int orthotropic;     /* 0: isotropic E, nu; 1: E_r, E_theta, nu_rtheta, G_rtheta */
  double E, nu;
  double E_r, E_theta, nu_rtheta, G_rtheta;
} rs_drum;

typedef enum rs_nip_update_kind {
  RS_NIP_UPDATE_ADAPTIVE, /* solve where T0 changes, extrapolate within T0_rtol elsewhere */
  RS_NIP_UPDATE_EVERY     /* solve every update_every layers (1: every layer) */
} rs_nip_update_kind;

typedef struct rs_nip_spec {
  rs_nip_model_kind model;
  rs_recipe load;          /* N/m */
  double mu_roll;          /* sheet on roll (upper contact) */
  double mu_drum;          /* sheet on drum (lower contact) */
  rs_winder_kind winder;
  double torque_share;     /* center-surface: share of the drive torque on the roll */
  rs_drum drum;
  int nodes;               /* contact nodes M */
  int terms;               /* Fourier terms of the cylinder series; 0 = automatic */
  rs_nip_update_kind update;
  int update_every;        /* every: layers between nip solves */
  double T0_rtol;          /* adaptive: tolerance on T0, relative to T0 */
} rs_nip_spec;

/* What the nip sees of the reel at one radius. */
typedef struct rs_nip_state {
  double roll_radius;     /* m, current outer radius of the wound roll */
  double core_radius;     /* m */
  double web_tension;     /* Ti, N/m (from the tension recipe) */
  double nip_load;        /* P, N/m (from the load recipe) */
  double surface_modulus; /* Pa, tangent E_r of the outer layers now */
  double surface_pressure;/* Pa, interlayer pressure under the outer layer now */
} rs_nip_state;

/* One converged nip. Arrays are owned; rs_nip_solution_free releases them. */
typedef struct rs_nip_solution {
  int M, capacity;
  double a;                 /* m, half-width */
  double dx;                /* m */
  double load;              /* N/m, int p dx (eq. (21)) of the returned state */
  double Ti, T0;            /* N/m, incoming and wound-on tension */
  double xi1;               /* creep of the upper contact (wound-on condition, docs/nip.md) */
  double xi2;               /* creep of the lower contact */
  double delta0;            /* m, approach of the cylinder centres */
  double eps0;              /* m, shift of the nip centre */
  double E_r;               /* Pa, radial modulus used for the roll (0 if set by hand) */
  double condition_number;  /* 1-norm estimate (dgecon's algorithm) of the equilibrated final
                               matrix, or of the kept one it was refined from with the final
                               stick/slip rows put in (they differ by the kernels' drift,
                               docs/nip.md) */
  int iterations;           /* active-set solves at the final half-width */
  int lcp_pivots;           /* Lemke pivots at the final half-width (0: the active-set
                               iteration found the state without the LCP) */
  int width_iterations;     /* half-widths tried by the load search (1 for a given a) */
  int total_solves;         /* linear solves in all */
  double dissipation;       /* int (q+ s+ + q- s-) dx >= 0, N/m per unit speed */
  double *x;                /* M nodes, m */
  double *pressure;         /* M, Pa, compression positive */
  double *x_shear;          /* M-1 element midpoints, m */
  double *shear_upper;      /* M-1, tau+ (Pa) */
  double *shear_lower;      /* M-1, tau- (Pa) */
  double *slip_rate_upper;  /* M-1, s+ (0 where stuck) */
  double *slip_rate_lower;  /* M-1, s- */
  unsigned char *slip_upper;/* M-1, 1 = slip */
  unsigned char *slip_lower;
} rs_nip_solution;

void rs_nip_solution_free(rs_nip_solution *s);

/* The contact model on its own (reelsim nip): one nip at a reel state, outside a reel. The
 * handle is used by one thread at a time; docs/nip.md gives the model and its signs. */
typedef struct rs_nip_contact rs_nip_contact;
void rs_nip_contact_destroy(rs_nip_contact **nc); /* accepts NULL and *nc == NULL */

/* Builds the contact model from a nip spec and the material (the drum, the sheet
 * constants, friction, winder); the roll is set per call by rs_nip_contact_solve_state. */
rs_status rs_nip_contact_create_from_spec(const rs_nip_spec *spec, const rs_material *mat,
                                          rs_nip_contact **out);

/* One nip at the reel state (roll radius, core radius, Ti, P, surface pressure): chooses
 * the roll's radial modulus (docs/nip.md: secant stack modulus over the mean nip pressure),
 * builds the roll and the sheet, and solves for the load. Needs create_from_spec. */
rs_status rs_nip_contact_solve_state(rs_nip_contact *nc, const rs_nip_state *st,
                                     rs_nip_solution *out);

RS_END_DECLS
#endif
