/* Calibration (docs/calibrate.md): the radial stack law fitted to a stack test.
 * Least squares on the strain at the measured pressure, bounded so that the modulus stays
 * positive (NLopt BOBYQA), 95 % confidence intervals from the Jacobian at the optimum
 * (LAPACK), the RMS residual and the worst point. The model strain is rs_radial_strain of
 * the law the solver uses (material.h). */
#ifndef REELSIM_FIT_H
#define REELSIM_FIT_H

#include "reelsim/material.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

enum { RS_FIT_MAX_PARAMS = 16 };

typedef struct rs_fit_stack_result {
  rs_radial_law radial;             /* the fitted law, prepared */
  int n_params;
  char name[RS_FIT_MAX_PARAMS][16]; /* "K1", "K2", "E_r", "C0".., "E(1e+05)".. */
  double value[RS_FIT_MAX_PARAMS];  /* Pa, or 1, 1/Pa.. (the law's units) */
  double half_width[RS_FIT_MAX_PARAMS]; /* the 95 % confidence interval: value +- this */
  int n_points;
  double rms;                       /* RMS strain residual */
  int worst;                        /* index of the worst point */
  double worst_residual;            /* model - measured strain there */
  double P_min, P_max;              /* Pa, the pressures fitted */
  int evaluations;                  /* objective evaluations */
} rs_fit_stack_result;

/* Fits `law` (RS_RADIAL_LINEAR, _PFEIFFER, _HAKIEL with `terms` coefficients (default 3),
 * _TABLE with `terms` points (default 6) spaced as P_max (i/(terms-1))^2) to n points
 * (P[i] Pa, eps[i] strain, compression positive). terms <= 0: the default.
 * RS_ERR_INPUT with the reason when the data cannot determine the law (too few points for
 * its parameters, fewer distinct pressures than parameters, no pressure range, a negative
 * pressure or strain, parameters the data leave undetermined). */
rs_status rs_fit_stack(int n, const double *P, const double *eps, rs_radial_kind law, int terms,
                       rs_fit_stack_result *out);

/* The same for a foreign-function interface (the Python package), plain arrays out:
 * law "linear", "pfeiffer", "hakiel" or "table"; value and half_width hold
 * RS_FIT_MAX_PARAMS entries, names RS_FIT_MAX_PARAMS x 16 chars; stats[4] = rms, worst
 * index, worst residual, evaluations. */
rs_status rs_fit_stack_flat(int n, const double *P, const double *eps, const char *law, int terms,
                            int *n_params, char *names, double *value, double *half_width,
                            double *stats);

/* A stack test's CSV: a header with `strain` and `pressure` (any order, other columns
 * ignored), optionally `cycle`; the loading branch of cycle `cycle` (< 0: the last), from
 * the cycle's first row to its peak pressure. *P, *eps malloc'd (the caller frees).
 * RS_ERR_INPUT naming the file and the line. */
rs_status rs_fit_stack_read(const char *path, int cycle, double **P, double **eps, int *n);

/* The material model YAML of the fit: `radial:` over the base model's other constants (base
 * NULL: `radial:` only), written atomically to path. base_text: the base model's YAML. */
rs_status rs_fit_stack_write_model(const char *path, const rs_fit_stack_result *fit,
                                   const char *source, const char *base_text);

/* A PNG of the data and the fitted law (strain against pressure, and the residuals) by
 * gnuplot. */
rs_status rs_fit_stack_plot(const char *path, int n, const double *P, const double *eps,
                            const rs_fit_stack_result *fit, const char *title);

/* 95 % confidence half widths of p parameters fitted to n > p residuals: t(0.975, n - p)
 * sqrt(diag(s^2 (J^T J)^-1)), s^2 = ssr/(n - p), J the n x p Jacobian (row-major) of the
 * residuals at the optimum; LAPACK's Cholesky on J^T J with unit-norm columns. rcond (may
 * be NULL): J^T J's reciprocal condition. RS_ERR_INPUT when J is rank-deficient. */
rs_status rs_fit_intervals(int n, int p, const double *J, double ssr, double *half_width,
                           double *rcond);

/* The law's name from a string ("pfeiffer" ..); -1 when unknown. */
int rs_fit_law_parse(const char *s);

RS_END_DECLS
#endif
