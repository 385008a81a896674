/* The nip seam (private to the library): how the wound-on tension T0 is found at each
 * radius. A problem without a nip (RS_NIP_NONE) creates no rs_nip at all (T0 = web
 * tension), so no nip code runs. Each model implements rs_nip_ops; the contact model of
 * the seed paper plugs in here as another implementation. */
#ifndef RS_NIP_NIP_SEAM_H
#define RS_NIP_NIP_SEAM_H

#include "reelsim/material.h"
#include "reelsim/nip.h"
#include "reelsim/status.h"

typedef struct rs_nip rs_nip;

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

#endif
