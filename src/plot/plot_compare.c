/* The figures of a comparison file: each quantity with every run overlaid, one colour
 * per run, the legend naming the run and its scene's title. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "reelsim/reader.h"

#include "plot/plot_internal.h"
#include "util/error.h"

typedef enum quantity { Q_PRESSURE, Q_HOOP, Q_TENSION, Q_AIR } quantity;

static const struct {
  const char *file, *what, *ylabel;
} figs[] = {
    [Q_PRESSURE] = {"pressure", "interlayer pressure in the wound reels",
                    "interlayer pressure P = −σr (kPa)"},
    [Q_HOOP] = {"hoop", "hoop stress in the wound reels (compression negative)",
                "hoop stress σθ (MPa)"},
    [Q_TENSION] = {"tension", "wound-on tension T0 (solid) and web tension of the recipe "
                              "(dashed)",
                   "tension per unit width (N/m)"},
    [Q_AIR] = {"air", "entrained air film under each layer in the wound reels",
               "air film (µm)"},
};

/* Each run's material.pressure_limit (its /defects/pressure limit), dashed in the run's
 * colour; one line when the runs share it. */
static void limits(plot_ctx *c, const run_data *runs, int n, double scale)
{
  double drawn = NAN;
  for (int i = 0; i < n; ++i) {
    char path[PLOT_PATH], title[128];
    double limit;
    rsi_plot_at(path, "%s/defects/pressure", runs[i].base);
    if (!rs_reader_exists(c->rd, path) ||
        rs_reader_attr_double(c->rd, path, "limit", &limit) != RS_OK || !isfinite(limit) ||
        !(limit > 0)) {
      rs_error_clear();
      continue;
    }
    if (limit == drawn) continue;
    snprintf(title, sizeof title, "pressure limit %.4g %s (%s)", limit * scale,
             scale < 1e-3 ? "MPa" : "kPa", runs[i].name);
    rsi_plot_hline(c, limit * scale, rsi_plot_color(i), title);
    drawn = limit;
  }
}

static rs_status overlay(plot_ctx *c, const run_data *runs, int n, quantity q)
{
  char *out = rsi_plot_path(c, figs[q].file), head[512], style[160], title[768];
  if (!out) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rs_gp_figure(&c->gp, out);
  free(out);
  if (st != RS_OK) return st;
  snprintf(head, sizeof head, "comparison of %d run%s (%s)", n, n == 1 ? "" : "s", c->stem);
  rsi_plot_title(c, head, figs[q].what);
  /* the pressures in kPa, or MPa once any reaches 1000 kPa */
  double top = 0.0, scale = 1e-3, f = 1.0;
  for (int i = 0; q == Q_PRESSURE && i < n; ++i)
    for (size_t j = 0; runs[i].p_kpa && j < runs[i].n; ++j) top = fmax(top, runs[i].p_kpa[j]);
  if (top >= 1000.0) {
    scale = 1e-6;
    f = 1e-3;
  }
  rs_gp_printf(&c->gp, "set xlabel 'radius r (mm)'\nset ylabel '%s'\nset grid\n"
                       "set key below left Left reverse height 1.5\n",
               f < 1 ? "interlayer pressure P = −σr (MPa)" : figs[q].ylabel);
  if (q == Q_HOOP) rs_gp_printf(&c->gp, "set xzeroaxis linetype -1\n");
  if (q == Q_TENSION) { /* from 0: constant recipes would otherwise sit on the border */
    double t_max = 0.0;
    for (int i = 0; i < n; ++i)
      for (size_t j = 0; j < runs[i].n; ++j)
        t_max = fmax(t_max, fmax(runs[i].t0[j], runs[i].web[j]));
    if (t_max > 0.0) rs_gp_printf(&c->gp, "set yrange [0:%.10g]\n", 1.1 * t_max);
  }
  for (int i = 0; st == RS_OK && i < n; ++i) {
    const run_data *d = &runs[i];
    const double *y = q == Q_PRESSURE ? d->p_kpa : q == Q_HOOP ? d->hoop_mpa
                    : q == Q_AIR    ? d->air_um : d->t0;
    if (!y) continue; /* Q_AIR: a run without air */
    double *ys = NULL;
    if (q == Q_PRESSURE && f < 1) { /* in MPa */
      ys = malloc((d->n ? d->n : 1) * sizeof *ys);
      if (!ys) {
        st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
        break;
      }
      for (size_t j = 0; j < d->n; ++j) ys[j] = y[j] * f;
      y = ys;
    }
    snprintf(style, sizeof style, "with lines linewidth 2.5 linecolor rgb '%s'", rsi_plot_color(i));
    snprintf(title, sizeof title, "%s: %s", d->name, d->title);
    st = rsi_plot_curve(c, d->r_mm, y, d->n, style, title, NULL);
    free(ys);
    /* the centrifugal load: the roll spinning (/final_at_speed), dashed in the run's colour */
    const double *spin = q == Q_PRESSURE ? d->spin_p_kpa : q == Q_HOOP ? d->spin_hoop_mpa : NULL;
    if (st == RS_OK && spin) {
      snprintf(style, sizeof style, "with lines dashtype 2 linewidth 1.5 linecolor rgb '%s'",
               rsi_plot_color(i));
      snprintf(title, sizeof title, "%s spinning (/final_at_speed)", d->name);
      double *ss = q == Q_PRESSURE && f < 1 ? malloc((d->n ? d->n : 1) * sizeof *ss) : NULL;
      for (size_t j = 0; ss && j < d->n; ++j) ss[j] = spin[j] * f;
      if (q == Q_PRESSURE && f < 1 && !ss) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
      else st = rsi_plot_curve(c, d->r_mm, ss ? ss : spin, d->n, style, title, NULL);
      free(ss);
    }
    if (st == RS_OK && q == Q_TENSION) {
      snprintf(style, sizeof style, "with lines dashtype 2 linewidth 1.5 linecolor rgb '%s'",
               rsi_plot_color(i));
      st = rsi_plot_curve(c, d->r_mm, d->web, d->n, style, "", NULL);
    }
  }
  if (st == RS_OK && q == Q_PRESSURE) limits(c, runs, n, scale);
  if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no layers wound");
  rs_gp_plot_end(&c->gp);
  return st;
}

rs_status rsi_plot_compare_figures(plot_ctx *c, const run_data *runs, int n)
{
  rs_status st = overlay(c, runs, n, Q_PRESSURE);
  if (st == RS_OK) st = overlay(c, runs, n, Q_HOOP);
  if (st == RS_OK) st = overlay(c, runs, n, Q_TENSION);
  int air = 0;
  for (int i = 0; i < n; ++i) air |= runs[i].air_um != NULL;
  if (st == RS_OK && air) st = overlay(c, runs, n, Q_AIR);
  return st;
}
