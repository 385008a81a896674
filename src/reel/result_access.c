/* The result's accessors (reel.h): one per field, named after it. The struct is private
 * (reel/result_internal.h), so fields can be added without breaking a program or the
 * Python package, which calls these by name. */
#include <math.h>
#include <stdlib.h>

#include "reel/result_internal.h"

/* a count or scalar: the field, or `none` for a NULL result */
#define RS_RESULT_VALUE(type, field, none) \
  type rs_reel_result_##field(const rs_reel_result *res) { return res ? res->field : (none); }

/* an array of `count` values: the field and its length, or NULL and 0 when the result has
 * none (NULL, an effect the problem did not have, no entries) */
#define RS_RESULT_ARRAY(type, field, count)                                    \
  const type *rs_reel_result_##field(const rs_reel_result *res, int *n)       \
  {                                                                            \
    const int len = res && res->field ? (count) : 0;                           \
    if (n) *n = len > 0 ? len : 0;                                             \
    return len > 0 ? res->field : NULL;                                        \
  }

RS_RESULT_VALUE(int, n_layers, 0)
RS_RESULT_ARRAY(double, radius, res->n_layers)
RS_RESULT_ARRAY(double, wound_on_tension, res->n_layers)
RS_RESULT_ARRAY(double, web_tension, res->n_layers)
RS_RESULT_ARRAY(double, nip_load, res->n_layers)
RS_RESULT_ARRAY(double, sigma_r, res->n_layers)
RS_RESULT_ARRAY(double, sigma_theta, res->n_layers)
RS_RESULT_VALUE(double, core_pressure, NAN)
RS_RESULT_VALUE(double, core_radius, NAN)
RS_RESULT_ARRAY(double, deformed_radius, res->n_layers)
RS_RESULT_ARRAY(double, wound_radius, res->n_layers)
RS_RESULT_ARRAY(double, wound_in_tension, res->n_layers)

RS_RESULT_ARRAY(double, at_speed_sigma_r, res->n_layers)
RS_RESULT_ARRAY(double, at_speed_sigma_theta, res->n_layers)
double rs_reel_result_at_speed_core_pressure(const rs_reel_result *res)
{
  return res && res->at_speed_sigma_r ? res->at_speed_core_pressure : NAN;
}

RS_RESULT_ARRAY(double, air_film_entrained, res->n_layers)
RS_RESULT_ARRAY(double, air_film, res->n_layers)
double rs_reel_result_air_wound_length(const rs_reel_result *res)
{
  return res && res->air_film ? res->air_wound_length : NAN;
}

RS_RESULT_VALUE(long, increments, 0)
RS_RESULT_VALUE(long, cvode_steps, 0)
RS_RESULT_VALUE(long, rhs_evals, 0)
RS_RESULT_VALUE(long, full_integrations, 0)
RS_RESULT_VALUE(double, wall_seconds, NAN)

RS_RESULT_VALUE(int, n_stages, 0)
RS_RESULT_ARRAY(int, stage_layers, res->n_stages)
RS_RESULT_ARRAY(double, stage_radius, res->n_stages)
RS_RESULT_ARRAY(double, stage_sigma_r, res->n_stages * res->n_layers)
RS_RESULT_ARRAY(double, stage_sigma_theta, res->n_stages * res->n_layers)

RS_RESULT_VALUE(int, n_nip, 0)
RS_RESULT_ARRAY(double, nip_radius, res->n_nip)
RS_RESULT_ARRAY(double, nip_T0, res->n_nip)
RS_RESULT_ARRAY(double, nip_Ti, res->n_nip)
RS_RESULT_ARRAY(double, nip_a, res->n_nip)
RS_RESULT_ARRAY(double, nip_solve_load, res->n_nip)
RS_RESULT_ARRAY(int, nip_iterations, res->n_nip)
RS_RESULT_VALUE(long, nip_solves, 0)
RS_RESULT_VALUE(long, nip_rejected, 0)
RS_RESULT_VALUE(int, n_profiles, 0)
RS_RESULT_ARRAY(double, profile_radius, res->n_profiles)
RS_RESULT_ARRAY(rs_nip_solution, profiles, res->n_profiles)

void rs_reel_result_drop_history(rs_reel_result *res)
{
  if (!res) return;
  free(res->stage_layers);
  free(res->stage_radius);
  free(res->stage_sigma_r);
  free(res->stage_sigma_theta);
  res->stage_layers = NULL;
  res->stage_radius = res->stage_sigma_r = res->stage_sigma_theta = NULL;
  res->n_stages = 0;
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
