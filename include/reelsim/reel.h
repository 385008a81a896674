/* Winding a whole reel: the outer loop that grows the roll and asks the nip for T0. */
#ifndef REELSIM_REEL_H
#define REELSIM_REEL_H

#include "reelsim/scene.h"
#include "reelsim/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rs_reel_result {
  int n_layers;
  double *radius;            /* m, outer radius of each layer */
  double *wound_on_tension;  /* N/m, T0 */
  double *web_tension;       /* N/m, Ti from the recipe */
  double *nip_load;          /* N/m (0 without a nip) */
  double *sigma_r;           /* Pa, final radial stress per layer (compression < 0) */
  double *sigma_theta;       /* Pa, final hoop stress per layer */
  double core_pressure;      /* Pa, compression positive */
  double core_radius;        /* m */
  long increments, cvode_steps, rhs_evals;
  double wall_seconds;
  /* Stress history, when the scene's output.history_every > 0 (else n_stages = 0 and
   * the arrays are NULL). Stage s is the roll after stage_layers[s] layers: stored at
   * the first increment boundary at or after each multiple of history_every, and the
   * last stage is always the final state. The stage arrays are n_stages x n_layers,
   * row-major, NaN for the layers not yet wound at that stage. */
  int n_stages;
  int *stage_layers;         /* layers wound at each stage, increasing */
  double *stage_radius;      /* m, outer radius of the roll at each stage */
  double *stage_sigma_r;     /* Pa, compression negative */
  double *stage_sigma_theta; /* Pa, compression negative */
} rs_reel_result;

/* Optional observer: called after each increment with the layers wound so far.
 * Return nonzero to stop the run (the result then holds what was finished and the
 * status is RS_ERR_INTERRUPTED). */
typedef int (*rs_reel_progress_fn)(void *user, int layers_done, int layers_total);

typedef struct rs_reel_options {
  rs_reel_progress_fn progress;
  void *user;
} rs_reel_options;

/* Winds the scene's reel. On a solver failure *out still holds the layers finished
 * (n_layers counts them) and the error record says where it stopped. Caller owns *out. */
rs_status rs_reel_wind(const rs_scene *scene, const rs_reel_options *opts, rs_reel_result **out);
void rs_reel_result_destroy(rs_reel_result **res);

/* Summary figures a user reads first. */
typedef struct rs_reel_summary {
  double final_radius;       /* m */
  int layers;
  double core_pressure;      /* Pa */
  double peak_pressure;      /* Pa, max of -sigma_r */
  double peak_pressure_radius;
  double min_hoop;           /* Pa, min sigma_theta */
  double min_hoop_radius;
  double wot_min, wot_max;   /* N/m */
} rs_reel_summary;

void rs_reel_summarize(const rs_reel_result *res, rs_reel_summary *sum);

#ifdef __cplusplus
}
#endif
#endif
