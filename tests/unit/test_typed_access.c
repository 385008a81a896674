/* The lanes' and the storage stages' typed accessors (reel.h rs_lanes_result_<field>,
 * storage.h rs_storage_result_<field>; what the Python package calls by name): each gives
 * exactly the record's field (the same pointer) with its shape, and a result without lanes,
 * nip_load without a nip, and NULL give NULL and 0, 0. */
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/storage.h"
#include "storage/storage_result.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

static rs_reel_result *wind(const char *scene, rs_scene **keep)
{
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL;
  CHECK(rs_scene_load(scene, 0, NULL, &sc) == RS_OK);
  if (sc) CHECK(rs_scene_wind(sc, NULL, &res) == RS_OK);
  if (keep) *keep = sc;
  else rs_scene_destroy(&sc);
  return res;
}

typedef const double *(*lanes_fn)(const rs_reel_result *, int *, int *);

/* Three lanes, 200 layers: each accessor is its field, per lane m x 0, per layer N x 0,
 * layers x lanes N x m; no nip: nip_load NULL. */
static void lanes_arrays_are_the_fields(void)
{
  rs_reel_result *res = wind(RS_TESTS_DIR "/cli/scenes/lanes/band.yaml", NULL);
  if (!res) return;
  const rs_lanes_result *lr = res->lanes;
  CHECK(lr != NULL && lr->count == 3 && lr->n_layers == 200);
  if (!lr) return;
  const int m = lr->count, N = lr->n_layers;
  CHECK(rs_lanes_result_count(res) == m);
  const struct {
    lanes_fn get;
    const double *field;
    int rows, cols;
  } a[] = {{rs_lanes_result_x, lr->x, m, 0},
           {rs_lanes_result_width, lr->width, m, 0},
           {rs_lanes_result_caliper, lr->caliper, m, 0},
           {rs_lanes_result_core_pressure, lr->core_pressure, m, 0},
           {rs_lanes_result_outer_radius, lr->outer_radius, m, 0},
           {rs_lanes_result_strain, lr->strain, N, 0},
           {rs_lanes_result_wound_on_tension, lr->wound_on_tension, N, m},
           {rs_lanes_result_web_tension, lr->web_tension, N, m},
           {rs_lanes_result_final_sigma_r, lr->sigma_r, N, m},
           {rs_lanes_result_final_sigma_theta, lr->sigma_theta, N, m},
           {rs_lanes_result_final_radius, lr->radius, N, m}};
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i) {
    int rows = -1, cols = -1;
    CHECK(a[i].field != NULL);
    CHECK(a[i].get(res, &rows, &cols) == a[i].field);
    CHECK(rows == a[i].rows && cols == a[i].cols);
    CHECK(a[i].get(res, NULL, NULL) == a[i].field);
  }
  int rows = -1, cols = -1;
  CHECK(rs_lanes_result_slack(res, &rows, &cols) == lr->slack && rows == N && cols == m);
  rows = cols = -1;
  CHECK(rs_lanes_result_nip_load(res, &rows, &cols) == NULL && rows == 0 && cols == 0);
  CHECK(rs_lanes_result_x(res, NULL, NULL)[1] == 0.45); /* the middle of 0.9 m */
  rs_reel_result_destroy(&res);
}

/* A result without lanes and NULL: NULL, 0, 0 from every accessor. */
static void lanes_absent_and_null(void)
{
  rs_reel_result *res = wind(RS_TESTS_DIR "/cli/scenes/small.yaml", NULL);
  if (!res) return;
  const lanes_fn all[] = {rs_lanes_result_x, rs_lanes_result_width, rs_lanes_result_caliper,
                          rs_lanes_result_core_pressure, rs_lanes_result_outer_radius,
                          rs_lanes_result_strain, rs_lanes_result_wound_on_tension,
                          rs_lanes_result_web_tension, rs_lanes_result_nip_load,
                          rs_lanes_result_final_sigma_r, rs_lanes_result_final_sigma_theta,
                          rs_lanes_result_final_radius};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) {
    int rows = -1, cols = -1;
    CHECK(all[i](res, &rows, &cols) == NULL && rows == 0 && cols == 0);
    rows = cols = -1;
    CHECK(all[i](NULL, &rows, &cols) == NULL && rows == 0 && cols == 0);
  }
  int rows = -1, cols = -1;
  CHECK(rs_lanes_result_slack(res, &rows, &cols) == NULL && rows == 0 && cols == 0);
  CHECK(rs_lanes_result_count(res) == 0 && rs_lanes_result_count(NULL) == 0);
  rs_reel_result_destroy(&res);
}

/* The storage stages: S values of hours, temperature, humidity and core pressure, S x N of
 * the stresses, the fields themselves; NULL gives NULL and 0. */
static void storage_arrays_are_the_fields(void)
{
  rs_scene *sc = NULL;
  rs_reel_result *res = wind(RS_TESTS_DIR "/cli/scenes/storage-small.yaml", &sc);
  rs_storage_result *sr = NULL;
  if (res) CHECK(rs_storage_run(rs_scene_problem(sc), res, &sr) == RS_OK);
  if (sr) {
    const int S = sr->n_stages, N = sr->n_layers;
    CHECK(S == 4 && N == rs_reel_result_n_layers(res));
    CHECK(rs_storage_result_stages(sr) == S && rs_storage_result_n_layers(sr) == N);
    typedef const double *(*fn)(const rs_storage_result *, int *);
    const struct {
      fn get;
      const double *field;
      int n;
    } a[] = {{rs_storage_result_hours, sr->hours, S},
             {rs_storage_result_temperature, sr->temperature, S},
             {rs_storage_result_humidity, sr->humidity, S},
             {rs_storage_result_core_pressure, sr->core_pressure, S},
             {rs_storage_result_sigma_r, sr->sigma_r, S * N},
             {rs_storage_result_sigma_theta, sr->sigma_theta, S * N}};
    for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i) {
      int n = -1;
      CHECK(a[i].field != NULL && a[i].get(sr, &n) == a[i].field && n == a[i].n);
      CHECK(a[i].get(sr, NULL) == a[i].field);
      n = -1;
      CHECK(a[i].get(NULL, &n) == NULL && n == 0);
    }
    CHECK(rs_storage_result_core_pressure(sr, NULL)[0] == rs_reel_result_core_pressure(res));
    CHECK(rs_storage_result_defects(sr, S - 1) == sr->defects[S - 1]);
    CHECK(rs_storage_result_defects(sr, S) == NULL);
    CHECK(rs_storage_result_elastic_solves(sr) == sr->elastic_solves && sr->elastic_solves > 0);
    CHECK(rs_storage_result_max_substeps(sr) == sr->max_substeps && sr->max_substeps >= 1);
    CHECK(rs_storage_result_wall_seconds(sr) == sr->wall_seconds && sr->wall_seconds >= 0.0);
  }
  CHECK(rs_storage_result_stages(NULL) == 0 && rs_storage_result_n_layers(NULL) == 0);
  CHECK(rs_storage_result_elastic_solves(NULL) == 0 && rs_storage_result_max_substeps(NULL) == 0 &&
        rs_storage_result_wall_seconds(NULL) == 0.0);
  rs_storage_result_destroy(&sr);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

int main(int argc, char **argv)
{
  static const check_case cases[] = {
      {"lanes_arrays_are_the_fields", lanes_arrays_are_the_fields},
      {"lanes_absent_and_null", lanes_absent_and_null},
      {"storage_arrays_are_the_fields", storage_arrays_are_the_fields},
  };
  return CHECK_MAIN(argc, argv, cases);
}
