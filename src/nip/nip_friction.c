/* The empirical friction nip (Good, Wu & Fikes 1994, J. Appl. Mech. 61):
 *   T0 = Ti + mu_k N        T0, Ti, N in N/m; mu_k web-on-web kinetic friction.
 * Measurements follow this slope at low nip load and level off at high load; the
 * contact model of the seed paper reproduces that, this model does not. */
#include <stdlib.h>

#include "nip/nip_seam.h"
#include "util/error.h"

typedef struct friction_ctx {
  double mu, load;
} friction_ctx;

static rs_status friction_wot(void *ctx, const rs_nip_state *st, double *T0)
{
  friction_ctx *f = ctx;
  f->load = st->nip_load;
  *T0 = st->web_tension + f->mu * st->nip_load;
  return RS_OK;
}

static void friction_report(void *ctx, rs_nip_report *rep)
{
  rep->load = ((const friction_ctx *)ctx)->load;
}

static const rs_nip_ops friction_ops = {
    .name = "friction", .wound_on_tension = friction_wot, .destroy = free,
    .report = friction_report};

rs_status rs_nip_friction_create(double mu_roll, rs_nip **out)
{
  *out = NULL;
  if (!(mu_roll >= 0.0)) return RS_ERROR(RS_ERR_INPUT, "nip.friction.roll must be >= 0 (got %g)", mu_roll);
  friction_ctx *f = malloc(sizeof *f);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the friction nip");
  f->mu = mu_roll;
  f->load = 0.0;
  return rs_nip_wrap(&friction_ops, f, out);
}
