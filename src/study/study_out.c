/* The accuracy study's files (reelsim study; docs/accuracy.md, docs/output.md): an HDF5
 * file and a CSV file of every run, with the same columns, both staged (temporary + rename)
 * like every reelsim output. One table of columns describes both, so they cannot drift. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output/h5_layout.h"
#include "output/h5_util.h"
#include "util/atomic_file.h"
#include "reelsim/study.h"
#include "util/error.h"

typedef enum col_kind { COL_DOUBLE, COL_INT, COL_STRING } col_kind;

typedef struct column {
  const char *name, *units, *description;
  col_kind kind;
} column;

enum {
  C_LABEL, C_KNOB, C_SETS, C_LEVEL, C_RTOL, C_LAYERS, C_NODES, C_TERMS, C_UPDATE_EVERY, C_T0_RTOL,
  C_HISTORY, C_WALL, C_CPU, C_STEPS, C_NIP_SOLVES, C_CORE, C_PEAK, C_T0, C_ERR0,
  C_ERR_FRONT = C_ERR0 + RS_N_FIGURES, C_ON_FRONT, C_IDENTICAL, N_COLUMNS
};

static const column columns[N_COLUMNS] = {
    [C_LABEL] = {"label", "", "the run", COL_STRING},
    [C_KNOB] = {"knob", "", "what the run varies: reference, reference2, default, a knob, grid", COL_STRING},
    [C_SETS] = {"sets", "", "the --set overrides that make the run's scene, space-separated", COL_STRING},
    [C_LEVEL] = {"level", "", "the varied knob's value (0 for reference, default, grid)", COL_DOUBLE},
    [C_RTOL] = {"rtol", "", "numerics.rtol", COL_DOUBLE},
    [C_LAYERS] = {"layers_per_step", "", "numerics.layers_per_step", COL_INT},
    [C_NODES] = {"nodes", "", "nip.nodes (0: no contact nip)", COL_INT},
    [C_TERMS] = {"terms", "", "nip.terms (0: no contact nip)", COL_INT},
    [C_UPDATE_EVERY] = {"update_every", "layers", "nip.update every k layers (0: adaptive or no nip)", COL_INT},
    [C_T0_RTOL] = {"T0_rtol", "", "nip.T0_rtol of the adaptive update (0: every k or no nip)", COL_DOUBLE},
    [C_HISTORY] = {"history_every", "layers", "output.history_every", COL_INT},
    [C_WALL] = {"wall_seconds", "s", "wall-clock time of the winding", COL_DOUBLE},
    [C_CPU] = {"cpu_seconds", "s", "CPU time of the winding's thread", COL_DOUBLE},
    [C_STEPS] = {"cvode_steps", "", "CVODE steps, all increments", COL_INT},
    [C_NIP_SOLVES] = {"nip_solves", "", "nip solves, rejected ones included", COL_INT},
    [C_CORE] = {"core_pressure", "Pa", "pressure on the core; compression positive", COL_DOUBLE},
    [C_PEAK] = {"peak_pressure", "Pa", "greatest interlayer pressure (or the core pressure)", COL_DOUBLE},
    [C_T0] = {"T0_final", "N/m", "wound-on tension of the last layer", COL_DOUBLE},
    [C_ERR0 + RS_FIG_CORE] = {"err_core_pressure", "", "|core pressure - reference| / reference", COL_DOUBLE},
    [C_ERR0 + RS_FIG_PEAK] = {"err_peak_pressure", "", "|peak pressure - reference| / reference", COL_DOUBLE},
    [C_ERR0 + RS_FIG_SIGMA_R] = {"err_sigma_r", "", "max over layers of |sigma_r - reference| / |reference|", COL_DOUBLE},
    [C_ERR0 + RS_FIG_SIGMA_THETA] = {"err_sigma_theta", "", "max over layers of |sigma_theta - reference| / (T0_ref / caliper): hoop stress crosses zero, so against the hoop stress each layer was wound with", COL_DOUBLE},
    [C_ERR0 + RS_FIG_T0] = {"err_T0_final", "", "|T0 of the last layer - reference| / reference", COL_DOUBLE},
    [C_ERR0 + RS_FIG_MAX] = {"err_max", "", "the largest of the five errors", COL_DOUBLE},
    [C_ERR_FRONT] = {"err_front", "", "err_max raised to the reference's uncertainty, to 3 significant digits (what the Pareto front uses)", COL_DOUBLE},
    [C_ON_FRONT] = {"on_front", "", "1: on the Pareto front of (cpu_seconds, err_front); references excluded", COL_INT},
    [C_IDENTICAL] = {"identical_to_default", "", "1: the same numbers as the default run, bit for bit", COL_INT},
};

/* Value of column c for run i (doubles and integers; strings separately). */
static double col_value(const rs_study_report *rep, int c, int i)
{
  const rs_study_run *r = &rep->plan->runs[i];
  const rs_study_row *w = &rep->rows[i];
  if (c >= C_ERR0 && c < C_ERR0 + RS_N_FIGURES) return w->err[c - C_ERR0];
  switch (c) {
  case C_LEVEL: return r->level;
  case C_RTOL: return r->set.rtol;
  case C_LAYERS: return r->set.layers_per_step;
  case C_NODES: return r->set.nodes;
  case C_TERMS: return r->set.terms;
  case C_UPDATE_EVERY: return r->set.update_every;
  case C_T0_RTOL: return r->set.T0_rtol;
  case C_HISTORY: return r->set.history_every;
  case C_WALL: return w->wall_seconds;
  case C_CPU: return w->cpu_seconds;
  case C_STEPS: return (double)w->cvode_steps;
  case C_NIP_SOLVES: return (double)w->nip_solves;
  case C_CORE: return w->core_pressure;
  case C_PEAK: return w->peak_pressure;
  case C_T0: return w->T0_final;
  case C_ERR_FRONT: return w->err_front;
  case C_ON_FRONT: return w->on_front;
  case C_IDENTICAL: return w->identical_to_default;
  default: return NAN;
  }
}

static void run_sets(const rs_study_run *r, char *buf, size_t size)
{
  size_t used = 0;
  buf[0] = '\0';
  for (int k = 0; k < r->n_sets && used < size; ++k)
    used += (size_t)snprintf(buf + used, size - used, "%s%s", k ? " " : "", r->sets[k]);
}

static const char *col_string(const rs_study_report *rep, int c, int i, char *buf, size_t size)
{
  const rs_study_run *r = &rep->plan->runs[i];
  if (c == C_LABEL) return r->label;
  if (c == C_KNOB) return rs_study_knob_name(r->knob);
  run_sets(r, buf, size);
  return buf;
}

/* ---- HDF5 ------------------------------------------------------------------------------- */

typedef struct study_ctx {
  const rs_scene *scene;
  const rs_study_report *rep;
} study_ctx;

static rs_status write_columns(hid_t g, const rs_study_report *rep)
{
  const int n = rep->plan->n_runs;
  double *v = malloc((size_t)n * sizeof *v);
  long long *iv = malloc((size_t)n * sizeof *iv);
  char (*text)[RS_STUDY_MAX_SETS * RS_STUDY_SET_LEN] = malloc((size_t)n * sizeof *text);
  const char **sp = malloc((size_t)n * sizeof *sp);
  rs_status st = RS_OK;
  if (!v || !iv || !text || !sp) st = RS_ERROR(RS_ERR_MEMORY, "out of memory for %d study runs", n);
  for (int c = 0; st == RS_OK && c < N_COLUMNS; ++c) {
    const column *col = &columns[c];
    for (int i = 0; i < n; ++i) {
      if (col->kind == COL_STRING) sp[i] = col_string(rep, c, i, text[i], sizeof text[i]);
      else if (col->kind == COL_INT) iv[i] = (long long)col_value(rep, c, i);
      else v[i] = col_value(rep, c, i);
    }
    if (col->kind == COL_STRING) st = rs_h5_write_1d_strings(g, col->name, sp, (size_t)n, col->description);
    else if (col->kind == COL_INT)
      st = rs_h5_write_1d_int64(g, col->name, iv, (size_t)n, col->units, col->description);
    else st = rs_h5_write_1d(g, col->name, v, (size_t)n, col->units, col->description);
  }
  free(v);
  free(iv);
  free(text);
  free(sp);
  return st;
}

static rs_status write_orders(hid_t g, const rs_study_report *rep)
{
  const char *names[RS_N_KNOBS];
  double p[2][RS_N_KNOBS], fl[2][RS_N_KNOBS];
  long long pts[2][RS_N_KNOBS];
  int n = 0;
  for (int k = RS_KNOB_RTOL; k <= RS_KNOB_EVERY; ++k) {
    int used = 0;
    for (int i = 0; i < rep->plan->n_runs; ++i) used |= rep->plan->runs[i].knob == (rs_study_knob)k;
    if (!used) continue;
    names[n] = rs_study_knob_name((rs_study_knob)k);
    for (int f = 0; f < 2; ++f) {
      p[f][n] = rep->order[k][f].order;
      fl[f][n] = rep->order[k][f].floor;
      pts[f][n] = rep->order[k][f].points;
    }
    ++n;
  }
  rs_status st = rs_h5_write_1d_strings(g, "knob", names, (size_t)n, "knob of each row");
  static const char *const fig[2] = {"core", "max"};
  char name[64], desc[256];
  for (int f = 0; st == RS_OK && f < 2; ++f) {
    snprintf(name, sizeof name, "order_%s", fig[f]);
    snprintf(desc, sizeof desc,
             "observed order p in err_%s ~ x^p along the knob's sweep (x: rtol, layers_per_step "
             "- 1, 1/nodes, 1/terms, T0_rtol, update_every); NaN: fewer than two points above "
             "the floor",
             f ? "max" : "core_pressure");
    st = rs_h5_write_1d(g, name, p[f], (size_t)n, "", desc);
    snprintf(name, sizeof name, "points_%s", fig[f]);
    if (st == RS_OK) st = rs_h5_write_1d_int64(g, name, pts[f], (size_t)n, "", "sweep points the fit used");
    snprintf(name, sizeof name, "floor_%s", fig[f]);
    if (st == RS_OK)
      st = rs_h5_write_1d(g, name, fl[f], (size_t)n, "",
                          "errors at or below this were left out of the fit");
  }
  return st;
}

static rs_status build_study(hid_t file, const void *vctx)
{
  const study_ctx *c = vctx;
  const rs_study_report *rep = c->rep;
  hid_t g = -1, runs = -1, orders = -1;
  rs_status st = rs_h5_group_create(file, "study", &g);
  if (st == RS_OK) st = rs_h5_attr_string(g, "title", rs_scene_title(c->scene));
  if (st == RS_OK) st = rs_h5_attr_string(g, "scene_file", rs_scene_path(c->scene));
  if (st == RS_OK) st = rs_h5_attr_string(g, "scene", rs_scene_resolved_text(c->scene));
  if (st == RS_OK) st = rs_h5_attr_int64(g, "layers", rep->n_layers);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "quick", rep->plan->quick);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "runs", rep->plan->n_runs);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "front_runs", rep->n_front);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "default_on_front", rep->default_on_front);
  if (st == RS_OK) st = rs_h5_attr_double(g, "time_noise", rep->time_noise);
  if (st == RS_OK) st = rs_h5_attr_double(g, "default_cpu_seconds", rep->default_cpu);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "default_timings", rep->default_timings);
  if (st == RS_OK) st = rs_h5_attr_double(g, "smallest_error", rep->smallest_error);
  if (st == RS_OK)
    st = rs_h5_attr_string(g, "docs", "docs/accuracy.md (errors, reference, front), docs/output.md");
  if (st == RS_OK) {
    const char *names[RS_N_FIGURES];
    for (int f = 0; f < RS_N_FIGURES; ++f) names[f] = rs_study_figure_name((rs_study_figure)f);
    st = rs_h5_write_1d_strings(g, "figure", names, RS_N_FIGURES, "the error figures, in order");
  }
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "uncertainty", rep->uncertainty, RS_N_FIGURES, "",
                        "reference2 against the reference, per figure: how far the reference "
                        "has converged");
  if (st == RS_OK) st = rs_h5_group_create(g, "runs", &runs);
  if (st == RS_OK) st = write_columns(runs, rep);
  if (st == RS_OK) st = rs_h5_group_create(g, "orders", &orders);
  if (st == RS_OK) st = write_orders(orders, rep);
  if (orders >= 0) H5Gclose(orders);
  if (runs >= 0) H5Gclose(runs);
  if (g >= 0) H5Gclose(g);
  return st;
}

rs_status rs_study_write(const char *path, const rs_scene *scene, const rs_study_report *rep)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no output file name given");
  if (!scene || !rep || !rep->plan || !rep->rows)
    return RS_ERROR(RS_ERR_INTERNAL, "no study to write");
  study_ctx c = {scene, rep};
  return rs_h5_write_staged(path, build_study, &c);
}

/* ---- CSV -------------------------------------------------------------------------------- */

/* A CSV field: quoted when it holds a comma, a quote or a space. */
static void csv_string(FILE *f, const char *s)
{
  if (!strpbrk(s, ",\" \n")) {
    fputs(s, f);
    return;
  }
  fputc('"', f);
  for (; *s; ++s) {
    if (*s == '"') fputc('"', f);
    fputc(*s == '\n' ? ' ' : *s, f);
  }
  fputc('"', f);
}

rs_status rs_study_write_csv(const char *path, const rs_study_report *rep)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no output file name given");
  rs_status st = rs_atomic_file_check_target(path);
  if (st != RS_OK) return st;
  char *text = NULL, buf[RS_STUDY_MAX_SETS * RS_STUDY_SET_LEN];
  size_t size = 0;
  FILE *f = open_memstream(&text, &size);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the study CSV");
  for (int c = 0; c < N_COLUMNS; ++c) {
    fputs(c ? "," : "", f);
    fputs(columns[c].name, f);
    /* units as a suffix, as in the run's CSV files (core_pressure_Pa), unless the name
     * says them already (wall_seconds) or they are a count (layers) */
    if (columns[c].units[0] && strcmp(columns[c].units, "layers") != 0 &&
        strcmp(columns[c].units, "s") != 0)
      fprintf(f, "_%s", strcmp(columns[c].units, "N/m") == 0 ? "N_per_m" : columns[c].units);
  }
  fputc('\n', f);
  for (int i = 0; i < rep->plan->n_runs; ++i) {
    for (int c = 0; c < N_COLUMNS; ++c) {
      fputs(c ? "," : "", f);
      if (columns[c].kind == COL_STRING) csv_string(f, col_string(rep, c, i, buf, sizeof buf));
      else if (columns[c].kind == COL_INT) fprintf(f, "%lld", (long long)col_value(rep, c, i));
      else fprintf(f, "%.17g", col_value(rep, c, i));
    }
    fputc('\n', f);
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) {
    free(text);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory for the study CSV");
  }
  st = rs_atomic_file_write(path, text, size);
  free(text);
  return st;
}
