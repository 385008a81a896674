/* Winding a whole reel: the outer loop that grows the roll and asks the nip for T0. */
#ifndef REELSIM_REEL_H
#define REELSIM_REEL_H

#include "reelsim/nip.h"
#include "reelsim/problem.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

/* The result of a wind, opaque: read it through the accessors below (the struct's layout
 * may change between versions without breaking a program). */
typedef struct rs_reel_result rs_reel_result;

/* The lanes' record of a result wound with lanes (docs/lanes.md), opaque: read it with
 * the rs_lanes_result_<field> accessors and rs_lanes_summarize below. */
typedef struct rs_lanes_result rs_lanes_result;

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
/* The lanes' record, one accessor per array, named after it (src/reel/lanes_access.c; the
 * run file's /lanes/<name>, final_* its /lanes/final/<name>), the one way to read it from C
 * and from a foreign-function interface alike:
 *   const T *rs_lanes_result_<field>(const rs_reel_result *res, int *rows, int *cols)
 * the array (owned by the result, valid until it is destroyed) with *rows x *cols values,
 * row-major: per lane, *rows = lanes and *cols = 0; per layer, *rows = layers and *cols =
 * 0; layers x lanes, *rows = layers and *cols = lanes (row k = layer k). rows and cols may
 * be NULL. NULL and 0, 0 for NULL, a result without lanes, or nip_load without a nip. */
int rs_lanes_result_count(const rs_reel_result *res); /* lanes; 0 without */
const double *rs_lanes_result_x(const rs_reel_result *res, int *rows, int *cols);       /* m, centres */
const double *rs_lanes_result_width(const rs_reel_result *res, int *rows, int *cols);   /* m */
const double *rs_lanes_result_caliper(const rs_reel_result *res, int *rows, int *cols); /* m */
const double *rs_lanes_result_core_pressure(const rs_reel_result *res, int *rows, int *cols); /* Pa */
/* m, each lane's deformed outer radius at the end (the diameter profile a gauge reads) */
const double *rs_lanes_result_outer_radius(const rs_reel_result *res, int *rows, int *cols);
/* per layer: the web's mean machine-direction strain e */
const double *rs_lanes_result_strain(const rs_reel_result *res, int *rows, int *cols);
/* layers x lanes: N/m, T_i plus the lane's nip-induced part; T_i, the web's share (0:
 * slack); 1 where the lane went on slack; N/m, the lane's nip load */
const double *rs_lanes_result_wound_on_tension(const rs_reel_result *res, int *rows, int *cols);
const double *rs_lanes_result_web_tension(const rs_reel_result *res, int *rows, int *cols);
const unsigned char *rs_lanes_result_slack(const rs_reel_result *res, int *rows, int *cols);
const double *rs_lanes_result_nip_load(const rs_reel_result *res, int *rows, int *cols);
/* layers x lanes, the final state: Pa (compression negative); m, each layer's deformed
 * outer radius */
const double *rs_lanes_result_final_sigma_r(const rs_reel_result *res, int *rows, int *cols);
const double *rs_lanes_result_final_sigma_theta(const rs_reel_result *res, int *rows, int *cols);
const double *rs_lanes_result_final_radius(const rs_reel_result *res, int *rows, int *cols);

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

/* ---- reading a result ------------------------------------------------------------------
 * One accessor per field, named after it (src/reel/result_access.c); the one way to read a
 * result, from C and from a foreign-function interface alike (Python's ctypes calls them
 * by name). Each accepts NULL (0, NaN or NULL back).
 *   counts and scalars:  T rs_reel_result_<field>(const rs_reel_result *res)
 *   arrays:              const T *rs_reel_result_<field>(const rs_reel_result *res, int *n)
 *     the array (owned by the result, valid until it is destroyed) and its length in *n
 *     (n may be NULL); NULL and *n = 0 when the result has no such array (an effect the
 *     problem did not have, no history, no nip). */

/* Per layer j = 0..n_layers-1 (the layers wound; on a failed wind, those finished). */
int rs_reel_result_n_layers(const rs_reel_result *res);
const double *rs_reel_result_radius(const rs_reel_result *res, int *n);           /* m, outer radius of each layer */
const double *rs_reel_result_wound_on_tension(const rs_reel_result *res, int *n); /* N/m, T0 */
const double *rs_reel_result_web_tension(const rs_reel_result *res, int *n);      /* N/m, Ti from the recipe */
const double *rs_reel_result_nip_load(const rs_reel_result *res, int *n);         /* N/m (0 without a nip) */
const double *rs_reel_result_sigma_r(const rs_reel_result *res, int *n);     /* Pa, final radial stress (compression < 0) */
const double *rs_reel_result_sigma_theta(const rs_reel_result *res, int *n); /* Pa, final hoop stress */
double rs_reel_result_core_pressure(const rs_reel_result *res); /* Pa, compression positive */
double rs_reel_result_core_radius(const rs_reel_result *res);   /* m */
/* What gauges read (docs/output.md): the roll's outer radius with the stack compressed
 * (rs_reel_deformed_radius) in the finished roll and as the layer went on (m), and the
 * wound-in tension sigma_theta t of the finished roll (N/m). */
const double *rs_reel_result_deformed_radius(const rs_reel_result *res, int *n);
const double *rs_reel_result_wound_radius(const rs_reel_result *res, int *n);
const double *rs_reel_result_wound_in_tension(const rs_reel_result *res, int *n);

/* Centrifugal load (problem.centrifugal; else NULL, NaN): the roll spinning at the last
 * layer's speed, the rest state plus the spin field. Pa. */
const double *rs_reel_result_at_speed_sigma_r(const rs_reel_result *res, int *n);
const double *rs_reel_result_at_speed_sigma_theta(const rs_reel_result *res, int *n);
double rs_reel_result_at_speed_core_pressure(const rs_reel_result *res);

/* Entrained air (problem.air.on; else NULL, NaN): the film under each layer as it survived
 * into the roll at the ambient pressure, and as the final pressure compresses it (m; the
 * radius then includes the compressed films); the web wound, at the radii it went on (m). */
const double *rs_reel_result_air_film_entrained(const rs_reel_result *res, int *n);
const double *rs_reel_result_air_film(const rs_reel_result *res, int *n);
double rs_reel_result_air_wound_length(const rs_reel_result *res);

/* The work done: increments, CVODE steps and right-hand sides, increments integrated from
 * the core (numerics.reuse), the solver's wall-clock time (s). */
long rs_reel_result_increments(const rs_reel_result *res);
long rs_reel_result_cvode_steps(const rs_reel_result *res);
long rs_reel_result_rhs_evals(const rs_reel_result *res);
long rs_reel_result_full_integrations(const rs_reel_result *res);
double rs_reel_result_wall_seconds(const rs_reel_result *res);

/* Stress history (record.history_every > 0; else n_stages = 0). Stage s is the roll after
 * stage_layers[s] layers: at the first increment boundary at or after each multiple of
 * history_every, the last stage the final state. stage_radius: n_stages values (m, the
 * roll's outer radius); stage_sigma_r, stage_sigma_theta: n_stages x n_layers, row-major
 * (Pa, compression negative; NaN for the layers not yet wound at that stage). */
int rs_reel_result_n_stages(const rs_reel_result *res);
const int *rs_reel_result_stage_layers(const rs_reel_result *res, int *n);
const double *rs_reel_result_stage_radius(const rs_reel_result *res, int *n);
const double *rs_reel_result_stage_sigma_r(const rs_reel_result *res, int *n);
const double *rs_reel_result_stage_sigma_theta(const rs_reel_result *res, int *n);

/* The nip record (a problem with a nip): one entry per nip solve the reel kept, in the
 * order of winding (n_nip of each); solves whose prediction was rejected (adaptive) are
 * counted in nip_solves and nip_rejected, not kept. */
int rs_reel_result_n_nip(const rs_reel_result *res);
const double *rs_reel_result_nip_radius(const rs_reel_result *res, int *n);     /* m, roll radius */
const double *rs_reel_result_nip_T0(const rs_reel_result *res, int *n);         /* N/m, T0 found */
const double *rs_reel_result_nip_Ti(const rs_reel_result *res, int *n);         /* N/m, web tension */
const double *rs_reel_result_nip_a(const rs_reel_result *res, int *n);          /* m, half-width */
const double *rs_reel_result_nip_solve_load(const rs_reel_result *res, int *n); /* N/m */
const int *rs_reel_result_nip_iterations(const rs_reel_result *res, int *n);    /* stick/slip */
long rs_reel_result_nip_solves(const rs_reel_result *res);
long rs_reel_result_nip_rejected(const rs_reel_result *res);
/* Full contact distributions at record.nip_profiles_at (contact model only): n_profiles
 * of them, at the roll radii profile_radius (m). */
int rs_reel_result_n_profiles(const rs_reel_result *res);
const double *rs_reel_result_profile_radius(const rs_reel_result *res, int *n);
const rs_nip_solution *rs_reel_result_profiles(const rs_reel_result *res, int *n);

/* Forgets the stress history (n_stages becomes 0, its memory freed): a program that keeps
 * many results (the accuracy study) keeps only what it reads. Accepts NULL. */
void rs_reel_result_drop_history(rs_reel_result *res);

/* rs_reel_summary_finite of the result's summary: 1 when every figure a user reads is a
 * number; else 0, *what naming the first that is not ("result" for NULL). */
int rs_reel_result_finite(const rs_reel_result *res, const char **what);

RS_END_DECLS
#endif
