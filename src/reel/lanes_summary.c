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

const double *rs_lanes_result_array(const rs_reel_result *res, const char *name, int *rows,
                                    int *cols)
{
  if (rows) *rows = 0;
  if (cols) *cols = 0;
  const rs_lanes_result *lr = res ? res->lanes : NULL;
  if (!lr || !name) return NULL;
  const int m = lr->count, N = lr->n_layers;
  const struct {
    const char *name;
    const double *v;
    int rows, cols;
  } a[] = {
      {"x", lr->x, m, 0},
      {"width", lr->width, m, 0},
      {"caliper", lr->caliper, m, 0},
      {"core_pressure", lr->core_pressure, m, 0},
      {"outer_radius", lr->outer_radius, m, 0},
      {"strain", lr->strain, N, 0},
      {"wound_on_tension", lr->wound_on_tension, N, m},
      {"web_tension", lr->web_tension, N, m},
      {"nip_load", lr->nip_load, N, m},
      {"final/sigma_r", lr->sigma_r, N, m},
      {"final/sigma_theta", lr->sigma_theta, N, m},
      {"final/radius", lr->radius, N, m},
  };
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i)
    if (strcmp(name, a[i].name) == 0 && a[i].v) {
      if (rows) *rows = a[i].rows;
      if (cols) *cols = a[i].cols;
      return a[i].v;
    }
  return NULL;
}
