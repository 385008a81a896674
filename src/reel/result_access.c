/* The result by name (reel.h): what a foreign-function interface reads instead of
 * mirroring rs_reel_result's layout. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "reelsim/reel.h"

int rs_reel_result_layers(const rs_reel_result *res) { return res ? res->n_layers : 0; }

const double *rs_reel_result_array(const rs_reel_result *res, const char *name, int *n)
{
  if (n) *n = 0;
  if (!res || !name) return NULL;
  const struct {
    const char *name;
    const double *v;
  } a[] = {
      {"radius", res->radius},           {"wound_on_tension", res->wound_on_tension},
      {"web_tension", res->web_tension}, {"nip_load", res->nip_load},
      {"sigma_r", res->sigma_r},         {"sigma_theta", res->sigma_theta},
      {"air_film", res->air_film},       {"air_film_entrained", res->air_film_entrained},
      {"at_speed_sigma_r", res->at_speed_sigma_r},
      {"at_speed_sigma_theta", res->at_speed_sigma_theta},
      {"deformed_radius", res->deformed_radius}, {"wound_radius", res->wound_radius},
      {"wound_in_tension", res->wound_in_tension},
  };
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i)
    if (strcmp(name, a[i].name) == 0) {
      if (!a[i].v) return NULL; /* an effect the problem did not call for */
      if (n) *n = res->n_layers;
      return a[i].v;
    }
  return NULL;
}

double rs_reel_result_scalar(const rs_reel_result *res, const char *name)
{
  if (!res || !name) return NAN;
  if (strcmp(name, "core_pressure") == 0) return res->core_pressure;
  if (strcmp(name, "core_radius") == 0) return res->core_radius;
  if (strcmp(name, "wall_seconds") == 0) return res->wall_seconds;
  if (strcmp(name, "at_speed_core_pressure") == 0)
    return res->at_speed_sigma_r ? res->at_speed_core_pressure : NAN;
  if (strcmp(name, "air_wound_length") == 0) return res->air_film ? res->air_wound_length : NAN;
  return NAN;
}

int rs_reel_result_finite(const rs_reel_result *res, const char **what)
{
  if (!res) {
    if (what) *what = "result";
    return 0;
  }
  rs_reel_summary sum;
  rs_reel_summarize(res, &sum);
  return rs_reel_summary_finite(&sum, what);
}
