/* A lane's deformed outer radius, layer by layer (lanes_radius.h; docs/lanes.md, "The
 * lanes' radii"): full-stack sums at geometrically spaced layers, the top of the stack
 * summed exactly in between and the deep part carried linearly. */
#include "reel/lanes_radius.h"

#include <math.h>
#include <stdlib.h>

#include "reelsim/material.h"
#include "reelsim/reel.h"
#include "util/error.h"

rs_status rs_lane_radius_init(rs_lane_radius *g, int N)
{
  *g = (rs_lane_radius){.k_r = -1, .k_p = -1};
  const size_t n = (size_t)(N > 0 ? N : 1);
  g->prefix = malloc((n + 1) * sizeof(double));
  g->prev = malloc((n + 1) * sizeof(double));
  g->scratch = malloc(n * sizeof(double));
  if (!g->prefix || !g->prev || !g->scratch)
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate a lane's radii (%d layers)", N);
  return RS_OK;
}

void rs_lane_radius_free(rs_lane_radius *g)
{
  free(g->prefix), free(g->prev), free(g->scratch);
  rs_reel_strain_free(&g->eps);
  *g = (rs_lane_radius){.k_r = -1, .k_p = -1};
}

/* eps(P) tabulated to twice the largest pressure P it is asked for (a new table when P
 * exceeds its range) */
static rs_status strain_cover(rs_lane_radius *g, const rs_problem *pb, double P)
{
  if (g->eps && P <= rs_reel_strain_max(g->eps)) return RS_OK;
  rs_reel_strain_free(&g->eps);
  g->eps = rs_reel_strain_new(&pb->material.radial, 2.0 * P + 1.0);
  return g->eps ? RS_OK : RS_ERROR(RS_ERR_MEMORY, "cannot allocate a lane's strain table");
}

/* The full-stack sum at k layers: R exactly and the compression prefix (the last sum's
 * kept as prev). One layer before the next interval starts it is taken only to be kept;
 * at the interval's start the split j0, the deep part's compression and its rate, from
 * the layer wound since that sum (both over layers 0..j0-1). */
static rs_status radius_full(rs_lane_radius *g, const rs_problem *pb, const rs_roll *roll,
                             const double *film, const double *T0, int k, double *R)
{
  const double Pc = rs_roll_core_pressure(roll), *sr = rs_roll_sigma_r(roll);
  rs_status st = rs_reel_deformed_radius(pb, Pc, sr, film, k, g->scratch);
  if (st) return st;
  *R = g->scratch[k - 1];
  double *t = g->prev;
  g->prev = g->prefix;
  g->prefix = t;
  const double base = pb->core.radius + rs_reel_core_displacement(pb, Pc);
  const double cal = pb->material.caliper;
  double Pmax = Pc;
  g->prefix[0] = 0.0;
  for (int j = 0; j < k; ++j) {
    g->prefix[j + 1] = base + (j + 1) * cal - g->scratch[j];
    Pmax = fmax(Pmax, -sr[j]);
  }
  g->full_sums++;
  g->full_nodes += k;
  const int last = g->k_p;
  g->k_p = k;
  if (k == g->next - 1) return RS_OK; /* kept for the next interval's rate */
  const int h = (int)(RS_LANE_RADIUS_STEP * k);
  g->k_r = k;
  g->next = h < 2 ? k + 1 : k + h;
  g->j0 = k - h - RS_LANE_RADIUS_MARGIN > 0 ? k - h - RS_LANE_RADIUS_MARGIN : 0;
  g->deep = g->prefix[g->j0];
  g->rate = last == k - 1 && T0[k - 1] > 0.0 ? 1.0 / T0[k - 1] : 0.0;
  return strain_cover(g, pb, Pmax);
}

rs_status rs_lane_radius_update(rs_lane_radius *g, const rs_problem *pb, const rs_roll *roll,
                                const double *film, const double *T0, double *R)
{
  const int k = rs_roll_layers(roll);
  if (k == 0) {
    *R = pb->core.radius;
    return RS_OK;
  }
  /* a full sum at the interval's ends, and at two layers in a row after a slack layer
   * before k_r (no rate to carry the deep part with: it holds while the lane stays slack) */
  if (k >= g->next - 1 || k <= g->k_r || (!(g->rate > 0.0) && T0[k - 1] > 0.0))
    return radius_full(g, pb, roll, film, T0, k, R);
  /* the deep part: layer k - 1 compressed the layers below j0, now d = k - 1 - k_r layers
   * deeper than at k_r, as the layer before k_r compressed those below j0 - d */
  const int jd = g->j0 - (k - 1 - g->k_r);
  if (jd > 0) g->deep += T0[k - 1] * g->rate * (g->prefix[jd] - g->prev[jd]);
  /* the top: layers j0..k-1 at the roll's current pressures, node j0 up to the surface */
  const double cal = pb->material.caliper, Pc = rs_roll_core_pressure(roll);
  double P_in = g->j0 == 0 ? Pc : -rs_roll_layer_sigma_r(roll, g->j0 - 1), top = 0.0;
  rs_status st = strain_cover(g, pb, P_in);
  if (st) return st;
  double e_in = rs_reel_strain_eval(g->eps, P_in), films = 0.0;
  for (int j = g->j0; j < k; ++j) {
    const double P_out = j + 1 < k ? -rs_roll_layer_sigma_r(roll, j) : 0.0;
    if (P_out > rs_reel_strain_max(g->eps) && (st = strain_cover(g, pb, P_out))) return st;
    const double e_out = rs_reel_strain_eval(g->eps, P_out);
    top += e_in + e_out;
    if (film) films += rs_air_compressed_film(film[j], P_in, pb->air.pressure);
    e_in = e_out;
    P_in = P_out;
  }
  g->top_layers += k - g->j0;
  *R = pb->core.radius + rs_reel_core_displacement(pb, Pc) + k * cal - g->deep -
       0.5 * cal * top + films;
  return RS_OK;
}
