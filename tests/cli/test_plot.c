/* reelsim plot (reelsim/plot.h) with the real gnuplot: every expected PNG is written,
 * decodes, is not blank, and shows the curves it should (their exact colours are in the
 * image); optional groups are drawn when present and absent files are refused; failures
 * of gnuplot leave no PNG and no temporary directory. */
#include <hdf5.h>
#include <signal.h>
#include <sys/resource.h>

#include "check.h"
#include "output/h5_util.h"
#include "png_check.h"
#include "reel/result_internal.h"
#include "reelsim/output.h"
#include "reelsim/plot.h"
#include "synthetic.h"

enum { N_LAYERS = 200 };

/* The colours the plot module draws with (src/plot). */
static const uint32_t BLUE = 0x1f77b4, RED = 0xd62728, GREEN = 0x2ca02c, LAST_STAGE = 0x6a51a3;

/* A private TMPDIR, so the test can see that the plot's temporary directory is removed. */
static char *private_tmpdir(void)
{
  char *t = scratch_dir("plot_tmp");
  setenv("TMPDIR", t, 1);
  return t;
}

static char *write_run_file(const char *dir, const char *name, int n)
{
  char *path = scratch_join(dir, name);
  rs_scene *s = syn_scene("cases/synthetic-reel.yaml", "Synthetic reel \"quoted\" \\ 100% {x}");
  rs_reel_result *r = syn_result(n, 1.0);
  CHECK(rs_output_write(path, s, r) == RS_OK);
  rs_reel_result_destroy(&r);
  syn_scene_free(s);
  return path;
}

static void write_1d(hid_t g, const char *name, const double *v, size_t n)
{
  CHECK(rs_h5_write_1d(g, name, v, n, "", name) == RS_OK);
}

/* Adds what the other writers will add: /history (4 stages), /defects (ranges and a
 * pressure limit) and /nip/profiles/0 (the contact model's layout, shears on midpoints). */
static void add_optional_groups(const char *path)
{
  hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT), g, h;
  CHECK(f >= 0);
  rs_reel_result *r = syn_result(N_LAYERS, 1.0);
  enum { S = 4 };
  double layers[S], outer[S], *sr = malloc(sizeof(double) * S * N_LAYERS),
                              *st = malloc(sizeof(double) * S * N_LAYERS);
  for (int s = 0; s < S; ++s) {
    int k = (s + 1) * N_LAYERS / S;
    layers[s] = k;
    outer[s] = r->radius[k - 1];
    for (int j = 0; j < N_LAYERS; ++j) {
      sr[s * N_LAYERS + j] = j < k ? r->sigma_r[j] * (s + 1) / S : NAN;
      st[s * N_LAYERS + j] = j < k ? r->sigma_theta[j] * (s + 1) / S : NAN;
    }
  }
  CHECK(rs_h5_group_create(f, "history", &g) == RS_OK);
  write_1d(g, "layers", layers, S);
  write_1d(g, "outer_radius", outer, S);
  CHECK(rs_h5_write_2d_chunked(g, "sigma_r", sr, S, N_LAYERS, "Pa", "") == RS_OK);
  CHECK(rs_h5_write_2d_chunked(g, "sigma_theta", st, S, N_LAYERS, "Pa", "") == RS_OK);
  H5Gclose(g);

  /* replace the writer's own /defects by one with known ranges to draw */
  CHECK(H5Ldelete(f, "defects", H5P_DEFAULT) >= 0);
  CHECK(rs_h5_group_create(f, "defects", &g) == RS_OK);
  double r0[1] = {r->radius[0]}, r1[1] = {r->radius[50]};
  CHECK(rs_h5_group_create(g, "hoop_compression", &h) == RS_OK);
  write_1d(h, "range_inner_radius", r0, 1);
  write_1d(h, "range_outer_radius", r1, 1);
  H5Gclose(h);
  CHECK(rs_h5_group_create(g, "pressure", &h) == RS_OK);
  CHECK(rs_h5_attr_double(h, "limit", 1.5e5) == RS_OK);
  H5Gclose(h);
  H5Gclose(g);

  enum { M = 41 };
  double x[M], p[M], xs[M - 1], up[M - 1], lo[M - 1], su[M - 1], sl[M - 1];
  for (int i = 0; i < M; ++i) {
    x[i] = -2e-3 + 4e-3 * i / (M - 1);
    p[i] = 8e5 * sqrt(fmax(0.0, 1.0 - (x[i] / 2e-3) * (x[i] / 2e-3)));
  }
  for (int e = 0; e < M - 1; ++e) {
    xs[e] = 0.5 * (x[e] + x[e + 1]);
    up[e] = 1e5 * sin(3.14159 * xs[e] / 2e-3);
    lo[e] = -0.5 * up[e];
    su[e] = fabs(xs[e]) > 1e-3; /* stick in the middle */
    sl[e] = xs[e] > 0.5e-3;
  }
  hid_t n;
  CHECK(rs_h5_group_create(f, "nip", &n) == RS_OK);
  CHECK(rs_h5_group_create(n, "profiles", &g) == RS_OK);
  CHECK(rs_h5_group_create(g, "0", &h) == RS_OK);
  CHECK(rs_h5_attr_double(h, "roll_radius", 0.06) == RS_OK);
  write_1d(h, "x", x, M);
  write_1d(h, "pressure", p, M);
  write_1d(h, "x_shear", xs, M - 1);
  write_1d(h, "shear_upper", up, M - 1);
  write_1d(h, "shear_lower", lo, M - 1);
  write_1d(h, "slip_upper", su, M - 1);
  write_1d(h, "slip_lower", sl, M - 1);
  H5Gclose(h);
  H5Gclose(g);
  H5Gclose(n);
  H5Fclose(f);
  free(sr);
  free(st);
  rs_reel_result_destroy(&r);
}

/* Decodes a plot; checks it is a 1000 x 650 image with at least 1% of it drawn on. */
static int read_plot(const char *path, png_image *img)
{
  if (!png_read_drawn(path, img)) return 0;
  CHECK(img->width == 1000 && img->height == 650);
  return 1;
}

/* Pixels of colour rgb, printed; at least `least`. */
static void expect_color(const png_image *img, uint32_t rgb, size_t least)
{
  size_t n = png_count(img, rgb);
  printf("    #%06x: %zu pixels\n", (unsigned)rgb, n);
  CHECK_LT((double)least - 0.5, (double)n);
}

static int ends_with(const char *s, const char *tail)
{
  size_t a = strlen(s), b = strlen(tail);
  return a >= b && strcmp(s + a - b, tail) == 0;
}

/* RS_KEEP_PLOTS=1 keeps the plots of a case for a look (their directory is printed). */
static void remove_plots(const char *dir)
{
  if (getenv("RS_KEEP_PLOTS")) printf("  kept %s\n", dir);
  else scratch_remove_tree(dir);
}

static void rich_run(void)
{
  char *tmp = private_tmpdir(), *dir = scratch_dir("plot");
  char *file = write_run_file(dir, "reel.h5", N_LAYERS);
  add_optional_groups(file);
  char **out = NULL;
  int n = 0;
  CHECK(rs_plot_file(file, dir, NULL, &out, &n) == RS_OK);
  const char *want[] = {"/reel-pressure.png", "/reel-hoop.png", "/reel-tension.png",
                        "/reel-nip-0.png"};
  CHECK(n == 4);
  for (int i = 0; i < n && i < 4; ++i) {
    CHECK(ends_with(out[i], want[i]));
    png_image img;
    if (!read_plot(out[i], &img)) continue;
    if (i <= 1) expect_color(&img, BLUE, 800);       /* the final profile */
    if (i <= 1) expect_color(&img, LAST_STAGE, 150); /* the last history stage shown */
    if (i == 0) expect_color(&img, RED, 300);        /* the pressure limit */
    if (i == 2) expect_color(&img, BLUE, 800);       /* T0 */
    if (i == 2) expect_color(&img, GREEN, 300);      /* the nip load */
    if (i == 3) {
      expect_color(&img, BLUE, 300);                 /* nip pressure */
      expect_color(&img, RED, 300);                  /* tau+ */
      expect_color(&img, GREEN, 300);                /* tau- */
    }
    free(img.rgb);
  }
  rs_plot_list_free(&out, n);
  CHECK(out == NULL);
  CHECK(scratch_count_entries(tmp) == 0); /* the private directory is gone */
  remove_plots(dir);
  rmdir(tmp);
  free(file);
  free(dir);
  free(tmp);
}

/* Without the optional groups: three plots, and nothing of what they would add. */
static void plain_run(void)
{
  char *tmp = private_tmpdir(), *dir = scratch_dir("plot");
  char *file = write_run_file(dir, "plain.h5", N_LAYERS);
  char **out = NULL;
  int n = 0;
  CHECK(rs_plot_file(file, dir, NULL, &out, &n) == RS_OK);
  CHECK(n == 3);
  for (int i = 0; i < n; ++i) {
    png_image img;
    if (!read_plot(out[i], &img)) continue;
    expect_color(&img, BLUE, 800);
    CHECK(png_count(&img, LAST_STAGE) == 0);
    free(img.rgb);
  }
  CHECK(scratch_count_entries(dir) == 4); /* the file and three plots, no temporaries */
  rs_plot_list_free(&out, n);
  CHECK(scratch_count_entries(tmp) == 0);
  remove_plots(dir);
  rmdir(tmp);
  free(file);
  free(dir);
  free(tmp);
}

/* Optional groups in a layout this code does not know (a 1-D history, a profile without
 * pressure): the plots are drawn without them rather than failing. */
static void odd_optional_groups(void)
{
  char *tmp = private_tmpdir(), *dir = scratch_dir("plot");
  char *file = write_run_file(dir, "odd.h5", N_LAYERS);
  hid_t f = H5Fopen(file, H5F_ACC_RDWR, H5P_DEFAULT), g, n, h;
  double v[3] = {1, 2, 3};
  CHECK(rs_h5_group_create(f, "history", &g) == RS_OK);
  write_1d(g, "sigma_r", v, 3);
  write_1d(g, "sigma_theta", v, 3);
  H5Gclose(g);
  CHECK(rs_h5_group_create(f, "nip", &n) == RS_OK);
  CHECK(rs_h5_group_create(n, "profiles", &g) == RS_OK);
  CHECK(rs_h5_group_create(g, "0", &h) == RS_OK);
  write_1d(h, "x", v, 3);
  H5Gclose(h);
  H5Gclose(g);
  H5Gclose(n);
  H5Fclose(f);
  char **out = NULL;
  int k = 0;
  CHECK(rs_plot_file(file, dir, NULL, &out, &k) == RS_OK);
  CHECK(k == 3);
  for (int i = 0; i < k; ++i) {
    png_image img;
    if (!read_plot(out[i], &img)) continue;
    CHECK(png_count(&img, LAST_STAGE) == 0);
    free(img.rgb);
  }
  rs_plot_list_free(&out, k);
  CHECK(scratch_count_entries(tmp) == 0);
  remove_plots(dir);
  rmdir(tmp);
  free(file);
  free(dir);
  free(tmp);
}

/* A comparison: each run in its own colour in every overlay. */
static void compare_overlay(void)
{
  char *tmp = private_tmpdir(), *dir = scratch_dir("plot");
  char *file = scratch_join(dir, "cmp.h5");
  rs_scene *sc[3];
  rs_reel_result *res[3];
  rs_output_run runs[3];
  for (int i = 0; i < 3; ++i) {
    char p[64];
    snprintf(p, sizeof p, "recipes/r%d.yaml", i);
    sc[i] = syn_scene(p, "recipe");
    res[i] = syn_result(N_LAYERS, 1.0 + 0.6 * i);
    runs[i] = (rs_output_run){sc[i], res[i]};
  }
  CHECK(rs_output_write_compare(file, 3, runs) == RS_OK);
  char **out = NULL;
  int n = 0;
  CHECK(rs_plot_file(file, dir, NULL, &out, &n) == RS_OK);
  CHECK(n == 3);
  for (int i = 0; i < n; ++i) {
    png_image img;
    if (!read_plot(out[i], &img)) continue;
    expect_color(&img, BLUE, 500);
    expect_color(&img, RED, 500);
    expect_color(&img, GREEN, 500);
    free(img.rgb);
  }
  CHECK(n == 3 && ends_with(out[0], "/cmp-pressure.png") && ends_with(out[2], "/cmp-tension.png"));
  rs_plot_list_free(&out, n);
  for (int i = 0; i < 3; ++i) {
    syn_scene_free(sc[i]);
    rs_reel_result_destroy(&res[i]);
  }
  CHECK(scratch_count_entries(tmp) == 0);
  remove_plots(dir);
  rmdir(tmp);
  free(file);
  free(dir);
  free(tmp);
}

/* A run stopped before any layer: frames that say so, still valid, not blank. */
static void empty_run(void)
{
  char *tmp = private_tmpdir(), *dir = scratch_dir("plot");
  char *file = write_run_file(dir, "empty.h5", 0);
  char **out = NULL;
  int n = 0;
  CHECK(rs_plot_file(file, dir, NULL, &out, &n) == RS_OK);
  CHECK(n == 3);
  for (int i = 0; i < n; ++i) {
    png_image img;
    if (read_plot(out[i], &img)) free(img.rgb);
  }
  rs_plot_list_free(&out, n);
  remove_plots(dir);
  rmdir(tmp);
  free(file);
  free(dir);
  free(tmp);
}

static void refuses_bad_input(void)
{
  char *dir = scratch_dir("plot");
  char *file = write_run_file(dir, "reel.h5", 10), *missing = scratch_join(dir, "no-such-dir");
  char **out = (char **)1;
  int n = 7;
  CHECK(rs_plot_file(file, missing, NULL, &out, &n) == RS_ERR_INPUT);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), "no-such-dir") && strstr(rs_error_message(), "does not exist"));
  CHECK(out == NULL && n == 0);
  CHECK(rs_plot_file(file, file, NULL, NULL, NULL) == RS_ERR_INPUT); /* a file, not a dir */
  CHECK(strstr(rs_error_message(), "not a directory") != NULL);
  char *text = scratch_join(dir, "scene.yaml");
  FILE *f = fopen(text, "w");
  fputs("title: x\n", f);
  fclose(f);
  CHECK(rs_plot_file(text, dir, NULL, NULL, NULL) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "scene.yaml") && strstr(rs_error_message(), "not an HDF5"));
  CHECK(scratch_count_entries(dir) == 2); /* nothing drawn */
  scratch_remove_tree(dir);
  free(text);
  free(missing);
  free(file);
  free(dir);
}

/* A curve whose data file cannot be written (a 2 kB file-size limit: the second history
 * stage's data is larger) fails the plot with the reason still recorded: the figure's
 * later steps must not clear the error of a failed curve. No PNG, no temporary left. */
static void curve_failure_reported(void)
{
  char *tmp = private_tmpdir(), *dir = scratch_dir("plot");
  char *file = write_run_file(dir, "reel.h5", N_LAYERS);
  add_optional_groups(file); /* history stages, and a pressure limit read after the curves */
  struct rlimit old, small;
  CHECK(getrlimit(RLIMIT_FSIZE, &old) == 0);
  small = old;
  small.rlim_cur = 2048;
  void (*old_xfsz)(int) = signal(SIGXFSZ, SIG_IGN); /* the write fails instead (EFBIG) */
  CHECK(setrlimit(RLIMIT_FSIZE, &small) == 0);
  rs_error_clear();
  rs_status st = rs_plot_file(file, dir, NULL, NULL, NULL);
  CHECK(setrlimit(RLIMIT_FSIZE, &old) == 0);
  signal(SIGXFSZ, old_xfsz);
  printf("  status %s: '%s'\n", rs_status_name(st), rs_error_message());
  CHECK(st == RS_ERR_IO);
  CHECK(rs_error_status() == RS_ERR_IO);
  CHECK(strstr(rs_error_message(), "cannot write") != NULL);
  CHECK(strstr(rs_error_message(), "File too large") != NULL);
  CHECK(scratch_count_entries(dir) == 1); /* the run file only */
  CHECK(scratch_count_entries(tmp) == 0);
  scratch_remove_tree(dir);
  rmdir(tmp);
  free(file);
  free(dir);
  free(tmp);
}

/* gnuplot missing, or failing: RS_ERR_IO, no PNG, no temporary directory left. */
static void gnuplot_missing_or_failing(void)
{
  char *tmp = private_tmpdir(), *dir = scratch_dir("plot");
  char *file = write_run_file(dir, "reel.h5", 10);
  rs_plot_options o = {.gnuplot = "reelsim-test-no-such-gnuplot"};
  CHECK(rs_plot_file(file, dir, &o, NULL, NULL) == RS_ERR_IO);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), "not found (apt-get install gnuplot-nox)") != NULL);
  o.gnuplot = "false"; /* runs, exits 1 */
  CHECK(rs_plot_file(file, dir, &o, NULL, NULL) == RS_ERR_IO);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), "failed (exit status 1)") != NULL);
  CHECK(scratch_count_entries(dir) == 1);
  CHECK(scratch_count_entries(tmp) == 0);
  scratch_remove_tree(dir);
  rmdir(tmp);
  free(file);
  free(dir);
  free(tmp);
}

/* ---- the checker itself can say "blank": a hand-made PNG ---------------------------- */

static void put32(unsigned char *p, uint32_t v)
{
  p[0] = (unsigned char)(v >> 24);
  p[1] = (unsigned char)(v >> 16);
  p[2] = (unsigned char)(v >> 8);
  p[3] = (unsigned char)v;
}

static void chunk(FILE *f, const char *type, const unsigned char *data, uint32_t len)
{
  unsigned char head[8];
  put32(head, len);
  memcpy(head + 4, type, 4);
  fwrite(head, 1, 8, f);
  if (len) fwrite(data, 1, len, f);
  uLong crc = crc32(crc32(0L, Z_NULL, 0), (const Bytef *)type, 4);
  if (len) crc = crc32(crc, data, len);
  put32(head, (uint32_t)crc);
  fwrite(head, 1, 4, f);
}

/* A w x h white RGB image with `dots` red pixels on the diagonal, Paeth-filtered rows. */
static void write_png(const char *path, uint32_t w, uint32_t h, uint32_t dots)
{
  size_t stride = 3 * (size_t)w, rawn = (stride + 1) * h;
  unsigned char *img = malloc(stride * h), *raw = malloc(rawn);
  memset(img, 255, stride * h);
  for (uint32_t k = 1; k <= dots && k < w && k < h; ++k) { /* (0, 0) stays background */
    img[k * stride + 3 * k + 1] = 0;
    img[k * stride + 3 * k + 2] = 0;
  }
  for (uint32_t y = 0; y < h; ++y) {
    raw[y * (stride + 1)] = 4;
    for (size_t i = 0; i < stride; ++i) {
      int a = i >= 3 ? img[y * stride + i - 3] : 0, b = y ? img[(y - 1) * stride + i] : 0;
      int c = y && i >= 3 ? img[(y - 1) * stride + i - 3] : 0;
      raw[y * (stride + 1) + 1 + i] = (unsigned char)(img[y * stride + i] - png_paeth(a, b, c));
    }
  }
  uLongf zn = compressBound((uLong)rawn);
  unsigned char *z = malloc(zn), ihdr[13] = {0};
  compress(z, &zn, raw, (uLong)rawn);
  put32(ihdr, w);
  put32(ihdr + 4, h);
  ihdr[8] = 8;
  ihdr[9] = 2;
  FILE *f = fopen(path, "wb");
  fwrite("\x89PNG\r\n\x1a\n", 1, 8, f);
  chunk(f, "IHDR", ihdr, 13);
  chunk(f, "IDAT", z, (uint32_t)zn);
  chunk(f, "IEND", NULL, 0);
  fclose(f);
  free(img);
  free(raw);
  free(z);
}

static void checker_sees_blank(void)
{
  char *dir = scratch_dir("plot"), *blank = scratch_join(dir, "blank.png"),
       *dots = scratch_join(dir, "dots.png");
  write_png(blank, 64, 48, 0);
  write_png(dots, 64, 48, 5);
  png_image img;
  CHECK(png_read(blank, &img) == 0);
  CHECK(img.width == 64 && img.height == 48 && png_ink(&img) == 0);
  free(img.rgb);
  CHECK(png_read(dots, &img) == 0);
  CHECK(png_ink(&img) == 5 && png_count(&img, 0xff0000) == 5);
  free(img.rgb);
  FILE *f = fopen(blank, "wb");
  fputs("not a png", f);
  fclose(f);
  CHECK(png_read(blank, &img) != 0);
  scratch_remove_tree(dir);
  free(blank);
  free(dots);
  free(dir);
}

static const check_case cases[] = {
    {"rich_run", rich_run},
    {"plain_run", plain_run},
    {"odd_optional_groups", odd_optional_groups},
    {"compare_overlay", compare_overlay},
    {"empty_run", empty_run},
    {"refuses_bad_input", refuses_bad_input},
    {"gnuplot_missing_or_failing", gnuplot_missing_or_failing},
    {"curve_failure_reported", curve_failure_reported},
    {"checker_sees_blank", checker_sees_blank},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
