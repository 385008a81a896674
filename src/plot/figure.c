/* The pieces every figure uses (plot_internal.h): paths, colours, curves, bands, titles,
 * and a run's data read from the file in plotting units. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot_internal.h"
#include "util/error.h"

const char *rsi_plot_at(char *buf, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, PLOT_PATH, fmt, ap);
  va_end(ap);
  return buf;
}

const char *rsi_plot_color(int i)
{
  static const char *const palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                        "#9467bd", "#8c564b", "#e377c2", "#17becf",
                                        "#bcbd22", "#7f7f7f"};
  return palette[i % (int)(sizeof palette / sizeof palette[0])];
}

char *rsi_plot_path(const plot_ctx *c, const char *what)
{
  size_t n = strlen(c->dir) + strlen(c->stem) + strlen(what) + 8;
  char *p = malloc(n);
  if (p) {
    int slash = c->dir[0] && c->dir[strlen(c->dir) - 1] != '/';
    snprintf(p, n, "%s%s%s-%s.png", c->dir, slash ? "/" : "", c->stem, what);
  }
  return p;
}

void rsi_plot_title(plot_ctx *c, const char *line1, const char *line2)
{
  size_t n = strlen(line1) + (line2 ? strlen(line2) : 0) + 2;
  char *t = malloc(n);
  if (!t) return;
  snprintf(t, n, "%s%s%s", line1, line2 ? "\n" : "", line2 ? line2 : "");
  rs_gp_printf(&c->gp, "set title ");
  rs_gp_string(&c->gp, t);
  rs_gp_printf(&c->gp, "\n");
  free(t);
}

rs_status rsi_plot_curve(plot_ctx *c, const double *x, const double *y, size_t n,
                     const char *style, const char *title, size_t *rows)
{
  const double *cols[2] = {x, y};
  char *name = NULL;
  size_t k = 0;
  rs_status st = rs_gp_data(&c->gp, 2, cols, n, &name, &k);
  if (st == RS_OK && k > 0) {
    rs_gp_plot_item(&c->gp);
    rs_gp_string(&c->gp, name);
    rs_gp_printf(&c->gp, " using 1:2 %s title ", style);
    rs_gp_string(&c->gp, title);
  }
  free(name);
  if (rows) *rows = k;
  return st;
}

void rsi_plot_hline(plot_ctx *c, double value, const char *color, const char *title)
{
  rs_gp_plot_item(&c->gp);
  rs_gp_printf(&c->gp, "%.10g with lines dashtype 2 linewidth 2 linecolor rgb '%s' title ",
               value, color);
  rs_gp_string(&c->gp, title);
}

void rsi_plot_bands(plot_ctx *c, const double *x0, const double *x1, size_t n, double y0,
                double y1, const char *color)
{
  for (size_t k = 0; k < n; ++k) {
    if (!isfinite(x0[k]) || !isfinite(x1[k])) continue;
    rs_gp_printf(&c->gp,
                 "set object rectangle from first %.10g, graph %g to first %.10g, graph %g "
                 "behind fillcolor rgb '%s' fillstyle transparent solid 0.25 noborder\n",
                 x0[k], y0, x1[k], y1, color);
  }
}

void rsi_plot_band_key(plot_ctx *c, const char *color, const char *title)
{
  rs_gp_plot_item(&c->gp);
  rs_gp_printf(&c->gp,
               "NaN with boxes fillcolor rgb '%s' fillstyle transparent solid 0.25 title ",
               color);
  rs_gp_string(&c->gp, title);
}

void rsi_plot_empty(plot_ctx *c, const char *why)
{
  rs_gp_printf(&c->gp, "set xrange [0:1]\nset yrange [0:1]\nset label ");
  rs_gp_string(&c->gp, why);
  rs_gp_printf(&c->gp, " at graph 0.5, 0.5 center\n");
  rs_gp_plot_item(&c->gp);
  rs_gp_printf(&c->gp, "NaN notitle");
}

/* ---- a run's data --------------------------------------------------------------------- */

void rsi_plot_run_free(run_data *d)
{
  free(d->title);
  free(d->r_mm);
  free(d->p_kpa);
  free(d->hoop_mpa);
  free(d->t0);
  free(d->web);
  free(d->nip);
  free(d->spin_p_kpa);
  free(d->spin_hoop_mpa);
  free(d->air_um);
  free(d->air0_um);
  memset(d, 0, sizeof *d);
}

/* Reads base + rel; checks it has n values (n = 0: sets it). */
static rs_status read_layers(const plot_ctx *c, const char *base, const char *rel, double **v,
                             size_t *n)
{
  char path[PLOT_PATH];
  size_t k = 0;
  rs_status st = rs_reader_read_1d(c->rd, rsi_plot_at(path, "%s%s", base, rel), v, &k);
  if (st != RS_OK) return st;
  if (*n == 0) *n = k;
  if (k != *n)
    return RS_ERROR(RS_ERR_INPUT, "%s: '%s' has %zu values, /final/radius %zu",
                    rs_reader_path(c->rd), path, k, *n);
  return RS_OK;
}

/* read_layers for a dataset only some files have, scaled; *v = NULL when absent */
static rs_status read_optional(const plot_ctx *c, const char *base, const char *rel,
                               double scale, double **v, size_t n)
{
  char path[PLOT_PATH];
  *v = NULL;
  if (!rs_reader_exists(c->rd, rsi_plot_at(path, "%s%s", base, rel))) return RS_OK;
  rs_status st = read_layers(c, base, rel, v, &n);
  if (st != RS_OK) {
    free(*v);
    *v = NULL;
    return st;
  }
  for (size_t j = 0; j < n; ++j) (*v)[j] *= scale;
  return RS_OK;
}

rs_status rsi_plot_run_read(const plot_ctx *c, int i, run_data *d)
{
  memset(d, 0, sizeof *d);
  d->base = rs_reader_run_base(c->rd, i);
  d->name = rs_reader_run_name(c->rd, i);
  d->core_r_mm = NAN;
  double *sr = NULL;
  char path[PLOT_PATH];
  if (rs_reader_attr_string(c->rd, d->base, "title", &d->title) != RS_OK || !d->title[0]) {
    free(d->title);
    d->title = strdup(d->name);
    if (!d->title) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  rs_error_clear();
  rs_status st = read_layers(c, d->base, "/final/radius", &d->r_mm, &d->n);
  if (st == RS_OK) st = read_layers(c, d->base, "/final/sigma_r", &sr, &d->n);
  if (st == RS_OK) st = read_layers(c, d->base, "/final/sigma_theta", &d->hoop_mpa, &d->n);
  if (st == RS_OK) st = read_layers(c, d->base, "/layers/wound_on_tension", &d->t0, &d->n);
  if (st == RS_OK) st = read_layers(c, d->base, "/layers/web_tension", &d->web, &d->n);
  if (st == RS_OK) st = read_layers(c, d->base, "/layers/nip_load", &d->nip, &d->n);
  if (st == RS_OK)
    st = rs_reader_read_scalar(c->rd, rsi_plot_at(path, "%s/final/core_pressure", d->base),
                               &d->core_kpa);
  if (st == RS_OK)
    st = read_optional(c, d->base, "/final_at_speed/sigma_r", -1e-3, &d->spin_p_kpa, d->n);
  if (st == RS_OK)
    st = read_optional(c, d->base, "/final_at_speed/sigma_theta", 1e-6, &d->spin_hoop_mpa, d->n);
  if (st == RS_OK) st = read_optional(c, d->base, "/layers/air_film", 1e6, &d->air_um, d->n);
  if (st == RS_OK)
    st = read_optional(c, d->base, "/layers/air_film_entrained", 1e6, &d->air0_um, d->n);
  if (st == RS_OK && !(d->p_kpa = malloc((d->n ? d->n : 1) * sizeof *d->p_kpa)))
    st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) {
    for (size_t j = 0; j < d->n; ++j) {
      d->p_kpa[j] = -sr[j] / 1e3;
      d->hoop_mpa[j] /= 1e6;
      d->r_mm[j] *= 1e3;
    }
    d->core_kpa /= 1e3;
    /* layers are one caliper apart: the core is one spacing inside the first layer */
    if (d->n >= 2) d->core_r_mm = 2 * d->r_mm[0] - d->r_mm[1];
  }
  free(sr);
  if (st != RS_OK) rsi_plot_run_free(d);
  return st;
}
