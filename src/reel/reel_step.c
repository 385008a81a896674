/* One increment of the reel loop (effect.h): the effects' begin, each layer (where it goes
 * on, the recipes' tension and load, the effects' T0, the check, what the roll carries, the
 * records), the roll's increment, the effects' records. */
#include <math.h>

#include "reel/effect.h"
#include "util/error.h"

/* One layer: where it goes on, the recipes' tension and load, the effects' T0 (they may end
 * the increment before it or ask to plan it again), the check, what the roll carries, the
 * records. */
static rs_status reel_layer(rs_reel_state *s, rs_reel_step *step, int b)
{
  const rs_problem *pb = s->pb;
  rs_reel_result *res = s->res;
  rs_reel_layer L = {.j = step->first + b, .b = b};
  rs_status st;
  rs_reel_place(s, &L);
  L.Ti = L.T0 = rs_reel_web_tension(s, L.r);
  L.load = pb->nip.model != RS_NIP_NONE ? rs_reel_nip_load(s, L.r) : 0.0;
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->tension && ((st = e->ops->tension(e, s, step, &L)) || step->m == b || step->again))
      return st;
  }
  if (!(L.T0 >= 0.0) || !isfinite(L.T0))
    return RS_ERROR(RS_ERR_SOLVER,
                    "wound-on tension %g N/m at r = %.6g m (layer %d of %d) is %s: the web would "
                    "go slack on the roll",
                    L.T0, L.r, L.j + 1, s->N, isfinite(L.T0) ? "negative" : "not finite");
  L.radius = L.r;
  L.carried = L.T0;
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->wound && (st = e->ops->wound(e, s, &L))) return st;
  }
  res->radius[L.j] = L.radius;
  res->web_tension[L.j] = L.Ti;
  res->nip_load[L.j] = L.load;
  res->wound_on_tension[L.j] = L.T0;
  s->block[b] = L.carried;
  return RS_OK;
}

/* The roll went back to `layers` (an adaptive nip's check failed): every effect drops what
 * it recorded beyond. */
static void reel_rewind(rs_reel_state *s, int layers)
{
  s->first = layers;
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->rewind) e->ops->rewind(e, s, layers);
  }
}

/* After the roll's increment: the effects' records (the history, the wound radius). */
static rs_status reel_records(rs_reel_state *s)
{
  rs_status st = RS_OK;
  for (int k = 0; k < s->n_effects && !st; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->after_increment) st = e->ops->after_increment(e, s);
  }
  return st;
}

rs_status rs_reel_state_step(rs_reel_state *s)
{
  const int left = s->N - s->first;
  rs_reel_step step = {.first = s->first, .m = left < s->per_step ? left : s->per_step, .rewind = -1};
  rs_status st = RS_OK;
  for (int k = 0; k < s->n_effects && !st && step.rewind < 0; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->begin) st = e->ops->begin(e, s, &step);
  }
  if (st) return st;
  if (step.rewind >= 0) {
    reel_rewind(s, step.rewind);
    return RS_OK;
  }
  for (int b = 0; b < step.m && !step.again; ++b)
    if ((st = reel_layer(s, &step, b))) return st;
  if (step.again) return RS_OK;
  if (step.m == 0) { /* the roll reached its size */
    s->done = 1;
    return RS_OK;
  }
  if ((st = rs_roll_add_layers(s->roll, step.m, s->block)))
    return rs_error_wrap("winding layers %d-%d of %d (r = %.6g m)", s->first + 1, s->first + step.m,
                         s->N, rs_roll_layer_radius(s->roll, s->first + step.m - 1));
  s->first += step.m;
  s->done = step.end || s->first >= s->N;
  return reel_records(s);
}
