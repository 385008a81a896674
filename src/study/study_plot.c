/* The accuracy study's picture: error against time (CPU time of the run's thread), both on log scales, one colour
 * per knob, the Pareto front as a staircase with its runs named, the shipped defaults and
 * the reference marked (docs/accuracy.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/gnuplot.h"
#include "reelsim/study.h"

static const char *const knob_color[RS_N_KNOBS] = {
    [RS_KNOB_RTOL] = "#1f77b4",    [RS_KNOB_LAYERS] = "#d62728",  [RS_KNOB_NODES] = "#2ca02c",
    [RS_KNOB_TERMS] = "#9467bd",   [RS_KNOB_T0_RTOL] = "#ff7f0e", [RS_KNOB_EVERY] = "#8c564b",
    [RS_KNOB_HISTORY] = "#7f7f7f", [RS_KNOB_GRID] = "#17becf"};

static const char *const knob_title[RS_N_KNOBS] = {
    [RS_KNOB_RTOL] = "numerics.rtol",
    [RS_KNOB_LAYERS] = "numerics.layers_per_step",
    [RS_KNOB_NODES] = "nip.nodes",
    [RS_KNOB_TERMS] = "nip.terms",
    [RS_KNOB_T0_RTOL] = "nip.T0_rtol (adaptive)",
    [RS_KNOB_EVERY] = "nip.update_every",
    [RS_KNOB_HISTORY] = "output.history_every (same answer)",
    [RS_KNOB_GRID] = "grid (rtol x layers per step x T0_rtol)"};

/* One plot item of the given points (x, y). */
static rs_status points(rs_gp *gp, const double *x, const double *y, size_t n, const char *style,
                        const char *title)
{
  const double *cols[2] = {x, y};
  char *name = NULL;
  size_t rows = 0;
  rs_status st = rs_gp_data(gp, 2, cols, n, &name, &rows);
  if (st == RS_OK && rows > 0) {
    rs_gp_plot_item(gp);
    rs_gp_string(gp, name);
    rs_gp_printf(gp, " using 1:2 %s title ", style);
    rs_gp_string(gp, title);
  }
  free(name);
  return st;
}

static int by_time(const void *a, const void *b)
{
  const double *x = a, *y = b;
  return (x[0] > y[0]) - (x[0] < y[0]);
}

/* The title, log axes and ranges: a decade around the points, errors from the reference's
 * noise up. */
static void axes(rs_gp *gp, const rs_study_report *rep, const char *title)
{
  const rs_study_plan *plan = rep->plan;
  const int n = plan->n_runs;
  double tmin = INFINITY, tmax = 0, emin = INFINITY, emax = 0;
  for (int i = 0; i < n; ++i) {
    const rs_study_row *r = &rep->rows[i];
    if (!(r->cpu_seconds > 0) || !isfinite(r->err_front)) continue;
    tmin = fmin(tmin, r->cpu_seconds);
    tmax = fmax(tmax, r->cpu_seconds);
    if (r->err_front > 0) {
      emin = fmin(emin, r->err_front);
      emax = fmax(emax, r->err_front);
    }
  }
  if (!(emin < INFINITY)) emin = emax = 1e-16;
  char head[768];
  snprintf(head, sizeof head, "%s\nerror against time: %d runs%s, %d layers", title, n,
           plan->quick ? " (quick)" : "", rep->n_layers);
  rs_gp_printf(gp, "set title ");
  rs_gp_string(gp, head);
  rs_gp_printf(gp,
               "\nset logscale xy\nset format y '%%.0e'\n"
               "set xlabel 'time of the winding (s, CPU time of its thread: the wall time on a free core)'\n"
               "set ylabel 'largest relative error against the reference'\n"
               "set grid xtics ytics\nset key below left Left reverse maxrows 6 width -8\n"
               "set xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\n",
               tmin / 1.5, tmax * 1.5, emin / 5, emax * 5);
}

/* The front's runs named beside their points; front[] gets their (time, error) pairs in
 * time order. Returns how many. */
static int front_labels(rs_gp *gp, const rs_study_report *rep, double *front)
{
  const rs_study_plan *plan = rep->plan;
  int nf = 0;
  for (int i = 0; i < plan->n_runs; ++i) {
    const rs_study_row *r = &rep->rows[i];
    if (!r->on_front) continue;
    front[2 * nf] = i == 2 ? rep->default_cpu : r->cpu_seconds; /* the defaults: least of their timings */
    front[2 * nf + 1] = r->err_front;
    ++nf;
    rs_gp_printf(gp, "set label ");
    rs_gp_string(gp, plan->runs[i].label);
    rs_gp_printf(gp, " at %.10g,%.10g offset 0.7,0.6 font ',9' textcolor rgb '#333333'\n",
                 r->cpu_seconds, r->err_front);
  }
  qsort(front, (size_t)nf, 2 * sizeof *front, by_time);
  return nf;
}

/* One colour per knob: the runs that vary it. x, y: scratch of n_runs values. */
static rs_status knob_points(rs_gp *gp, const rs_study_report *rep, double *x, double *y)
{
  const rs_study_plan *plan = rep->plan;
  rs_status st = RS_OK;
  for (int k = RS_KNOB_RTOL; st == RS_OK && k <= RS_KNOB_GRID; ++k) {
    size_t m = 0;
    for (int i = 0; i < plan->n_runs; ++i)
      if (plan->runs[i].knob == (rs_study_knob)k) {
        x[m] = rep->rows[i].cpu_seconds;
        y[m++] = rep->rows[i].err_front;
      }
    if (m == 0) continue;
    char style[160];
    snprintf(style, sizeof style, "with points pointtype %d pointsize 1.6 linecolor rgb '%s'",
             k == RS_KNOB_GRID ? 8 : k == RS_KNOB_HISTORY ? 1 : 7, knob_color[k]);
    st = points(gp, x, y, m, style, knob_title[k]);
  }
  return st;
}

/* The Pareto front as a staircase with its points ringed. */
static rs_status front_steps(rs_gp *gp, const double *front, int nf)
{
  if (nf <= 0) return RS_OK;
  rs_status st = RS_OK;
  double *fx = malloc((size_t)nf * sizeof *fx), *fy = malloc((size_t)nf * sizeof *fy);
  if (!fx || !fy) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  for (int i = 0; st == RS_OK && i < nf; ++i) {
    fx[i] = front[2 * i];
    fy[i] = front[2 * i + 1];
  }
  if (st == RS_OK)
    st = points(gp, fx, fy, (size_t)nf, "with steps linewidth 2 linecolor rgb '#000000'",
                "Pareto front (no run is both faster and more accurate)");
  if (st == RS_OK)
    st = points(gp, fx, fy, (size_t)nf,
                "with points pointtype 6 pointsize 2.6 linewidth 2 linecolor rgb '#000000'", "");
  free(fx);
  free(fy);
  return st;
}

/* The shipped defaults (named with their settings) and the reference at its noise floor. */
static rs_status defaults_and_reference(rs_gp *gp, const rs_study_report *rep, double floor)
{
  const rs_study_plan *plan = rep->plan;
  double dx = rep->default_cpu, dy = rep->rows[2].err_front;
  const rs_study_setting *d = &plan->runs[2].set;
  char what[256];
  int k = snprintf(what, sizeof what, "shipped defaults (rtol %g, %d layer/step", d->rtol,
                   d->layers_per_step);
  if (plan->has_nip) k += snprintf(what + k, sizeof what - k, ", nip adaptive T0_rtol %g", d->T0_rtol);
  if (plan->contact) snprintf(what + k, sizeof what - k, ", %d nodes, %d terms", d->nodes, d->terms);
  strncat(what, ")", sizeof what - strlen(what) - 1);
  rs_status st = points(gp, &dx, &dy, 1,
                        "with points pointtype 3 pointsize 4 linewidth 3 linecolor rgb '#e41a1c'",
                        what);
  if (st != RS_OK) return st;
  double rx = rep->rows[0].cpu_seconds, ry = floor;
  return points(gp, &rx, &ry, 1, "with points pointtype 5 pointsize 2 linecolor rgb '#000000'",
                "reference, at its change under a tighter one");
}

rs_status rs_study_plot(const rs_study_report *rep, const char *title, const char *png,
                        const rs_plot_options *opts)
{
  const int n = rep->plan->n_runs;
  rs_gp gp;
  rs_status st = rs_gp_begin(&gp, opts && opts->width > 0 ? opts->width : 1100,
                             opts && opts->height > 0 ? opts->height : 850);
  double *x = malloc((size_t)n * sizeof *x), *y = malloc((size_t)n * sizeof *y);
  double *front = malloc((size_t)n * 2 * sizeof *front);
  if (st == RS_OK && (!x || !y || !front)) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) st = rs_gp_figure(&gp, png);
  const double floor = fmax(rep->uncertainty[RS_FIG_MAX], 1e-300);
  int nf = 0;
  if (st == RS_OK) {
    axes(&gp, rep, title);
    nf = front_labels(&gp, rep, front);
    st = knob_points(&gp, rep, x, y);
  }
  if (st == RS_OK) st = front_steps(&gp, front, nf);
  if (st == RS_OK) st = defaults_and_reference(&gp, rep, floor);
  if (st == RS_OK) {
    rs_gp_plot_item(&gp);
    rs_gp_printf(&gp, "%.10g with lines dashtype 2 linecolor rgb '#666666' title ", floor);
    rs_gp_string(&gp, "the reference's uncertainty (errors below it are shown on it)");
    rs_gp_plot_item(&gp);
    rs_gp_printf(&gp, "1e-3 with lines dashtype 3 linecolor rgb '#e41a1c' title ");
    rs_gp_string(&gp, "0.1 %");
    rs_gp_plot_end(&gp);
    st = rs_gp_run(&gp, opts ? opts->gnuplot : NULL);
  }
  rs_gp_end(&gp);
  free(x);
  free(y);
  free(front);
  return st;
}
