/* reelsim fit roll (docs/calibrate.md): scene keys fitted to what the plant measured on a
 * roll (a diameter-length curve, pull-tab pressures, a wound-in-tension profile) by bounded
 * least squares (NLopt BOBYQA), the intervals from the Jacobian at the optimum
 * (rs_fit_intervals), its reels wound in parallel. Application layer (reelsim_optimize,
 * which links NLopt): public headers and sweep/ only. */
#ifndef RS_SWEEP_FITROLL_H
#define RS_SWEEP_FITROLL_H

#include <stddef.h>

#include "reelsim/fit.h"
#include "reelsim/reel.h"
#include "sweep/vary.h"

typedef enum fr_x { FR_LENGTH, FR_RADIUS } fr_x;
typedef enum fr_y { FR_DIAMETER, FR_PRESSURE, FR_WIT } fr_y;

/* The measured points: a header naming x (`length` m or `radius` m) then y (`diameter` m,
 * `pressure` Pa or `wound_in_tension` N/m). */
typedef struct fr_data {
  fr_x xkind;
  fr_y ykind;
  int n;
  double *x, *y;
} fr_data;

/* Returns 0, or -1 with "FILE:LINE: why" in err. */
int fr_data_read(const char *path, fr_data *d, char *err, size_t size);
void fr_data_free(fr_data *d);
const char *fr_x_name(fr_x x);
const char *fr_y_name(fr_y y);

/* The model's quantity at the data's x (out[n]), interpolated linearly between layers:
 * x = length: the wound length as the summary counts it (the free layers' mid-thickness
 * circumferences); x = radius: the deformed radius of the finished roll. y = diameter: twice
 * the wound radius (length) or the deformed radius; pressure: -sigma_r; wound_in_tension.
 * Returns -1 when the result has no layers. */
int fr_model(const fr_data *d, const rs_reel_result *res, double *out);

typedef struct fr_problem {
  const char *scene;
  int n_sets;
  const char *const *sets;
  int n_vars;
  const sweep_vary *vars; /* SWEEP_RANGE */
  const fr_data *data;
  const rs_reel_options *wind; /* progress (stops a run on a signal), or NULL */
  int threads;            /* for the Jacobian's reels (0: one per core) */
  void (*after)(void *user, int evaluation, const double *x, double rms); /* or NULL */
  void *user;
} fr_problem;

typedef struct fr_result {
  double x[RS_FIT_MAX_PARAMS];          /* the fitted values of the keys */
  double half_width[RS_FIT_MAX_PARAMS]; /* their 95 % intervals (NaN: not determined) */
  double rms;                           /* RMS residual, the data's unit */
  int worst;                            /* the worst point's index */
  double worst_residual;                /* model - measured there */
  int evaluations;
  int stopped;                          /* interrupted */
  int intervals_ok;                     /* 0: the Jacobian was rank-deficient */
  char nlopt[32];
} fr_result;

/* Runs the fit. RS_OK (r filled; r->stopped when a reel was interrupted), or an error: a
 * reel that fails at the start point, the optimiser refusing its settings. */
rs_status fr_run(const fr_problem *p, fr_result *r);
/* The --set list of values x (the problem's sets, then KEY=VALUE per key) in a malloc'd
 * block; NULL when out of memory. */
char **fr_sets_of(const fr_problem *p, const double *x, int *n);

#endif
