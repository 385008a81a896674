/* The figures of a run file: pressure and hoop stress through the reel (with stages of
 * /history and the ranges of /defects when the file has them) and the tensions. Every
 * optional group is looked for first and simply left out when absent. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot_internal.h"
#include "util/error.h"

enum { MAX_STAGES = 5 };

/* Stages in light to dark purple, the later the darker; the final state in blue on top. */
static const char *const stage_color[MAX_STAGES] = {"#cbc9e2", "#aeabd3", "#9390c4", "#7b6db5",
                                                    "#6a51a3"};
static const char final_color[] = "#1f77b4";
/* /final_at_speed (the centrifugal load): the roll spinning, beside /final at rest */
static const char spin_style[] = "with lines dashtype 2 linewidth 2 linecolor rgb '#ff7f0e'";

/* /history, if there: which stages to draw (up to MAX_STAGES, evenly spread, the final
 * stage left out: it is /final), their layer counts and outer radii, and one stress. */
typedef struct history {
  int n_pick;
  size_t pick[MAX_STAGES];
  size_t stages, cols;
  double *layers, *outer, *stress;
} history;

static void history_free(history *h)
{
  free(h->layers);
  free(h->outer);
  free(h->stress);
  memset(h, 0, sizeof *h);
}

/* Reads base/history/<what> when the file has a history; h->n_pick = 0 when not, or when
 * its layout is not the one this code knows (docs/output.md): the plot then shows the
 * final state alone rather than failing. */
static rs_status history_read(plot_ctx *c, const run_data *d, const char *what, history *h)
{
  char path[PLOT_PATH];
  size_t ns = 0, nl = 0;
  memset(h, 0, sizeof *h);
  rsi_plot_at(path, "%s/history/%s", d->base, what);
  if (!rs_reader_exists(c->rd, path)) return RS_OK;
  rs_status st = rs_reader_read_2d(c->rd, path, &h->stress, &h->stages, &h->cols);
  if (st == RS_OK)
    st = rs_reader_read_1d(c->rd, rsi_plot_at(path, "%s/history/layers", d->base), &h->layers,
                           &nl);
  if (st == RS_OK)
    st = rs_reader_read_1d(c->rd, rsi_plot_at(path, "%s/history/outer_radius", d->base),
                           &h->outer, &ns);
  if (st == RS_ERR_INPUT || (st == RS_OK && (nl != h->stages || ns != h->stages ||
                                             h->cols > d->n))) {
    rs_error_clear();
    history_free(h);
    return RS_OK;
  }
  if (st != RS_OK) {
    history_free(h);
    return st;
  }
  size_t before_final = h->stages > 0 ? h->stages - 1 : 0;
  int m = before_final < MAX_STAGES ? (int)before_final : MAX_STAGES;
  for (int k = 0; k < m; ++k) h->pick[k] = (size_t)(k + 1) * before_final / (size_t)m - 1;
  h->n_pick = m;
  return RS_OK;
}

/* Draws the picked stages of h, values scaled by `scale` (and negated for pressure). */
static rs_status history_curves(plot_ctx *c, const run_data *d, const history *h,
                                double scale)
{
  double *y = malloc((h->cols ? h->cols : 1) * sizeof *y);
  if (!y) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = RS_OK;
  for (int k = 0; st == RS_OK && k < h->n_pick; ++k) {
    size_t s = h->pick[k];
    for (size_t j = 0; j < h->cols; ++j) y[j] = scale * h->stress[s * h->cols + j];
    char style[128], title[128];
    snprintf(style, sizeof style, "with lines linewidth 1.5 linecolor rgb '%s'",
             stage_color[MAX_STAGES - h->n_pick + k]);
    snprintf(title, sizeof title, "after %.0f layers (r = %.1f mm)", h->layers[s],
             h->outer[s] * 1e3);
    st = rsi_plot_curve(c, d->r_mm, y, h->cols, style, title, NULL);
  }
  free(y);
  return st;
}

/* Flagged ranges of a defect rule, as radius bands (mm) from the inner edge of the first
 * layer to the outer edge of the last (none when the file has none, or another layout). */
static rs_status defect_bands(plot_ctx *c, const run_data *d, const char *rule,
                              const char *color, int *drawn)
{
  char p0[PLOT_PATH], p1[PLOT_PATH];
  rsi_plot_at(p0, "%s/defects/%s/range_inner_radius", d->base, rule);
  rsi_plot_at(p1, "%s/defects/%s/range_outer_radius", d->base, rule);
  *drawn = 0;
  if (!rs_reader_exists(c->rd, p0) || !rs_reader_exists(c->rd, p1)) return RS_OK;
  double *r0 = NULL, *r1 = NULL;
  size_t n0 = 0, n1 = 0;
  rs_status st = rs_reader_read_1d(c->rd, p0, &r0, &n0);
  if (st == RS_OK) st = rs_reader_read_1d(c->rd, p1, &r1, &n1);
  if (st == RS_ERR_INPUT) { /* not the layout this code knows: no bands */
    rs_error_clear();
    st = RS_OK;
    n0 = 0;
  }
  if (st == RS_OK && n0 == n1 && n0 > 0) {
    double t = d->n >= 2 ? d->r_mm[1] - d->r_mm[0] : 0.0;
    for (size_t k = 0; k < n0; ++k) {
      r0[k] = r0[k] * 1e3 - t;
      r1[k] *= 1e3;
    }
    rsi_plot_bands(c, r0, r1, n0, 0.0, 1.0, color);
    *drawn = 1;
  }
  free(r0);
  free(r1);
  return st;
}

static void axes_radius(plot_ctx *c)
{
  /* the legend below the frame: inside it covered the peak and the curves' ends */
  rs_gp_printf(&c->gp, "set xlabel 'radius r (mm)'\nset grid\nset key below left Left reverse\n");
}

static rs_status fig_pressure(plot_ctx *c, const run_data *d)
{
  char *out = rsi_plot_path(c, "pressure"), title[256];
  if (!out) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rs_gp_figure(&c->gp, out);
  free(out);
  history h;
  int slip = 0;
  if (st == RS_OK) st = history_read(c, d, "sigma_r", &h);
  if (st != RS_OK) return st;
  rsi_plot_title(c, d->title, "interlayer pressure in the wound reel");
  axes_radius(c);
  /* kPa, or MPa once the pressures reach 1000 kPa (2500 kPa reads better as 2.5 MPa) */
  double top = d->core_kpa, f = 1.0;
  for (size_t j = 0; j < d->n; ++j) top = fmax(top, d->p_kpa[j]);
  const char *unit = top >= 1000.0 ? "MPa" : "kPa";
  if (top >= 1000.0) f = 1e-3;
  double *p = malloc((d->n ? d->n : 1) * sizeof *p), *sp = NULL, core = d->core_kpa * f;
  if (d->spin_p_kpa) sp = malloc((d->n ? d->n : 1) * sizeof *sp);
  if (!p || (d->spin_p_kpa && !sp)) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  for (size_t j = 0; p && j < d->n; ++j) p[j] = d->p_kpa[j] * f;
  for (size_t j = 0; sp && j < d->n; ++j) sp[j] = d->spin_p_kpa[j] * f;
  rs_gp_printf(&c->gp, "set ylabel 'interlayer pressure P = −σr (%s)'\n", unit);
  if (st == RS_OK) st = defect_bands(c, d, "interlayer_slip", "#ff7f0e", &slip);
  if (st == RS_OK) st = history_curves(c, d, &h, -1e-3 * f);
  snprintf(title, sizeof title, "final (%zu layers)", d->n);
  char style[128];
  snprintf(style, sizeof style, "with lines linewidth 2.5 linecolor rgb '%s'", final_color);
  if (st == RS_OK) st = rsi_plot_curve(c, d->r_mm, p, d->n, style, title, NULL);
  if (st == RS_OK && sp)
    st = rsi_plot_curve(c, d->r_mm, sp, d->n, spin_style,
                    "spinning at the last layer's speed (/final at rest)", NULL);
  if (st == RS_OK && isfinite(d->core_r_mm)) {
    snprintf(title, sizeof title, "core pressure %.*f %s", f < 1 ? 3 : 2, core, unit);
    snprintf(style, sizeof style, "with points pointtype 7 pointsize 1.6 linecolor rgb '%s'",
             final_color);
    st = rsi_plot_curve(c, &d->core_r_mm, &core, 1, style, title, NULL);
  }
  char path[PLOT_PATH];
  double limit;
  rsi_plot_at(path, "%s/defects/pressure", d->base);
  if (st == RS_OK && rs_reader_exists(c->rd, path)) {
    if (rs_reader_attr_double(c->rd, path, "limit", &limit) == RS_OK && isfinite(limit)) {
      snprintf(title, sizeof title, "pressure limit %.*f %s", f < 1 ? 3 : 1, limit / 1e3 * f, unit);
      rsi_plot_hline(c, limit / 1e3 * f, "#d62728", title);
    } else {
      rs_error_clear(); /* no limit recorded: the figure goes without it */
    }
  }
  if (st == RS_OK && slip) rsi_plot_band_key(c, "#ff7f0e", "interlayer slip risk");
  if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no layers wound");
  rs_gp_plot_end(&c->gp);
  history_free(&h);
  free(p);
  free(sp);
  return st;
}

static rs_status fig_hoop(plot_ctx *c, const run_data *d)
{
  char *out = rsi_plot_path(c, "hoop"), title[256], style[128];
  if (!out) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rs_gp_figure(&c->gp, out);
  free(out);
  history h;
  int hoop = 0, star = 0;
  if (st == RS_OK) st = history_read(c, d, "sigma_theta", &h);
  if (st != RS_OK) return st;
  rsi_plot_title(c, d->title, "hoop stress in the wound reel (compression negative)");
  axes_radius(c);
  rs_gp_printf(&c->gp, "set ylabel 'hoop stress σθ (MPa)'\nset xzeroaxis linetype -1\n");
  st = defect_bands(c, d, "hoop_compression", "#d62728", &hoop);
  /* the layers at starring risk over it (older files: the single-layer rule's group) */
  if (st == RS_OK) st = defect_bands(c, d, "starring", "#7f0000", &star);
  if (st == RS_OK && !star) st = defect_bands(c, d, "hoop_buckling", "#7f0000", &star);
  if (st == RS_OK) st = history_curves(c, d, &h, 1e-6);
  snprintf(title, sizeof title, "final (%zu layers)", d->n);
  snprintf(style, sizeof style, "with lines linewidth 2.5 linecolor rgb '%s'", final_color);
  if (st == RS_OK) st = rsi_plot_curve(c, d->r_mm, d->hoop_mpa, d->n, style, title, NULL);
  if (st == RS_OK && d->spin_hoop_mpa)
    st = rsi_plot_curve(c, d->r_mm, d->spin_hoop_mpa, d->n, spin_style,
                    "spinning at the last layer's speed (/final at rest)", NULL);
  if (st == RS_OK && hoop) rsi_plot_band_key(c, "#d62728", "hoop compression (σθ < 0)");
  if (st == RS_OK && star) rsi_plot_band_key(c, "#7f0000", "starring risk (docs/defects.md §2)");
  if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no layers wound");
  rs_gp_plot_end(&c->gp);
  history_free(&h);
  return st;
}

static rs_status fig_tension(plot_ctx *c, const run_data *d)
{
  char *out = rsi_plot_path(c, "tension");
  if (!out) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rs_gp_figure(&c->gp, out);
  free(out);
  if (st != RS_OK) return st;
  double nip_max = 0.0, t_max = 0.0;
  for (size_t j = 0; j < d->n; ++j) {
    nip_max = fmax(nip_max, d->nip[j]);
    t_max = fmax(t_max, fmax(d->t0[j], d->web[j]));
  }
  int nip = nip_max > 0.0;
  rsi_plot_title(c, d->title, nip ? "wound-on tension T0 and the recipe (web tension, nip load)"
                              : "wound-on tension T0 and the web tension of the recipe");
  axes_radius(c);
  /* from 0, with room for the legend above the curves: constant recipes are common and
   * would otherwise sit on the border; the load's axis goes to twice its greatest value so
   * that a constant load and a constant T0 do not draw on top of each other */
  rs_gp_printf(&c->gp, "set ylabel 'tension per unit width (N/m)'\n");
  if (t_max > 0.0) rs_gp_printf(&c->gp, "set yrange [0:%.10g]\n", 1.3 * t_max);
  if (nip)
    rs_gp_printf(&c->gp, "set ytics nomirror\nset y2tics\nset y2label 'nip load (N/m)'\n"
                         "set y2range [0:%.10g]\n", 2.0 * nip_max);
  st = rsi_plot_curve(c, d->r_mm, d->web, d->n,
                  "with lines dashtype 2 linewidth 2 linecolor rgb '#7f7f7f'",
                  "web tension (recipe)", NULL);
  if (st == RS_OK)
    st = rsi_plot_curve(c, d->r_mm, d->t0, d->n,
                    "with lines linewidth 2.5 linecolor rgb '#1f77b4'", "wound-on tension T0",
                    NULL);
  if (st == RS_OK && nip)
    st = rsi_plot_curve(c, d->r_mm, d->nip, d->n,
                    "axes x1y2 with lines dashtype 4 linewidth 2 linecolor rgb '#2ca02c'",
                    "nip load (recipe, right axis)", NULL);
  if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no layers wound");
  rs_gp_plot_end(&c->gp);
  return st;
}

/* Entrained air (only when the file has /layers/air_film): the film under each layer as
 * it went on and as the final pressure compresses it. */
static rs_status fig_air(plot_ctx *c, const run_data *d)
{
  if (!d->air_um) return RS_OK;
  double most = 0.0;
  for (size_t j = 0; j < d->n; ++j) {
    if (d->air0_um && d->air0_um[j] > most) most = d->air0_um[j];
    if (d->air_um[j] > most) most = d->air_um[j];
  }
  char *out = rsi_plot_path(c, "air");
  if (!out) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rs_gp_figure(&c->gp, out);
  free(out);
  if (st != RS_OK) return st;
  rsi_plot_title(c, d->title, "entrained air film under each layer");
  axes_radius(c);
  rs_gp_printf(&c->gp, "set ylabel 'air film (µm)'\nset yrange [0:*]\n");
  if (!(most > 0.0)) { /* a flat 0 um line reads as a broken chart: say what happened */
    rsi_plot_empty(c, "no air kept: every entrained film is below air.cutoff roughnesses");
    rs_gp_plot_end(&c->gp);
    return st;
  }
  if (d->air0_um)
    st = rsi_plot_curve(c, d->r_mm, d->air0_um, d->n,
                    "with lines dashtype 2 linewidth 2 linecolor rgb '#7f7f7f'",
                    "as wound on (ambient pressure)", NULL);
  if (st == RS_OK)
    st = rsi_plot_curve(c, d->r_mm, d->air_um, d->n,
                    "with lines linewidth 2.5 linecolor rgb '#1f77b4'",
                    "in the wound reel (compressed)", NULL);
  if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no layers wound");
  rs_gp_plot_end(&c->gp);
  return st;
}

rs_status rsi_plot_run_figures(plot_ctx *c, const run_data *d)
{
  rs_status st = fig_pressure(c, d);
  if (st == RS_OK) st = fig_hoop(c, d);
  if (st == RS_OK) st = fig_tension(c, d);
  if (st == RS_OK) st = fig_air(c, d);
  if (st == RS_OK) st = rsi_plot_storage_figures(c, d); /* only when the file has /storage */
  if (st == RS_OK) st = rsi_plot_lanes_figures(c, d);   /* only when the file has /lanes */
  return st;
}
