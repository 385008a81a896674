/* The accuracy study (reelsim study, docs/accuracy.md): what accuracy costs in time.
 *
 * A study winds one scene many times: a reference with every numerical knob at its
 * tightest, a second, tighter reference that shows how far the first has converged, the
 * shipped defaults, each knob alone at coarser (and finer) settings than the default, and
 * a small grid of combinations. Each run is the scene with "key=value" overrides, so each
 * is a normal scene. This module plans the runs, measures their errors against the
 * reference and finds the Pareto front of (time, error), and writes the study's files and
 * picture (rs_study_write, rs_study_write_csv, rs_study_plot); it does no winding. */
#ifndef REELSIM_STUDY_H
#define REELSIM_STUDY_H

#include "reelsim/plot.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

/* ---- the Pareto front ----------------------------------------------------------------- */

/* Marks in on_front[i] (1 or 0) the points (time[i], error[i]) that no other point
 * dominates, and returns how many there are. j dominates i when time[j] <= time[i] and
 * error[j] <= error[i], one of them strictly. So of two points with equal time only the
 * smaller error is on the front, while equal points (duplicates) are all on it, dominating
 * neither each other. A point with a NaN or infinite coordinate is never on the front and
 * dominates nothing. n >= 0; O(n^2). */
int rs_pareto_front(int n, const double *time, const double *error, int *on_front);

/* 1 when point i is on the front or within the noise of it: no point of the front
 * dominates (time[i] (1 - time_rtol), error[i] (1 - error_rtol)), i.e. i would be on the
 * front were it that much faster and that much more accurate. */
int rs_pareto_within(int n, const double *time, const double *error, const int *on_front,
                     int i, double time_rtol, double error_rtol);

/* ---- errors against the reference --------------------------------------------------- */

/* The errors of a run in what users read, each relative:
 *   core_pressure, peak_pressure  |x - x_ref| / |x_ref|
 *   sigma_r      max over layers of |sigma_r - sigma_r,ref| / |sigma_r,ref|
 *   sigma_theta  max over layers of |sigma_theta - sigma_theta,ref| / (T0_ref / t): the
 *                hoop stress crosses zero, so it is measured against the hoop stress the
 *                layer was wound with (its wound-on tension over the caliper)
 *   T0_final     |T0 - T0_ref| / T0_ref of the last layer wound
 * and max, the largest of the five. */
typedef enum rs_study_figure {
  RS_FIG_CORE, RS_FIG_PEAK, RS_FIG_SIGMA_R, RS_FIG_SIGMA_THETA, RS_FIG_T0, RS_FIG_MAX,
  RS_N_FIGURES
} rs_study_figure;

/* "core_pressure", "peak_pressure", "sigma_r", "sigma_theta", "T0_final", "max" */
const char *rs_study_figure_name(rs_study_figure f);

/* err[RS_N_FIGURES]. RS_ERR_INPUT when the two results do not have the same layers (the
 * same scene, wound to the end). */
rs_status rs_study_errors(const rs_reel_result *run, const rs_reel_result *ref, double caliper,
                          double *err);

/* 1 when the two results are the same numbers, bit for bit (layers, T0, stresses, core). */
int rs_study_identical(const rs_reel_result *a, const rs_reel_result *b);

/* ---- the runs ----------------------------------------------------------------------- */

typedef enum rs_study_knob {
  RS_KNOB_REFERENCE,   /* every knob at its tightest */
  RS_KNOB_REFERENCE2,  /* tighter still where a knob can be: the reference's uncertainty */
  RS_KNOB_DEFAULT,     /* the shipped defaults */
  RS_KNOB_RTOL,        /* numerics.rtol */
  RS_KNOB_LAYERS,      /* numerics.layers_per_step */
  RS_KNOB_NODES,       /* nip.nodes (contact nip) */
  RS_KNOB_TERMS,       /* nip.terms (contact nip) */
  RS_KNOB_T0_RTOL,     /* nip.update: adaptive, nip.T0_rtol (any nip) */
  RS_KNOB_EVERY,       /* nip.update: every, nip.update_every (any nip) */
  RS_KNOB_HISTORY,     /* output.history_every: time only */
  RS_KNOB_GRID,        /* several knobs at once */
  RS_N_KNOBS
} rs_study_knob;

/* "reference", "reference2", "default", "rtol", "layers_per_step", "nodes", "terms",
 * "T0_rtol", "update_every", "history_every", "grid" */
const char *rs_study_knob_name(rs_study_knob k);

/* One setting of every knob. A knob the scene does not use holds 0. */
typedef struct rs_study_setting {
  double rtol;          /* numerics.rtol (numerics.atol stays 0: = rtol) */
  int layers_per_step;  /* numerics.layers_per_step */
  int nodes;            /* nip.nodes (contact nip) */
  int terms;            /* nip.terms (contact nip; the default 0 means 256) */
  int update_every;     /* nip: > 0 update: every k layers, 0 update: adaptive */
  double T0_rtol;       /* nip, adaptive */
  int history_every;    /* output.history_every */
} rs_study_setting;

/* The shipped defaults (src/scene/defaults.c) for a scene with (has_nip) and with a
 * contact nip (contact). */
void rs_study_defaults(int has_nip, int contact, rs_study_setting *s);

/* 1 when a is coarser than or equal to b in every knob: rtol, layers per step, update
 * interval and history interval no smaller, nodes and terms no larger; an adaptive nip
 * policy is coarser than solving every layer (every 1) and not comparable with every
 * k > 1 or with another adaptive tolerance unless its T0_rtol is no smaller. */
int rs_study_coarser_or_equal(const rs_study_setting *a, const rs_study_setting *b);

enum { RS_STUDY_MAX_SETS = 8, RS_STUDY_SET_LEN = 64 };

typedef struct rs_study_run {
  char label[64];          /* "reference", "rtol=1e-05", "grid rtol=1e-05 m=5", ... */
  rs_study_knob knob;      /* what this run varies */
  double level;            /* the varied knob's value (rtol, m, M, terms, T0_rtol, k) */
  rs_study_setting set;
  int n_sets;              /* the overrides that make this run's scene */
  char sets[RS_STUDY_MAX_SETS][RS_STUDY_SET_LEN];
} rs_study_run;

typedef struct rs_study_plan {
  int has_nip, contact;    /* what the scene uses: knobs it does not use are skipped */
  int quick;
  int n_runs;
  rs_study_run *runs;      /* [0] the reference, [1] the second reference, [2] the defaults */
} rs_study_plan;

/* Plans the runs for `scene` (full, or quick: fewer levels and a smaller grid; the same
 * reference). Levels that the scene cannot take are left out (layers per step or update
 * intervals beyond its layers). Caller owns *out (rs_study_plan_destroy). */
rs_status rs_study_plan_create(const rs_scene *scene, int quick, rs_study_plan **out);
void rs_study_plan_destroy(rs_study_plan **plan); /* accepts NULL and *plan == NULL */

/* The overrides of a setting ("numerics.rtol=1e-06", ...): every knob the scene uses is
 * written, so each run's resolved scene states all of them. Returns the count. */
int rs_study_setting_sets(const rs_study_setting *s, int has_nip, int contact,
                          char sets[RS_STUDY_MAX_SETS][RS_STUDY_SET_LEN]);

/* ---- a finished study ------------------------------------------------------------------ */

typedef struct rs_study_row {
  double wall_seconds, cpu_seconds;   /* of the winding */
  long cvode_steps, nip_solves;
  double core_pressure, peak_pressure; /* Pa */
  double T0_final;                    /* N/m, wound-on tension of the last layer */
  double err[RS_N_FIGURES];           /* against the reference (0 for the reference) */
  double err_front;     /* err[MAX] raised to the reference's uncertainty and rounded to three
                           significant digits: what the front uses (errors below the
                           uncertainty, or equal to three digits, cannot be told apart) */
  int on_front;         /* on the Pareto front of (CPU time, err_front); references excluded.
                           CPU time of the run's thread, not wall time: on a shared machine
                           the wall time of a run includes other programs' turns on the core */
  int identical_to_default; /* the same numbers as the default run, bit for bit */
} rs_study_row;

typedef struct rs_study_knob_order {
  double order;         /* observed order p in error ~ x^p (x: rtol, m - 1, 1/nodes,
                           1/terms, T0_rtol, update_every), NAN when not measurable */
  int points;           /* sweep points the fit used */
  double floor;         /* errors at or below this were left out (3 x the sweep's least
                           error or the reference's uncertainty, whichever is larger) */
} rs_study_knob_order;

typedef struct rs_study_report {
  const rs_study_plan *plan;
  int n_layers;
  rs_study_row *rows;                      /* [plan->n_runs], in plan order */
  double uncertainty[RS_N_FIGURES];        /* reference2 against the reference */
  double smallest_error;                   /* least err[MAX] > 0 of the other runs */
  int smallest_run;                        /* its index, -1 if none */
  rs_study_knob_order order[RS_N_KNOBS][2]; /* per knob: [0] core pressure, [1] max error */
  int n_front;
  int default_on_front;                    /* rs_pareto_within at time_noise, 0 error noise */
  double time_noise;                       /* relative timing noise allowed (0.1) */
  /* The defaults' work is timed more than once (runs whose answer is the default's, bit for
   * bit: history_every, and the nip knobs when T0 never changes). Timing noise only adds
   * time, so the least of those CPU times is the defaults' time on the front. */
  double default_cpu;                      /* s: that least time */
  int default_timings;                     /* how many runs it is the least of (>= 1) */
  double default_spread;                   /* (most - least) / least of those times */
} rs_study_report;

/* Measures every run against the reference (run 0) and the reference against the second
 * (run 1); finds the front and the orders. results[i], wall[i], cpu[i] belong to
 * plan->runs[i]; all must have wound the same reel. results[i] may be NULL for a run that
 * failed (not the references nor the defaults): its errors are NaN, it is not on the front. rep->rows is allocated (free with
 * rs_study_report_free). */
rs_status rs_study_analyze(const rs_study_plan *plan, const rs_reel_result *const *results,
                           const double *wall, const double *cpu, double caliper,
                           rs_study_report *rep);
void rs_study_report_free(rs_study_report *rep);

/* ---- the study's files and picture ------------------------------------------------------ */

/* Every run's settings, time, key figures and errors against the reference, as
 * /study/runs/<column> datasets with the reference's uncertainty, the observed orders per
 * knob (/study/orders) and the base scene (docs/output.md, "Study files"); and the same
 * columns as CSV, one row per run. Both staged (temporary + rename) like rs_output_write. */
rs_status rs_study_write(const char *path, const rs_scene *scene, const rs_study_report *rep);
rs_status rs_study_write_csv(const char *path, const rs_study_report *rep);

/* The study's picture: the largest relative error of each run against its time (CPU time
 * of its thread), log-log, one colour per knob, the Pareto front as a staircase with its
 * runs named, the shipped defaults and the reference marked, the reference's uncertainty
 * and 0.1 % as dashed lines. Written to `png`, staged. Errors as rs_plot_file. */
rs_status rs_study_plot(const rs_study_report *rep, const char *title, const char *png,
                        const rs_plot_options *opts);

/* ---- convergence order ------------------------------------------------------------------ */

/* Least-squares slope of log(error) against log(x) over the points with error > floor
 * (and finite, positive x and error). Returns NAN with fewer than two such points. */
double rs_study_order(int n, const double *x, const double *error, double floor);

RS_END_DECLS
#endif
