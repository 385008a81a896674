/* The nip seam: a handle around one wound-on-tension model (see reelsim/nip.h). */
#include <stdlib.h>

#include "reelsim/nip.h"
#include "reelsim/nip_contact.h"

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

rs_status rs_nip_create(const rs_nip_spec *spec, const rs_material *material, rs_nip **out)
{
  *out = NULL;
  switch (spec->model) {
  case RS_NIP_NONE: return RS_OK; /* no nip, no nip code */
  case RS_NIP_FRICTION: return rs_nip_friction_create(spec->mu_roll, out);
  case RS_NIP_CONTACT: return rs_nip_contact_nip_create(spec, material, out);
  }
  return RS_ERROR(RS_ERR_INPUT, "nip.model: unknown model %d", (int)spec->model);
}
