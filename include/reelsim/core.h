/* Winding cores: rigid, elastic (given stiffness E_c), or an isotropic tube. */
#ifndef REELSIM_CORE_H
#define REELSIM_CORE_H

#include "reelsim/export.h"
RS_BEGIN_DECLS

typedef enum rs_core_kind { RS_CORE_RIGID, RS_CORE_ELASTIC, RS_CORE_TUBE } rs_core_kind;

typedef struct rs_core {
  rs_core_kind kind;
  double radius;     /* m, outer radius r_c */
  double stiffness;  /* Pa, elastic: E_c as in u_core = r_c sigma_r / E_c */
  double bore;       /* m, tube: inner radius a */
  double modulus;    /* Pa, tube: E */
  double poisson;    /* tube: nu */
  double rating;     /* Pa, external pressure the core is rated for (defect check); 0 = none */
} rs_core;

/* Effective core stiffness E_c (Pa) for the Hakiel core condition; INFINITY if rigid.
 * Tube (plane stress, outer radius b, bore a):
 *   E_c = E (b^2 - a^2) / ((1 - nu) b^2 + (1 + nu) a^2)      (bore 0: E / (1 - nu)). */
double rs_core_stiffness(const rs_core *core);

const char *rs_core_kind_name(rs_core_kind kind);

RS_END_DECLS
#endif
