/* reelsim plot of a sweep file and of an optimisation's history, with the real gnuplot:
 * one PNG per figure, not blank, the curve in its colour (one parameter) or the palette's
 * colours (a heat map over two), the failed run left out; /optimize's objective drawn
 * with its best point marked. */
#include <hdf5.h>
#include <math.h>

#include "check.h"
#include "output/h5_layout.h"
#include "output/h5_util.h"
#include "png_check.h"
#include "reelsim/output.h"
#include "reelsim/plot.h"
#include "scratch.h"

static const uint32_t BLUE = 0x1f77b4, ORANGE = 0xff7f0e;
static const char *const FIGS[] = {"core_pressure", "peak_pressure", "min_sigma_theta",
                                   "final_radius", "layers", "buckling_layers",
                                   "wall_seconds", "status"};
enum { NF = 8, R = 6 };

/* A sweep of R runs over n_keys keys (the second, when there, a word-valued one), run 3
 * failed (NaN figures). */
static char *write_sweep(const char *dir, const char *name, int n_keys)
{
  char *path = scratch_join(dir, name);
  const char *keys[2] = {"winding.tension", "numerics.load_placement"};
  const char *const words1[] = {"beneath", "hakiel"};
  const char *const *words[2] = {NULL, words1};
  int n_words[2] = {0, 2};
  double values[R * 2], figures[NF * R];
  for (int i = 0; i < R; ++i) {
    double t = 100.0 + 50.0 * (n_keys == 1 ? i : i / 2);
    if (n_keys == 1) values[i] = t;
    else {
      values[2 * i] = t;
      values[2 * i + 1] = i % 2;
    }
    for (int f = 0; f < NF; ++f) figures[f * R + i] = i == 3 && f < 6 ? NAN : 1000.0 * t + f;
    figures[7 * R + i] = i == 3 ? 3 : 0;
  }
  rs_output_sweep sw = {.scene_path = "synthetic.yaml", .sample = "grid", .n_keys = n_keys,
                        .keys = keys, .n_words = n_words, .words = words, .n_runs = R,
                        .values = values, .n_figures = NF, .figure_names = FIGS,
                        .figures = figures};
  CHECK(rs_output_write_sweep(path, &sw) == RS_OK);
  return path;
}

/* The PNGs of a sweep file: the 7 figures but status, in order. */
static void check_list(char **written, int n, const char *stem)
{
  CHECK(n == 7);
  for (int i = 0; i < n && i < 7; ++i) {
    char want[256];
    snprintf(want, sizeof want, "%s-%s.png", stem, FIGS[i]);
    const char *base = strrchr(written[i], '/');
    CHECK(base && strcmp(base + 1, want) == 0);
  }
}

static void one_parameter(void)
{
  char *dir = scratch_dir("plot_sweep1"), *file = write_sweep(dir, "one.h5", 1);
  char **written = NULL;
  int n = 0;
  CHECK(rs_plot_file(file, dir, NULL, &written, &n) == RS_OK);
  check_list(written, n, "one");
  png_image img;
  if (n > 0 && png_read_drawn(written[0], &img)) {
    size_t blue = png_count(&img, BLUE);
    printf("    #%06x: %zu pixels\n", (unsigned)BLUE, blue);
    CHECK(blue > 300); /* the line and its points */
    free(img.rgb);
  }
  rs_plot_list_free(&written, n);
  free(file);
  scratch_remove_tree(dir);
  free(dir);
}

static void two_parameters(void)
{
  char *dir = scratch_dir("plot_sweep2"), *file = write_sweep(dir, "two.h5", 2);
  char **written = NULL;
  int n = 0;
  CHECK(rs_plot_file(file, dir, NULL, &written, &n) == RS_OK);
  check_list(written, n, "two");
  png_image img;
  if (n > 0 && png_read_drawn(written[0], &img)) {
    /* a heat map: coloured squares, none of them the line colour */
    size_t colours = 0;
    for (size_t p = 0; p < (size_t)img.width * img.height; ++p) {
      uint32_t c = img.rgb[p];
      int r = (int)(c >> 16), g = (int)(c >> 8 & 0xff), b = (int)(c & 0xff);
      colours += abs(r - g) > 80 || abs(g - b) > 80 || abs(r - b) > 80;
    }
    printf("    saturated pixels: %zu\n", colours);
    CHECK(colours > 2000);
    CHECK(png_count(&img, BLUE) == 0);
    free(img.rgb);
  }
  rs_plot_list_free(&written, n);
  free(file);
  scratch_remove_tree(dir);
  free(dir);
}

/* /optimize as the optimize command writes it: 10 evaluations, the best the 7th. */
static void optimize_history(void)
{
  char *dir = scratch_dir("plot_opt"), *file = scratch_join(dir, "opt.h5");
  hid_t f = H5Fcreate(file, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), g, fg;
  CHECK(f >= 0);
  CHECK(rs_h5_write_file_attributes(f) == RS_OK);
  CHECK(rs_h5_group_create(f, "optimize", &g) == RS_OK);
  CHECK(rs_h5_attr_string(g, "objective", "core_pressure") == RS_OK);
  CHECK(rs_h5_attr_string(g, "sense", "minimize") == RS_OK);
  CHECK(rs_h5_group_create(g, "figures", &fg) == RS_OK);
  double y[10];
  for (int i = 0; i < 10; ++i) y[i] = 1e5 * (1.0 + 0.5 * fabs(6.0 - i));
  CHECK(rs_h5_write_1d(fg, "core_pressure", y, 10, "Pa", "") == RS_OK);
  CHECK(rs_h5_write_scalar(g, "best", 6, "", "") == RS_OK);
  H5Gclose(fg);
  H5Gclose(g);
  H5Fclose(f);
  char **written = NULL;
  int n = 0;
  CHECK(rs_plot_file(file, dir, NULL, &written, &n) == RS_OK);
  CHECK(n == 1);
  png_image img;
  if (n == 1 && strstr(written[0], "opt-optimize.png") && png_read_drawn(written[0], &img)) {
    size_t blue = png_count(&img, BLUE), orange = png_count(&img, ORANGE);
    printf("    evaluations #%06x: %zu, best #%06x: %zu pixels\n", (unsigned)BLUE, blue,
           (unsigned)ORANGE, orange);
    CHECK(blue > 100 && orange > 20);
    free(img.rgb);
  }
  rs_plot_list_free(&written, n);
  free(file);
  scratch_remove_tree(dir);
  free(dir);
}

static const check_case cases[] = {
    {"one_parameter", one_parameter},
    {"two_parameters", two_parameters},
    {"optimize_history", optimize_history},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
