/* The HDF5 reader (reelsim/reader.h): what the writers put in comes back bit for bit,
 * runs are found in order, and files that are not reelsim's are refused with a message
 * that names them. */
#include <hdf5.h>

#include "check.h"
#include "output/h5_util.h"
#include "reel/result_internal.h"
#include "reelsim/output.h"
#include "reelsim/reader.h"
#include "synthetic.h"

static int same_bits(const double *a, const double *b, size_t n)
{
  return n == 0 || memcmp(a, b, n * sizeof *a) == 0;
}

/* Writes a run file of n layers; returns its path (malloc'd). */
static char *write_run(const char *dir, const char *name, int n, double variant)
{
  char *path = scratch_join(dir, name);
  rs_scene *s = syn_scene("cases/some-reel.yaml", "A synthetic reel");
  rs_reel_result *r = syn_result(n, variant);
  CHECK(rs_output_write(path, s, r) == RS_OK);
  rs_reel_result_destroy(&r);
  syn_scene_free(s);
  return path;
}

static void run_file(void)
{
  char *dir = scratch_dir("reader");
  char *path = write_run(dir, "my-reel.h5", 120, 1.5);
  rs_reel_result *want = syn_result(120, 1.5);
  rs_reader *r = NULL;
  CHECK(rs_reader_open(path, &r) == RS_OK);
  if (r) {
    CHECK(strcmp(rs_reader_path(r), path) == 0);
    CHECK(rs_reader_is_compare(r) == 0);
    CHECK(rs_reader_runs(r) == 1);
    CHECK(strcmp(rs_reader_run_base(r, 0), "") == 0);
    CHECK(strcmp(rs_reader_run_name(r, 0), "my-reel") == 0);
    CHECK(rs_reader_run_base(r, 1) == NULL);
    double *v = NULL;
    size_t n = 0;
    CHECK(rs_reader_read_1d(r, "/final/sigma_r", &v, &n) == RS_OK);
    CHECK(n == 120 && same_bits(v, want->sigma_r, n));
    free(v);
    CHECK(rs_reader_read_1d(r, "/layers/wound_on_tension", &v, &n) == RS_OK);
    CHECK(n == 120 && same_bits(v, want->wound_on_tension, n));
    free(v);
    double p = 0;
    CHECK(rs_reader_read_scalar(r, "/final/core_pressure", &p) == RS_OK);
    CHECK(memcmp(&p, &want->core_pressure, sizeof p) == 0);
    char *s = NULL;
    CHECK(rs_reader_attr_string(r, "", "program", &s) == RS_OK && strcmp(s, "reelsim") == 0);
    free(s);
    CHECK(rs_reader_attr_string(r, "/", "title", &s) == RS_OK &&
          strcmp(s, "A synthetic reel") == 0);
    free(s);
    CHECK(rs_reader_attr_string(r, "/final/pressure", "units", &s) == RS_OK &&
          strcmp(s, "Pa") == 0);
    free(s);
    long long layers = 0;
    CHECK(rs_reader_attr_int64(r, "", "layers", &layers) == RS_OK && layers == 120);
    double wall = 0;
    CHECK(rs_reader_attr_double(r, "", "wall_seconds", &wall) == RS_OK);
    CHECK(memcmp(&wall, &want->wall_seconds, sizeof wall) == 0);
    CHECK(rs_reader_exists(r, "/final/radius") == 1);
    CHECK(rs_reader_exists(r, "/history") == 0);
    CHECK(rs_reader_exists(r, "/history/sigma_r") == 0); /* a missing parent is no error */
    CHECK(rs_reader_exists(r, "") == 1);
    char **names = NULL;
    CHECK(rs_reader_children(r, "/", &names, &n) == RS_OK);
    /* a run file always carries /defects (the indicators' verdicts) beside the contract groups */
    CHECK(n == 3 && strcmp(names[0], "defects") == 0 && strcmp(names[1], "final") == 0 &&
          strcmp(names[2], "layers") == 0);
    rs_reader_free_strings(&names, n);
    CHECK(names == NULL);
  }
  rs_reader_close(&r);
  CHECK(r == NULL);
  rs_reader_close(&r); /* NULL is fine */
  rs_reel_result_destroy(&want);
  unlink(path);
  free(path);
  rmdir(dir);
  free(dir);
}

/* A comparison's runs come back in run order, each with its own data. */
static void compare_file(void)
{
  char *dir = scratch_dir("reader");
  char *path = scratch_join(dir, "cmp.h5");
  enum { N = 11 }; /* two-digit run numbers: "01-..", sorted like the runs */
  rs_scene *sc[N];
  rs_reel_result *res[N];
  rs_output_run runs[N];
  for (int i = 0; i < N; ++i) {
    char p[64], t[64];
    snprintf(p, sizeof p, "dir/recipe-%c.yaml", 'a' + i);
    snprintf(t, sizeof t, "recipe %d", i);
    sc[i] = syn_scene(p, t);
    res[i] = syn_result(10 + i, 1.0 + i);
    runs[i] = (rs_output_run){sc[i], res[i]};
  }
  CHECK(rs_output_write_compare(path, N, runs) == RS_OK);
  rs_reader *r = NULL;
  CHECK(rs_reader_open(path, &r) == RS_OK);
  if (r) {
    CHECK(rs_reader_is_compare(r) == 1);
    CHECK(rs_reader_runs(r) == N);
    CHECK(strcmp(rs_reader_run_name(r, 0), "01-recipe-a") == 0);
    CHECK(strcmp(rs_reader_run_base(r, 10), "/runs/11-recipe-k") == 0);
    for (int i = 0; i < N && i < rs_reader_runs(r); ++i) {
      char p[256];
      double *v = NULL;
      size_t n = 0;
      snprintf(p, sizeof p, "%s/final/sigma_theta", rs_reader_run_base(r, i));
      CHECK(rs_reader_read_1d(r, p, &v, &n) == RS_OK);
      CHECK(n == (size_t)(10 + i) && same_bits(v, res[i]->sigma_theta, n));
      free(v);
      char *t = NULL;
      CHECK(rs_reader_attr_string(r, rs_reader_run_base(r, i), "title", &t) == RS_OK &&
            strcmp(t, rs_scene_title(sc[i])) == 0);
      free(t);
    }
    char **s = NULL;
    size_t n = 0;
    CHECK(rs_reader_read_strings(r, "/summary/scene_file", &s, &n) == RS_OK);
    CHECK(n == N && strcmp(s[3], "dir/recipe-d.yaml") == 0);
    rs_reader_free_strings(&s, n);
  }
  rs_reader_close(&r);
  for (int i = 0; i < N; ++i) {
    syn_scene_free(sc[i]);
    rs_reel_result_destroy(&res[i]);
  }
  unlink(path);
  free(path);
  rmdir(dir);
  free(dir);
}

static void expect_input_error(const char *path, const char *fragment)
{
  rs_reader *r = (rs_reader *)1;
  CHECK(rs_reader_open(path, &r) == RS_ERR_INPUT);
  CHECK(r == NULL);
  printf("  message: %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), path) != NULL);
  CHECK(strstr(rs_error_message(), fragment) != NULL);
}

static void refuses_other_files(void)
{
  char *dir = scratch_dir("reader");
  char *missing = scratch_join(dir, "missing.h5"), *text = scratch_join(dir, "text.h5"),
       *foreign = scratch_join(dir, "foreign.h5"), *liar = scratch_join(dir, "liar.h5");
  expect_input_error(missing, "No such file");
  FILE *f = fopen(text, "w");
  fputs("title: not HDF5 at all\n", f);
  fclose(f);
  expect_input_error(text, "is not an HDF5 file");
  hid_t h = H5Fcreate(foreign, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  CHECK(h >= 0);
  H5Fclose(h);
  expect_input_error(foreign, "not a reelsim file");
  h = H5Fcreate(liar, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  CHECK(rs_h5_attr_string(h, "program", "something-else") == RS_OK);
  H5Fclose(h);
  expect_input_error(liar, "not a reelsim file");
  expect_input_error(dir, "is a directory");
  unlink(text);
  unlink(foreign);
  unlink(liar);
  free(missing);
  free(text);
  free(foreign);
  free(liar);
  rmdir(dir);
  free(dir);
}

/* Missing datasets and wrong shapes are input errors naming the file and the path. */
static void shapes_and_missing(void)
{
  char *dir = scratch_dir("reader");
  char *path = write_run(dir, "r.h5", 5, 1.0);
  hid_t h = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
  double m[6] = {1, 2, 3, 4, 5, 6};
  CHECK(rs_h5_write_2d_chunked(h, "matrix", m, 2, 3, "Pa", "a 2 x 3 matrix") == RS_OK);
  unsigned char flags[4] = {0, 1, 1, 0};
  hsize_t dims[1] = {4};
  hid_t sp = H5Screate_simple(1, dims, NULL), dcpl;
  CHECK(rs_h5_dcpl_checked(sp, 1, &dcpl) == RS_OK);
  hid_t d = H5Dcreate2(h, "flags", H5T_STD_U8LE, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  CHECK(H5Dwrite(d, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, flags) >= 0);
  H5Dclose(d);
  /* the same without a checksum: a checksummed file never holds one */
  d = H5Dcreate2(h, "bare", H5T_STD_U8LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  CHECK(H5Dwrite(d, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, flags) >= 0);
  H5Dclose(d);
  H5Pclose(dcpl);
  H5Sclose(sp);
  H5Fclose(h);

  rs_reader *r = NULL;
  CHECK(rs_reader_open(path, &r) == RS_OK);
  if (r) {
    double *v = NULL;
    size_t n = 9, rows = 0, cols = 0;
    CHECK(rs_reader_read_1d(r, "/final/nothing", &v, &n) == RS_ERR_INPUT);
    CHECK(v == NULL && n == 0);
    CHECK(strstr(rs_error_message(), "/final/nothing") && strstr(rs_error_message(), path));
    CHECK(rs_reader_read_1d(r, "/matrix", &v, &n) == RS_ERR_INPUT);
    CHECK(strstr(rs_error_message(), "2 dimensions") != NULL);
    CHECK(rs_reader_read_2d(r, "/final/radius", &v, &rows, &cols) == RS_ERR_INPUT);
    CHECK(rs_reader_read_2d(r, "/matrix", &v, &rows, &cols) == RS_OK);
    CHECK(rows == 2 && cols == 3 && v && v[5] == 6.0 && v[1] == 2.0);
    free(v);
    CHECK(rs_reader_read_1d(r, "/flags", &v, &n) == RS_OK); /* integers come as doubles */
    CHECK(n == 4 && v[0] == 0.0 && v[1] == 1.0 && v[3] == 0.0);
    free(v);
    v = NULL;
    CHECK(rs_reader_read_1d(r, "/bare", &v, &n) == RS_ERR_INPUT);
    CHECK(v == NULL && strstr(rs_error_message(), "'/bare'") &&
          strstr(rs_error_message(), "without a checksum"));
    printf("  %s\n", rs_error_message());
    double x;
    CHECK(rs_reader_read_scalar(r, "/final/radius", &x) == RS_ERR_INPUT); /* 5 values */
    CHECK(rs_reader_read_1d(r, "/final", &v, &n) == RS_ERR_INPUT);        /* a group */
    char *s = NULL;
    CHECK(rs_reader_attr_string(r, "/", "layers", &s) == RS_ERR_INPUT);   /* a number */
    CHECK(rs_reader_attr_string(r, "/", "nothing", &s) == RS_ERR_INPUT);
    CHECK(s == NULL);
    CHECK(rs_reader_attr_double(r, "/", "title", &x) == RS_ERR_INPUT);    /* a string */
    CHECK(rs_reader_attr_double(r, "/nowhere", "title", &x) == RS_ERR_INPUT);
    char **names = NULL;
    CHECK(rs_reader_children(r, "/final/radius", &names, &n) == RS_ERR_INPUT);
  }
  rs_reader_close(&r);
  unlink(path);
  free(path);
  rmdir(dir);
  free(dir);
}

/* Profiles are numbered groups: 2 before 10, names after numbers; fixed-length strings. */
static void children_order(void)
{
  char *dir = scratch_dir("reader");
  char *path = write_run(dir, "r.h5", 3, 1.0);
  hid_t h = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
  const char *names_in[] = {"10", "2", "b", "1", "a", "007"};
  hid_t g;
  CHECK(rs_h5_group_create(h, "profiles", &g) == RS_OK);
  for (size_t i = 0; i < sizeof names_in / sizeof *names_in; ++i) {
    hid_t c;
    CHECK(rs_h5_group_create(g, names_in[i], &c) == RS_OK);
    H5Gclose(c);
  }
  /* a fixed-length string attribute, as other tools write them */
  hid_t t = H5Tcopy(H5T_C_S1), sp = H5Screate(H5S_SCALAR);
  H5Tset_size(t, 8);
  hid_t a = H5Acreate2(g, "fixed", t, sp, H5P_DEFAULT, H5P_DEFAULT);
  CHECK(H5Awrite(a, t, "abc\0\0\0\0\0") >= 0);
  H5Aclose(a);
  H5Sclose(sp);
  H5Tclose(t);
  H5Gclose(g);
  H5Fclose(h);

  rs_reader *r = NULL;
  CHECK(rs_reader_open(path, &r) == RS_OK);
  char **names = NULL;
  size_t n = 0;
  CHECK(r && rs_reader_children(r, "/profiles", &names, &n) == RS_OK);
  const char *want[] = {"1", "2", "007", "10", "a", "b"};
  CHECK(n == 6);
  for (size_t i = 0; i < n && i < 6; ++i) {
    printf("  child %zu: %s\n", i, names[i]);
    CHECK(strcmp(names[i], want[i]) == 0);
  }
  rs_reader_free_strings(&names, n);
  char *s = NULL;
  CHECK(r && rs_reader_attr_string(r, "/profiles", "fixed", &s) == RS_OK &&
        strcmp(s, "abc") == 0);
  free(s);
  rs_reader_close(&r);
  unlink(path);
  free(path);
  rmdir(dir);
  free(dir);
}

static const check_case cases[] = {
    {"run_file", run_file},
    {"compare_file", compare_file},
    {"refuses_other_files", refuses_other_files},
    {"shapes_and_missing", shapes_and_missing},
    {"children_order", children_order},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
