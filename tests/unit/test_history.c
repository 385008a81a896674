/* The stress history: stages land where docs/scenes.md says (first increment boundary at
 * or after each multiple of output.history_every, the final state last), hold NaN
 * exactly for the layers not yet wound, and each stage is the reel a shorter run winds
 * (an independent run to that radius). The file's /history reads back bit for bit. */

#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#include <hdf5.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/output.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

static const char *small = RS_TESTS_DIR "/cli/scenes/small.yaml"; /* 200 layers, t = 100 um */

/* Loads small.yaml with overrides and winds it; NULL result on failure. */
static rs_reel_result *wind(int n_sets, const char **sets, rs_status *st_out,
                            const rs_reel_options *opts)
{
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL;
  rs_status st = rs_scene_load(small, n_sets, sets, &sc);
  if (st == RS_OK) st = rs_scene_wind(sc, opts, &res);
  if (st_out) *st_out = st;
  if (st != RS_OK && !st_out) printf("  error: %s\n", rs_error_message());
  rs_scene_destroy(&sc);
  return res;
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* Every stage: finite below its outer radius, NaN exactly above; stages increasing. */
static void check_stage_shape(const rs_reel_result *res)
{
  int n = res->n_layers, bad = 0;
  for (int s = 0; s < res->n_stages; ++s) {
    int k = res->stage_layers[s];
    if (s > 0) {
      CHECK(k > res->stage_layers[s - 1]);
      CHECK_LT(res->stage_radius[s - 1], res->stage_radius[s]);
    }
    CHECK_CLOSE(res->stage_radius[s], res->radius[k - 1], 1e-15);
    for (int j = 0; j < n; ++j) {
      double a = res->stage_sigma_r[(size_t)s * n + j],
             b = res->stage_sigma_theta[(size_t)s * n + j];
      if (j < k)
        bad += !isfinite(a) || !isfinite(b);
      else
        bad += !isnan(a) || !isnan(b);
    }
  }
  CHECK(bad == 0);
}

static void check_last_is_final(const rs_reel_result *res)
{
  int n = res->n_layers, S = res->n_stages, diff = 0;
  CHECK(S >= 1);
  if (S < 1) return;
  CHECK(res->stage_layers[S - 1] == n);
  CHECK(same_bits(res->stage_radius[S - 1], res->radius[n - 1]));
  for (int j = 0; j < n; ++j)
    diff += !same_bits(res->stage_sigma_r[(size_t)(S - 1) * n + j], res->sigma_r[j]) ||
            !same_bits(res->stage_sigma_theta[(size_t)(S - 1) * n + j], res->sigma_theta[j]);
  CHECK(diff == 0);
}

static void last_stage_is_final(void)
{
  const char *sets[] = {"output.history_every=50"};
  rs_reel_result *res = wind(1, sets, NULL, NULL);
  CHECK(res && res->n_stages == 4);
  if (!res) return;
  for (int s = 0; s < res->n_stages; ++s)
    CHECK(res->stage_layers[s] == 50 * (s + 1));
  check_last_is_final(res);
  rs_reel_result_destroy(&res);
}

static void nan_above_outer_radius(void)
{
  const char *sets[] = {"output.history_every=7"};
  rs_reel_result *res = wind(1, sets, NULL, NULL);
  CHECK(res && res->n_stages == 200 / 7 + 1); /* 28 multiples, then the final 200 */
  if (!res) return;
  check_stage_shape(res);
  check_last_is_final(res);
  rs_reel_result_destroy(&res);
}

/* A stage after k layers is the reel that a run wound only to k layers ends with
 * (constant tension, one layer per step: the same increments in the same order). */
static void stage_is_shorter_run(void)
{
  const char *sets[] = {"output.history_every=60"};
  rs_reel_result *res = wind(1, sets, NULL, NULL);
  CHECK(res && res->n_stages == 4); /* 60, 120, 180, 200 */
  if (!res) return;
  for (int s = 0; s < res->n_stages - 1; ++s) {
    int k = res->stage_layers[s];
    char set[64];
    snprintf(set, sizeof set, "winding.final_radius=%.17g", 0.05 + k * 100.0e-6);
    const char *sets2[] = {set};
    rs_reel_result *part = wind(1, sets2, NULL, NULL);
    CHECK(part && part->n_layers == k);
    if (!part) continue;
    double worst = 0.0;
    for (int j = 0; j < k; ++j) {
      double a = res->stage_sigma_r[(size_t)s * res->n_layers + j];
      double b = res->stage_sigma_theta[(size_t)s * res->n_layers + j];
      worst = fmax(worst, fabs(a - part->sigma_r[j]) / fabs(part->sigma_r[j]));
      worst = fmax(worst, fabs(b - part->sigma_theta[j]) / fabs(part->sigma_theta[j]));
    }
    CHECK_LOG("stage layers", k);
    CHECK_LOG("  worst relative difference to a run of k layers", worst);
    CHECK(worst <= 1e-12);
    CHECK_CLOSE(res->stage_radius[s], part->radius[k - 1], 1e-15);
    rs_reel_result_destroy(&part);
  }
  rs_reel_result_destroy(&res);
}

/* Increments of 3 layers end at 3, 6, ..., 198, 200: the first at or after 50, 100,
 * 150, 200 are 51, 102, 150, 200. */
static void step_boundaries(void)
{
  const char *sets[] = {"output.history_every=50", "numerics.layers_per_step=3"};
  rs_reel_result *res = wind(2, sets, NULL, NULL);
  static const int want[] = {51, 102, 150, 200};
  CHECK(res && res->n_stages == 4);
  if (!res || res->n_stages != 4) return;
  for (int s = 0; s < 4; ++s)
    CHECK(res->stage_layers[s] == want[s]);
  check_stage_shape(res);
  check_last_is_final(res);
  rs_reel_result_destroy(&res);
}

static void every_beyond_reel(void)
{
  const char *sets[] = {"output.history_every=1000"};
  rs_reel_result *res = wind(1, sets, NULL, NULL);
  CHECK(res && res->n_stages == 1);
  if (!res) return;
  check_last_is_final(res);
  rs_reel_result_destroy(&res);
}

static void no_history(void)
{
  rs_reel_result *res = wind(0, NULL, NULL, NULL);
  CHECK(res && res->n_stages == 0);
  if (!res) return;
  CHECK(!res->stage_layers && !res->stage_radius && !res->stage_sigma_r && !res->stage_sigma_theta);
  rs_reel_result_destroy(&res);
}

/* 49 500 layers stored every layer would be 39 GB: refused before winding. */
static void memory_cap(void)
{
  const char *sets[] = {"winding.final_radius=5", "output.history_every=1"};
  rs_status st;
  rs_reel_result *res = wind(2, sets, &st, NULL);
  printf("  message: %s\n", rs_error_message());
  CHECK(st == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "output.history_every = 1 would store 49500 stages") != NULL);
  /* at most N/e + 1 stages of N layers, 16 bytes a cell, within 2 GiB:
   * N/e + 1 <= floor(2^31 / (16 N)) = 2711, so e >= 49500/2710 -> 19 */
  CHECK(strstr(rs_error_message(), "use output.history_every >= 19") != NULL);
  rs_reel_result_destroy(&res);
}

static int stop_at_120(void *user, int done, int total)
{
  (void)user;
  (void)total;
  return done >= 120;
}

/* A run stopped early closes its history with the state it reached, rows packed to
 * the layers wound. */
static void early_stop(void)
{
  const char *sets[] = {"output.history_every=50"};
  rs_reel_options opts = {.progress = stop_at_120, .user = NULL};
  rs_status st;
  rs_reel_result *res = wind(1, sets, &st, &opts);
  CHECK(st == RS_ERR_INTERRUPTED);
  CHECK(res && res->n_layers == 120 && res->n_stages == 3);
  if (!res || res->n_stages != 3) return;
  CHECK(res->stage_layers[0] == 50 && res->stage_layers[1] == 100 && res->stage_layers[2] == 120);
  check_stage_shape(res);
  check_last_is_final(res);
  rs_reel_result_destroy(&res);
}

/* ---- the file ---------------------------------------------------------------------- */

static char *tmp_path(const char *name)
{
  static char dir[64];
  snprintf(dir, sizeof dir, "/tmp/rs_test_history_XXXXXX");
  if (!mkdtemp(dir)) exit(2);
  size_t n = strlen(dir) + strlen(name) + 2;
  char *p = malloc(n);
  snprintf(p, n, "%s/%s", dir, name);
  return p;
}

static void remove_file_and_dir(char *path)
{
  unlink(path);
  char *slash = strrchr(path, '/');
  *slash = '\0';
  rmdir(path);
  free(path);
}

/* Reads a whole dataset of doubles; *dims gets its shape (rank <= 2). */
static double *read_doubles(hid_t file, const char *name, hsize_t dims[2], int *rank)
{
  hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
  if (d < 0) return NULL;
  hid_t sp = H5Dget_space(d);
  dims[0] = dims[1] = 1;
  *rank = H5Sget_simple_extent_dims(sp, dims, NULL);
  size_t n = (size_t)H5Sget_simple_extent_npoints(sp);
  double *v = malloc((n ? n : 1) * sizeof *v);
  if (n && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0) {
    free(v);
    v = NULL;
  }
  H5Sclose(sp);
  H5Dclose(d);
  return v;
}

static int write_run(const char *path, const char *every, rs_reel_result **res_out)
{
  rs_scene *sc = NULL;
  const char *sets[] = {every};
  rs_status st = rs_scene_load(small, 1, sets, &sc);
  if (st == RS_OK) st = rs_scene_wind(sc, NULL, res_out);
  if (st == RS_OK) st = rs_output_write(path, sc, *res_out);
  if (st != RS_OK) printf("  error: %s\n", rs_error_message());
  rs_scene_destroy(&sc);
  return st == RS_OK;
}

static void file_round_trip(void)
{
  char *path = tmp_path("h.h5");
  rs_reel_result *res = NULL;
  CHECK(write_run(path, "output.history_every=50", &res));
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  if (f >= 0 && res) {
    int S = res->n_stages, n = res->n_layers, rank, diff = 0;
    hsize_t dims[2];
    double *sr = read_doubles(f, "/history/sigma_r", dims, &rank);
    CHECK(sr && rank == 2 && dims[0] == (hsize_t)S && dims[1] == (hsize_t)n);
    double *st = read_doubles(f, "/history/sigma_theta", dims, &rank);
    CHECK(st && rank == 2 && dims[0] == (hsize_t)S && dims[1] == (hsize_t)n);
    double *rad = read_doubles(f, "/history/outer_radius", dims, &rank);
    CHECK(rad && rank == 1 && dims[0] == (hsize_t)S);
    double *fr = read_doubles(f, "/final/sigma_r", dims, &rank);
    double *ft = read_doubles(f, "/final/sigma_theta", dims, &rank);
    CHECK(fr && ft && dims[0] == (hsize_t)n);
    long long layers[8] = {0};
    hid_t d = H5Dopen2(f, "/history/layers", H5P_DEFAULT);
    CHECK(d >= 0 && S <= 8);
    if (d >= 0) {
      CHECK(H5Dread(d, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, layers) >= 0);
      H5Dclose(d);
    }
    if (sr && st && rad && fr && ft) {
      for (size_t i = 0; i < (size_t)S * n; ++i)
        diff += !same_bits(sr[i], res->stage_sigma_r[i]) ||
                !same_bits(st[i], res->stage_sigma_theta[i]);
      for (int s = 0; s < S; ++s)
        diff += !same_bits(rad[s], res->stage_radius[s]) || layers[s] != res->stage_layers[s];
      /* the last stored stage is /final, exactly */
      for (int j = 0; j < n; ++j)
        diff += !same_bits(sr[(size_t)(S - 1) * n + j], fr[j]) ||
                !same_bits(st[(size_t)(S - 1) * n + j], ft[j]);
      /* NaN exactly above each stage's outer radius */
      for (int s = 0; s < S; ++s)
        for (int j = 0; j < n; ++j)
          diff += (j < layers[s]) != (int)isfinite(sr[(size_t)s * n + j]);
    }
    CHECK(diff == 0);
    free(sr);
    free(st);
    free(rad);
    free(fr);
    free(ft);
    H5Fclose(f);
  }
  rs_reel_result_destroy(&res);
  remove_file_and_dir(path);
}

static void file_without_history(void)
{
  char *path = tmp_path("n.h5");
  rs_reel_result *res = NULL;
  CHECK(write_run(path, "output.history_every=0", &res));
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  if (f >= 0) {
    CHECK(H5Lexists(f, "/history", H5P_DEFAULT) == 0);
    CHECK(H5Lexists(f, "/final", H5P_DEFAULT) > 0);
    H5Fclose(f);
  }
  rs_reel_result_destroy(&res);
  remove_file_and_dir(path);
}

static const check_case cases[] = {
    {"last_stage_is_final", last_stage_is_final},
    {"nan_above_outer_radius", nan_above_outer_radius},
    {"stage_is_shorter_run", stage_is_shorter_run},
    {"step_boundaries", step_boundaries},
    {"every_beyond_reel", every_beyond_reel},
    {"no_history", no_history},
    {"memory_cap", memory_cap},
    {"early_stop", early_stop},
    {"file_round_trip", file_round_trip},
    {"file_without_history", file_without_history},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
