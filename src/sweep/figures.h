/* The figures of one wound recipe: what a sweep records per run and what optimize
 * minimises, maximises or constrains (docs/output.md, "Sweep files"; docs/cli.md).
 * Part of the recipe-search application layer (src/sweep): only public headers. */
#ifndef RS_SWEEP_FIGURES_H
#define RS_SWEEP_FIGURES_H

#include <stddef.h>

#include "reelsim/problem.h"
#include "reelsim/reel.h"
#include "reelsim/status.h"

/* In this order in the table below (and in a sweep file's CSV). */
typedef enum sweep_figure {
  SWEEP_FIG_CORE_PRESSURE,   /* Pa, compression positive */
  SWEEP_FIG_PEAK_PRESSURE,   /* Pa, greatest interlayer pressure (max of -sigma_r) */
  SWEEP_FIG_MIN_SIGMA_THETA, /* Pa, least hoop stress (negative: compression) */
  SWEEP_FIG_FINAL_RADIUS,    /* m */
  SWEEP_FIG_LAYERS,          /* layers wound */
  SWEEP_FIG_STARRING_LAYERS, /* layers at starring risk (rs_defects_assess) */
  SWEEP_FIG_SLIP_MARGIN,     /* least interlayer slip (cinching) margin */
  SWEEP_FIG_WALL_SECONDS,    /* s, wall-clock time of the run */
  SWEEP_FIG_STATUS,          /* 0 ok, 2 refused, 3 solver failed, 1 other */
  /* after the storage stages (docs/storage.md; NaN when the scene has none) */
  SWEEP_FIG_STORAGE_CORE_PRESSURE,     /* Pa, at the end of the last stage */
  SWEEP_FIG_STORAGE_PEAK_PRESSURE,     /* Pa, at the end of the last stage */
  SWEEP_FIG_STORAGE_MIN_SIGMA_THETA,   /* Pa, at the end of the last stage */
  SWEEP_FIG_STORAGE_MAX_CORE_PRESSURE, /* Pa, the greatest at the end of any stage */
  SWEEP_FIG_STORAGE_MAX_PEAK_PRESSURE, /* Pa, the greatest at the end of any stage */
  SWEEP_FIG_STORAGE_STARRING_LAYERS,   /* the most layers at starring risk after any stage */
  /* across the width (docs/lanes.md; NaN when the scene has no lanes), rs_lanes_summarize's */
  SWEEP_FIG_RIDGE_HEIGHT,      /* m, max - min of the lanes' final outer radii */
  SWEEP_FIG_MAX_LANE_PRESSURE, /* Pa, the hardest lane's peak pressure (core or -sigma_r) */
  SWEEP_FIG_SLACK_LANES,       /* lanes that went slack while winding */
  SWEEP_N_FIGURES
} sweep_figure;

/* The figures of the winding alone: those every scene has (a sweep file of a scene
 * without storage stages or lanes holds these only, as before either was wound). */
enum { SWEEP_N_WIND_FIGURES = SWEEP_FIG_STATUS + 1 };

/* NULL when a run of `problem` has figure f (the winding's always; storage_* with storage
 * stages; ridge_height, max_lane_pressure, slack_lanes with lanes), else what the scene
 * lacks: "no storage stages (docs/storage.md)", "no `lanes:` (docs/lanes.md)". */
const char *sweep_figure_lacks(const rs_problem *problem, int f);
/* The figures a run of `problem` has, in table order, into idx[SWEEP_N_FIGURES]; their
 * count. */
int sweep_figure_list(const rs_problem *problem, int idx[SWEEP_N_FIGURES]);

typedef struct sweep_figure_info {
  const char *name; /* "core_pressure": the HDF5 dataset, the CSV column, optimize's FIGURE */
  const char *unit; /* "Pa", "m", "s", "" */
  const char *help; /* one line */
} sweep_figure_info;

extern const sweep_figure_info sweep_figures[SWEEP_N_FIGURES];

/* The index of the figure called `name`, or -1. */
int sweep_figure_find(const char *name);
/* "core_pressure, peak_pressure, ..." into buf (for "unknown figure" messages). */
void sweep_figure_names(char *buf, size_t size);

/* The figures of one run into fig[SWEEP_N_FIGURES]. `st` is the run's status, `res` its
 * result (may be NULL when st != RS_OK), `problem` what was wound (for the defect rules'
 * inputs; may be NULL when st != RS_OK). A failed run (st != RS_OK, or a summary figure
 * that is not a finite number: status 3) has NaN for every figure but status and
 * wall_seconds. starring_layers is NaN when the rule cannot be assessed (no E_theta or
 * radial law), slip_margin when the slip rule cannot (no material.friction_layer; it is
 * infinite where no torque passes through the roll): docs/defects.md. Returns RS_OK, or
 * the defect assessment's failure (RS_ERR_MEMORY; the two are then NaN, the other
 * figures are filled). A problem with storage stages has them wound
 * here (rs_storage_run) into the storage_* figures, their time in wall_seconds; a storage
 * run that fails leaves the winding's figures and sets the status. A result with lanes
 * fills ridge_height, max_lane_pressure and slack_lanes (rs_lanes_summarize). */
rs_status sweep_figures_compute(const rs_problem *problem, const rs_reel_result *res,
                                rs_status st, double wall_seconds, double fig[SWEEP_N_FIGURES]);

/* The status figure of a run's rs_status: 0 ok, 2 input refused, 3 solver failed, 1 other. */
int sweep_status_code(rs_status st);

#endif
