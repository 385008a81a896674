/* The figures of /storage (docs/storage.md), when a run file has it: pressure and hoop
 * stress through the reel at the end of each storage stage, and the core pressure against
 * storage time. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot_internal.h"
#include "util/error.h"

enum { MAX_DRAWN = 8 };

/* Light to dark: the later the stage, the darker; stage 0 (the wound roll) in blue. */
static const char *const stage_color[MAX_DRAWN] = {"#1f77b4", "#fdd0a2", "#fdae6b", "#fd8d3c",
                                                   "#f16913", "#d94801", "#a63603", "#7f2704"};

typedef struct storage {
  size_t S, cols;
  double *hours, *temp, *hum, *core, *stress;
} storage;

static void storage_free(storage *s)
{
  free(s->hours);
  free(s->temp);
  free(s->hum);
  free(s->core);
  free(s->stress);
  memset(s, 0, sizeof *s);
}

/* Reads base/storage (what: the 2-D dataset, or NULL); S = 0 when the file has none or
 * another layout: no figure then. */
static rs_status storage_read(plot_ctx *c, const run_data *d, const char *what, storage *s)
{
  char path[PLOT_PATH];
  size_t n1 = 0, n2 = 0, n3 = 0, n4 = 0;
  memset(s, 0, sizeof *s);
  if (!rs_reader_exists(c->rd, rsi_plot_at(path, "%s/storage/hours", d->base))) return RS_OK;
  rs_status st = rs_reader_read_1d(c->rd, path, &s->hours, &n1);
  if (st == RS_OK)
    st = rs_reader_read_1d(c->rd, rsi_plot_at(path, "%s/storage/temperature", d->base), &s->temp, &n2);
  if (st == RS_OK)
    st = rs_reader_read_1d(c->rd, rsi_plot_at(path, "%s/storage/humidity", d->base), &s->hum, &n3);
  if (st == RS_OK)
    st = rs_reader_read_1d(c->rd, rsi_plot_at(path, "%s/storage/core_pressure", d->base), &s->core,
                           &n4);
  size_t rows = n1;
  if (st == RS_OK && what)
    st = rs_reader_read_2d(c->rd, rsi_plot_at(path, "%s/storage/%s", d->base, what), &s->stress,
                           &rows, &s->cols);
  if (st == RS_ERR_INPUT || (st == RS_OK && (n2 != n1 || n3 != n1 || n4 != n1 || rows != n1 ||
                                             (what && s->cols != d->n)))) {
    rs_error_clear();
    storage_free(s);
    return RS_OK;
  }
  if (st != RS_OK) {
    storage_free(s);
    return st;
  }
  s->S = n1;
  return RS_OK;
}

/* the stages drawn: all up to MAX_DRAWN, else stage 0, the last and evenly between */
static int pick(size_t S, size_t *out)
{
  int m = S < MAX_DRAWN ? (int)S : MAX_DRAWN;
  for (int k = 0; k < m; ++k) out[k] = m > 1 ? (size_t)k * (S - 1) / (size_t)(m - 1) : 0;
  return m;
}

static rs_status fig_by_stage(plot_ctx *c, const run_data *d, const char *what, double scale,
                              const char *file, const char *sub, const char *ylabel)
{
  storage s;
  rs_status st = storage_read(c, d, what, &s);
  if (st != RS_OK || s.S == 0) return st;
  char *out = rsi_plot_path(c, file);
  if (!out) {
    storage_free(&s);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  st = rs_gp_figure(&c->gp, out);
  free(out);
  double *y = malloc((s.cols ? s.cols : 1) * sizeof *y);
  if (st == RS_OK && !y) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) {
    rsi_plot_title(c, d->title, sub);
    rs_gp_printf(&c->gp, "set xlabel 'radius r (mm)'\nset grid\nset key below left Left reverse\n"
                         "set ylabel '%s'\nset xzeroaxis linetype -1\n", ylabel);
    size_t idx[MAX_DRAWN];
    int m = pick(s.S, idx);
    for (int k = 0; st == RS_OK && k < m; ++k) {
      const size_t i = idx[k];
      for (size_t j = 0; j < s.cols; ++j) y[j] = scale * s.stress[i * s.cols + j];
      char style[128], title[160];
      snprintf(style, sizeof style, "with lines linewidth %s linecolor rgb '%s'",
               i == 0 ? "2.5" : "1.8", stage_color[i == 0 ? 0 : 1 + (k - 1) * 7 / (m > 1 ? m - 1 : 1)]);
      if (i == 0)
        snprintf(title, sizeof title, "wound (%.1f C, %.0f %% RH)", s.temp[i], s.hum[i]);
      else
        snprintf(title, sizeof title, "stage %zu: %.1f h, %.1f C, %.0f %% RH", i, s.hours[i],
                 s.temp[i], s.hum[i]);
      st = rsi_plot_curve(c, d->r_mm, y, s.cols, style, title, NULL);
    }
    if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no layers wound");
    rs_gp_plot_end(&c->gp);
  }
  free(y);
  storage_free(&s);
  return st;
}

static rs_status fig_core(plot_ctx *c, const run_data *d)
{
  storage s;
  rs_status st = storage_read(c, d, NULL, &s);
  if (st != RS_OK || s.S == 0) return st;
  char *out = rsi_plot_path(c, "storage-core");
  if (!out) {
    storage_free(&s);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  st = rs_gp_figure(&c->gp, out);
  free(out);
  if (st == RS_OK) {
    /* kPa, or MPa from 1000 kPa up */
    double top = 0.0, tlo = INFINITY, thi = -INFINITY;
    for (size_t i = 0; i < s.S; ++i) {
      top = fmax(top, s.core[i] * 1e-3);
      tlo = fmin(tlo, s.temp[i]);
      thi = fmax(thi, s.temp[i]);
    }
    const double f = top >= 1000.0 ? 1e-6 : 1e-3;
    for (size_t i = 0; i < s.S; ++i) s.core[i] *= f;
    rsi_plot_title(c, d->title, "core pressure after each stage's change, held to its end (steps)");
    rs_gp_printf(&c->gp, "set xlabel 'storage time (h)'\nset grid\nset key below left Left reverse\n"
                         "set ylabel 'core pressure (%s)'\nset ytics nomirror\nset y2tics\n"
                         "set y2label 'temperature (C)'\n", f < 1e-3 ? "MPa" : "kPa");
    /* the temperature off the frame: a tenth of its span (or 1 C) above and below */
    double pad = thi > tlo ? 0.1 * (thi - tlo) : 1.0;
    if (isfinite(tlo)) rs_gp_printf(&c->gp, "set y2range [%.10g:%.10g]\n", tlo - pad, thi + pad);
    /* a stage changes temperature and humidity at its start (the elastic response) and
     * holds them to its end: the value at the end of stage s is drawn from its start */
    st = rsi_plot_curve(c, s.hours, s.core, s.S,
                    "with fsteps linewidth 2.5 linecolor rgb '#1f77b4'",
                    "core pressure (each stage's end value from its start)", NULL);
    if (st == RS_OK)
      st = rsi_plot_curve(c, s.hours, s.core, s.S, "with points pointtype 7 linecolor rgb '#1f77b4'",
                      "", NULL);
    if (st == RS_OK)
      st = rsi_plot_curve(c, s.hours, s.temp, s.S,
                      "axes x1y2 with fsteps dashtype 2 linewidth 1.5 linecolor rgb '#d62728'",
                      "temperature (right axis)", NULL);
    rs_gp_plot_end(&c->gp);
  }
  storage_free(&s);
  return st;
}

rs_status rsi_plot_storage_figures(plot_ctx *c, const run_data *d)
{
  rs_status st = fig_by_stage(c, d, "sigma_r", -1e-3, "storage-pressure",
                              "interlayer pressure at the end of each storage stage",
                              "interlayer pressure P = −σr (kPa)");
  if (st == RS_OK)
    st = fig_by_stage(c, d, "sigma_theta", 1e-6, "storage-hoop",
                      "hoop stress at the end of each storage stage (compression negative)",
                      "hoop stress σθ (MPa)");
  if (st == RS_OK) st = fig_core(c, d);
  return st;
}
