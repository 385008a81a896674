/* Effective stiffness of a winding core for the Hakiel core condition. */
#include <math.h>

#include "reelsim/core.h"

/* E_c (Pa) such that the core's radial surface displacement is u = r_c sigma_r / E_c.
 * Tube, plane stress, isotropic E, nu, outer radius b, bore a (Lame):
 *   E_c = E (b^2 - a^2) / ((1 - nu) b^2 + (1 + nu) a^2)       solid (a = 0): E / (1 - nu). */
double rs_core_stiffness(const rs_core *core)
{
  switch (core->kind) {
  case RS_CORE_RIGID: return INFINITY;
  case RS_CORE_ELASTIC: return core->stiffness;
  case RS_CORE_TUBE: {
    double b2 = core->radius * core->radius, a2 = core->bore * core->bore;
    return core->modulus * (b2 - a2) / ((1.0 - core->poisson) * b2 + (1.0 + core->poisson) * a2);
  }
  }
  return NAN;
}

const char *rs_core_kind_name(rs_core_kind kind)
{
  switch (kind) {
  case RS_CORE_RIGID: return "rigid";
  case RS_CORE_ELASTIC: return "elastic";
  case RS_CORE_TUBE: return "tube";
  }
  return "unknown";
}
