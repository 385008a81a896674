/* The reel's result as the library fills it (private: applications read it through the
 * typed accessors of reelsim/reel.h, src/reel/result_access.c). The library's own files
 * that fill or read the result (reel, storage, output, study) include this header; so may
 * the tests. A new field goes here and gets its accessor in reel.h. */
#ifndef RS_REEL_RESULT_INTERNAL_H
#define RS_REEL_RESULT_INTERNAL_H

#include "reelsim/nip.h"
#include "reelsim/reel.h"

/* Lanes across the width (problem.lanes.count > 0; docs/lanes.md): each lane's record.
 * Arrays "layers x lanes" are row-major, row k = layer k. */
struct rs_lanes_result {
  int count, n_layers;
  double *x, *width;         /* m, each lane's centre and width */
  double *caliper;           /* m, each lane's caliper */
  double *core_pressure;     /* Pa, each lane's core pressure (compression positive) */
  double *outer_radius;      /* m, each lane's deformed outer radius at the end (the diameter
                                profile a gauge reads) */
  double *wound_on_tension;  /* N/m, layers x lanes: T_i (+ the lane's nip-induced part) */
  double *web_tension;       /* N/m, layers x lanes: T_i, the web's share (0: slack) */
  unsigned char *slack;      /* layers x lanes: 1 where T_i = 0 (the lane is baggy) */
  double *strain;            /* [n_layers] the web's mean machine-direction strain e */
  double *nip_load;          /* N/m, layers x lanes (NULL without a nip) */
  double *sigma_r, *sigma_theta; /* Pa, layers x lanes, the final state */
  double *radius;            /* m, layers x lanes: each layer's deformed outer radius, final */
  double Tbar_W_misfit;      /* max over layers of |sum w_i T_i - Tbar W| / (Tbar W) */
  int threads;               /* threads the lanes were wound on */
};
void rs_lanes_result_destroy(rs_lanes_result **lr);

struct rs_reel_result {
  int n_layers;
  double *radius;            /* m, outer radius of each layer */
  double *wound_on_tension;  /* N/m, T0 */
  double *web_tension;       /* N/m, Ti from the recipe */
  double *nip_load;          /* N/m (0 without a nip) */
  double *sigma_r;           /* Pa, final radial stress per layer (compression < 0) */
  double *sigma_theta;       /* Pa, final hoop stress per layer */
  double core_pressure;      /* Pa, compression positive */
  double core_radius;        /* m */
  /* Centrifugal load on (problem.centrifugal): the roll spinning at the last layer's speed,
   * the rest state above plus the spin field (NULL otherwise). */
  double *at_speed_sigma_r;     /* Pa, per layer */
  double *at_speed_sigma_theta; /* Pa, per layer */
  double at_speed_core_pressure; /* Pa */
  /* Entrained air on (problem.air.on; NULL otherwise): the film under each layer as it
   * survived into the roll at the ambient pressure, and as the final pressure compresses
   * it (radius then includes the compressed films); the web wound, at the radii it went
   * on at (m). */
  double *air_film_entrained;   /* m, per layer */
  double *air_film;             /* m, per layer, in the roll at rest */
  double air_wound_length;      /* m */
  long increments, cvode_steps, rhs_evals;
  long full_integrations;    /* increments integrated from the core (numerics.reuse) */
  double wall_seconds;
  /* Stress history, when the problem's record.history_every > 0 (else n_stages = 0 and
   * the arrays are NULL). Stage s is the roll after stage_layers[s] layers: stored at
   * the first increment boundary at or after each multiple of history_every, and the
   * last stage is always the final state. The stage arrays are n_stages x n_layers,
   * row-major, NaN for the layers not yet wound at that stage. */
  int n_stages;
  int *stage_layers;         /* layers wound at each stage, increasing */
  double *stage_radius;      /* m, outer radius of the roll at each stage */
  double *stage_sigma_r;     /* Pa, compression negative */
  double *stage_sigma_theta; /* Pa, compression negative */
  /* The nip record (a problem with a nip): one entry per nip solve the reel kept, in the
   * order of winding. Solves whose prediction was rejected (adaptive) are counted, not kept. */
  int n_nip;
  double *nip_radius;        /* m, roll radius at the solve */
  double *nip_T0;            /* N/m, wound-on tension found */
  double *nip_Ti;            /* N/m, web tension there */
  double *nip_a;             /* m, contact half-width (0 for the friction model) */
  double *nip_solve_load;    /* N/m, load of the converged contact */
  int *nip_iterations;       /* stick/slip iterations */
  long nip_solves;           /* all nip solves, rejected ones included */
  long nip_rejected;         /* adaptive: rewinds after a failed prediction */
  /* Full contact distributions at record.nip_profiles_at (contact model only). */
  int n_profiles;
  double *profile_radius;    /* m, roll radius of each profile */
  struct rs_nip_solution *profiles;
  /* What gauges read (docs/output.md): per layer, the roll's outer radius with the stack
   * compressed (rs_reel_deformed_radius) in the finished roll and as the layer went on,
   * and the wound-in tension sigma_theta t of the finished roll. */
  double *deformed_radius;   /* m */
  double *wound_radius;      /* m */
  double *wound_in_tension;  /* N/m */
  /* Lanes across the width (problem.lanes.count > 0; NULL otherwise). The per-layer arrays
   * above are then the width-weighted means of the lanes' (the nip record, history and
   * profiles: the lane nearest the middle of the width). */
  rs_lanes_result *lanes;
};

#endif
