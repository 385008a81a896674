/* CSV export: the files hold a header and one row per layer whose numbers read back
 * (strtod) to exactly the doubles of the HDF5 file's /final and /layers datasets; a bad
 * directory is an input error that writes nothing; a failure half-way leaves neither
 * file nor temporary. */

#include <dirent.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <hdf5.h>

#include "check.h"
#include "reel/result_internal.h"
#include "scratch.h"
#include "reelsim/output.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

/* Linerboard with a tension table and a tapered friction nip, cut to 60 m (107 layers):
 * every CSV column varies. */
static rs_reel_result *wind_small(rs_scene **sc_out)
{
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL;
  const char *sets[] = {"winding.web_length=60"};
  if (rs_scene_load(RS_ROOT_DIR "/cases/linerboard-table.yaml", 1, sets, &sc) != RS_OK ||
      rs_scene_wind(sc, NULL, &res) != RS_OK)
    printf("  error: %s\n", rs_error_message());
  *sc_out = sc;
  return res;
}

static double *read_h5(hid_t f, const char *name, size_t n)
{
  double *v = malloc(n * sizeof *v);
  hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
  if (d < 0 || H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0) {
    free(v);
    v = NULL;
  }
  if (d >= 0) H5Dclose(d);
  return v;
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* Parses a CSV file of `cols` numeric columns after the header: values[col][row]. */
static int parse_csv(const char *path, const char *header, int cols, double **values, int max_rows)
{
  FILE *f = fopen(path, "r");
  if (!f) return -1;
  char line[1024];
  int rows = -1;
  if (!fgets(line, sizeof line, f) || strcmp(line, header) != 0) {
    printf("  header of %s: %s", path, line);
    fclose(f);
    return -1;
  }
  rows = 0;
  while (fgets(line, sizeof line, f)) {
    char *p = line, *end;
    if (rows >= max_rows) {
      rows = -1;
      break;
    }
    for (int c = 0; c < cols; ++c) {
      values[c][rows] = strtod(p, &end);
      if (end == p || (*end != (c + 1 < cols ? ',' : '\n'))) {
        printf("  bad row %d: %s", rows + 1, line);
        fclose(f);
        return -1;
      }
      p = end + 1;
    }
    ++rows;
  }
  fclose(f);
  return rows;
}

static void round_trip(void)
{
  char *dir = scratch_dir("csv");
  rs_scene *sc = NULL;
  rs_reel_result *res = wind_small(&sc);
  CHECK(res != NULL);
  if (!res) return;
  int n = res->n_layers;
  char *h5 = scratch_join(dir, "r.h5");
  CHECK(rs_output_write(h5, sc, res) == RS_OK);
  CHECK(rs_output_write_csv(dir, "small", res) == RS_OK);
  CHECK(n == 107);
  CHECK(scratch_count_entries(dir) == 3);

  hid_t f = H5Fopen(h5, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  const char *names[] = {"/final/radius",   "/final/sigma_r",           "/final/sigma_theta",
                         "/final/pressure", "/layers/wound_on_tension", "/layers/web_tension",
                         "/layers/nip_load"};
  double *h[7];
  for (int i = 0; i < 7; ++i) {
    h[i] = read_h5(f, names[i], (size_t)n);
    CHECK(h[i] != NULL);
  }
  H5Fclose(f);

  double *p[6], *w[4];
  for (int c = 0; c < 6; ++c)
    p[c] = malloc((size_t)n * sizeof(double));
  for (int c = 0; c < 4; ++c)
    w[c] = malloc((size_t)n * sizeof(double));
  char *prof = scratch_join(dir, "small-profile.csv"), *wot = scratch_join(dir, "small-wot.csv");
  int rp = parse_csv(prof,
                     "layer,radius_m,sigma_r_Pa,sigma_theta_Pa,pressure_Pa,"
                     "wound_on_tension_N_per_m\n",
                     6, p, n);
  int rw = parse_csv(
      wot, "radius_m,web_tension_N_per_m,nip_load_N_per_m,wound_on_tension_N_per_m\n", 4, w, n);
  CHECK(rp == n && rw == n);
  int diff = 0;
  for (int i = 0; i < 7; ++i)
    if (!h[i]) diff = -1;
  if (rp == n && rw == n && diff == 0) {
    for (int j = 0; j < n; ++j) {
      diff += p[0][j] != j + 1;
      diff += !same_bits(p[1][j], h[0][j]) || !same_bits(p[2][j], h[1][j]) ||
              !same_bits(p[3][j], h[2][j]) || !same_bits(p[4][j], h[3][j]) ||
              !same_bits(p[5][j], h[4][j]);
      diff += !same_bits(w[0][j], h[0][j]) || !same_bits(w[1][j], h[5][j]) ||
              !same_bits(w[2][j], h[6][j]) || !same_bits(w[3][j], h[4][j]);
    }
    CHECK_LOG("first row sigma_r (Pa)", p[2][0]);
    CHECK_LOG("last row pressure (Pa)", p[4][n - 1]);
  }
  CHECK(diff == 0);
  for (int i = 0; i < 7; ++i)
    free(h[i]);
  for (int c = 0; c < 6; ++c)
    free(p[c]);
  for (int c = 0; c < 4; ++c)
    free(w[c]);
  free(prof);
  free(wot);
  free(h5);
  scratch_remove_tree(dir);
  free(dir);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

static void bad_directory(void)
{
  char *dir = scratch_dir("csv");
  rs_scene *sc = NULL;
  rs_reel_result *res = wind_small(&sc);
  char *missing = scratch_join(dir, "no-such-dir");
  CHECK(rs_output_write_csv(missing, "small", res) == RS_ERR_INPUT);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), "no such directory") != NULL);
  /* a regular file where the directory should be */
  char *file = scratch_join(dir, "plain");
  FILE *fp = fopen(file, "w");
  if (fp) fclose(fp);
  CHECK(rs_output_write_csv(file, "small", res) == RS_ERR_INPUT);
  printf("  %s\n", rs_error_message());
  CHECK(scratch_count_entries(dir) == 1); /* only "plain" */
  free(missing);
  free(file);
  scratch_remove_tree(dir);
  free(dir);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

/* The second file cannot be placed (a directory sits at its name): the first must not
 * appear either, and no temporary is left. */
static void nothing_half_written(void)
{
  char *dir = scratch_dir("csv");
  rs_scene *sc = NULL;
  rs_reel_result *res = wind_small(&sc);
  char *blocker = scratch_join(dir, "small-wot.csv");
  CHECK(mkdir(blocker, 0700) == 0);
  CHECK(rs_output_write_csv(dir, "small", res) == RS_ERR_IO);
  printf("  %s\n", rs_error_message());
  CHECK(scratch_count_entries(dir) == 1); /* only the blocking directory */
  char *prof = scratch_join(dir, "small-profile.csv");
  CHECK(access(prof, F_OK) != 0);
  free(prof);
  free(blocker);
  scratch_remove_tree(dir);
  free(dir);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

/* A disk that fills up after the first file's temporary (a file-size limit between the
 * two files' sizes): the earlier pair stays byte for byte, no temporary is left. */
static void failed_write_keeps_old_files(void)
{
  char *dir = scratch_dir("csv");
  rs_scene *sc = NULL;
  rs_reel_result *res = wind_small(&sc);
  CHECK(rs_output_write_csv(dir, "small", res) == RS_OK);
  char *prof = scratch_join(dir, "small-profile.csv"), *wot = scratch_join(dir, "small-wot.csv");
  size_t np = 0, nw = 0, np2 = 0, nw2 = 0;
  char *old_p = scratch_slurp(prof, &np), *old_w = scratch_slurp(wot, &nw);
  CHECK_LOG("profile bytes", np);
  CHECK_LOG("wot bytes", nw);
  CHECK(old_p && old_w && nw < np);
  for (int j = 0; j < res->n_layers; ++j)
    res->sigma_r[j] *= 1.5; /* a different reel */

  struct rlimit saved, lim;
  CHECK(getrlimit(RLIMIT_FSIZE, &saved) == 0);
  lim = saved;
  lim.rlim_cur = (nw + np) / 2; /* the wot file fits, the profile does not */
  void (*prev)(int) = signal(SIGXFSZ, SIG_IGN);
  CHECK(setrlimit(RLIMIT_FSIZE, &lim) == 0);
  rs_status st = rs_output_write_csv(dir, "small", res);
  CHECK(setrlimit(RLIMIT_FSIZE, &saved) == 0);
  signal(SIGXFSZ, prev);
  CHECK(st == RS_ERR_IO);
  printf("  %s\n", rs_error_message());

  char *new_p = scratch_slurp(prof, &np2), *new_w = scratch_slurp(wot, &nw2);
  CHECK(new_p && new_w && np2 == np && nw2 == nw);
  if (new_p && new_w && old_p && old_w && np2 == np && nw2 == nw)
    CHECK(memcmp(new_p, old_p, np) == 0 && memcmp(new_w, old_w, nw) == 0);
  CHECK(scratch_count_entries(dir) == 2);
  free(old_p);
  free(old_w);
  free(new_p);
  free(new_w);
  free(prof);
  free(wot);
  scratch_remove_tree(dir);
  free(dir);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

static const check_case cases[] = {
    {"round_trip", round_trip},
    {"bad_directory", bad_directory},
    {"nothing_half_written", nothing_half_written},
    {"failed_write_keeps_old_files", failed_write_keeps_old_files},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
