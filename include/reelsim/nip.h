/* The nip seam: how the wound-on tension T0 is found at each radius.
 *
 * A problem without a nip (RS_NIP_NONE) creates no rs_nip at all (T0 = web tension), so
 * no nip code runs. Each model implements rs_nip_ops; the contact model of the seed paper
 * plugs in here as another implementation. */
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

typedef struct rs_nip rs_nip;
struct rs_nip_solution; /* a converged contact nip (reelsim/nip_contact.h) */

/* What the model found at its last call (the /nip/ record of a run). */
typedef struct rs_nip_report {
  double a;        /* m, contact half-width (0: the model has no contact) */
  double load;     /* N/m, the load of the converged contact (eq. (21)); else the given load */
  int iterations;  /* stick/slip iterations (0: none) */
} rs_nip_report;

typedef struct rs_nip_ops {
  const char *name;
  rs_status (*wound_on_tension)(void *ctx, const rs_nip_state *state, double *T0);
  void (*destroy)(void *ctx);
  /* optional: */
  void (*report)(void *ctx, rs_nip_report *rep);
  const struct rs_nip_solution *(*solution)(void *ctx);
} rs_nip_ops;

/* Creates the nip model the spec asks for; *out = NULL for RS_NIP_NONE. */
rs_status rs_nip_create(const rs_nip_spec *spec, const rs_material *material, rs_nip **out);
void rs_nip_destroy(rs_nip **nip);
rs_status rs_nip_wound_on_tension(rs_nip *nip, const rs_nip_state *state, double *T0);
const char *rs_nip_name(const rs_nip *nip);
/* The last call's report; zeros (and the state's load) for models without a contact. */
void rs_nip_get_report(const rs_nip *nip, rs_nip_report *rep);
/* The last converged contact solution, or NULL (owned by the model, valid until its next
 * call). */
const struct rs_nip_solution *rs_nip_last_solution(const rs_nip *nip);

/* For model implementations: wraps ctx and ops in a handle (takes ownership of ctx). */
rs_status rs_nip_wrap(const rs_nip_ops *ops, void *ctx, rs_nip **out);

/* The friction model: T0 = Ti + mu * P (Good, Wu & Fikes 1994). */
rs_status rs_nip_friction_create(double mu_roll, rs_nip **out);

RS_END_DECLS
#endif
