/* The figures of /lanes (docs/lanes.md), when a run file has it: the pressure map (width x
 * radius), the final radius profile across the width with each lane's core pressure, and
 * the lanes' web tension against radius. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot_internal.h"
#include "util/error.h"

enum { MAX_LANE_CURVES = 8, MAP_ROWS = 160 };

typedef struct lanes {
  size_t m, N;                     /* lanes, layers */
  double *x, *width, *outer, *core; /* per lane */
  double *web, *pressure;          /* N x m: web tension, -sigma_r */
} lanes;

static void lanes_free(lanes *L)
{
  free(L->x), free(L->width), free(L->outer), free(L->core), free(L->web), free(L->pressure);
  memset(L, 0, sizeof *L);
}

/* Reads base/lanes; m = 0 when the file has none or another layout (no figure then). */
static rs_status lanes_read(plot_ctx *c, const run_data *d, lanes *L)
{
  char path[PLOT_PATH];
  size_t n[4] = {0}, r1 = 0, c1 = 0, r2 = 0, c2 = 0;
  memset(L, 0, sizeof *L);
  if (!rs_reader_exists(c->rd, rsi_plot_at(path, "%s/lanes/x", d->base))) return RS_OK;
  const char *names[4] = {"x", "width", "outer_radius", "core_pressure"};
  double **dst[4] = {&L->x, &L->width, &L->outer, &L->core};
  rs_status st = RS_OK;
  for (int k = 0; st == RS_OK && k < 4; ++k)
    st = rs_reader_read_1d(c->rd, rsi_plot_at(path, "%s/lanes/%s", d->base, names[k]), dst[k], &n[k]);
  if (st == RS_OK)
    st = rs_reader_read_2d(c->rd, rsi_plot_at(path, "%s/lanes/web_tension", d->base), &L->web, &r1, &c1);
  if (st == RS_OK)
    st = rs_reader_read_2d(c->rd, rsi_plot_at(path, "%s/lanes/final/sigma_r", d->base), &L->pressure,
                           &r2, &c2);
  const int bad = st == RS_OK && (n[1] != n[0] || n[2] != n[0] || n[3] != n[0] || c1 != n[0] ||
                                  c2 != n[0] || r1 != d->n || r2 != d->n || n[0] == 0);
  if (st == RS_ERR_INPUT || bad) {
    rs_error_clear();
    lanes_free(L);
    return RS_OK;
  }
  if (st != RS_OK) {
    lanes_free(L);
    return st;
  }
  L->m = n[0];
  L->N = d->n;
  for (size_t i = 0; i < L->m * L->N; ++i) L->pressure[i] = -L->pressure[i] * 1e-3; /* kPa */
  return RS_OK;
}

static rs_status begin(plot_ctx *c, const char *what)
{
  char *out = rsi_plot_path(c, what);
  if (!out) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rs_gp_figure(&c->gp, out);
  free(out);
  return st;
}

/* pressure map: each lane's width x a band of layers, coloured by the pressure (kPa) */
static rs_status fig_map(plot_ctx *c, const run_data *d, const lanes *L)
{
  const size_t rows = L->N < MAP_ROWS ? L->N : MAP_ROWS, n = rows * L->m;
  double *col[5];
  for (int k = 0; k < 5; ++k) col[k] = malloc(n * sizeof(double));
  rs_status st = col[0] && col[1] && col[2] && col[3] && col[4] ? begin(c, "lanes-pressure")
                                                                 : RS_ERROR(RS_ERR_MEMORY, "out of memory");
  for (size_t q = 0; st == RS_OK && q < rows; ++q) {
    const size_t j0 = q * L->N / rows, j1 = (q + 1) * L->N / rows - 1, j = (j0 + j1) / 2;
    const double lo = j0 > 0 ? d->r_mm[j0 - 1] : d->core_r_mm, hi = d->r_mm[j1];
    for (size_t i = 0; i < L->m; ++i) {
      const size_t at = q * L->m + i;
      col[0][at] = L->x[i] * 1e3, col[2][at] = 0.5 * L->width[i] * 1e3;
      col[1][at] = 0.5 * (lo + hi), col[3][at] = 0.5 * (hi - lo);
      col[4][at] = L->pressure[j * L->m + i];
    }
  }
  if (st == RS_OK) {
    char *name = NULL;
    rsi_plot_title(c, d->title, "interlayer pressure across the width and through the reel (lanes)");
    rs_gp_printf(&c->gp, "set xlabel 'across the width x (mm)'\nset ylabel 'radius r (mm)'\n"
                         "set cblabel 'pressure (kPa)'\nset palette rgb 33,13,10\n"
                         "set style fill solid noborder\n");
    st = rs_gp_data(&c->gp, 5, (const double *const *)col, n, &name, NULL);
    if (st == RS_OK) {
      rs_gp_plot_item(&c->gp);
      rs_gp_string(&c->gp, name);
      rs_gp_printf(&c->gp, " using 1:2:3:4:5 with boxxyerror linecolor palette notitle");
    }
    free(name);
    rs_gp_plot_end(&c->gp);
  }
  for (int k = 0; k < 5; ++k) free(col[k]);
  return st;
}

/* the final radius profile across the width (um from the lanes' mean) and the core pressure
 * of each lane on the right axis */
static rs_status fig_profile(plot_ctx *c, const run_data *d, const lanes *L)
{
  double *dev = malloc(L->m * sizeof *dev), *pc = malloc(L->m * sizeof *pc), *xm = malloc(L->m * sizeof *xm);
  double mean = 0.0, W = 0.0;
  rs_status st = dev && pc && xm ? begin(c, "lanes-profile") : RS_ERROR(RS_ERR_MEMORY, "out of memory");
  for (size_t i = 0; i < L->m; ++i) mean += L->width[i] * L->outer[i], W += L->width[i];
  mean /= W;
  for (size_t i = 0; st == RS_OK && i < L->m; ++i)
    dev[i] = (L->outer[i] - mean) * 1e6, pc[i] = L->core[i] * 1e-3, xm[i] = L->x[i] * 1e3;
  if (st == RS_OK) {
    char sub[160];
    snprintf(sub, sizeof sub, "final outer radius across the width (mean %.2f mm) and core pressure",
             mean * 1e3);
    rsi_plot_title(c, d->title, sub);
    rs_gp_printf(&c->gp, "set xlabel 'across the width x (mm)'\nset grid\n"
                         "set ylabel 'outer radius - mean (um)'\nset ytics nomirror\nset y2tics\n"
                         "set y2label 'core pressure (kPa)'\nset key below left Left reverse\n");
    st = rsi_plot_curve(c, xm, dev, L->m, "with linespoints pointtype 7 linewidth 2.5 linecolor rgb '#1f77b4'",
                    "outer radius (deformed: what a gauge reads)", NULL);
    if (st == RS_OK)
      st = rsi_plot_curve(c, xm, pc, L->m,
                      "axes x1y2 with linespoints pointtype 5 dashtype 2 linewidth 1.5 linecolor rgb '#d62728'",
                      "core pressure (right axis)", NULL);
    rs_gp_plot_end(&c->gp);
  }
  free(dev), free(pc), free(xm);
  return st;
}

/* each lane's share of the web's tension against the (mean) radius: up to 8 lanes */
static rs_status fig_tension(plot_ctx *c, const run_data *d, const lanes *L)
{
  double *y = malloc(L->N * sizeof *y);
  rs_status st = y ? begin(c, "lanes-tension") : RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) {
    rsi_plot_title(c, d->title, "each lane's web tension as its layers went on (0: slack)");
    rs_gp_printf(&c->gp, "set xlabel 'radius r (mm)'\nset ylabel 'web tension (N/m)'\nset grid\n"
                         "set key below left Left reverse\n");
    const size_t k = L->m < MAX_LANE_CURVES ? L->m : MAX_LANE_CURVES;
    for (size_t q = 0; st == RS_OK && q < k; ++q) {
      const size_t i = k > 1 ? q * (L->m - 1) / (k - 1) : 0;
      for (size_t j = 0; j < L->N; ++j) y[j] = L->web[j * L->m + i];
      char style[96], title[64];
      snprintf(style, sizeof style, "with lines linewidth 2 linecolor rgb '%s'", rsi_plot_color((int)q));
      snprintf(title, sizeof title, "lane %zu, x = %.0f mm", i + 1, L->x[i] * 1e3);
      st = rsi_plot_curve(c, d->r_mm, y, L->N, style, title, NULL);
    }
    rs_gp_plot_end(&c->gp);
  }
  free(y);
  return st;
}

rs_status rsi_plot_lanes_figures(plot_ctx *c, const run_data *d)
{
  lanes L;
  rs_status st = lanes_read(c, d, &L);
  if (st != RS_OK || L.m == 0) return st;
  st = fig_map(c, d, &L);
  if (st == RS_OK) st = fig_profile(c, d, &L);
  if (st == RS_OK) st = fig_tension(c, d, &L);
  lanes_free(&L);
  return st;
}
