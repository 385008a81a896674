/* reelsim plot study.h5: the study's picture again, from its file. The plot module knows
 * run and compare files; a study file is the study's (an application beside plot), so the
 * CLI dispatches on the file's kind (cmd_plot.c) and rebuilds here, from /study, the part
 * of the report the picture draws: each run's label, knob, CPU time, error on the front
 * and front flag, the defaults' setting and time, the reference's uncertainty. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/plot_study.h"
#include "reelsim/reader.h"
#include "reelsim/study.h"
#include "sweep/app_error.h"

static rs_study_knob knob_of(const char *name)
{
  for (int k = 0; k < RS_N_KNOBS; ++k)
    if (strcmp(rs_study_knob_name((rs_study_knob)k), name) == 0) return (rs_study_knob)k;
  return RS_KNOB_GRID;
}

enum { COL_CPU, COL_ERR, COL_FRONT, COL_RTOL, COL_M, COL_NODES, COL_TERMS, COL_EVERY,
       COL_T0, COL_HISTORY, N_COLS };
static const char *const cols[N_COLS] = {"cpu_seconds", "err_front", "on_front", "rtol",
                                         "layers_per_step", "nodes", "terms", "update_every",
                                         "T0_rtol", "history_every"};

int cli_is_study_file(const char *path)
{
  rs_reader *r = NULL;
  if (rs_reader_open(path, &r) != RS_OK) {
    app_error_clear();
    return 0;
  }
  int yes = rs_reader_exists(r, "/study/runs");
  rs_reader_close(&r);
  return yes;
}

rs_status cli_plot_study(const char *path, const char *png)
{
  rs_reader *r = NULL;
  char **labels = NULL, **knobs = NULL, *title = NULL;
  size_t n = 0, n_knobs = 0, n_unc = 0, len[N_COLS] = {0};
  double *col[N_COLS] = {NULL}, *unc = NULL, layers = 0, quick = 0, default_cpu = 0;
  rs_study_plan plan = {0};
  rs_study_report rep = {0};
  rs_status st = rs_reader_open(path, &r);
  if (st == RS_OK) st = rs_reader_read_strings(r, "/study/runs/label", &labels, &n);
  if (st == RS_OK) st = rs_reader_read_strings(r, "/study/runs/knob", &knobs, &n_knobs);
  for (int c = 0; st == RS_OK && c < N_COLS; ++c) {
    char where[64];
    snprintf(where, sizeof where, "/study/runs/%s", cols[c]);
    st = rs_reader_read_1d(r, where, &col[c], &len[c]);
    if (st == RS_OK && len[c] != n)
      st = APP_ERROR(RS_ERR_INPUT, "%s: %s has %zu values for %zu runs", path, where, len[c], n);
  }
  if (st == RS_OK) st = rs_reader_read_1d(r, "/study/uncertainty", &unc, &n_unc);
  if (st == RS_OK) st = rs_reader_attr_string(r, "/study", "title", &title);
  if (st == RS_OK) st = rs_reader_attr_double(r, "/study", "layers", &layers);
  if (st == RS_OK) st = rs_reader_attr_double(r, "/study", "quick", &quick);
  if (st == RS_OK) st = rs_reader_attr_double(r, "/study", "default_cpu_seconds", &default_cpu);
  if (st == RS_OK && (n_knobs != n || n < 3 || n_unc != RS_N_FIGURES))
    st = APP_ERROR(RS_ERR_INPUT, "%s: not a whole study (%zu runs, %zu knobs, %zu figures)", path,
                  n, n_knobs, n_unc);
  if (st == RS_OK) {
    plan.n_runs = (int)n;
    plan.quick = quick != 0;
    plan.runs = calloc(n, sizeof *plan.runs);
    rep.rows = calloc(n, sizeof *rep.rows);
    if (!plan.runs || !rep.rows) st = APP_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  for (size_t i = 0; st == RS_OK && i < n; ++i) {
    rs_study_run *run = &plan.runs[i];
    snprintf(run->label, sizeof run->label, "%s", labels[i]);
    run->knob = knob_of(knobs[i]);
    run->set = (rs_study_setting){.rtol = col[COL_RTOL][i],
                                  .layers_per_step = (int)col[COL_M][i],
                                  .nodes = (int)col[COL_NODES][i],
                                  .terms = (int)col[COL_TERMS][i],
                                  .update_every = (int)col[COL_EVERY][i],
                                  .T0_rtol = col[COL_T0][i],
                                  .history_every = (int)col[COL_HISTORY][i]};
    rep.rows[i].cpu_seconds = col[COL_CPU][i];
    rep.rows[i].err_front = col[COL_ERR][i];
    rep.rows[i].on_front = col[COL_FRONT][i] != 0;
  }
  if (st == RS_OK) {
    /* what the scene used: a nip has a T0_rtol or an update interval, a contact nip nodes */
    const rs_study_setting *d = &plan.runs[2].set;
    plan.has_nip = d->T0_rtol > 0 || d->update_every > 0;
    plan.contact = d->nodes > 0;
    rep.plan = &plan;
    rep.n_layers = (int)layers;
    rep.default_cpu = default_cpu;
    memcpy(rep.uncertainty, unc, sizeof rep.uncertainty);
    st = rs_study_plot(&rep, title, png, NULL);
  }
  for (int c = 0; c < N_COLS; ++c) free(col[c]);
  free(unc);
  free(title);
  free(plan.runs);
  free(rep.rows);
  rs_reader_free_strings(&labels, n);
  rs_reader_free_strings(&knobs, n_knobs);
  rs_reader_close(&r);
  return st;
}
