/* The lanes' summary figures (reel.h, rs_lanes_summarize; docs/lanes.md, "Outputs"). */
#include <math.h>
#include <string.h>

#include "reelsim/reel.h"
#include "reel/result_internal.h"

int rs_lanes_summarize(const rs_reel_result *res, double pressure_limit, rs_lanes_summary *sum)
{
  memset(sum, 0, sizeof *sum);
  const rs_lanes_result *lr = res ? res->lanes : NULL;
  if (!lr || lr->count < 1) return 0;
  const int m = lr->count, N = lr->n_layers;
  double rmin = INFINITY, rmax = -INFINITY;
  sum->count = m;
  sum->pressure_limit = pressure_limit > 0.0 ? pressure_limit : 0.0;
  sum->hardest_pressure = -INFINITY;
  sum->tension_min = INFINITY;
  sum->tension_max = -INFINITY;
  for (int i = 0; i < m; ++i) {
    double peak = lr->core_pressure[i];
    sum->slack_from[i] = NAN;
    for (int k = 0; k < N; ++k) {
      const size_t at = (size_t)k * m + i;
      peak = fmax(peak, -lr->sigma_r[at]);
      sum->tension_min = fmin(sum->tension_min, lr->web_tension[at]);
      sum->tension_max = fmax(sum->tension_max, lr->web_tension[at]);
      if (lr->slack[at] && isnan(sum->slack_from[i]))
        sum->slack_from[i] = res->core_radius + (k + 1) * lr->caliper[i];
    }
    if (!isnan(sum->slack_from[i])) sum->slack_lanes++;
    if (peak > sum->hardest_pressure) {
      sum->hardest_pressure = peak;
      sum->hardest = i;
      sum->hardest_x = lr->x[i];
    }
    if (sum->pressure_limit > 0.0 && peak > sum->pressure_limit) sum->hard_lanes++;
    if (lr->outer_radius[i] > rmax) {
      rmax = lr->outer_radius[i];
      sum->ridge_x = lr->x[i];
    }
    rmin = fmin(rmin, lr->outer_radius[i]);
  }
  sum->ridge_height = rmax - rmin;
  if (N == 0) sum->tension_min = sum->tension_max = NAN;
  return 1;
}
