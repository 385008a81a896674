/* The nip seam: a handle around one wound-on-tension model (see reelsim/nip.h). The models
 * (nip_friction.c, contact_model.c) wrap themselves in it; nip_create.c picks one. */
#include <stdlib.h>

#include "nip/nip_seam.h"
#include "util/error.h"

struct rs_nip {
  const rs_nip_ops *ops;
  void *ctx;
};

rs_status rs_nip_wrap(const rs_nip_ops *ops, void *ctx, rs_nip **out)
{
  *out = NULL;
  rs_nip *nip = malloc(sizeof *nip);
  if (!nip) {
    if (ops->destroy) ops->destroy(ctx);
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the nip model");
  }
  nip->ops = ops;
  nip->ctx = ctx;
  *out = nip;
  return RS_OK;
}

void rs_nip_destroy(rs_nip **nip)
{
  if (!nip || !*nip) return;
  if ((*nip)->ops->destroy) (*nip)->ops->destroy((*nip)->ctx);
  free(*nip);
  *nip = NULL;
}

rs_status rs_nip_wound_on_tension(rs_nip *nip, const rs_nip_state *state, double *T0)
{
  return nip->ops->wound_on_tension(nip->ctx, state, T0);
}

const char *rs_nip_name(const rs_nip *nip) { return nip ? nip->ops->name : "none"; }

void rs_nip_get_report(const rs_nip *nip, rs_nip_report *rep)
{
  rep->a = rep->load = 0.0;
  rep->iterations = 0;
  if (nip && nip->ops->report) nip->ops->report(nip->ctx, rep);
}

const struct rs_nip_solution *rs_nip_last_solution(const rs_nip *nip)
{
  return nip && nip->ops->solution ? nip->ops->solution(nip->ctx) : NULL;
}
