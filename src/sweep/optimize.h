/* reelsim optimize (docs/optimize.md): a constrained, derivative-free search over scene
 * values with NLopt's COBYLA from the best point of a small Latin hypercube. Application
 * layer: it winds reels through the public API only, and it alone links NLopt. */
#ifndef RS_SWEEP_OPTIMIZE_H
#define RS_SWEEP_OPTIMIZE_H

#include <stddef.h>
#include <stdio.h>

#include "reelsim/reel.h"
#include "sweep/figures.h"
#include "sweep/vary.h"

/* The figures of one evaluation: sweep's (sweep/figures.h, in its order) and then the
 * misfit to a target profile; the objective and the constraints may name any of them, or
 * a varied key (its value). */
enum {
  OPT_MISFIT = SWEEP_N_FIGURES, /* Pa, RMS misfit to --target-profile (NaN without one) */
  OPT_N_FIGURES
};
enum { OPT_STATUS = SWEEP_FIG_STATUS };

/* The name of figure f (0 <= f < OPT_N_FIGURES). */
const char *opt_figure_name(int f);
/* The index of figure `name`, or -1. */
int opt_figure_index(const char *name);
/* "core_pressure, ..., misfit" into buf (for messages). */
void opt_figure_list(char *buf, size_t size);

/* A desired pressure profile: n (radius m, pressure Pa) pairs. */
typedef struct opt_target {
  int n;
  double *radius, *pressure;
} opt_target;

/* Reads FILE.csv: one "radius,pressure" pair a line (m, Pa), an optional header line
 * (first line not two numbers), blank lines and '#' comments skipped. Returns 0, or -1
 * with "FILE:LINE: why" in err[size]. */
int opt_target_read(const char *path, opt_target *t, char *err, size_t size);
void opt_target_free(opt_target *t);

/* RMS (Pa) over the target's radii of (p(r_i) - P_i), p the roll's final interlayer
 * pressure (-sigma_r, compression positive) interpolated linearly in radius between the
 * core (core pressure at the core radius) and the layers' outer radii, held at the end
 * values outside that range. NaN when the result has no layers. */
double opt_target_misfit(const opt_target *t, const rs_reel_result *res);

/* What is optimised or constrained: a figure (0..OPT_N_FIGURES-1) or a varied key's value
 * (OPT_N_FIGURES + k). */
typedef struct opt_constraint {
  int quantity;
  int ge;       /* 1: quantity >= bound, 0: quantity <= bound */
  double bound;
  char text[160]; /* as given, for messages and the history file */
} opt_constraint;

/* The varied keys: --vary KEY=LO:HI (sweep/vary.h, kind SWEEP_RANGE). */
typedef sweep_vary opt_var;

/* The resolution a varied value is rounded to before it is wound: the power of ten a
 * thousandth to a ten-thousandth of HI - LO (100:600 N/m: 0.1 N/m; 0.5:2: 0.001), so
 * that no run is spent on decimals no controller holds; 0 for an empty range. Rounded
 * values are kept within [LO, HI], and a recipe met again is not wound again. */
double opt_resolution(const opt_var *v);

/* The quantity NAME names: a figure or one of the n varied keys; -1 if none. */
int opt_quantity_index(const char *name, int n_vars, const opt_var *vars);

/* Parses "FIGURE<=X" or "FIGURE>=X" (spaces allowed around each part). Returns 0, or -1
 * with the reason in why[size]. */
int opt_constraint_parse(const char *text, int n_vars, const opt_var *vars, opt_constraint *c,
                         char *why, size_t size);

/* The search's settings (defaults: opt_settings_default). */
typedef struct opt_settings {
  int n_start;     /* Latin-hypercube points before COBYLA (0: 4 K + 4) */
  int maxeval;     /* COBYLA's evaluations after the start (0: 30 K + 30) */
  double xtol_rel; /* COBYLA's relative step tolerance on the scaled variables */
  double xtol_abs; /* and its absolute one (the scaled variables live in [0, 1]) */
  double ftol_rel; /* relative tolerance on the objective */
  unsigned seed;   /* the hypercube's */
} opt_settings;
void opt_settings_default(opt_settings *s);

struct opt_history;

typedef struct opt_problem {
  const char *scene;        /* the scene file */
  int n_sets;               /* --set overrides applied before the varied values */
  const char *const *sets;
  int n_vars;
  const opt_var *vars;
  int objective;            /* a quantity index */
  int maximize;
  int n_cons;
  const opt_constraint *cons;
  const opt_target *target; /* NULL: no misfit */
  opt_settings settings;
  /* Optional: passed to every rs_scene_wind (a progress callback that stops a run on a
   * signal); a run it stops stops the search. */
  const rs_reel_options *wind;
  /* Optional: called after each evaluation (the last row of h); nonzero stops the search. */
  int (*after)(void *user, const struct opt_history *h);
  void *user;
} opt_problem;

/* Every evaluation, in order: E rows of K values and of the figures. */
typedef struct opt_history {
  int n, cap, n_vars;
  double *values;  /* n x n_vars */
  double *figures; /* n x OPT_N_FIGURES */
  int *phase;      /* 0: start (hypercube), 1: COBYLA */
  int best;        /* index of the best feasible evaluation, -1 if none */
  int n_start;     /* evaluations in the start phase */
  int nlopt_result;
  int stopped;     /* the stop callback asked to stop */
  unsigned char recorded[SWEEP_N_FIGURES]; /* 1: a run's scene has figure f (the storage_*
                                              figures with stages, the lanes' with lanes) */
} opt_history;
void opt_history_free(opt_history *h);

/* How COBYLA ended ("XTOL_REACHED", "MAXEVAL_REACHED", ...; "not run"). */
const char *opt_result_text(const opt_history *h);

/* 1 when figure f (0 <= f < OPT_N_FIGURES) is in the history's file and the best run's
 * figures: the winding's always, another that some run's scene has (h->recorded), misfit
 * with a target profile. */
int opt_figure_recorded(const opt_problem *p, const opt_history *h, int f);

/* 1 when evaluation i ran (status 0) and meets every constraint. */
int opt_feasible(const opt_problem *p, const opt_history *h, int i);
/* The value of quantity q at evaluation i. */
double opt_quantity(const opt_problem *p, const opt_history *h, int i, int q);

/* Runs the search. Returns 0 (h filled; h->best may be -1: nothing feasible found) or -1
 * (out of memory, or NLopt refused its settings: the reason in why). */
int opt_run(const opt_problem *p, opt_history *h, char *why, size_t size);

/* The --set overrides of evaluation i (the problem's sets, then "KEY=VALUE" per varied
 * key, VALUE in the fewest digits that read back as the value), in a malloc'd array whose strings live in the same block. */
char **opt_sets_of(const opt_problem *p, const opt_history *h, int i, int *n);

/* Writes the history (docs/output.md, /optimize) to an HDF5 file, whole or not at all.
 * Returns 0, or -1 with the reason in why. */
int opt_history_write(const char *path, const opt_problem *p, const opt_history *h, char *why,
                      size_t size);

#endif
