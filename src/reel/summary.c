/* Whether a summary can be shown (NaN or Inf in a figure means a broken solution), and
 * the roll's size as engineers quote it; the summary figures themselves. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "reelsim/reel.h"

int rs_reel_summary_finite(const rs_reel_summary *s, const char **what)
{
  const struct {
    const char *name;
    double v;
  } f[] = {
      {"final radius", s->final_radius},
      {"core pressure", s->core_pressure},
      {"peak pressure", s->peak_pressure},
      {"radius of the peak pressure", s->peak_pressure_radius},
      {"minimum hoop stress", s->min_hoop},
      {"radius of the minimum hoop stress", s->min_hoop_radius},
      {"least wound-on tension", s->wot_min},
      {"greatest wound-on tension", s->wot_max},
  };
  for (size_t i = 0; i < sizeof f / sizeof f[0]; ++i)
    if (!isfinite(f[i].v)) {
      if (what) *what = f[i].name;
      return 0;
    }
  return 1;
}

/* L = sum_j pi (r_{j-1} + r_j), r_{-1} the core radius; m = rho t L per unit width. */
void rs_reel_sizes_of(const rs_reel_result *res, const rs_problem *problem, rs_reel_sizes *out)
{
  double L = 0.0, inner = res->core_radius;
  for (int j = 0; j < res->n_layers; ++j) {
    L += 3.14159265358979323846 * (inner + res->radius[j]);
    inner = res->radius[j];
  }
  /* with entrained air the radii hold the films: the web is what was wound */
  if (res->air_film) L = res->air_wound_length;
  out->diameter = res->n_layers > 0 ? 2.0 * res->radius[res->n_layers - 1] : 2.0 * inner;
  out->deformed_diameter = res->n_layers > 0 && res->deformed_radius
                               ? 2.0 * res->deformed_radius[res->n_layers - 1] : out->diameter;
  out->wound_length = L;
  out->has_mass = problem && problem->material.density > 0.0;
  out->mass = out->has_mass ? problem->material.density * problem->material.caliper * L : 0.0;
  out->has_air = res->air_film != NULL && res->air_film_entrained != NULL;
  out->air_thickness = out->air_film_min = out->air_film_max = 0.0;
  out->air_entrained_min = out->air_entrained_max = 0.0;
  if (!out->has_air || res->n_layers < 1) return;
  out->air_film_min = out->air_entrained_min = INFINITY;
  out->air_film_max = out->air_entrained_max = -INFINITY;
  for (int j = 0; j < res->n_layers; ++j) {
    out->air_thickness += res->air_film[j];
    out->air_film_min = fmin(out->air_film_min, res->air_film[j]);
    out->air_film_max = fmax(out->air_film_max, res->air_film[j]);
    out->air_entrained_min = fmin(out->air_entrained_min, res->air_film_entrained[j]);
    out->air_entrained_max = fmax(out->air_entrained_max, res->air_film_entrained[j]);
  }
}

void rs_reel_summarize(const rs_reel_result *res, rs_reel_summary *sum)
{
  memset(sum, 0, sizeof *sum);
  int n = res->n_layers;
  sum->layers = n;
  sum->core_pressure = res->core_pressure;
  if (n == 0) return;
  sum->final_radius = res->radius[n - 1];
  sum->peak_pressure = -INFINITY;
  sum->min_hoop = INFINITY;
  sum->wot_min = INFINITY;
  sum->wot_max = -INFINITY;
  for (int j = 0; j < n; ++j) {
    if (-res->sigma_r[j] > sum->peak_pressure) {
      sum->peak_pressure = -res->sigma_r[j];
      sum->peak_pressure_radius = res->radius[j];
    }
    if (res->sigma_theta[j] < sum->min_hoop) {
      sum->min_hoop = res->sigma_theta[j];
      sum->min_hoop_radius = res->radius[j];
    }
    sum->wot_min = fmin(sum->wot_min, res->wound_on_tension[j]);
    sum->wot_max = fmax(sum->wot_max, res->wound_on_tension[j]);
  }
  /* the core carries a pressure too; report it as the peak if it is the largest */
  if (res->core_pressure > sum->peak_pressure) {
    sum->peak_pressure = res->core_pressure;
    sum->peak_pressure_radius = res->core_radius;
  }
}
