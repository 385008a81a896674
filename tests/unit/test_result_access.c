/* The result by name (rs_reel_result_array/scalar/layers/finite, what the Python package
 * reads): each name gives exactly the struct's field (the same pointer, the same value),
 * unknown names and NULL give NULL/NaN/0, and the finite check is rs_reel_summary_finite
 * of the result's summary (a NaN planted in the outer radius, an infinite core pressure). */
#include <math.h>
#include <string.h>

#include "check.h"
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
  CHECK(rs_reel_result_layers(res) == res->n_layers);
  const struct {
    const char *name;
    const double *field;
  } a[] = {{"radius", res->radius},           {"wound_on_tension", res->wound_on_tension},
           {"web_tension", res->web_tension}, {"nip_load", res->nip_load},
           {"sigma_r", res->sigma_r},         {"sigma_theta", res->sigma_theta}};
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i) {
    int n = -1;
    CHECK(rs_reel_result_array(res, a[i].name, &n) == a[i].field);
    CHECK(n == res->n_layers);
    CHECK(rs_reel_result_array(res, a[i].name, NULL) == a[i].field);
  }
  CHECK(memcmp(&(double){rs_reel_result_scalar(res, "core_pressure")}, &res->core_pressure,
               sizeof(double)) == 0);
  CHECK(rs_reel_result_scalar(res, "core_radius") == res->core_radius);
  CHECK(rs_reel_result_scalar(res, "wall_seconds") == res->wall_seconds);
  CHECK(res->core_pressure > 0.0 && res->core_radius == 0.0762);
  rs_reel_result_destroy(&res);
}

static void unknown_names(void)
{
  rs_reel_result *res = wind_small();
  if (!res) return;
  int n = -1;
  CHECK(rs_reel_result_array(res, "pressure", &n) == NULL); /* not a field: -sigma_r */
  CHECK(n == 0);
  n = -1;
  CHECK(rs_reel_result_array(res, "Radius", &n) == NULL && n == 0);
  CHECK(rs_reel_result_array(res, NULL, &n) == NULL && n == 0);
  n = -1;
  CHECK(rs_reel_result_array(NULL, "radius", &n) == NULL && n == 0);
  CHECK(isnan(rs_reel_result_scalar(res, "n_layers")));
  CHECK(isnan(rs_reel_result_scalar(res, NULL)));
  CHECK(isnan(rs_reel_result_scalar(NULL, "core_pressure")));
  CHECK(rs_reel_result_layers(NULL) == 0);
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
      {"unknown_names", unknown_names},
      {"finite", finite},
  };
  return CHECK_MAIN(argc, argv, cases);
}
