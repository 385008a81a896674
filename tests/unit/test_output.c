/* The HDF5 output: what rs_output_write writes is what the HDF5 C API reads back, bit
 * for bit, and a failed write leaves neither a file nor a temporary behind. */

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <hdf5.h>

#include "check.h"
#include "scratch.h"
#include "output/h5_util.h"
#include "reel/result_internal.h"
#include "util/atomic_file.h"
#include "reelsim/output.h"
#include "scene/scene_type.h" /* make_scene fills one by hand */
#include "reelsim/version.h"

static const char *yaml_text = "title: round trip\n"
                               "material: {model: linear, E_r: 1.0e6}\n"
                               "core: {radius: 0.0381}\n"
                               "note: \"d\xc3\xa9j\xc3\xa0 vu, UTF-8 survives\"\n";

/* ---- scratch directories ------------------------------------------------------------ */

static void write_text(const char *path, const char *text)
{
  FILE *f = fopen(path, "wb");
  CHECK(f != NULL);
  if (!f) return;
  fputs(text, f);
  fclose(f);
}

/* ---- a synthetic scene and result ---------------------------------------------------- */

static rs_scene *make_scene(const char *text)
{
  rs_scene *s = calloc(1, sizeof *s);
  snprintf(s->path, sizeof s->path, "cases/round_trip.yaml");
  snprintf(s->title, sizeof s->title, "Round trip \xe2\x80\x94 synthetic");
  s->problem.core.radius = 0.0381;
  s->problem.n_layers = 1000;
  s->resolved_text = text ? strdup(text) : NULL;
  return s;
}

static void free_scene(rs_scene *s)
{
  free(s->resolved_text);
  free(s);
}

/* Values with awkward bits (signed zero, subnormals, huge and tiny) so that any
 * conversion on the way shows up in a bitwise comparison. */
static rs_reel_result *make_result(int n)
{
  rs_reel_result *r = calloc(1, sizeof *r);
  r->n_layers = n;
  double **arrays[] = {&r->radius, &r->wound_on_tension, &r->web_tension,
                       &r->nip_load, &r->sigma_r, &r->sigma_theta};
  for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; ++k)
    *arrays[k] = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
  for (int i = 0; i < n; ++i) {
    r->radius[i] = 0.0381 + (i + 1) * 1.0e-4 * (1.0 + 1.0e-9 * i);
    r->wound_on_tension[i] = 250.0 + sin(0.1 * i) / 3.0;
    r->web_tension[i] = 200.0 + i / 7.0;
    r->nip_load[i] = i % 3 == 0 ? 0.0 : 1750.0 / (i + 1);
    r->sigma_r[i] = -1.0e5 * exp(-i / 300.0) / 3.0;
    r->sigma_theta[i] = 4.0e6 * cos(0.01 * i) / 7.0;
  }
  if (n > 3) {
    r->sigma_r[n - 1] = -0.0;       /* the free surface, both signs of zero */
    r->sigma_r[n - 2] = 0.0;
    r->sigma_theta[0] = 4.9e-324;   /* smallest subnormal */
    r->nip_load[1] = 1.0e300;
    r->web_tension[2] = -2.2250738585072014e-308;
  }
  r->core_pressure = 123456.78901234567;
  r->increments = 1000;
  r->cvode_steps = 9876543210LL;
  r->rhs_evals = 3;
  r->full_integrations = 2;
  r->wall_seconds = 1.0 / 3.0;
  return r;
}

static void free_result(rs_reel_result *r)
{
  free(r->radius);
  free(r->wound_on_tension);
  free(r->web_tension);
  free(r->nip_load);
  free(r->sigma_r);
  free(r->sigma_theta);
  free(r);
}

/* ---- reading back with the plain HDF5 C API ------------------------------------------ */

/* Reads dataset `name` of rank `rank`; returns a malloc'd array and its size in *n. */
static double *read_doubles(hid_t file, const char *name, int rank, size_t *n)
{
  *n = 0;
  hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
  CHECK(d >= 0);
  if (d < 0) {
    fprintf(stderr, "  missing dataset %s\n", name);
    return NULL;
  }
  hid_t space = H5Dget_space(d), type = H5Dget_type(d);
  CHECK(H5Sget_simple_extent_ndims(space) == rank);
  CHECK(H5Tequal(type, H5T_IEEE_F64LE) > 0);
  *n = (size_t)H5Sget_simple_extent_npoints(space);
  double *v = malloc((*n ? *n : 1) * sizeof *v);
  if (*n) CHECK(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) >= 0);
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(d);
  return v;
}

/* A scalar fixed-length UTF-8 string attribute (NUL-padded, inside the checksummed object
 * header), malloc'd ("" -> "", absent -> NULL). */
static char *read_attr_string(hid_t obj, const char *name)
{
  if (H5Aexists(obj, name) <= 0) {
    fprintf(stderr, "  missing attribute %s\n", name);
    return NULL;
  }
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT), ftype = H5Aget_type(a);
  CHECK(H5Tget_class(ftype) == H5T_STRING);
  CHECK(H5Tis_variable_str(ftype) == 0);
  CHECK(H5Tget_cset(ftype) == H5T_CSET_UTF8);
  CHECK(H5Tget_strpad(ftype) == H5T_STR_NULLPAD);
  hid_t mtype = H5Tcopy(ftype);
  size_t len = H5Tget_size(ftype) + 1;
  H5Tset_size(mtype, len);
  H5Tset_strpad(mtype, H5T_STR_NULLTERM);
  char *copy = calloc(1, len);
  if (copy && H5Aread(a, mtype, copy) < 0) {
    free(copy);
    copy = NULL;
  }
  H5Tclose(mtype);
  H5Tclose(ftype);
  H5Aclose(a);
  return copy;
}

static int attr_string_is(hid_t obj, const char *name, const char *expected)
{
  char *v = read_attr_string(obj, name);
  int ok = v && strcmp(v, expected) == 0;
  if (!ok) fprintf(stderr, "  attribute %s = '%s', expected '%s'\n", name, v ? v : "(none)", expected);
  free(v);
  return ok;
}

static double read_attr_double(hid_t obj, const char *name)
{
  double v = NAN;
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  CHECK(a >= 0);
  if (a < 0) return v;
  hid_t t = H5Aget_type(a);
  CHECK(H5Tequal(t, H5T_IEEE_F64LE) > 0);
  CHECK(H5Aread(a, H5T_NATIVE_DOUBLE, &v) >= 0);
  H5Tclose(t);
  H5Aclose(a);
  return v;
}

static long long read_attr_int64(hid_t obj, const char *name)
{
  long long v = -1;
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  CHECK(a >= 0);
  if (a < 0) return v;
  hid_t t = H5Aget_type(a);
  CHECK(H5Tequal(t, H5T_STD_I64LE) > 0);
  CHECK(H5Aread(a, H5T_NATIVE_LLONG, &v) >= 0);
  H5Tclose(t);
  H5Aclose(a);
  return v;
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* Dataset `name` holds exactly `expected` (bitwise) and says its units. */
static void check_dataset(hid_t file, const char *name, const double *expected, size_t n,
                          const char *units)
{
  size_t got_n;
  double *got = read_doubles(file, name, 1, &got_n);
  CHECK(got_n == n);
  if (got && got_n == n) {
    size_t bad = 0;
    for (size_t i = 0; i < n; ++i) bad += !same_bits(got[i], expected[i]);
    if (bad) fprintf(stderr, "  %s: %zu of %zu values differ in their bits\n", name, bad, n);
    CHECK(bad == 0);
  }
  free(got);
  hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
  if (d >= 0) {
    CHECK(attr_string_is(d, "units", units));
    char *desc = read_attr_string(d, "description");
    CHECK(desc && strlen(desc) > 10);
    free(desc);
    H5Dclose(d);
  }
}

/* ---- cases ---------------------------------------------------------------------------- */

static void round_trip(void)
{
  const int n = 1000;
  char *dir = scratch_dir("output"), *path = scratch_join(dir, "reel.h5");
  rs_scene *scene = make_scene(yaml_text);
  rs_reel_result *res = make_result(n);
  rs_error_clear();
  rs_status st = rs_output_write(path, scene, res);
  if (st != RS_OK) fprintf(stderr, "  %s\n", rs_error_message());
  CHECK(st == RS_OK);

  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  if (f >= 0) {
    check_dataset(f, "/layers/radius", res->radius, (size_t)n, "m");
    check_dataset(f, "/layers/wound_on_tension", res->wound_on_tension, (size_t)n, "N/m");
    check_dataset(f, "/layers/web_tension", res->web_tension, (size_t)n, "N/m");
    check_dataset(f, "/layers/nip_load", res->nip_load, (size_t)n, "N/m");
    check_dataset(f, "/final/sigma_r", res->sigma_r, (size_t)n, "Pa");
    check_dataset(f, "/final/sigma_theta", res->sigma_theta, (size_t)n, "Pa");
    check_dataset(f, "/final/radius", res->radius, (size_t)n, "m");
    double *p = malloc((size_t)n * sizeof *p);
    for (int i = 0; i < n; ++i) p[i] = -res->sigma_r[i];
    p[n - 2] = 0.0; /* sigma_r = +0 must give pressure +0, not -0 */
    check_dataset(f, "/final/pressure", p, (size_t)n, "Pa");
    free(p);

    size_t one;
    double *cp = read_doubles(f, "/final/core_pressure", 0, &one);
    CHECK(one == 1 && cp && same_bits(cp[0], res->core_pressure));
    free(cp);

    CHECK(attr_string_is(f, "scene", yaml_text));
    CHECK(attr_string_is(f, "version", RS_VERSION_STRING));
    CHECK(attr_string_is(f, "program", "reelsim"));
    CHECK(attr_string_is(f, "title", rs_scene_title(scene)));
    CHECK(attr_string_is(f, "scene_file", rs_scene_path(scene)));
    char *created = read_attr_string(f, "created");
    CHECK(created && strlen(created) == 20 && created[4] == '-' && created[10] == 'T' &&
          created[19] == 'Z');
    if (created) printf("  created = %s\n", created);
    free(created);
    CHECK(read_attr_int64(f, "layers") == n);
    CHECK(read_attr_int64(f, "layers_planned") == rs_scene_problem(scene)->n_layers);
    CHECK(read_attr_int64(f, "increments") == res->increments);
    CHECK(read_attr_int64(f, "cvode_steps") == res->cvode_steps);
    CHECK(read_attr_int64(f, "rhs_evals") == res->rhs_evals);
    CHECK(read_attr_int64(f, "full_integrations") == res->full_integrations);
    CHECK(same_bits(read_attr_double(f, "final_radius"), res->radius[n - 1]));
    CHECK(same_bits(read_attr_double(f, "core_pressure"), res->core_pressure));
    CHECK(same_bits(read_attr_double(f, "wall_seconds"), res->wall_seconds));
    H5Fclose(f);
  }
  free_result(res);
  free_scene(scene);
  free(path);
  scratch_remove_tree(dir);
  free(dir);
}

/* An interrupted run may finish no layer: the file is still well formed. */
static void zero_layers(void)
{
  char *dir = scratch_dir("output"), *path = scratch_join(dir, "empty.h5");
  rs_scene *scene = make_scene(NULL); /* no resolved text: written as "" */
  rs_reel_result *res = make_result(0);
  rs_status st = rs_output_write(path, scene, res);
  if (st != RS_OK) fprintf(stderr, "  %s\n", rs_error_message());
  CHECK(st == RS_OK);
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  if (f >= 0) {
    check_dataset(f, "/layers/radius", NULL, 0, "m");
    check_dataset(f, "/final/sigma_r", NULL, 0, "Pa");
    check_dataset(f, "/final/pressure", NULL, 0, "Pa");
    CHECK(attr_string_is(f, "scene", ""));
    CHECK(read_attr_int64(f, "layers") == 0);
    CHECK(same_bits(read_attr_double(f, "final_radius"), rs_scene_problem(scene)->core.radius));
    H5Fclose(f);
  }
  free_result(res);
  free_scene(scene);
  free(path);
  scratch_remove_tree(dir);
  free(dir);
}

/* A scene with a long table (a measured modulus curve) is far past HDF5's 64 KiB
 * limit for compact attributes: the variable-length string must still go through. */
static void large_scene_text(void)
{
  char *dir = scratch_dir("output"), *path = scratch_join(dir, "big.h5");
  size_t len = 300000;
  char *text = malloc(len + 1);
  for (size_t i = 0; i < len; ++i) text[i] = i % 61 == 60 ? '\n' : (char)('a' + i % 26);
  text[len] = '\0';
  rs_scene *scene = make_scene(text);
  rs_reel_result *res = make_result(10);
  rs_status st = rs_output_write(path, scene, res);
  if (st != RS_OK) fprintf(stderr, "  %s\n", rs_error_message());
  CHECK(st == RS_OK);
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  if (f >= 0) {
    char *back = read_attr_string(f, "scene");
    CHECK(back && strlen(back) == len && strcmp(back, text) == 0);
    free(back);
    H5Fclose(f);
  }
  free(text);
  free_result(res);
  free_scene(scene);
  free(path);
  scratch_remove_tree(dir);
  free(dir);
}

/* A successful write leaves exactly the file; writing again replaces it whole. */
static void no_temp_left(void)
{
  char *dir = scratch_dir("output"), *path = scratch_join(dir, "reel.h5");
  rs_scene *scene = make_scene(yaml_text);
  rs_reel_result *res = make_result(50);
  CHECK(rs_output_write(path, scene, res) == RS_OK);
  CHECK(scratch_count_entries(dir) == 1);
  res->core_pressure = 42.0;
  CHECK(rs_output_write(path, scene, res) == RS_OK);
  CHECK(scratch_count_entries(dir) == 1);
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  if (f >= 0) {
    CHECK(read_attr_double(f, "core_pressure") == 42.0);
    H5Fclose(f);
  }
  /* A bare file name goes to the current directory, and its temporary too. */
  char cwd[4096];
  CHECK(getcwd(cwd, sizeof cwd) != NULL);
  CHECK(chdir(dir) == 0);
  CHECK(rs_output_write("bare.h5", scene, res) == RS_OK);
  CHECK(chdir(cwd) == 0);
  CHECK(scratch_count_entries(dir) == 2);
  free_result(res);
  free_scene(scene);
  free(path);
  scratch_remove_tree(dir);
  free(dir);
}

static int message_names(const char *path)
{
  int ok = strstr(rs_error_message(), path) != NULL;
  printf("  message: %s\n", rs_error_message());
  return ok;
}

static void missing_directory(void)
{
  char *dir = scratch_dir("output"), *missing = scratch_join(dir, "no_such_dir"), *path = scratch_join(missing, "x.h5");
  rs_scene *scene = make_scene(yaml_text);
  rs_reel_result *res = make_result(10);
  rs_error_clear();
  CHECK(rs_output_write(path, scene, res) == RS_ERR_IO);
  CHECK(message_names(path));
  CHECK(strstr(rs_error_message(), "does not exist") != NULL);
  struct stat sb;
  CHECK(stat(missing, &sb) != 0 && errno == ENOENT);
  CHECK(scratch_count_entries(dir) == 0);

  /* A file where a directory should be. */
  char *file = scratch_join(dir, "plain"), *under = scratch_join(file, "x.h5");
  write_text(file, "plain\n");
  CHECK(rs_output_write(under, scene, res) == RS_ERR_IO);
  CHECK(message_names(under));
  CHECK(scratch_count_entries(dir) == 1);
  free(file);
  free(under);
  free_result(res);
  free_scene(scene);
  free(missing);
  free(path);
  scratch_remove_tree(dir);
  free(dir);
}

/* Output path is a directory, or a link to a device: refused, and nothing changes. */
static void not_a_regular_target(void)
{
  char *dir = scratch_dir("output"), *sub = scratch_join(dir, "sub"), *link = scratch_join(dir, "null.h5");
  rs_scene *scene = make_scene(yaml_text);
  rs_reel_result *res = make_result(10);
  CHECK(mkdir(sub, 0700) == 0);
  CHECK(symlink("/dev/null", link) == 0);
  CHECK(rs_output_write(sub, scene, res) == RS_ERR_IO);
  CHECK(message_names(sub));
  CHECK(rs_output_write(link, scene, res) == RS_ERR_IO);
  CHECK(message_names(link));
  struct stat sb;
  CHECK(stat(sub, &sb) == 0 && S_ISDIR(sb.st_mode));
  CHECK(lstat(link, &sb) == 0 && S_ISLNK(sb.st_mode));
  CHECK(stat("/dev/null", &sb) == 0 && S_ISCHR(sb.st_mode));
  CHECK(scratch_count_entries(dir) == 2);
  CHECK(scratch_count_entries(sub) == 0);
  free_result(res);
  free_scene(scene);
  free(sub);
  free(link);
  scratch_remove_tree(dir);
  free(dir);
}

/* Returns 0 when the write into a read-only directory failed as it should. */
static int write_into_readonly(const char *path)
{
  rs_scene *scene = make_scene(yaml_text);
  rs_reel_result *res = make_result(10);
  rs_error_clear();
  rs_status st = rs_output_write(path, scene, res);
  int ok = st == RS_ERR_IO && message_names(path);
  free_result(res);
  free_scene(scene);
  return ok ? 0 : 1;
}

static void readonly_directory(void)
{
  char *dir = scratch_dir("output"), *ro = scratch_join(dir, "ro"), *path = scratch_join(ro, "x.h5");
  CHECK(mkdir(ro, 0700) == 0);
  CHECK(chmod(ro, 0555) == 0);
  if (geteuid() != 0) {
    CHECK(write_into_readonly(path) == 0);
  } else {
    /* Root ignores permissions: try as user nobody in a child process instead. */
    CHECK(chmod(dir, 0755) == 0);
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    CHECK(pid >= 0);
    if (pid == 0) {
      int rc = 77;
      if (setgid(65534) == 0 && setuid(65534) == 0) rc = write_into_readonly(path);
      fflush(stdout);
      free(path); /* the child's copies: valgrind checks its leaks too */
      free(ro);
      free(dir);
      _exit(rc);
    }
    int status = 0;
    CHECK(waitpid(pid, &status, 0) == pid);
    CHECK(WIFEXITED(status));
    if (WIFEXITED(status) && WEXITSTATUS(status) == 77)
      printf("  note: running as root and cannot become nobody: read-only check skipped\n");
    else
      CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  CHECK(scratch_count_entries(ro) == 0);
  free(path);
  free(ro);
  scratch_remove_tree(dir);
  free(dir);
}

/* The disk fills up halfway through (a file size limit stands in for a full disk):
 * the error names the file, the old file at the path is untouched, no temporary left. */
static void failed_write_keeps_old_file(void)
{
  char *dir = scratch_dir("output"), *path = scratch_join(dir, "reel.h5");
  const char *old = "previous results, not HDF5 at all\n";
  write_text(path, old);
  rs_scene *scene = make_scene(yaml_text);
  rs_reel_result *res = make_result(20000); /* 160 kB per array */

  struct rlimit saved, lim;
  CHECK(getrlimit(RLIMIT_FSIZE, &saved) == 0);
  lim = saved;
  lim.rlim_cur = 64 * 1024;
  void (*prev)(int) = signal(SIGXFSZ, SIG_IGN); /* write() then fails with EFBIG */
  CHECK(setrlimit(RLIMIT_FSIZE, &lim) == 0);
  rs_error_clear();
  rs_status st = rs_output_write(path, scene, res);
  CHECK(setrlimit(RLIMIT_FSIZE, &saved) == 0);
  signal(SIGXFSZ, prev);

  CHECK(st == RS_ERR_IO);
  CHECK(message_names(path));
  size_t len = 0;
  char *now = scratch_slurp(path, &len);
  CHECK(now && len == strlen(old) && memcmp(now, old, len) == 0);
  free(now);
  CHECK(scratch_count_entries(dir) == 1);

  /* With the limit gone the same write succeeds and replaces the old file. */
  CHECK(rs_output_write(path, scene, res) == RS_OK);
  CHECK(scratch_count_entries(dir) == 1);
  CHECK(H5Fis_hdf5(path) > 0);
  free_result(res);
  free_scene(scene);
  free(path);
  scratch_remove_tree(dir);
  free(dir);
}

static const check_case cases[] = {
  {"round_trip", round_trip},
  {"zero_layers", zero_layers},
  {"large_scene_text", large_scene_text},
  {"no_temp_left", no_temp_left},
  {"missing_directory", missing_directory},
  {"not_a_regular_target", not_a_regular_target},
  {"readonly_directory", readonly_directory},
  {"failed_write_keeps_old_file", failed_write_keeps_old_file},
};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
