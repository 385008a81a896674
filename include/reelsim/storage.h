/* After the winder: a wound roll stored through stages of temperature, humidity and time
 * (docs/storage.md). Each stage first brings the whole roll to its temperature and humidity
 * (the elastic response to the free thermal and hygroscopic strains of web and core, with
 * the stack's current tangent modulus) and then holds it there for the stage's hours
 * (viscoelastic creep, when the material has a Prony series). The defect rules run after
 * every stage. Physics on a result: no I/O. */
#ifndef REELSIM_STORAGE_H
#define REELSIM_STORAGE_H

#include "reelsim/defects.h"
#include "reelsim/problem.h"
#include "reelsim/reel.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

/* The stages a stored roll went through: an opaque handle, read through the typed
 * accessors below (rs_storage_result_<field>); created by rs_storage_run. */
typedef struct rs_storage_result rs_storage_result;

/* 1 when the problem has storage stages (problem->storage.n_stages > 0). */
int rs_storage_requested(const rs_problem *problem);

/* Stores the wound roll `wound` (the result of winding `problem`) through the problem's
 * stages. Stage 0 of the result is `wound` itself. Caller owns *out
 * (rs_storage_result_destroy). On a failure *out holds the stages finished (n_stages
 * counts them) and the error record says why. */
rs_status rs_storage_run(const rs_problem *problem, const rs_reel_result *wound,
                         rs_storage_result **out);
void rs_storage_result_destroy(rs_storage_result **res);


/* The stage (0 .. S-1) where each defect rule reads worst, -1 when it was assessed at no
 * stage: hoop compression and starring by the least hoop stress / margin, pressure by the
 * greatest ratio to its limit (or pressure), slip by the least margin, the core by the
 * core pressure. */
typedef struct rs_storage_worst {
  int hoop, starring, pressure, slip, core;
} rs_storage_worst;
void rs_storage_worst_stages(const rs_storage_result *res, rs_storage_worst *worst);

/* The figures of a stored roll (compare's table, sweep's and optimize's storage_*
 * figures): at the end of the last stage, and the greatest over the stages (stage 0, the
 * wound roll, included). Pa; peak_pressure is the greatest interlayer pressure or the
 * core pressure if larger (as rs_reel_summary's). starring_layers: the most layers at
 * starring risk after any stage, NaN when the rule was assessed at no stage. All NaN
 * for NULL or an empty result. */
typedef struct rs_storage_summary {
  double core_pressure, peak_pressure, min_hoop;
  double max_core_pressure, max_peak_pressure;
  double starring_layers;
  double hours; /* h of storage in all */
} rs_storage_summary;
void rs_storage_summarize(const rs_storage_result *res, rs_storage_summary *sum);

/* One accessor per field, named after it (storage/access.c), as the reel result's: what a
 * foreign-function interface (Python's ctypes) calls instead of mirroring the struct. Each
 * accepts NULL (0, or NULL and *n = 0). An array is owned by the result; its length goes to
 * *n (n may be NULL): S values, or S x N row-major (row s = stage s) for the stresses.
 * rs_storage_result_defects: stage s's defect report (NULL outside 0 .. S-1). */
int rs_storage_result_stages(const rs_storage_result *res);   /* S */
int rs_storage_result_n_layers(const rs_storage_result *res); /* N */
const double *rs_storage_result_hours(const rs_storage_result *res, int *n);         /* h, cumulative */
const double *rs_storage_result_temperature(const rs_storage_result *res, int *n);   /* C */
const double *rs_storage_result_humidity(const rs_storage_result *res, int *n);      /* % RH */
const double *rs_storage_result_core_pressure(const rs_storage_result *res, int *n); /* Pa */
const double *rs_storage_result_sigma_r(const rs_storage_result *res, int *n);     /* Pa, S x N */
const double *rs_storage_result_sigma_theta(const rs_storage_result *res, int *n); /* Pa, S x N */
long rs_storage_result_elastic_solves(const rs_storage_result *res); /* tridiagonal solves of the changes */
int rs_storage_result_max_substeps(const rs_storage_result *res);    /* the most sub-steps one change took */
double rs_storage_result_wall_seconds(const rs_storage_result *res); /* s, the stages' wall time */
const rs_defect_report *rs_storage_result_defects(const rs_storage_result *res, int s);
/* rs_defects_assess with the problem's limits (rs_defect_limits_from_problem). */
rs_status rs_defects_of_problem(const rs_problem *problem, const rs_reel_result *res,
                                rs_defect_report **out);

RS_END_DECLS
#endif
