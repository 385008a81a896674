/* The figures of one wound recipe (figures.h). */
#include "sweep/figures.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "reelsim/clock.h"
#include "reelsim/defects.h"
#include "reelsim/storage.h"

const sweep_figure_info sweep_figures[SWEEP_N_FIGURES] = {
    [SWEEP_FIG_CORE_PRESSURE] = {"core_pressure", "Pa", "pressure on the core (compression positive)"},
    [SWEEP_FIG_PEAK_PRESSURE] = {"peak_pressure", "Pa", "greatest interlayer pressure, max of -sigma_r"},
    [SWEEP_FIG_MIN_SIGMA_THETA] = {"min_sigma_theta", "Pa", "least hoop stress (negative: compression)"},
    [SWEEP_FIG_FINAL_RADIUS] = {"final_radius", "m", "outer radius of the wound reel"},
    [SWEEP_FIG_LAYERS] = {"layers", "", "layers wound"},
    [SWEEP_FIG_STARRING_LAYERS] = {"starring_layers", "", "layers at starring risk (docs/defects.md)"},
    [SWEEP_FIG_SLIP_MARGIN] = {"slip_margin", "", "least interlayer slip (cinching) margin, capacity / torque"},
    [SWEEP_FIG_WALL_SECONDS] = {"wall_seconds", "s", "wall-clock time of the run"},
    [SWEEP_FIG_STATUS] = {"status", "", "0 ok, 2 refused, 3 solver failed, 1 other"},
    [SWEEP_FIG_STORAGE_CORE_PRESSURE] = {"storage_core_pressure", "Pa",
                                         "pressure on the core after the last storage stage"},
    [SWEEP_FIG_STORAGE_PEAK_PRESSURE] = {"storage_peak_pressure", "Pa",
                                         "greatest interlayer pressure after the last storage stage"},
    [SWEEP_FIG_STORAGE_MIN_SIGMA_THETA] = {"storage_min_sigma_theta", "Pa",
                                           "least hoop stress after the last storage stage"},
    [SWEEP_FIG_STORAGE_MAX_CORE_PRESSURE] = {"storage_max_core_pressure", "Pa",
                                             "greatest core pressure after any storage stage"},
    [SWEEP_FIG_STORAGE_MAX_PEAK_PRESSURE] = {"storage_max_peak_pressure", "Pa",
                                             "greatest interlayer pressure after any storage stage"},
    [SWEEP_FIG_STORAGE_STARRING_LAYERS] = {"storage_starring_layers", "",
                                           "most layers at starring risk after any storage stage"},
    [SWEEP_FIG_RIDGE_HEIGHT] = {"ridge_height", "m",
                                "max - min of the lanes' final outer radii (docs/lanes.md)"},
    [SWEEP_FIG_MAX_LANE_PRESSURE] = {"max_lane_pressure", "Pa",
                                     "the hardest lane's peak pressure, core or -sigma_r"},
    [SWEEP_FIG_SLACK_LANES] = {"slack_lanes", "", "lanes that went slack while winding"},
};

int sweep_figure_find(const char *name)
{
  for (int i = 0; name && i < SWEEP_N_FIGURES; ++i)
    if (strcmp(sweep_figures[i].name, name) == 0) return i;
  /* the name of the single-layer rule starring_layers replaced, for older commands */
  if (name && strcmp(name, "buckling_layers") == 0) return SWEEP_FIG_STARRING_LAYERS;
  return -1;
}

void sweep_figure_names(char *buf, size_t size)
{
  size_t used = 0;
  if (size) buf[0] = '\0';
  for (int i = 0; i < SWEEP_N_FIGURES && used < size; ++i)
    used += (size_t)snprintf(buf + used, size - used, "%s%s", i ? ", " : "", sweep_figures[i].name);
}

const char *sweep_figure_lacks(const rs_problem *problem, int f)
{
  if (f >= SWEEP_FIG_STORAGE_CORE_PRESSURE && f <= SWEEP_FIG_STORAGE_STARRING_LAYERS &&
      !(problem && rs_storage_requested(problem)))
    return "no storage stages (docs/storage.md)";
  if (f >= SWEEP_FIG_RIDGE_HEIGHT && f <= SWEEP_FIG_SLACK_LANES &&
      !(problem && problem->lanes.count > 0))
    return "no `lanes:` (docs/lanes.md)";
  return NULL;
}

int sweep_figure_list(const rs_problem *problem, int idx[SWEEP_N_FIGURES])
{
  int n = 0;
  for (int f = 0; f < SWEEP_N_FIGURES; ++f)
    if (!sweep_figure_lacks(problem, f)) idx[n++] = f;
  return n;
}

int sweep_status_code(rs_status st)
{
  switch (st) {
  case RS_OK: return 0;
  case RS_ERR_INPUT: return 2;
  case RS_ERR_SOLVER: return 3;
  default: return 1;
  }
}

/* The stored roll's figures (rs_storage_summarize); the stages' time goes to wall_seconds. */
static rs_status storage_figures(const rs_problem *problem, const rs_reel_result *res,
                                 double fig[SWEEP_N_FIGURES])
{
  double t0 = rs_clock_wall();
  rs_storage_result *sr = NULL;
  rs_status st = rs_storage_run(problem, res, &sr);
  fig[SWEEP_FIG_WALL_SECONDS] += rs_clock_wall() - t0;
  if (st != RS_OK) {
    fig[SWEEP_FIG_STATUS] = sweep_status_code(st);
    rs_storage_result_destroy(&sr);
    return RS_OK; /* a failed run, not a failed sweep */
  }
  rs_storage_summary sum;
  rs_storage_summarize(sr, &sum);
  rs_storage_result_destroy(&sr);
  double v[] = {sum.core_pressure, sum.peak_pressure, sum.min_hoop, sum.max_core_pressure,
                sum.max_peak_pressure};
  int finite = 1;
  for (int k = 0; k < 5; ++k) finite = finite && isfinite(v[k]);
  if (!finite) { /* as the winding's: a figure must be a number */
    fig[SWEEP_FIG_STATUS] = sweep_status_code(RS_ERR_SOLVER);
    return RS_OK;
  }
  for (int k = 0; k < 5; ++k) fig[SWEEP_FIG_STORAGE_CORE_PRESSURE + k] = v[k];
  fig[SWEEP_FIG_STORAGE_STARRING_LAYERS] = sum.starring_layers;
  return RS_OK;
}

rs_status sweep_figures_compute(const rs_problem *problem, const rs_reel_result *res,
                                rs_status st, double wall_seconds, double fig[SWEEP_N_FIGURES])
{
  for (int i = 0; i < SWEEP_N_FIGURES; ++i) fig[i] = NAN;
  fig[SWEEP_FIG_WALL_SECONDS] = wall_seconds;
  fig[SWEEP_FIG_STATUS] = sweep_status_code(st);
  if (st != RS_OK || !res || !problem) return RS_OK;

  rs_reel_summary sum;
  const char *what = NULL;
  rs_reel_summarize(res, &sum);
  if (!rs_reel_summary_finite(&sum, &what)) { /* as compare: a figure must be a number */
    fig[SWEEP_FIG_STATUS] = sweep_status_code(RS_ERR_SOLVER);
    return RS_OK;
  }
  rs_lanes_summary lanes; /* across the width: the run summary's figures */
  int has_lanes = rs_lanes_summarize(res, problem->material.pressure_limit, &lanes);
  if (has_lanes && !(isfinite(lanes.ridge_height) && isfinite(lanes.hardest_pressure))) {
    fig[SWEEP_FIG_STATUS] = sweep_status_code(RS_ERR_SOLVER);
    return RS_OK;
  }
  fig[SWEEP_FIG_CORE_PRESSURE] = sum.core_pressure;
  fig[SWEEP_FIG_PEAK_PRESSURE] = sum.peak_pressure;
  fig[SWEEP_FIG_MIN_SIGMA_THETA] = sum.min_hoop;
  fig[SWEEP_FIG_FINAL_RADIUS] = sum.final_radius;
  fig[SWEEP_FIG_LAYERS] = sum.layers;

  rs_defect_limits lim;
  rs_defect_limits_from_problem(problem, &lim);
  rs_defect_report *rep = NULL;
  rs_status ds = rs_defects_assess(res, &lim, &rep);
  if (ds != RS_OK) return ds;
  if (rep->starring.verdict != RS_DEFECT_NOT_ASSESSED)
    fig[SWEEP_FIG_STARRING_LAYERS] = rep->starring.layers;
  if (rep->slip.verdict != RS_DEFECT_NOT_ASSESSED) fig[SWEEP_FIG_SLIP_MARGIN] = rep->slip.margin_min;
  rs_defect_report_destroy(&rep);
  if (has_lanes) {
    fig[SWEEP_FIG_RIDGE_HEIGHT] = lanes.ridge_height;
    fig[SWEEP_FIG_MAX_LANE_PRESSURE] = lanes.hardest_pressure;
    fig[SWEEP_FIG_SLACK_LANES] = lanes.slack_lanes;
  }
  if (rs_storage_requested(problem)) return storage_figures(problem, res, fig);
  return RS_OK;
}
