/* reelsim compare's library parts: rs_reel_wind_many gives each scene exactly what
 * rs_reel_wind gives it alone, whatever the number of threads, and keeps a failure to
 * its own job; rs_output_write_compare lays each run out as a run file does and
 * summarises them in order. */
#include <hdf5.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/output.h"
#include "reelsim/reader.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "synthetic.h"

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

static const char small_scene[] = RS_ROOT_DIR "/tests/cli/scenes/small.yaml";

static rs_scene *load(const char *path, int n_sets, const char *const *sets)
{
  rs_scene *s = NULL;
  rs_status st = rs_scene_load(path, n_sets, sets, &s);
  if (st != RS_OK) fprintf(stderr, "  load %s: %s\n", path, rs_error_message());
  CHECK(st == RS_OK);
  return s;
}

static int same_bits(const double *a, const double *b, int n)
{
  return n == 0 || memcmp(a, b, (size_t)n * sizeof *a) == 0;
}

static int same_result(const rs_reel_result *a, const rs_reel_result *b)
{
  int n = a->n_layers;
  return n == b->n_layers && same_bits(a->radius, b->radius, n) &&
         same_bits(a->wound_on_tension, b->wound_on_tension, n) &&
         same_bits(a->web_tension, b->web_tension, n) &&
         same_bits(a->nip_load, b->nip_load, n) && same_bits(a->sigma_r, b->sigma_r, n) &&
         same_bits(a->sigma_theta, b->sigma_theta, n) &&
         memcmp(&a->core_pressure, &b->core_pressure, sizeof(double)) == 0 &&
         a->cvode_steps == b->cvode_steps && a->rhs_evals == b->rhs_evals;
}

/* Three copies of one scene (one with a different tension) on 1, 2 and 3 threads, and
 * alone through rs_reel_wind: all bitwise alike. */
static void wind_many_matches_single(void)
{
  /* 100 layers: quick under valgrind */
  const char *sets[] = {"winding.final_radius=0.06", "winding.tension=260"};
  rs_scene *sc[3] = {load(small_scene, 1, sets), load(small_scene, 1, sets),
                     load(small_scene, 2, sets)};
  if (!sc[0] || !sc[1] || !sc[2]) return;
  rs_reel_result *alone[3] = {NULL, NULL, NULL};
  for (int i = 0; i < 3; ++i) CHECK(rs_scene_wind(sc[i], NULL, &alone[i]) == RS_OK);
  for (int threads = 1; threads <= 3; ++threads) {
    rs_reel_job jobs[3];
    memset(jobs, 0, sizeof jobs);
    for (int i = 0; i < 3; ++i) jobs[i].problem = rs_scene_problem(sc[i]);
    int used = 0;
    CHECK(rs_reel_wind_many(3, jobs, threads, &used) == RS_OK);
    printf("  %d threads asked, %d used\n", threads, used);
    CHECK(used == threads);
    for (int i = 0; i < 3; ++i) {
      CHECK(jobs[i].status == RS_OK && jobs[i].message[0] == '\0');
      CHECK(jobs[i].result && same_result(jobs[i].result, alone[i]));
      CHECK_LT(0.0, jobs[i].wall_seconds);
      rs_reel_result_destroy(&jobs[i].result);
    }
  }
  CHECK(alone[0]->n_layers == 100);
  CHECK_LOG("core pressure, 200 N/m (Pa)", alone[0]->core_pressure);
  CHECK_LOG("core pressure, 260 N/m (Pa)", alone[2]->core_pressure);
  CHECK(alone[0]->core_pressure != alone[2]->core_pressure); /* the jobs were not mixed */
  for (int i = 0; i < 3; ++i) {
    rs_reel_result_destroy(&alone[i]);
    rs_scene_destroy(&sc[i]);
  }
}

/* One job's solver failure stays in that job: the others finish, its message is its own. */
static void wind_many_failure_isolated(void)
{
  const char *fail[] = {"numerics.max_steps=1"};
  rs_scene *sc[3] = {load(small_scene, 0, NULL), load(small_scene, 1, fail),
                     load(small_scene, 0, NULL)};
  if (!sc[0] || !sc[1] || !sc[2]) return;
  rs_reel_job jobs[3];
  memset(jobs, 0, sizeof jobs);
  for (int i = 0; i < 3; ++i) jobs[i].problem = rs_scene_problem(sc[i]);
  CHECK(rs_reel_wind_many(3, jobs, 2, NULL) == RS_OK);
  printf("  job 2: %s\n  at %s\n", jobs[1].message, jobs[1].where);
  CHECK(jobs[0].status == RS_OK && jobs[2].status == RS_OK);
  CHECK(jobs[1].status == RS_ERR_SOLVER);
  CHECK(strstr(jobs[1].message, "CVODE") != NULL && jobs[1].where[0] != '\0');
  CHECK(jobs[0].result && jobs[0].result->n_layers == 200);
  CHECK(jobs[1].result && jobs[1].result->n_layers < 200); /* what it finished */
  CHECK(jobs[2].message[0] == '\0');
  for (int i = 0; i < 3; ++i) {
    rs_reel_result_destroy(&jobs[i].result);
    rs_scene_destroy(&sc[i]);
  }
  CHECK(rs_reel_wind_many(0, NULL, 0, NULL) == RS_OK);
  rs_reel_job bad = {0};
  CHECK(rs_reel_wind_many(1, &bad, 1, NULL) == RS_ERR_INTERNAL); /* no scene */
}

static void run_names(void)
{
  char b[64];
  rs_output_run_name(0, 2, "cases/newsprint-rider.yaml", b, sizeof b);
  CHECK(strcmp(b, "1-newsprint-rider") == 0);
  rs_output_run_name(2, 12, "a.b/c.d.yaml", b, sizeof b);
  CHECK(strcmp(b, "03-c.d") == 0);
  rs_output_run_name(99, 100, "plain", b, sizeof b);
  CHECK(strcmp(b, "100-plain") == 0);
  rs_output_run_name(0, 1, "dir/.yaml", b, sizeof b);
  CHECK(strcmp(b, "1-.yaml") == 0);
  rs_output_run_name(0, 1, "dir/", b, sizeof b);
  CHECK(strcmp(b, "1-scene") == 0);
}

static long long root_int(hid_t f, const char *obj, const char *name)
{
  long long v = -1;
  hid_t a = H5Aopen_by_name(f, obj, name, H5P_DEFAULT, H5P_DEFAULT);
  CHECK(a >= 0);
  if (a >= 0) {
    H5Aread(a, H5T_NATIVE_LLONG, &v);
    H5Aclose(a);
  }
  return v;
}

/* The comparison file's run `2-second` (reader a) has the datasets and run attributes of
 * the run file of the same run (reader b), bit for bit */
static void same_as_run_file(rs_reader *a, rs_reader *b)
{
  const char *sets[] = {"/final/radius", "/final/sigma_r", "/final/sigma_theta",
                        "/final/pressure", "/final/core_pressure", "/layers/radius",
                        "/layers/wound_on_tension", "/layers/web_tension",
                        "/layers/nip_load"};
  for (size_t k = 0; k < sizeof sets / sizeof *sets; ++k) {
    char p[256];
    snprintf(p, sizeof p, "/runs/2-second%s", sets[k]);
    double *x = NULL, *y = NULL;
    size_t nx = 0, ny = 0;
    CHECK(rs_reader_read_1d(a, p, &x, &nx) == RS_OK);
    CHECK(rs_reader_read_1d(b, sets[k], &y, &ny) == RS_OK);
    CHECK(nx == ny && x && y && same_bits(x, y, (int)nx));
    free(x);
    free(y);
  }
  const char *attrs[] = {"title", "scene_file", "scene"};
  for (size_t k = 0; k < 3; ++k) {
    char *x = NULL, *y = NULL;
    CHECK(rs_reader_attr_string(a, "/runs/2-second", attrs[k], &x) == RS_OK);
    CHECK(rs_reader_attr_string(b, "/", attrs[k], &y) == RS_OK);
    CHECK(x && y && strcmp(x, y) == 0);
    free(x);
    free(y);
  }
}

/* /summary of the comparison file (reader a): each figure of the two runs' results, in
 * run order, and the runs' names */
static void summary_in_run_order(rs_reader *a, rs_reel_result *const res[2])
{
  rs_reel_summary s[2];
  rs_reel_summarize(res[0], &s[0]);
  rs_reel_summarize(res[1], &s[1]);
  const struct {
    const char *name;
    double v0, v1;
  } fig[] = {{"core_pressure", s[0].core_pressure, s[1].core_pressure},
             {"peak_pressure", s[0].peak_pressure, s[1].peak_pressure},
             {"peak_pressure_radius", s[0].peak_pressure_radius, s[1].peak_pressure_radius},
             {"min_hoop_stress", s[0].min_hoop, s[1].min_hoop},
             {"min_hoop_stress_radius", s[0].min_hoop_radius, s[1].min_hoop_radius},
             {"wot_min", s[0].wot_min, s[1].wot_min},
             {"wot_max", s[0].wot_max, s[1].wot_max},
             {"final_radius", s[0].final_radius, s[1].final_radius},
             {"wall_seconds", res[0]->wall_seconds, res[1]->wall_seconds},
             {"layers", 30, 45}};
  for (size_t k = 0; k < sizeof fig / sizeof *fig; ++k) {
    char p[128];
    snprintf(p, sizeof p, "/summary/%s", fig[k].name);
    double *v = NULL;
    size_t n = 0;
    CHECK(rs_reader_read_1d(a, p, &v, &n) == RS_OK);
    CHECK(n == 2 && v && same_bits(&v[0], &fig[k].v0, 1) && same_bits(&v[1], &fig[k].v1, 1));
    if (n == 2) printf("  %-24s %.17g %.17g\n", fig[k].name, v[0], v[1]);
    free(v);
  }
  char **names = NULL;
  size_t n = 0;
  CHECK(rs_reader_read_strings(a, "/summary/run", &names, &n) == RS_OK);
  CHECK(n == 2 && strcmp(names[0], "1-first") == 0 && strcmp(names[1], "2-second") == 0);
  rs_reader_free_strings(&names, n);
}

/* Every run's layout equals a run file's; /summary holds rs_reel_summarize's figures. */
static void compare_layout(void)
{
  char *dir = scratch_dir("compare");
  char *cmp = scratch_join(dir, "cmp.h5"), *one = scratch_join(dir, "one.h5");
  rs_scene *sc[2] = {syn_scene("x/first.yaml", "first"), syn_scene("second.yml", "second")};
  rs_reel_result *res[2] = {syn_result(30, 1.0), syn_result(45, 2.0)};
  rs_output_run runs[2] = {{sc[0], res[0]}, {sc[1], res[1]}};
  CHECK(rs_output_write_compare(cmp, 2, runs) == RS_OK);
  CHECK(rs_output_write(one, sc[1], res[1]) == RS_OK);

  hid_t f = H5Fopen(cmp, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  CHECK(root_int(f, "/", "runs") == 2);
  CHECK(root_int(f, "/runs/2-second", "layers") == 45);
  CHECK(root_int(f, "/runs/1-first", "layers_planned") == 200);
  CHECK(H5Aexists_by_name(f, "/", "version", H5P_DEFAULT) > 0);
  CHECK(H5Aexists_by_name(f, "/", "title", H5P_DEFAULT) == 0); /* titles are per run */
  H5Fclose(f);

  /* the same datasets and run attributes as the run file of the same run; /summary */
  rs_reader *a = NULL, *b = NULL;
  CHECK(rs_reader_open(cmp, &a) == RS_OK && rs_reader_open(one, &b) == RS_OK);
  if (a && b) {
    same_as_run_file(a, b);
    summary_in_run_order(a, res);
  }
  rs_reader_close(&a);
  rs_reader_close(&b);

  /* a missing directory fails first, and nothing is left */
  char *bad = scratch_join(dir, "missing/cmp.h5");
  CHECK(rs_output_write_compare(bad, 2, runs) == RS_ERR_IO);
  CHECK(strstr(rs_error_message(), "does not exist") != NULL);
  CHECK(scratch_count_entries(dir) == 2);
  for (int i = 0; i < 2; ++i) {
    syn_scene_free(sc[i]);
    rs_reel_result_destroy(&res[i]);
  }
  scratch_remove_tree(dir);
  free(bad);
  free(cmp);
  free(one);
  free(dir);
}

static const check_case cases[] = {
    {"wind_many_matches_single", wind_many_matches_single},
    {"wind_many_failure_isolated", wind_many_failure_isolated},
    {"run_names", run_names},
    {"compare_layout", compare_layout},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
