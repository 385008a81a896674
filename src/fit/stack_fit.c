/* The stack law fitted to a stack test (docs/calibrate.md).
 *
 * Residual: r_i = eps(P_i; theta) - eps_i, the law's strain at the measured pressure
 * against the measured strain (rs_radial_strain: the integral of 1/E_r the solver's own
 * law gives). In a stack test the load cell's pressure is the accurate, controlled
 * quantity and the strain (crosshead travel over the stack height, with seating and platen
 * compliance) carries the error; eps(P) is defined for every law at every P, where P(eps)
 * would need an inversion; and strain residuals weigh the soft low-pressure start and the
 * stiff top alike, where pressure residuals, spanning decades, would fit the top only.
 *
 * Parameters as the optimiser sees them (positive ones by their logarithm, so the modulus
 * stays positive; Hakiel's higher coefficients bounded below by 0, scaled by P_max^i over
 * the modulus at P_max): minimised by NLopt's BOBYQA (bounded, derivative free) from the
 * best of a scan over Pfeiffer's K1 (K2 then in closed form). The confidence intervals:
 * s^2 (J^T J)^-1 with J the residuals' Jacobian in the law's own parameters (central
 * differences), s^2 = SSR/(n - p), Student's t at n - p degrees of freedom; J^T J by
 * LAPACK's Cholesky (dpotrf, dpocon, dpotri) on columns scaled to unit norm. */
#include <float.h>
#include <lapacke.h>
#include <math.h>
#include <nlopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/fit.h"
#include "util/error.h"

typedef struct fit_ctx {
  int n, p;
  const double *P, *eps;
  rs_radial_kind kind;
  double Pmax, Escale, eps_scale;
  int evals;
} fit_ctx;

/* the law of optimiser parameters x */
static rs_status law_of(const fit_ctx *c, const double *x, rs_radial_law *L)
{
  memset(L, 0, sizeof *L);
  L->law = c->kind;
  switch (c->kind) {
  case RS_RADIAL_LINEAR: L->E_r = exp(x[0]); break;
  case RS_RADIAL_PFEIFFER: L->K1 = exp(x[0]); L->K2 = exp(x[1]); break;
  case RS_RADIAL_HAKIEL:
    L->n_coef = c->p;
    L->C[0] = exp(x[0]);
    for (int i = 1; i < c->p; ++i) L->C[i] = x[i] * c->Escale / pow(c->Pmax, i);
    break;
  case RS_RADIAL_TABLE:
    L->n_points = c->p;
    for (int k = 0; k < c->p; ++k) {
      const double s = (double)k / (c->p - 1);
      L->P[k] = c->Pmax * s * s;
      L->E[k] = exp(x[k]);
    }
    break;
  }
  return rs_radial_law_prepare(L);
}

/* the law's own parameters theta <-> x */
static void theta_of(const fit_ctx *c, const rs_radial_law *L, double *th)
{
  for (int k = 0; k < c->p; ++k)
    th[k] = c->kind == RS_RADIAL_LINEAR ? L->E_r
          : c->kind == RS_RADIAL_PFEIFFER ? (k ? L->K2 : L->K1)
          : c->kind == RS_RADIAL_HAKIEL ? L->C[k] : L->E[k];
}

static void law_of_theta(const fit_ctx *c, const rs_radial_law *base, const double *th,
                         rs_radial_law *L)
{
  *L = *base;
  for (int k = 0; k < c->p; ++k) {
    if (c->kind == RS_RADIAL_LINEAR) L->E_r = th[0];
    else if (c->kind == RS_RADIAL_PFEIFFER) *(k ? &L->K2 : &L->K1) = th[k];
    else if (c->kind == RS_RADIAL_HAKIEL) L->C[k] = th[k];
    else L->E[k] = th[k];
  }
}

static double ssr_of(const fit_ctx *c, const rs_radial_law *L, double *r)
{
  double s = 0.0;
  for (int i = 0; i < c->n; ++i) {
    const double d = rs_radial_strain(L, c->P[i]) - c->eps[i];
    if (r) r[i] = d;
    s += d * d;
  }
  return s;
}

static double objective(unsigned p, const double *x, double *grad, void *data)
{
  (void)p;
  (void)grad;
  fit_ctx *c = data;
  c->evals++;
  rs_radial_law L;
  rs_error_clear();
  if (law_of(c, x, &L) != RS_OK) {
    rs_error_clear();
    return HUGE_VAL;
  }
  const double s = ssr_of(c, &L, NULL) / (c->eps_scale * c->eps_scale);
  return isfinite(s) ? s : HUGE_VAL;
}

/* Pfeiffer's start: K1 scanned over decades, 1/K2 = sum f e / sum f^2, f = ln(1 + P/K1) */
static void pfeiffer_start(const fit_ctx *c, double *K1, double *K2)
{
  double best = HUGE_VAL, lo = c->Pmax * 1e-7;
  for (int i = 0; i <= 80; ++i) {
    const double k1 = lo * pow(10.0, i / 10.0);
    double sfe = 0.0, sff = 0.0, ssr = 0.0;
    for (int j = 0; j < c->n; ++j) {
      const double f = log1p(c->P[j] / k1);
      sfe += f * c->eps[j];
      sff += f * f;
    }
    if (!(sfe > 0.0)) continue;
    const double inv = sfe / sff;
    for (int j = 0; j < c->n; ++j) {
      const double d = inv * log1p(c->P[j] / k1) - c->eps[j];
      ssr += d * d;
    }
    if (ssr < best) {
      best = ssr;
      *K1 = k1;
      *K2 = 1.0 / inv;
    }
  }
}

/* Student's t, two-sided 95 %, at nu degrees of freedom: exact for nu <= 4, else the
 * Cornish-Fisher expansion about z = 1.959964 (Abramowitz & Stegun 26.7.5; 1e-4 at nu = 5) */
static double student_t95(int nu)
{
  static const double exact[] = {12.706204736, 4.302652730, 3.182446305, 2.776445105};
  if (nu <= 4) return exact[nu < 1 ? 0 : nu - 1];
  const double z = 1.959963984540054, v = nu, z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z,
               z9 = z7 * z * z;
  return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v) +
         (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * v * v * v) +
         (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / (92160 * v * v * v * v);
}

static rs_status check_data(int n, const double *P, const double *eps, int p, const char *law)
{
  if (n < p + 1)
    return RS_ERROR(RS_ERR_INPUT,
                    "%d points cannot determine the %s law's %d parameters with an error "
                    "estimate: at least %d are needed",
                    n, law, p, p + 1);
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < n; ++i) {
    if (!(P[i] >= 0.0) || !isfinite(P[i]) || !(eps[i] >= 0.0) || !isfinite(eps[i]))
      return RS_ERROR(RS_ERR_INPUT,
                      "point %d: pressure %g Pa and strain %g must be finite and >= 0 "
                      "(compression positive)",
                      i + 1, P[i], eps[i]);
    lo = fmin(lo, P[i]);
    hi = fmax(hi, P[i]);
  }
  if (!(hi > 0.0) || hi - lo <= 1e-6 * hi)
    return RS_ERROR(RS_ERR_INPUT,
                    "no pressure range: the points span %g .. %g Pa; a stack test must load "
                    "the stack over the pressures the law is to cover",
                    lo, hi);
  int distinct = 0;
  for (int i = 0; i < n; ++i) {
    int seen = 0;
    for (int j = 0; j < i && !seen; ++j) seen = P[j] == P[i];
    distinct += !seen && P[i] > 0.0;
  }
  if (distinct < p)
    return RS_ERROR(RS_ERR_INPUT,
                    "%d distinct positive pressures cannot determine the %s law's %d parameters",
                    distinct, law, p);
  return RS_OK;
}

rs_status rs_fit_intervals(int n, int p, const double *J, double ssr, double *half_width,
                           double *rcond_out)
{
  double A[RS_FIT_MAX_PARAMS * RS_FIT_MAX_PARAMS] = {0}, sc[RS_FIT_MAX_PARAMS];
  if (p < 1 || p > RS_FIT_MAX_PARAMS || n <= p)
    return RS_ERROR(RS_ERR_INPUT, "%d points cannot give intervals for %d parameters", n, p);
  for (int k = 0; k < p; ++k) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += J[(size_t)i * p + k] * J[(size_t)i * p + k];
    sc[k] = s > 0.0 ? 1.0 / sqrt(s) : 0.0;
  }
  for (int a = 0; a < p; ++a)
    for (int b = 0; b < p; ++b) {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += J[(size_t)i * p + a] * J[(size_t)i * p + b];
      A[a * p + b] = s * sc[a] * sc[b];
    }
  double anorm = 0.0;
  for (int a = 0; a < p; ++a) {
    double s = 0.0;
    for (int b = 0; b < p; ++b) s += fabs(A[a * p + b]);
    anorm = fmax(anorm, s);
  }
  lapack_int info = LAPACKE_dpotrf(LAPACK_ROW_MAJOR, 'U', p, A, p);
  double rcond = 0.0;
  if (info == 0) info = LAPACKE_dpocon(LAPACK_ROW_MAJOR, 'U', p, A, p, anorm, &rcond);
  for (int k = 0; k < p && info == 0; ++k)
    if (sc[k] == 0.0) info = 1;
  if (rcond_out) *rcond_out = rcond;
  if (info != 0 || rcond < 1e3 * DBL_EPSILON)
    return RS_ERROR(RS_ERR_INPUT,
                    "the data do not determine the parameters (the Jacobian at the fit is "
                    "rank-deficient, reciprocal condition %.3g)", rcond);
  LAPACKE_dpotri(LAPACK_ROW_MAJOR, 'U', p, A, p);
  const double s2 = ssr / (n - p), t = student_t95(n - p);
  for (int k = 0; k < p; ++k) half_width[k] = t * sqrt(s2 * A[k * p + k]) * sc[k];
  return RS_OK;
}

/* covariance of theta: s^2 (J^T J)^-1, the half widths t95 sqrt(diag) */
static rs_status intervals(fit_ctx *c, const rs_radial_law *L, double ssr, rs_fit_stack_result *out)
{
  const int n = c->n, p = c->p;
  double th[RS_FIT_MAX_PARAMS];
  double *J = calloc((size_t)n * p, sizeof *J), *rp = malloc((size_t)n * sizeof *rp),
         *rm = malloc((size_t)n * sizeof *rm);
  rs_status st = RS_OK;
  if (!J || !rp || !rm) {
    st = RS_ERROR(RS_ERR_MEMORY, "fit: out of memory");
    goto out;
  }
  theta_of(c, L, th);
  for (int k = 0; k < p; ++k) {
    /* a coefficient at its bound 0 takes its scale's step */
    const double scale = c->kind == RS_RADIAL_HAKIEL && k > 0 ? c->Escale / pow(c->Pmax, k) : fabs(th[k]);
    const double h = 1e-5 * fmax(fabs(th[k]), 1e-3 * scale);
    double tp[RS_FIT_MAX_PARAMS], tm[RS_FIT_MAX_PARAMS];
    memcpy(tp, th, sizeof tp);
    memcpy(tm, th, sizeof tm);
    tp[k] += h;
    tm[k] -= h;
    rs_radial_law Lp, Lm;
    law_of_theta(c, L, tp, &Lp);
    law_of_theta(c, L, tm, &Lm);
    if (c->kind == RS_RADIAL_TABLE) {
      rs_radial_law_prepare(&Lp);
      rs_radial_law_prepare(&Lm);
    }
    ssr_of(c, &Lp, rp);
    ssr_of(c, &Lm, rm);
    for (int i = 0; i < n; ++i) J[(size_t)i * p + k] = (rp[i] - rm[i]) / (2 * h);
  }
  st = rs_fit_intervals(n, p, J, ssr, out->half_width, NULL);
  if (st)
    rs_error_wrap("%s law: fewer parameters (--terms), or points over a wider pressure range",
                  c->kind == RS_RADIAL_TABLE ? "table" : c->kind == RS_RADIAL_HAKIEL ? "hakiel"
                  : c->kind == RS_RADIAL_PFEIFFER ? "pfeiffer" : "linear");
  for (int k = 0; k < p; ++k) out->value[k] = th[k];
out:
  free(J);
  free(rp);
  free(rm);
  return st;
}

static void param_names(const fit_ctx *c, const rs_radial_law *L, rs_fit_stack_result *out)
{
  for (int k = 0; k < c->p; ++k) {
    char *s = out->name[k];
    if (c->kind == RS_RADIAL_LINEAR) snprintf(s, 16, "E_r");
    else if (c->kind == RS_RADIAL_PFEIFFER) snprintf(s, 16, k ? "K2" : "K1");
    else if (c->kind == RS_RADIAL_HAKIEL) snprintf(s, 16, "C%d", k);
    else snprintf(s, 16, "E(%.3g)", L->P[k]);
  }
}

rs_status rs_fit_stack(int n, const double *P, const double *eps, rs_radial_kind law, int terms,
                       rs_fit_stack_result *out)
{
  memset(out, 0, sizeof *out);
  static const char *names[] = {"linear", "pfeiffer", "hakiel", "table"};
  if ((int)law < 0 || (int)law > 3) return RS_ERROR(RS_ERR_INPUT, "unknown stack law %d", (int)law);
  fit_ctx c = {.n = n, .P = P, .eps = eps, .kind = law};
  c.p = law == RS_RADIAL_LINEAR ? 1 : law == RS_RADIAL_PFEIFFER ? 2
      : terms > 0 ? terms : law == RS_RADIAL_HAKIEL ? 3 : 6;
  if (law == RS_RADIAL_HAKIEL && (c.p < 1 || c.p > RS_HAKIEL_MAX_COEF))
    return RS_ERROR(RS_ERR_INPUT, "--terms: the hakiel law takes 1 to %d coefficients (got %d)",
                    RS_HAKIEL_MAX_COEF, c.p);
  if (law == RS_RADIAL_TABLE && (c.p < 2 || c.p > RS_FIT_MAX_PARAMS))
    return RS_ERROR(RS_ERR_INPUT, "--terms: the table law takes 2 to %d points (got %d)",
                    RS_FIT_MAX_PARAMS, c.p);
  if (law != RS_RADIAL_HAKIEL && law != RS_RADIAL_TABLE && terms > 0)
    return RS_ERROR(RS_ERR_INPUT, "--terms is for the hakiel and table laws, not %s", names[law]);
  rs_status st = check_data(n, P, eps, c.p, names[law]);
  if (st) return st;
  c.Pmax = 0.0;
  for (int i = 0; i < n; ++i) {
    c.Pmax = fmax(c.Pmax, P[i]);
    c.eps_scale = fmax(c.eps_scale, eps[i]);
  }
  if (!(c.eps_scale > 0.0))
    return RS_ERROR(RS_ERR_INPUT, "every strain is 0: the data show no compression to fit");
  double K1 = c.Pmax, K2 = 1.0, x[RS_FIT_MAX_PARAMS], lo[RS_FIT_MAX_PARAMS], hi[RS_FIT_MAX_PARAMS];
  pfeiffer_start(&c, &K1, &K2);
  c.Escale = K2 * (K1 + c.Pmax);
  for (int k = 0; k < c.p; ++k) {
    const double s = c.p > 1 ? (double)k / (c.p - 1) : 0.0;
    if (law == RS_RADIAL_LINEAR) {
      double spp = 0.0, spe = 0.0;
      for (int i = 0; i < n; ++i) spp += P[i] * P[i], spe += P[i] * eps[i];
      x[0] = log(spe > 0.0 ? spp / spe : c.Escale);
    } else if (law == RS_RADIAL_PFEIFFER) x[k] = log(k ? K2 : K1);
    else if (law == RS_RADIAL_HAKIEL)
      x[k] = k == 0 ? log(K1 * K2) : k == 1 ? K2 * c.Pmax / c.Escale : 0.0;
    else x[k] = log(K2 * (K1 + c.Pmax * s * s));
    const int ranged = law == RS_RADIAL_HAKIEL && k > 0;
    lo[k] = ranged ? 0.0 : x[k] - 40.0;
    hi[k] = ranged ? 1e3 : x[k] + 40.0;
  }
  nlopt_opt opt = nlopt_create(NLOPT_LN_BOBYQA, (unsigned)c.p);
  if (!opt) return RS_ERROR(RS_ERR_MEMORY, "fit: cannot create the optimiser");
  nlopt_set_lower_bounds(opt, lo);
  nlopt_set_upper_bounds(opt, hi);
  nlopt_set_min_objective(opt, objective, &c);
  nlopt_set_xtol_rel(opt, 1e-12);
  nlopt_set_ftol_rel(opt, 1e-15);
  nlopt_set_maxeval(opt, 4000 * c.p);
  double f = 0.0;
  nlopt_result r = nlopt_optimize(opt, x, &f);
  nlopt_destroy(opt);
  if (r < 0 && r != NLOPT_ROUNDOFF_LIMITED)
    return RS_ERROR(RS_ERR_SOLVER, "fit: the optimiser failed (%s)", nlopt_result_to_string(r));
  if ((st = law_of(&c, x, &out->radial))) return st;
  double *res = malloc((size_t)n * sizeof *res);
  if (!res) return RS_ERROR(RS_ERR_MEMORY, "fit: out of memory");
  const double ssr = ssr_of(&c, &out->radial, res);
  out->n_params = c.p;
  out->n_points = n;
  out->rms = sqrt(ssr / n);
  out->P_min = INFINITY;
  for (int i = 0; i < n; ++i) {
    out->P_min = fmin(out->P_min, P[i]);
    if (fabs(res[i]) > fabs(out->worst_residual) || i == 0) {
      out->worst = i;
      out->worst_residual = res[i];
    }
  }
  free(res);
  out->P_max = c.Pmax;
  out->evaluations = c.evals;
  param_names(&c, &out->radial, out);
  return intervals(&c, &out->radial, ssr, out);
}

int rs_fit_law_parse(const char *s)
{
  static const char *names[] = {"linear", "pfeiffer", "hakiel", "table"};
  for (int i = 0; s && i < 4; ++i)
    if (strcmp(s, names[i]) == 0) return i;
  return -1;
}

rs_status rs_fit_stack_flat(int n, const double *P, const double *eps, const char *law, int terms,
                            int *n_params, char *names, double *value, double *half_width,
                            double *stats)
{
  const int k = rs_fit_law_parse(law);
  if (k < 0)
    return RS_ERROR(RS_ERR_INPUT, "unknown law '%s' (linear, pfeiffer, hakiel or table)",
                    law ? law : "(null)");
  rs_fit_stack_result fr;
  rs_status st = rs_fit_stack(n, P, eps, (rs_radial_kind)k, terms, &fr);
  if (st) return st;
  *n_params = fr.n_params;
  for (int i = 0; i < fr.n_params; ++i) {
    memcpy(names + 16 * i, fr.name[i], 16);
    value[i] = fr.value[i];
    half_width[i] = fr.half_width[i];
  }
  stats[0] = fr.rms;
  stats[1] = fr.worst;
  stats[2] = fr.worst_residual;
  stats[3] = fr.evaluations;
  return RS_OK;
}
