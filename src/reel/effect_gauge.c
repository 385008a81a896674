/* The wound radius as a reel effect (effect.h; the gauge: gauge.c), in every reel, last in
 * the list: the roll's deformed outer radius recorded as it grows, and at the end what
 * gauges read from the finished roll (the deformed radii now and as each layer went on, the
 * wound-in tension), after every other effect has finished the result (the air films). */
#include <stdlib.h>

#include "reel/effect.h"
#include "reel/gauge.h"
#include "util/error.h"

static rs_status gauge_setup(rs_reel_effect *e, rs_reel_state *s, rs_roll_params *params)
{
  (void)params;
  rs_reel_gauge *g = calloc(1, sizeof *g);
  if (!g) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the gauge");
  e->content = g;
  return rs_reel_gauge_init(g, s->N);
}

static rs_status gauge_after(rs_reel_effect *e, const rs_reel_state *s)
{
  /* the radial stresses in full only when a state is recorded (ln(N)/RS_GAUGE_STEP of the
   * increments): reading them is O(N) */
  if (!rs_reel_gauge_due(e->content, s->first)) return RS_OK;
  return rs_reel_gauge_record(e->content, s->pb, s->first, rs_roll_core_pressure(s->roll),
                              rs_roll_sigma_r(s->roll), s->film, 0);
}

static void gauge_rewind(rs_reel_effect *e, const rs_reel_state *s, int layers)
{
  (void)s;
  rs_reel_gauge_rewind(e->content, layers);
}

static rs_status gauge_finish(rs_reel_effect *e, const rs_reel_state *s, rs_status st)
{
  rs_reel_gauge *g = e->content;
  rs_reel_result *res = s->res;
  const int n = res->n_layers;
  (void)st;
  if (n == 0 || !g->layers) return RS_OK;
  res->deformed_radius = malloc((size_t)n * sizeof(double));
  res->wound_radius = malloc((size_t)n * sizeof(double));
  res->wound_in_tension = malloc((size_t)n * sizeof(double));
  if (!res->deformed_radius || !res->wound_radius || !res->wound_in_tension)
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the gauges' radii (%d layers)", n);
  rs_status gst = rs_reel_deformed_radius(s->pb, res->core_pressure, res->sigma_r, s->film, n,
                                          res->deformed_radius);
  if (!gst) gst = rs_reel_gauge_record(g, s->pb, n, res->core_pressure, res->sigma_r, s->film, 1);
  if (gst) return gst;
  rs_reel_gauge_finish(g, s->pb, n, res->wound_radius);
  rs_reel_wound_in_tension(s->pb, res->sigma_theta, n, res->wound_in_tension);
  return RS_OK;
}

static void gauge_destroy(rs_reel_effect *e)
{
  if (e->content) rs_reel_gauge_free(e->content);
  free(e->content);
  e->content = NULL;
}

const rs_reel_effect_ops rs_reel_gauge_effect = {
    .name = "gauge",
    .setup = gauge_setup,
    .after_increment = gauge_after,
    .rewind = gauge_rewind,
    .finish = gauge_finish,
    .destroy = gauge_destroy,
};
