/* reelsim optimize's pieces (src/sweep/optimize*.c): constraints as text, the figure
 * names, the target-profile file and its misfit (against a profile whose interpolation is
 * exact), the history file. The search itself is tested end to end (optimize.sh). */
#include <hdf5.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "scratch.h"
#include "sweep/optimize.h"

static opt_var two_vars[2];

static void setup_vars(void)
{
  memset(two_vars, 0, sizeof two_vars);
  snprintf(two_vars[0].key, sizeof two_vars[0].key, "winding.tension");
  two_vars[0].lo = 100, two_vars[0].hi = 500;
  snprintf(two_vars[1].key, sizeof two_vars[1].key, "nip.load");
  two_vars[1].lo = 0, two_vars[1].hi = 2000;
}

static void constraints(void)
{
  setup_vars();
  opt_constraint c;
  char why[256];
  CHECK(opt_constraint_parse("core_pressure<=2e6", 2, two_vars, &c, why, sizeof why) == 0);
  CHECK(c.quantity == SWEEP_FIG_CORE_PRESSURE && !c.ge && c.bound == 2e6);
  CHECK(opt_constraint_parse("  min_sigma_theta >= -1.5e3 ", 2, two_vars, &c, why, sizeof why) == 0);
  CHECK(c.quantity == SWEEP_FIG_MIN_SIGMA_THETA && c.ge && c.bound == -1.5e3);
  CHECK(opt_constraint_parse("nip.load<=1000", 2, two_vars, &c, why, sizeof why) == 0);
  CHECK(c.quantity == OPT_N_FIGURES + 1 && !c.ge);
  CHECK(opt_constraint_parse("misfit<=10", 2, two_vars, &c, why, sizeof why) == 0);
  CHECK(c.quantity == OPT_MISFIT);
  const char *bad[] = {"core_pressure<2e6", "core_pressure=2e6", "<=5", "core_pressure<=",
                       "core_pressure<=abc", "core_pressure<=1e999", "hoop<=1",
                       "core_pressure<=1>=2", "core_pressure<=5 kPa"};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    why[0] = '\0';
    CHECK(opt_constraint_parse(bad[i], 2, two_vars, &c, why, sizeof why) != 0);
    CHECK(why[0] != '\0');
  }
  CHECK(opt_constraint_parse("hoop<=1", 2, two_vars, &c, why, sizeof why) != 0);
  CHECK(strstr(why, "unknown figure 'hoop'") != NULL);
}

static void figures(void)
{
  setup_vars();
  /* every figure of sweep's table, then misfit, then the varied keys */
  for (int f = 0; f < SWEEP_N_FIGURES; ++f) {
    CHECK(opt_figure_index(sweep_figures[f].name) == f);
    CHECK(strcmp(opt_figure_name(f), sweep_figures[f].name) == 0);
  }
  CHECK(opt_figure_index("misfit") == OPT_MISFIT);
  CHECK(opt_figure_index("buckling_layers") >= 0);
  CHECK(opt_figure_index("nope") == -1);
  CHECK(opt_quantity_index("nip.load", 2, two_vars) == OPT_N_FIGURES + 1);
  CHECK(opt_quantity_index("nip", 2, two_vars) == -1);
  char list[512];
  opt_figure_list(list, sizeof list);
  CHECK(strstr(list, "core_pressure") != NULL && strstr(list, ", misfit") != NULL);
}

static char *write_file(const char *dir, const char *name, const char *text)
{
  char *p = scratch_join(dir, name);
  FILE *f = fopen(p, "w");
  CHECK(f != NULL);
  if (f) {
    fputs(text, f);
    fclose(f);
  }
  return p;
}

static void target_file(void)
{
  char *dir = scratch_dir("opt_target");
  char *p = write_file(dir, "t.csv",
                       "radius_m,pressure_Pa\n# a comment\n0.08, 1.5e5\n\n0.09\t2e5\n0.1;0\r\n");
  opt_target t;
  char err[512];
  CHECK(opt_target_read(p, &t, err, sizeof err) == 0);
  CHECK(t.n == 3);
  if (t.n == 3) {
    CHECK(t.radius[0] == 0.08 && t.pressure[0] == 1.5e5);
    CHECK(t.radius[1] == 0.09 && t.pressure[1] == 2e5);
    CHECK(t.radius[2] == 0.1 && t.pressure[2] == 0);
  }
  opt_target_free(&t);
  free(p);
  p = write_file(dir, "noheader.csv", "0.08,1\n0.09,2\n");
  CHECK(opt_target_read(p, &t, err, sizeof err) == 0 && t.n == 2);
  opt_target_free(&t);
  free(p);
  scratch_remove_tree(dir);
  free(dir);
}

/* A malformed file is refused naming the file and the line. */
static void target_refused(void)
{
  char *dir = scratch_dir("opt_target_bad");
  struct {
    const char *text, *line;
  } bad[] = {{"radius,pressure\n0.08,1e5\n0.09,abc\n", "bad.csv:3:"},
             {"0.08,1e5\nradius,pressure\n", "bad.csv:2:"},
             {"0.08\n", "bad.csv:1:"},
             {"0.08,1,2\n", "bad.csv:1:"},
             {"-0.08,1\n", "bad.csv:1: the radius must be positive"},
             {"radius,pressure\n", "bad.csv:1: no (radius, pressure) pairs"},
             {"0.08,nan\n", "bad.csv:1:"}};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    char *p = write_file(dir, "bad.csv", bad[i].text);
    opt_target t;
    char err[512] = "";
    CHECK(opt_target_read(p, &t, err, sizeof err) != 0);
    CHECK(t.n == 0 && t.radius == NULL);
    fprintf(stderr, "  %s\n", err);
    CHECK(strstr(err, bad[i].line) != NULL);
    free(p);
  }
  opt_target t;
  char err[512] = "";
  CHECK(opt_target_read("/nonexistent/t.csv", &t, err, sizeof err) != 0);
  CHECK(strstr(err, "/nonexistent/t.csv: cannot read") != NULL);
  scratch_remove_tree(dir);
  free(dir);
}

/* A profile linear in r, p = a - b r, is interpolated exactly: the misfit to points of
 * p + d at any radii inside the roll is |d|; outside, the end values hold. */
static void misfit_closed_form(void)
{
  enum { N = 20 };
  double radius[N], sigma_r[N];
  const double r0 = 0.05, a = 3e5, b = 2e6;
  rs_reel_result res;
  memset(&res, 0, sizeof res);
  res.n_layers = N;
  res.radius = radius;
  res.sigma_r = sigma_r;
  res.core_radius = r0;
  res.core_pressure = a - b * r0;
  for (int i = 0; i < N; ++i) {
    radius[i] = r0 + 0.001 * (i + 1);
    sigma_r[i] = -(a - b * radius[i]);
  }
  double tr[4] = {0.0503, 0.05, 0.0611, 0.07};
  double tp[4];
  for (int i = 0; i < 4; ++i) tp[i] = a - b * tr[i] + (i % 2 ? 100 : -100);
  opt_target t = {4, tr, tp};
  CHECK_CLOSE(opt_target_misfit(&t, &res), 100, 1e-9);
  /* beyond the outer radius the last layer's pressure; inside the core the core's */
  double far_r[2] = {0.2, 0.01}, far_p[2] = {a - b * radius[N - 1], a - b * r0};
  opt_target far = {2, far_r, far_p};
  CHECK_ABS(opt_target_misfit(&far, &res), 0, 1e-9);
  res.n_layers = 0;
  CHECK(isnan(opt_target_misfit(&t, &res)));
  CHECK(isnan(opt_target_misfit(NULL, &res)));
}

/* A history of three evaluations written and read back: the contract's paths. */
/* For reading a fixed-length string type (closed here) NUL-terminated: a copy one byte
 * wider (its width in *width), after checking it is not variable-length. */
static hid_t nul_terminated(hid_t ftype, size_t *width)
{
  CHECK(H5Tis_variable_str(ftype) == 0);
  hid_t t = H5Tcopy(ftype); /* H5Dget_type's and H5Aget_type's copies are read-only */
  H5Tclose(ftype);
  *width = H5Tget_size(t) + 1;
  H5Tset_size(t, *width);
  H5Tset_strpad(t, H5T_STR_NULLTERM);
  return t;
}

static void history_file(void)
{
  setup_vars();
  double values[6] = {100, 0, 300, 1000, 500, 2000};
  double figs[3 * OPT_N_FIGURES];
  for (int i = 0; i < 3; ++i)
    for (int f = 0; f < OPT_N_FIGURES; ++f) figs[i * OPT_N_FIGURES + f] = 10 * i + f;
  int phase[3] = {0, 0, 1};
  opt_history h = {.n = 3, .cap = 3, .n_vars = 2, .values = values, .figures = figs,
                   .phase = phase, .best = 1, .n_start = 2};
  opt_constraint c;
  char why[256];
  CHECK(opt_constraint_parse("core_pressure<=2e6", 2, two_vars, &c, why, sizeof why) == 0);
  opt_problem p = {.scene = "scene.yaml", .n_vars = 2, .vars = two_vars,
                   .objective = SWEEP_FIG_PEAK_PRESSURE, .maximize = 1, .n_cons = 1, .cons = &c};
  opt_settings_default(&p.settings);
  char *dir = scratch_dir("opt_history");
  char *path = scratch_join(dir, "h.h5");
  CHECK(opt_history_write(path, &p, &h, why, sizeof why) == 0);
  CHECK(scratch_count_entries(dir) == 1); /* no temporary left */
  hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(file >= 0);
  double back[6] = {0}, col[3] = {0};
  int best = -5;
  hid_t d = H5Dopen2(file, "/optimize/values", H5P_DEFAULT);
  CHECK(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, back) >= 0);
  H5Dclose(d);
  for (int i = 0; i < 6; ++i) CHECK(back[i] == values[i]);
  d = H5Dopen2(file, "/optimize/figures/min_sigma_theta", H5P_DEFAULT);
  CHECK(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, col) >= 0);
  H5Dclose(d);
  for (int i = 0; i < 3; ++i) CHECK(col[i] == 10 * i + SWEEP_FIG_MIN_SIGMA_THETA);
  d = H5Dopen2(file, "/optimize/best", H5P_DEFAULT);
  CHECK(H5Dread(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, &best) >= 0);
  H5Dclose(d);
  CHECK(best == 1);
  /* the keys: fixed-length strings (checksummed with the chunk), read NUL-terminated */
  d = H5Dopen2(file, "/optimize/parameters", H5P_DEFAULT);
  size_t w;
  hid_t vs = nul_terminated(H5Dget_type(d), &w);
  char *keys = calloc(2, w);
  CHECK(H5Dread(d, vs, H5S_ALL, H5S_ALL, H5P_DEFAULT, keys) >= 0);
  CHECK(strcmp(keys, "winding.tension") == 0);
  CHECK(strcmp(keys + w, "nip.load") == 0);
  free(keys);
  H5Tclose(vs);
  H5Dclose(d);
  CHECK(H5Lexists(file, "/optimize/figures/misfit", H5P_DEFAULT) == 0); /* no target */
  /* the settings and the root attributes: fixed-length strings */
  const char *attrs[][3] = {{"/optimize", "sense", "maximize"},
                            {"/optimize", "objective", "peak_pressure"},
                            {"/optimize", "constraints", "core_pressure <= 2000000"},
                            {"/", "program", "reelsim"},
                            {"/", "scene_file", "scene.yaml"}};
  for (size_t i = 0; i < sizeof attrs / sizeof attrs[0]; ++i) {
    hid_t at = H5Aopen_by_name(file, attrs[i][0], attrs[i][1], H5P_DEFAULT, H5P_DEFAULT);
    CHECK(at >= 0);
    size_t len;
    hid_t ty = nul_terminated(H5Aget_type(at), &len);
    char *text = calloc(1, len);
    CHECK(H5Aread(at, ty, text) >= 0);
    fprintf(stderr, "  %s @%s = '%s'\n", attrs[i][0], attrs[i][1], text);
    CHECK(strcmp(text, attrs[i][2]) == 0);
    free(text);
    H5Tclose(ty);
    H5Aclose(at);
  }
  H5Fclose(file);
  /* a file that cannot be made: refused, nothing left */
  char *bad = scratch_join(dir, "no/such/dir/h.h5");
  CHECK(opt_history_write(bad, &p, &h, why, sizeof why) != 0);
  CHECK(strstr(why, "cannot create output file") && strstr(why, "does not exist"));
  CHECK(scratch_count_entries(dir) == 1);
  free(bad);
  free(path);
  scratch_remove_tree(dir);
  free(dir);
}

static const check_case cases[] = {{"constraints", constraints},
                                   {"figures", figures},
                                   {"target_file", target_file},
                                   {"target_refused", target_refused},
                                   {"misfit_closed_form", misfit_closed_form},
                                   {"history_file", history_file}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
