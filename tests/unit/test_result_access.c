/* The result's typed accessors (reel.h; what the Python package calls by name): each gives
 * exactly the struct's field (the same pointer, the same value), absent effects and NULL
 * give NULL and 0, NaN or 0, and the finite check is rs_reel_summary_finite
 * of the result's summary (a NaN planted in the outer radius, an infinite core pressure). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

static rs_reel_result *wind_small(void)
{
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL;
  CHECK(rs_scene_load(RS_TESTS_DIR "/install/newsprint-small.yaml", 0, NULL, &sc) == RS_OK);
  if (sc) CHECK(rs_scene_wind(sc, NULL, &res) == RS_OK);
  rs_scene_destroy(&sc);
  return res;
}

static void arrays_are_the_fields(void)
{
  rs_reel_result *res = wind_small();
  if (!res) return;
  CHECK(res->n_layers > 10);
  CHECK(rs_reel_result_n_layers(res) == res->n_layers);
  typedef const double *(*array_fn)(const rs_reel_result *, int *);
  const struct {
    array_fn get;
    const double *field;
  } a[] = {{rs_reel_result_radius, res->radius},
           {rs_reel_result_wound_on_tension, res->wound_on_tension},
           {rs_reel_result_web_tension, res->web_tension},
           {rs_reel_result_nip_load, res->nip_load},
           {rs_reel_result_sigma_r, res->sigma_r},
           {rs_reel_result_sigma_theta, res->sigma_theta},
           {rs_reel_result_deformed_radius, res->deformed_radius},
           {rs_reel_result_wound_radius, res->wound_radius},
           {rs_reel_result_wound_in_tension, res->wound_in_tension}};
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i) {
    int n = -1;
    CHECK(a[i].field != NULL);
    CHECK(a[i].get(res, &n) == a[i].field);
    CHECK(n == res->n_layers);
    CHECK(a[i].get(res, NULL) == a[i].field);
  }
  CHECK(memcmp(&(double){rs_reel_result_core_pressure(res)}, &res->core_pressure,
               sizeof(double)) == 0);
  CHECK(rs_reel_result_core_radius(res) == res->core_radius);
  CHECK(rs_reel_result_wall_seconds(res) == res->wall_seconds);
  CHECK(rs_reel_result_increments(res) == res->increments && res->increments > 0);
  CHECK(rs_reel_result_cvode_steps(res) == res->cvode_steps && res->cvode_steps > 0);
  CHECK(rs_reel_result_rhs_evals(res) == res->rhs_evals);
  CHECK(rs_reel_result_full_integrations(res) == res->full_integrations);
  CHECK(res->core_pressure > 0.0 && res->core_radius == 0.0762);
  rs_reel_result_destroy(&res);
}

/* The history and the nip record by their accessors: the stage arrays are n_stages long
 * (radius, layers) or n_stages x n_layers (stresses); dropping the history empties them. */
static void history_and_nip(void)
{
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL;
  const char *sets[] = {"output.history_every=20"};
  CHECK(rs_scene_load(RS_TESTS_DIR "/install/newsprint-small.yaml", 1, sets, &sc) == RS_OK);
  if (sc) CHECK(rs_scene_wind(sc, NULL, &res) == RS_OK);
  rs_scene_destroy(&sc);
  if (!res) return;
  const int S = res->n_stages, N = res->n_layers;
  CHECK(S > 1 && rs_reel_result_n_stages(res) == S);
  int n = -1;
  CHECK(rs_reel_result_stage_layers(res, &n) == res->stage_layers && n == S);
  CHECK(rs_reel_result_stage_layers(res, &n)[S - 1] == N);
  CHECK(rs_reel_result_stage_radius(res, &n) == res->stage_radius && n == S);
  CHECK(rs_reel_result_stage_sigma_r(res, &n) == res->stage_sigma_r && n == S * N);
  CHECK(rs_reel_result_stage_sigma_theta(res, &n) == res->stage_sigma_theta && n == S * N);
  CHECK(rs_reel_result_n_nip(res) == res->n_nip);
  CHECK(rs_reel_result_nip_radius(res, &n) == (res->n_nip > 0 ? res->nip_radius : NULL));
  CHECK(n == res->n_nip);
  CHECK(rs_reel_result_nip_solves(res) == res->nip_solves);
  CHECK(rs_reel_result_nip_rejected(res) == res->nip_rejected);
  CHECK(rs_reel_result_n_profiles(res) == 0 && rs_reel_result_profiles(res, &n) == NULL && n == 0);
  rs_reel_result_drop_history(res);
  CHECK(rs_reel_result_n_stages(res) == 0 && res->stage_sigma_r == NULL);
  n = -1;
  CHECK(rs_reel_result_stage_sigma_r(res, &n) == NULL && n == 0);
  CHECK(rs_reel_result_radius(res, NULL) != NULL); /* the final state stays */
  rs_reel_result_destroy(&res);
}

/* Effects the problem did not have, and NULL: NULL arrays of length 0, NaN, 0. */
static void absent_and_null(void)
{
  rs_reel_result *res = wind_small();
  if (!res) return;
  int n = -1;
  CHECK(rs_reel_result_air_film(res, &n) == NULL && n == 0);
  n = -1;
  CHECK(rs_reel_result_at_speed_sigma_r(res, &n) == NULL && n == 0);
  CHECK(isnan(rs_reel_result_at_speed_core_pressure(res)));
  CHECK(isnan(rs_reel_result_air_wound_length(res)));
  n = -1;
  CHECK(rs_reel_result_radius(NULL, &n) == NULL && n == 0);
  CHECK(rs_reel_result_stage_layers(NULL, &n) == NULL && n == 0);
  CHECK(isnan(rs_reel_result_core_pressure(NULL)));
  CHECK(rs_reel_result_n_layers(NULL) == 0 && rs_reel_result_n_stages(NULL) == 0);
  CHECK(rs_reel_result_cvode_steps(NULL) == 0);
  rs_reel_result_drop_history(NULL);
  rs_reel_result_destroy(&res);
}

static void finite(void)
{
  rs_reel_result *res = wind_small();
  if (!res) return;
  const char *what = NULL;
  CHECK(rs_reel_result_finite(res, &what) == 1);
  CHECK(what == NULL);
  const int n = res->n_layers;
  const double outer = res->radius[n - 1];
  res->radius[n - 1] = NAN;
  CHECK(rs_reel_result_finite(res, &what) == 0);
  CHECK(what != NULL && strcmp(what, "final radius") == 0);
  res->radius[n - 1] = outer;
  what = NULL;
  CHECK(rs_reel_result_finite(res, &what) == 1);
  res->core_pressure = INFINITY;
  what = NULL;
  CHECK(rs_reel_result_finite(res, &what) == 0);
  CHECK(what != NULL && strcmp(what, "core pressure") == 0);
  CHECK(rs_reel_result_finite(NULL, &what) == 0);
  rs_reel_result_destroy(&res);
}

int main(int argc, char **argv)
{
  static const check_case cases[] = {
      {"arrays_are_the_fields", arrays_are_the_fields},
      {"history_and_nip", history_and_nip},
      {"absent_and_null", absent_and_null},
      {"finite", finite},
  };
  return CHECK_MAIN(argc, argv, cases);
}
