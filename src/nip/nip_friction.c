/* The empirical friction nip (Good, Wu & Fikes 1994, J. Appl. Mech. 61):
 *   T0 = Ti + mu_k N        T0, Ti, N in N/m; mu_k web-on-web kinetic friction.
 * Measurements follow this slope at low nip load and level off at high load; the
 * contact model of the seed paper reproduces that, this model does not. */
#include <stdlib.h>

#include "reelsim/nip.h"

typedef struct friction_ctx {
  double mu;
} friction_ctx;

static rs_status friction_wot(void *ctx, const rs_nip_state *st, double *T0)
{
  const friction_ctx *f = ctx;
  *T0 = st->web_tension + f->mu * st->nip_load;
  return RS_OK;
}

static const rs_nip_ops friction_ops = {"friction", friction_wot, free};

rs_status rs_nip_friction_create(double mu_roll, rs_nip **out)
{
  *out = NULL;
  if (!(mu_roll >= 0.0)) return RS_ERROR(RS_ERR_INPUT, "nip.friction.roll must be >= 0 (got %g)", mu_roll);
  friction_ctx *f = malloc(sizeof *f);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the friction nip");
  f->mu = mu_roll;
  return rs_nip_wrap(&friction_ops, f, out);
}
