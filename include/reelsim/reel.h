/* Winding a whole reel: the outer loop that grows the roll and asks the nip for T0. */
#ifndef REELSIM_REEL_H
#define REELSIM_REEL_H

#include "reelsim/problem.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

struct rs_nip_solution;

/* Lanes across the width (problem.lanes.count > 0; docs/lanes.md): each lane's record.
 * Arrays "layers x lanes" are row-major, row k = layer k. */
typedef struct rs_lanes_result {
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
} rs_lanes_result;
void rs_lanes_result_destroy(rs_lanes_result **lr);


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
} rs_reel_result;

/* Optional observer: called after each increment with the layers wound so far.
 * Return nonzero to stop the run (the result then holds what was finished and the
 * status is RS_ERR_INTERRUPTED). */
typedef int (*rs_reel_progress_fn)(void *user, int layers_done, int layers_total);

typedef struct rs_reel_options {
  rs_reel_progress_fn progress;
  void *user;
} rs_reel_options;

/* Winds the problem's reel (a loaded scene: rs_scene_wind). On a solver failure *out still
 * holds the layers finished (n_layers counts them) and the error record says where it
 * stopped. Caller owns *out. */
rs_status rs_reel_wind(const rs_problem *problem, const rs_reel_options *opts,
                       rs_reel_result **out);
void rs_reel_result_destroy(rs_reel_result **res);

/* The deformed outer radius of each layer j = 0..n-1 of a roll (m) in the state given: the
 * core's displacement -r_c P_c/E_c, the calipers, the air films (film: as entrained, per
 * layer, compressed here by their node's pressure; NULL: none) less the stack's radial
 * compression, the trapezoid rule of t eps(P) over the nodes (eps = rs_radial_strain,
 * tabulated). core_pressure Pa (compression positive), sigma_r[j] Pa at layer j's outer
 * face (compression negative; the outer face free). src/reel/gauge.c. */
rs_status rs_reel_deformed_radius(const rs_problem *problem, double core_pressure,
                                  const double *sigma_r, const double *film, int n, double *out);
/* The wound-in tension sigma_theta t (N/m) of n layers. */
void rs_reel_wound_in_tension(const rs_problem *problem, const double *sigma_theta, int n,
                              double *out);

/* What a user reads first of the lanes (the run's summary, --json "lanes"). A lane's peak
 * pressure is the largest of its core pressure and -sigma_r; its slack radius the outer
 * radius (nominal, r_c + (k+1) t_i) of the first layer it went on slack. The defect lines:
 * hard band where a lane's peak pressure exceeds pressure_limit (> 0; 0: not assessed),
 * baggy lane where a lane went slack while winding, the ridge height. */
typedef struct rs_lanes_summary {
  int count;
  double ridge_height;        /* m, max - min of the lanes' deformed outer radii */
  double ridge_x;             /* m, the highest lane's x */
  int hardest;                /* the lane (0-based) of the largest peak pressure */
  double hardest_x, hardest_pressure; /* m, Pa */
  double tension_min, tension_max;    /* N/m, the lanes' web tension over lanes and layers */
  int slack_lanes;            /* lanes slack at some layer */
  double slack_from[RS_LANES_MAX]; /* m, where each lane first went slack (NaN: never) */
  int hard_lanes;             /* lanes over pressure_limit (0 when not assessed) */
  double pressure_limit;      /* Pa, 0: not given */
} rs_lanes_summary;
/* 0 for a result without lanes (sum->count 0), else 1. */
int rs_lanes_summarize(const rs_reel_result *res, double pressure_limit, rs_lanes_summary *sum);
/* The lanes' array `name` by name, for a foreign-function interface: per lane ("x",
 * "width", "caliper", "core_pressure", "outer_radius": *rows = lanes, *cols = 0), per layer
 * ("strain": *rows = layers, *cols = 0), layers x lanes row-major ("wound_on_tension",
 * "web_tension", "nip_load", "final/sigma_r", "final/sigma_theta", "final/radius"; *rows =
 * layers, *cols = lanes). NULL (and 0, 0) for a result without lanes, an unknown name or
 * nip_load without a nip. Owned by the result. */
const double *rs_lanes_result_array(const rs_reel_result *res, const char *name, int *rows,
                                    int *cols);

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

/* 1 when every figure of the summary is a finite number; else 0 and *what names the first
 * that is not ("peak pressure"): a figure a user reads must be a number. */
int rs_reel_summary_finite(const rs_reel_summary *sum, const char **what);

/* The roll's size as engineers quote it. The wound length is the web actually wound: the
 * sum over the layers of the circumference at each layer's mid-thickness, 2 pi (r_in +
 * r_out) / 2 (for layers one caliper thick it equals pi (r_1^2 - r_c^2) / t). The mass per
 * metre of web width is rho t L, known only when the material's density is. */
typedef struct rs_reel_sizes {
  double diameter;     /* m, twice the outer radius of the last layer */
  double deformed_diameter; /* m, twice the deformed outer radius (what a gauge reads; the
                               same as diameter when the result has no deformed radius) */
  double wound_length; /* m */
  int has_mass;        /* 1 when material.density is given */
  double mass;         /* kg per metre of width (0 when has_mass is 0) */
  /* Entrained air (problem.air.on): the wound length is then the web's as it went on. */
  int has_air;         /* 1 when the reel has entrained air (the rest 0 otherwise) */
  double air_thickness;                      /* m, the films in the reel summed */
  double air_film_min, air_film_max;         /* m, the films in the reel (compressed) */
  double air_entrained_min, air_entrained_max; /* m, the films as they went on */
} rs_reel_sizes;

void rs_reel_sizes_of(const rs_reel_result *res, const rs_problem *problem, rs_reel_sizes *out);

/* Several reels wound at once (reelsim compare). A job is one rs_reel_wind: the problem
 * and options go in; the result (the caller's, as rs_reel_wind's *out), the status and a
 * copy of the job's error record come out. */
typedef struct rs_reel_job {
  const rs_problem *problem;
  rs_reel_options opts;      /* progress is called on the job's worker thread */
  rs_reel_result *result;
  rs_status status;
  char message[2048];        /* rs_error_message() of the failed job, "" when it succeeded */
  char where[256];           /* rs_error_where() likewise */
  double wall_seconds;       /* wall-clock time of the job, s */
  double cpu_seconds;        /* CPU time of the job's thread, s (the study's measure) */
} rs_reel_job;

/* Winds jobs[0..n-1] on up to `threads` POSIX threads (<= 0: one per online processor;
 * never more than n), the calling thread being one of them. Jobs are handed out in
 * order; each runs exactly as rs_reel_wind would on its own (every rs_roll owns its CVODE
 * context and the error record is per thread), so the results do not depend on the
 * number of threads. A failed job does not stop the others. Returns RS_ERR_INTERNAL for
 * bad arguments, otherwise RS_OK: look at each job's status. Reports in *used (may be
 * NULL) how many threads ran. */
rs_status rs_reel_wind_many(int n, rs_reel_job *jobs, int threads, int *used);

/* The result read through functions instead of the struct's layout, for programs that
 * call the library through a foreign-function interface (the Python package): they stay
 * right when fields are added. rs_reel_result_layers: n_layers (0 for NULL).
 * rs_reel_result_array: the per-layer array called `name` ("radius", "wound_on_tension",
 * "web_tension", "nip_load", "sigma_r", "sigma_theta", "deformed_radius", "wound_radius",
 * "wound_in_tension"; with entrained air "air_film",
 * "air_film_entrained"; with the centrifugal load "at_speed_sigma_r",
 * "at_speed_sigma_theta"; owned by the result) with its length in *n (may be NULL); NULL
 * and *n = 0 for an unknown name, an effect the problem did not have, or a NULL result.
 * rs_reel_result_scalar: "core_pressure", "core_radius", "wall_seconds",
 * "at_speed_core_pressure", "air_wound_length"; NaN for an unknown name, an effect the
 * problem did not have, or a NULL result. rs_reel_result_finite: rs_reel_summary_finite of the
 * result's summary (1 when every figure a user reads is a number; else 0, *what naming
 * the first that is not). */
int rs_reel_result_layers(const rs_reel_result *res);
const double *rs_reel_result_array(const rs_reel_result *res, const char *name, int *n);
double rs_reel_result_scalar(const rs_reel_result *res, const char *name);
int rs_reel_result_finite(const rs_reel_result *res, const char **what);

RS_END_DECLS
#endif
