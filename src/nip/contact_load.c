/* The nip for a given load: P(a) from the stick/slip solution at half-width a is
 * monotone (about a^2, Hertz), so a follows from a safeguarded secant (Dekker/Brent-like:
 * secant steps inside a bracket, bisection when they leave it or stall) on
 * f(ln a) = ln P(a) - ln P, started from the previous a (warm) or the Hertz half-width. */
#include "nip/contact_internal.h"
#include "util/error.h"

#include <math.h>

rs_status rs_nip_contact_solve_width(rs_nip_contact *nc, double a, double Ti, rs_nip_solution *out)
{
  if (!nc || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!(isfinite(a) && a > 0)) return RS_ERROR(RS_ERR_INPUT, "half-width a = %g m must be > 0", a);
  if (!isfinite(Ti)) return RS_ERROR(RS_ERR_INPUT, "web tension Ti = %g N/m is not finite", Ti);
  if (!nc->have_roll) return RS_ERROR(RS_ERR_INPUT, "nip contact: the roll is not set");
  double amax = 0.2 * fmin(nc->R[0], nc->R[1]);
  if (a > amax)
    return RS_ERROR(RS_ERR_INPUT, "half-width a = %g m exceeds 0.2 min(R1, R2) = %g m", a, amax);
  rs_status st = rs_nipc_solve_fixed(nc, a, Ti, out);
  if (st) return st;
  out->width_iterations = 1;
  out->total_solves = out->iterations;
  out->E_r = 0;
  return RS_OK;
}

/* Hertz half-width a^2 = 4 P R* / (pi E*), 1/E* = (H1_11 + H2_11)/2 of the half-planes
 * (Johnson 1985, eq. 4.45); the sheet is left out. */
static double estar(const rs_nip_contact *nc)
{
  return nc->H11[0] > 0 && nc->H11[1] > 0 ? 2.0 / (nc->H11[0] + nc->H11[1]) : 0.0;
}

static double hertz(double P, double Rs, double Es)
{
  return sqrt(4 * P * Rs / (3.14159265358979323846 * Es));
}

/* Cold start: the cylinders (Hertz, P_H = pi a^2 E* / (4 R*)) in series with the sheet's
 * through-thickness compliance C = 2h c22 as a Winkler layer (rigid cylinders: p = (a^2 -
 * x^2) / (2 R* C), P_W = 2 a^3 / (3 R* C)): 1/P = 1/P_H(a) + 1/P_W(a), solved for a by
 * Newton on ln a. A guess only (the layer and the cylinders do not share the same a); it
 * matters when the sheet is the softer part (stiff cylinders), where Hertz alone is far
 * too narrow and may not even carry the drum's traction. */
static double cold_guess(const rs_nip_contact *nc, double P, double Rs, double Es)
{
  double aH = hertz(P, Rs, Es), C = 2 * nc->cfg.sheet.h * nc->cfg.sheet.c22;
  if (!(C > 0)) return aH;
  double aW = cbrt(1.5 * P * Rs * C), x = log(fmax(aH, aW));
  for (int it = 0; it < 30; ++it) {
    double a = exp(x), PH = 3.14159265358979323846 * a * a * Es / (4 * Rs);
    double PW = 2 * a * a * a / (3 * Rs * C);
    double g = 1 / PH + 1 / PW - 1 / P, dg = -2 / PH - 3 / PW; /* d/d ln a */
    double step = -g / dg;
    x += fmax(fmin(step, 0.7), -0.7);
    if (fabs(step) < 1e-12) break;
  }
  return exp(x);
}

/* The polynomial through (x[i], y[i]), i < m, at x0 (Lagrange). */
static double lagrange(int m, const double *x, const double *y, double x0)
{
  double p = 0;
  for (int i = 0; i < m; ++i) {
    double l = 1;
    for (int j = 0; j < m; ++j)
      if (j != i) l *= (x0 - x[j]) / (x[i] - x[j]);
    p += l * y[i];
  }
  return p;
}

/* First half-width to try. Cold: cold_guess. Warm: the ratio phi = a / a_Hertz of the last
 * converged searches, extrapolated in ln R* and times the Hertz half-width now; a reel
 * calls with R growing by one caliper per layer, or (the adaptive policy) by steps that
 * grow with R, about evenly spaced in ln R*, where phi is smooth. The cubic through the
 * last four searches, unless it differs from the quadratic through the last three by more
 * than 1e-3 (then the extrapolation reaches too far for either: the quadratic); on the
 * adaptive reel's large radii the cubic meets the load to 1e-8, the quadratic in R* missed
 * by 1e-6 - 4e-5 (docs/nip.md, "Load -> half-width"). The same nip again (P, R*, E*
 * unchanged) starts exactly at the previous a (its kernels and factorization are kept).
 * A prediction more than 1 % off the last phi is not trusted. */
static double predict(const rs_nip_contact *nc, double P, double Rs, double Es)
{
  if (!(Es > 0)) return 1e-3 * fmin(nc->R[0], nc->R[1]);
  double aH = hertz(P, Rs, Es);
  if (nc->hist_n == 0) return cold_guess(nc, P, Rs, Es);
  if (P == nc->hist_P[0] && Rs == nc->hist_Rs[0] && Es == nc->hist_Es[0]) return nc->last_a;
  double phi[4], x[4];
  int m = 0;
  for (int i = 0; i < nc->hist_n; ++i) {
    int distinct = 1;
    for (int j = 0; j < m; ++j) distinct &= fabs(nc->hist_Rs[i] - nc->hist_Rs[j]) > 1e-12 * Rs;
    if (!distinct) break;
    x[m] = log(nc->hist_Rs[i]);
    phi[m++] = nc->hist_a[i] / hertz(nc->hist_P[i], nc->hist_Rs[i], nc->hist_Es[i]);
  }
  double p = lagrange(m < 3 ? m : 3, x, phi, log(Rs));
  if (m == 4) {
    double p3 = lagrange(4, x, phi, log(Rs));
    if (fabs(p3 / p - 1) <= 1e-3) p = p3;
  }
  if (!(fabs(p / phi[0] - 1) <= 0.01)) p = phi[0];
  return p * aH;
}

/* The slope d ln P / d ln a for the search's first step: the last search's, extrapolated
 * linearly in R* through the one before (the reel's: R grows, the slope falls from ~2.5
 * on a thin roll to ~2.1; the last search's alone was 0.3 - 0.6 % off, and the second
 * half-width then missed load_rtol, a third was needed). Not trusted beyond 2 %. */
static double first_slope(const rs_nip_contact *nc, double Rs)
{
  double s0 = nc->warm_slope;
  if (nc->hist_slope_n < 2 || s0 != nc->hist_slope[0]) return s0;
  double x0 = nc->hist_slope_Rs[0], x1 = nc->hist_slope_Rs[1];
  if (!(fabs(x0 - x1) > 1e-12 * Rs)) return s0;
  double s = s0 + (s0 - nc->hist_slope[1]) / (x0 - x1) * (Rs - x0);
  return fabs(s / s0 - 1) <= 0.02 ? s : s0;
}

static void remember(rs_nip_contact *nc, double P, double Rs, double Es, double a)
{
  for (int i = 3; i > 0; --i) {
    nc->hist_Rs[i] = nc->hist_Rs[i - 1];
    nc->hist_P[i] = nc->hist_P[i - 1];
    nc->hist_Es[i] = nc->hist_Es[i - 1];
    nc->hist_a[i] = nc->hist_a[i - 1];
  }
  nc->hist_Rs[0] = Rs;
  nc->hist_P[0] = P;
  nc->hist_Es[0] = Es;
  nc->hist_a[0] = a;
  if (nc->hist_n < 4) ++nc->hist_n;
}

/* The load search's state in x = ln a: the bracket [lo, hi] once found (P(lo) < P <
 * P(hi)), the last step and the secant slope d ln P / d ln a, and how many steps in a row
 * did not halve the misfit. */
typedef struct load_search {
  double P, lnP, carried, xmin, xmax;
  int have_lo, have_hi, evals, solves, stall;
  double lo, hi, xprev, fprev, fbest, slope;
} load_search;

/* The misfit f = ln P(a) - ln P at a = exp(x). A state that cannot exist at a half-width
 * too small for the drum's traction counts as too little load (widen), not as a failure. */
static rs_status load_misfit(rs_nip_contact *nc, double Ti, load_search *ls, double x,
                             rs_nip_solution *out, double *f)
{
  rs_status st = rs_nipc_solve_fixed(nc, exp(x), Ti, out);
  ++ls->evals;
  ls->solves += out->iterations;
  if (st == RS_ERR_SOLVER && ls->carried > 0 && !ls->have_hi) {
    /* No stick/slip state at this a: if the load it carries (the pressures of the last
     * linear solve) is too small for the drum's traction, no state can exist there; that
     * says the half-width is too small, so widen instead of failing. */
    double Pa = 0, dx = 2 * exp(x) / (nc->M - 1);
    for (int j = 1; j < nc->M - 1; ++j) Pa += dx * nc->z[j - 1];
    if (!(Pa > 0 && nc->cfg.mu_drum * Pa < 1.5 * ls->carried))
      return rs_error_wrap("load search for nip.load = %g N/m (try %d)", ls->P, ls->evals);
    rs_error_clear();
    nc->have_warm = 0;
    *f = fmin(log(Pa) - ls->lnP, -1e-3);
    return RS_OK;
  }
  if (st) return rs_error_wrap("load search for nip.load = %g N/m (try %d)", ls->P, ls->evals);
  if (!(out->load > 0))
    return RS_ERROR(RS_ERR_SOLVER, "load search: P(a = %g m) = %g N/m is not positive", exp(x), out->load);
  *f = log(out->load) - ls->lnP;
  return RS_OK;
}

/* The next x after misfit f at x: the secant step inside the bracket (bisection when it
 * leaves it or stalls); before a bracket, the secant step doubled for each step that did
 * not halve |f| (a poor slope), at most a factor 2 in a, within [xmin, xmax]. */
static rs_status load_step(load_search *ls, double x, double f, const rs_nip_solution *out,
                           double *xn_out)
{
  if (f < 0) { ls->have_lo = 1; ls->lo = x; }
  else { ls->have_hi = 1; ls->hi = x; }
  if (ls->evals > 1 && x != ls->xprev) {
    double s = (f - ls->fprev) / (x - ls->xprev);
    if (s > 0 && isfinite(s)) ls->slope = s;
  }
  ls->stall = fabs(f) > 0.5 * ls->fbest ? ls->stall + 1 : 0;
  ls->fbest = fmin(ls->fbest, fabs(f));
  double xn = x - f / ls->slope;
  if (ls->have_lo && ls->have_hi) {
    if (!(xn > ls->lo && xn < ls->hi) || ls->stall >= 2) {
      xn = 0.5 * (ls->lo + ls->hi);
      ls->stall = 0;
    }
  } else {
    xn = x - ldexp(f / ls->slope, ls->stall < 8 ? ls->stall : 8);
    if (!ls->have_hi) { /* P too small so far: widen */
      if (x >= ls->xmax)
        return RS_ERROR(RS_ERR_INPUT, "nip.load = %g N/m needs a contact half-width beyond "
                        "0.2 min(R1, R2) = %g m (P there is %g N/m): no half-width carries it",
                        ls->P, exp(ls->xmax), out->load);
      xn = fmin(fmin(xn, x + log(2.0)), ls->xmax);
    } else { /* P too large so far: narrow */
      if (x <= ls->xmin)
        return RS_ERROR(RS_ERR_INPUT, "nip.load = %g N/m is too small: P(a = %g m) = %g N/m",
                        ls->P, exp(ls->xmin), out->load);
      xn = fmax(fmax(xn, x - log(2.0)), ls->xmin);
    }
  }
  ls->xprev = x;
  ls->fprev = f;
  *xn_out = xn;
  return RS_OK;
}

/* The search's half-widths from x until P(a) meets load_rtol. Only the state it ends with
 * is reported, so the condition number is estimated for that one alone (the earlier states
 * are screened by the factorizations' pivots and the rank-k correction's conditioning). */
static rs_status search(rs_nip_contact *nc, double Ti, load_search *ls, double *x, double *f,
                        rs_nip_solution *out)
{
  rs_status st = RS_OK;
  nc->defer_cond = 1;
  for (;;) {
    st = load_misfit(nc, Ti, ls, *x, out, f);
    if (st || fabs(*f) <= nc->cfg.load_rtol) break;
    if (ls->evals >= 80) {
      st = RS_ERROR(RS_ERR_SOLVER, "load search for nip.load = %g N/m did not converge in %d "
                    "half-widths (last a = %g m, P(a) = %g N/m)", ls->P, ls->evals, exp(*x), out->load);
      break;
    }
    st = load_step(ls, *x, *f, out, x);
    if (st) break;
  }
  nc->defer_cond = 0;
  if (st) return st;
  st = rs_nipc_lin_cond(nc, out->a, &out->condition_number);
  if (st) {
    nc->have_warm = 0;
    return rs_error_wrap("converged stick/slip state at a = %g m", out->a);
  }
  return RS_OK;
}

rs_status rs_nip_contact_solve_load(rs_nip_contact *nc, double P, double Ti, rs_nip_solution *out)
{
  if (!nc || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!(isfinite(P) && P > 0)) return RS_ERROR(RS_ERR_INPUT, "nip.load must be > 0 (got %g N/m)", P);
  if (!(isfinite(Ti) && Ti >= 0)) return RS_ERROR(RS_ERR_INPUT, "web tension Ti = %g N/m must be >= 0", Ti);
  if (!nc->have_roll) return RS_ERROR(RS_ERR_INPUT, "nip contact: the roll is not set");
  /* The drum's drive carries (1 - share) Ti through friction alone: mu_drum P >= that. */
  double carried = (1.0 - rs_nipc_share(nc)) * Ti;
  if (carried > 0 && nc->cfg.mu_drum * P <= carried * (1 + 1e-9)) /* at capacity: every drum
                                                                      element slips, xi2 is free */
    return RS_ERROR(RS_ERR_INPUT, "nip.friction.drum * nip.load = %g * %g = %g N/m is less than "
                    "the tension the drum must carry by friction (%g N/m of the web tension %g N/m): "
                    "no stick/slip state exists; raise nip.load or nip.friction.drum",
                    nc->cfg.mu_drum, P, nc->cfg.mu_drum * P, carried, Ti);
  const double Rs = rs_nipc_rstar(nc), amax = 0.2 * fmin(nc->R[0], nc->R[1]), Es = estar(nc);
  load_search ls = {.P = P, .lnP = log(P), .carried = carried, .xmin = log(amax * 1e-7),
                    .xmax = log(amax), .fbest = INFINITY, .slope = 2.0};
  double a0 = predict(nc, P, Rs, Es);
  if (nc->hist_n > 0 && nc->warm_slope > 0.5 && nc->warm_slope < 4) ls.slope = first_slope(nc, Rs);
  if (!(a0 > 0) || !isfinite(a0)) a0 = 1e-3 * amax;
  double x = fmin(fmax(log(a0), ls.xmin), ls.xmax), f = 0;
  rs_status st = search(nc, Ti, &ls, &x, &f, out);
  if (st) return st;
  out->width_iterations = ls.evals;
  out->total_solves = ls.solves;
  out->E_r = 0;
  /* the secant slope through the last two half-widths (load_step takes it only for a next
   * step): the slope the next search starts from, not the one this search started with */
  if (ls.evals > 1 && x != ls.xprev) {
    double s = (f - ls.fprev) / (x - ls.xprev);
    if (s > 0 && isfinite(s)) ls.slope = s;
  }
  /* remember the half-width that carries P exactly, to first order: the predictor
   * extrapolates these, and the raw ones carry a noise of load_rtol / slope */
  remember(nc, P, Rs, Es, out->a * exp(-f / ls.slope));
  nc->last_a = out->a;
  nc->warm_slope = ls.slope;
  if (!(nc->hist_slope_n > 0 && Rs == nc->hist_slope_Rs[0])) {
    nc->hist_slope[1] = nc->hist_slope[0];
    nc->hist_slope_Rs[1] = nc->hist_slope_Rs[0];
    if (nc->hist_slope_n < 2) ++nc->hist_slope_n;
  }
  nc->hist_slope[0] = ls.slope;
  nc->hist_slope_Rs[0] = Rs;
  return RS_OK;
}
