/* The figures of a sweep file (/sweep) and of an optimisation's history (/optimize):
 *
 *   one parameter varies:   <stem>-<figure>.png, the figure against it (lines and points,
 *                           sorted by the parameter);
 *   two or more vary:       <stem>-<figure>.png, a heat map over the first two that vary
 *                           (one square per run, coloured by the figure: a grid's runs
 *                           tile the plane, a Latin hypercube's scatter over it);
 *   /optimize:              <stem>-optimize.png, the objective at each evaluation and the
 *                           best one (docs/output.md of the optimize command).
 *
 * Failed runs (NaN figures) are left out; a word-valued key is drawn at its words'
 * indices with the words as tick labels. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/figures.h"
#include "plot/plot_internal.h"
#include "util/error.h"

/* The figures drawn, with the factor to the unit on the axis (status is not drawn). */
static const struct {
  const char *name, *label;
  double scale;
} sweep_figs[] = {
    {"core_pressure", "core pressure (kPa)", 1e-3},
    {"peak_pressure", "peak interlayer pressure (kPa)", 1e-3},
    {"min_sigma_theta", "least hoop stress σθ (kPa)", 1e-3},
    {"final_radius", "final radius (mm)", 1e3},
    {"layers", "layers", 1},
    {"starring_layers", "layers at starring risk", 1},
    {"slip_margin", "least interlayer slip margin", 1},
    {"buckling_layers", "layers at hoop-buckling risk (older files)", 1},
    {"wall_seconds", "wall time of the run (s)", 1},
    {"ridge_height", "ridge height across the lanes (mm)", 1e3},
    {"max_lane_pressure", "the hardest lane's peak pressure (kPa)", 1e-3},
    {"slack_lanes", "lanes that went slack", 1},
};

typedef struct sweep_data {
  size_t k, r;      /* keys, runs */
  char **keys;
  double *values;   /* r x k */
  char **words;     /* per key: "w1,w2" or NULL */
  int vary[2], n_vary;
} sweep_data;

static void sweep_data_free(sweep_data *s)
{
  for (size_t j = 0; s->words && j < s->k; ++j) free(s->words[j]);
  free(s->words);
  rs_reader_free_strings(&s->keys, s->k);
  free(s->values);
}

static rs_status read_sweep(const plot_ctx *c, sweep_data *s)
{
  size_t rows = 0, cols = 0;
  rs_status st = rs_reader_read_strings(c->rd, "/sweep/parameters", &s->keys, &s->k);
  if (st == RS_OK) st = rs_reader_read_2d(c->rd, "/sweep/values", &s->values, &rows, &cols);
  if (st != RS_OK) return st;
  if (cols != s->k || rows == 0)
    return RS_ERROR(RS_ERR_INPUT, "'%s': /sweep/values is %zu x %zu for %zu parameters",
                    rs_reader_path(c->rd), rows, cols, s->k);
  s->r = rows;
  s->words = calloc(s->k, sizeof *s->words);
  if (!s->words) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  for (size_t j = 0; j < s->k; ++j) {
    char name[512];
    snprintf(name, sizeof name, "words:%s", s->keys[j]);
    if (rs_reader_attr_string(c->rd, "/sweep/values", name, &s->words[j]) != RS_OK)
      s->words[j] = NULL; /* a numeric key */
    /* does key j take more than one value? */
    int varies = 0;
    for (size_t i = 1; i < s->r && !varies; ++i)
      varies = s->values[i * s->k + j] != s->values[j];
    if (varies && s->n_vary < 2) s->vary[s->n_vary++] = (int)j;
  }
  rs_error_clear();
  if (s->n_vary == 0) s->vary[s->n_vary++] = 0;
  return RS_OK;
}

/* set xtics/ytics ("w1" 0, "w2" 1, ...) for a word-valued key. */
static void word_tics(plot_ctx *c, const char *axis, const char *words)
{
  if (!words) return;
  rs_gp_printf(&c->gp, "set %stics (", axis);
  const char *p = words;
  for (int i = 0; *p; ++i) {
    const char *comma = strchr(p, ',');
    size_t len = comma ? (size_t)(comma - p) : strlen(p);
    char w[256];
    snprintf(w, sizeof w, "%.*s", (int)(len < sizeof w ? len : sizeof w - 1), p);
    if (i) rs_gp_printf(&c->gp, ", ");
    rs_gp_string(&c->gp, w);
    rs_gp_printf(&c->gp, " %d", i);
    p += len + (comma ? 1 : 0);
  }
  rs_gp_printf(&c->gp, ")\n");
}

static int by_x(const void *a, const void *b)
{
  const double *x = a, *y = b;
  return (x[0] > y[0]) - (x[0] < y[0]);
}

static rs_status one_figure(plot_ctx *c, const sweep_data *s, int f, const double *fig)
{
  char *out = rsi_plot_path(c, sweep_figs[f].name), head[512];
  if (!out) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rs_gp_figure(&c->gp, out);
  free(out);
  if (st != RS_OK) return st;
  size_t n = s->r;
  int kx = s->vary[0], ky = s->vary[1];
  double *x = malloc(3 * n * sizeof *x);
  if (!x) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  double *y = x + n, *z = x + 2 * n;
  snprintf(head, sizeof head, "sweep of %zu run%s (%s)", n, n == 1 ? "" : "s", c->stem);
  rsi_plot_title(c, head, sweep_figs[f].label);
  rs_gp_printf(&c->gp, "set grid\nset xlabel ");
  rs_gp_string(&c->gp, s->keys[kx]);
  rs_gp_printf(&c->gp, "\n");
  word_tics(c, "x", s->words[kx]);
  if (s->n_vary == 1) {
    /* sorted by the parameter so that the line runs along it */
    double *pairs = malloc(2 * n * sizeof *pairs);
    if (!pairs) {
      free(x);
      return RS_ERROR(RS_ERR_MEMORY, "out of memory");
    }
    for (size_t i = 0; i < n; ++i) {
      pairs[2 * i] = s->values[i * s->k + (size_t)kx];
      pairs[2 * i + 1] = fig[i] * sweep_figs[f].scale;
    }
    qsort(pairs, n, 2 * sizeof *pairs, by_x);
    for (size_t i = 0; i < n; ++i) {
      x[i] = pairs[2 * i];
      y[i] = pairs[2 * i + 1];
    }
    free(pairs);
    rs_gp_printf(&c->gp, "set ylabel ");
    rs_gp_string(&c->gp, sweep_figs[f].label);
    rs_gp_printf(&c->gp, "\nset key off\n");
    char style[128];
    snprintf(style, sizeof style,
             "with linespoints linewidth 2 pointtype 7 pointsize 1.2 linecolor rgb '%s'",
             rsi_plot_color(0));
    st = rsi_plot_curve(c, x, y, n, style, "", NULL);
  } else {
    for (size_t i = 0; i < n; ++i) {
      x[i] = s->values[i * s->k + (size_t)kx];
      y[i] = s->values[i * s->k + (size_t)ky];
      z[i] = fig[i] * sweep_figs[f].scale;
    }
    rs_gp_printf(&c->gp, "set ylabel ");
    rs_gp_string(&c->gp, s->keys[ky]);
    rs_gp_printf(&c->gp, "\nset cblabel ");
    rs_gp_string(&c->gp, sweep_figs[f].label);
    rs_gp_printf(&c->gp, "\nset key off\nset palette rgbformulae 33,13,10\n"
                         "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n");
    word_tics(c, "y", s->words[ky]);
    const double *cols[3] = {x, y, z};
    char *name = NULL;
    size_t rows = 0;
    st = rs_gp_data(&c->gp, 3, cols, n, &name, &rows);
    if (st == RS_OK && rows > 0) {
      rs_gp_plot_item(&c->gp);
      rs_gp_string(&c->gp, name);
      rs_gp_printf(&c->gp, " using 1:2:3 with points pointtype 5 pointsize 4 palette notitle");
    }
    free(name);
  }
  if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no run succeeded");
  rs_gp_plot_end(&c->gp);
  free(x);
  return st;
}

static rs_status sweep_figures(plot_ctx *c)
{
  sweep_data s = {0};
  rs_status st = read_sweep(c, &s);
  for (int f = 0; st == RS_OK && f < (int)(sizeof sweep_figs / sizeof sweep_figs[0]); ++f) {
    char path[256];
    snprintf(path, sizeof path, "/sweep/figures/%s", sweep_figs[f].name);
    if (!rs_reader_exists(c->rd, path)) continue;
    double *fig = NULL;
    size_t n = 0;
    st = rs_reader_read_1d(c->rd, path, &fig, &n);
    if (st == RS_OK && n != s.r)
      st = RS_ERROR(RS_ERR_INPUT, "'%s': %s has %zu values for %zu runs",
                    rs_reader_path(c->rd), path, n, s.r);
    /* a figure no run has (a defect rule not assessed anywhere): nothing to draw */
    size_t finite = 0;
    for (size_t i = 0; st == RS_OK && i < n; ++i) finite += isfinite(fig[i]) != 0;
    if (st == RS_OK && finite > 0) st = one_figure(c, &s, f, fig);
    free(fig);
  }
  sweep_data_free(&s);
  return st;
}

int rsi_plot_is_search_file(const plot_ctx *c)
{
  return rs_reader_exists(c->rd, "/sweep") || rs_reader_exists(c->rd, "/optimize");
}

rs_status rsi_plot_search_figures(plot_ctx *c)
{
  rs_status st = RS_OK;
  if (rs_reader_exists(c->rd, "/sweep")) st = sweep_figures(c);
  if (st == RS_OK && rs_reader_exists(c->rd, "/optimize")) st = rsi_plot_optimize_history(c);
  return st;
}
