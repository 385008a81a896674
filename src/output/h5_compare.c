/* rs_output_write_compare: several runs in one file. Each run gets exactly the layout of a
 * run file (rs_h5_write_run) under /runs/<name>, and /summary holds one entry per run in
 * parallel 1-D datasets, which h5dump, h5py and MATLAB all read without compound types. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output/h5_layout.h"
#include "output/h5_util.h"
#include "reel/result_internal.h"
#include "reelsim/output.h"
#include "util/error.h"
#include "storage/storage_result.h"

void rs_output_run_name(int i, int n, const char *scene_path, char *buf, size_t size)
{
  const char *base = scene_path ? strrchr(scene_path, '/') : NULL;
  base = base ? base + 1 : scene_path ? scene_path : "";
  const char *dot = strrchr(base, '.');
  int len = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
  int width = snprintf(NULL, 0, "%d", n > 0 ? n : 1);
  if (len == 0) snprintf(buf, size, "%0*d-scene", width, i + 1);
  else snprintf(buf, size, "%0*d-%.*s", width, i + 1, len, base);
}

typedef struct compare_ctx {
  int n;
  const rs_output_run *runs;
  char (*names)[256];
  const rs_storage_result *const *storage; /* n, or NULL */
} compare_ctx;

static rs_status write_runs(hid_t file, const compare_ctx *c)
{
  hid_t runs;
  rs_status st = rs_h5_group_create(file, "runs", &runs);
  for (int i = 0; st == RS_OK && i < c->n; ++i) {
    hid_t g;
    st = rs_h5_group_create(runs, c->names[i], &g);
    if (st != RS_OK) break;
    st = rs_h5_write_run(g, c->runs[i].scene, c->runs[i].result);
    if (st == RS_OK && c->storage && c->storage[i]) st = rs_h5_write_storage(g, c->storage[i]);
    H5Gclose(g);
  }
  if (runs >= 0) H5Gclose(runs);
  return st;
}

/* The figures of rs_reel_summarize, one column per figure. */
enum {
  F_FINAL_RADIUS, F_CORE, F_PEAK, F_PEAK_R, F_HOOP, F_HOOP_R, F_WOT_MIN, F_WOT_MAX, F_WALL,
  N_FIGURES
};
static const struct {
  const char *name, *units, *description;
} figures[N_FIGURES] = {
    {"final_radius", "m", "outer radius of the wound reel"},
    {"core_pressure", "Pa", "pressure on the core; compression positive"},
    {"peak_pressure", "Pa", "greatest interlayer pressure (or the core pressure if larger)"},
    {"peak_pressure_radius", "m", "radius of peak_pressure"},
    {"min_hoop_stress", "Pa", "least hoop stress; compression negative"},
    {"min_hoop_stress_radius", "m", "radius of min_hoop_stress"},
    {"wot_min", "N/m", "least wound-on tension T0 over the layers"},
    {"wot_max", "N/m", "greatest wound-on tension T0 over the layers"},
    {"wall_seconds", "s", "wall-clock time of the winding"},
};

/* The after-storage figures (rs_storage_summarize), when any run has storage stages; NaN
 * for a run without. col: room for N_FIGURES x n doubles. */
static rs_status write_storage_summary(hid_t g, const compare_ctx *c, double *col)
{
  enum { S_CORE, S_PEAK, S_HOOP, S_MAX_CORE, S_MAX_PEAK, S_HOURS, N_S };
  static const struct {
    const char *name, *units, *description;
  } sfig[N_S] = {
      {"storage_core_pressure", "Pa", "pressure on the core after the last storage stage"},
      {"storage_peak_pressure", "Pa", "greatest interlayer pressure after the last storage stage"},
      {"storage_min_hoop_stress", "Pa", "least hoop stress after the last storage stage"},
      {"storage_max_core_pressure", "Pa", "greatest core pressure after any storage stage"},
      {"storage_max_peak_pressure", "Pa", "greatest interlayer pressure after any storage stage"},
      {"storage_hours", "h", "hours of storage in all"},
  };
  int any = 0;
  for (int i = 0; c->storage && i < c->n; ++i) any |= c->storage[i] != NULL;
  if (!any) return RS_OK;
  size_t n = (size_t)c->n;
  for (size_t i = 0; i < n; ++i) {
    rs_storage_summary s;
    rs_storage_summarize(c->storage[i], &s);
    double v[N_S] = {s.core_pressure, s.peak_pressure, s.min_hoop, s.max_core_pressure,
                     s.max_peak_pressure, s.hours};
    for (int f = 0; f < N_S; ++f) col[f * n + i] = v[f];
  }
  rs_status st = RS_OK;
  for (int f = 0; st == RS_OK && f < N_S; ++f)
    st = rs_h5_write_1d(g, sfig[f].name, col + f * n, n, sfig[f].units, sfig[f].description);
  return st;
}

/* The lanes' figures (rs_lanes_summarize, as sweep's and optimize's: ridge_height,
 * max_lane_pressure, slack_lanes), when any run has lanes; NaN for a run without. col: room
 * for 3 x n doubles. */
static rs_status write_lanes_summary(hid_t g, const compare_ctx *c, double *col)
{
  static const struct {
    const char *name, *units, *description;
  } lfig[3] = {
      {"ridge_height", "m", "max - min of the lanes' final outer radii (docs/lanes.md)"},
      {"max_lane_pressure", "Pa", "the hardest lane's peak pressure, core or -sigma_r"},
      {"slack_lanes", "", "lanes that went slack while winding"},
  };
  size_t n = (size_t)c->n;
  int any = 0;
  for (size_t i = 0; i < n; ++i) {
    rs_lanes_summary s;
    const rs_problem *p = rs_scene_problem(c->runs[i].scene);
    int has = rs_lanes_summarize(c->runs[i].result, p->material.pressure_limit, &s);
    double v[3] = {s.ridge_height, s.hardest_pressure, s.slack_lanes};
    for (int f = 0; f < 3; ++f) col[f * n + i] = has ? v[f] : NAN;
    any |= has;
  }
  rs_status st = RS_OK;
  for (int f = 0; any && st == RS_OK && f < 3; ++f)
    st = rs_h5_write_1d(g, lfig[f].name, col + f * n, n, lfig[f].units, lfig[f].description);
  return st;
}

static rs_status write_summary(hid_t file, const compare_ctx *c)
{
  size_t n = (size_t)c->n;
  double *col = malloc(n * N_FIGURES * sizeof *col);
  long long *layers = malloc(n * sizeof *layers);
  const char **group = malloc(n * sizeof *group), **scene = malloc(n * sizeof *scene),
             **title = malloc(n * sizeof *title);
  rs_status st = RS_OK;
  hid_t g = -1;
  if (!col || !layers || !group || !scene || !title) {
    st = RS_ERROR(RS_ERR_MEMORY, "out of memory for the summary of %zu runs", n);
    goto done;
  }
  for (size_t i = 0; i < n; ++i) {
    rs_reel_summary s;
    rs_reel_summarize(c->runs[i].result, &s);
    double v[N_FIGURES] = {s.final_radius, s.core_pressure, s.peak_pressure,
                           s.peak_pressure_radius, s.min_hoop, s.min_hoop_radius,
                           s.wot_min, s.wot_max, c->runs[i].result->wall_seconds};
    for (int f = 0; f < N_FIGURES; ++f) col[f * n + i] = v[f];
    layers[i] = s.layers;
    group[i] = c->names[i];
    scene[i] = rs_scene_path(c->runs[i].scene);
    title[i] = rs_scene_title(c->runs[i].scene);
  }
  if ((st = rs_h5_group_create(file, "summary", &g)) != RS_OK) goto done;
  st = rs_h5_write_1d_strings(g, "run", group, n, "group of each run under /runs, in run order");
  if (st == RS_OK)
    st = rs_h5_write_1d_strings(g, "scene_file", scene, n, "scene file as given");
  if (st == RS_OK) st = rs_h5_write_1d_strings(g, "title", title, n, "title of each scene");
  if (st == RS_OK) st = rs_h5_write_1d_int64(g, "layers", layers, n, "", "layers wound");
  for (int f = 0; st == RS_OK && f < N_FIGURES; ++f)
    st = rs_h5_write_1d(g, figures[f].name, col + f * n, n, figures[f].units,
                        figures[f].description);
  if (st == RS_OK) st = write_storage_summary(g, c, col);
  if (st == RS_OK) st = write_lanes_summary(g, c, col);
done:
  if (g >= 0) H5Gclose(g);
  free(col);
  free(layers);
  free(group);
  free(scene);
  free(title);
  return st;
}

static rs_status build_compare(hid_t file, const void *ctx)
{
  const compare_ctx *c = ctx;
  rs_status st = rs_h5_attr_int64(file, "runs", c->n);
  if (st == RS_OK) st = write_runs(file, c);
  if (st == RS_OK) st = write_summary(file, c);
  return st;
}

rs_status rs_output_write_compare(const char *path, int n, const rs_output_run *runs)
{
  return rs_output_write_compare_stored(path, n, runs, NULL, NULL);
}

rs_status rs_output_write_compare_stored(const char *path, int n, const rs_output_run *runs,
                                         const rs_storage_result *const *storage,
                                         const char *const *names)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no output file name given");
  if (n < 1 || !runs) return RS_ERROR(RS_ERR_INTERNAL, "no runs to write");
  rs_status st = RS_OK;
  for (int i = 0; st == RS_OK && i < n; ++i) {
    if (!runs[i].scene || !runs[i].result)
      return RS_ERROR(RS_ERR_INTERNAL, "run %d has no scene or no result", i + 1);
    st = rs_h5_check_result(runs[i].result);
    if (st == RS_OK && storage) st = rs_h5_check_storage(storage[i], runs[i].result);
  }
  if (st != RS_OK) return st;
  compare_ctx c = {n, runs, malloc((size_t)n * sizeof *c.names), storage};
  if (!c.names) return RS_ERROR(RS_ERR_MEMORY, "out of memory for %d run names", n);
  for (int i = 0; i < n; ++i)
    rs_output_run_name(i, n, names && names[i] ? names[i] : rs_scene_path(runs[i].scene),
                       c.names[i], sizeof c.names[i]);
  st = rs_h5_write_staged(path, build_compare, &c);
  free(c.names);
  return st;
}
