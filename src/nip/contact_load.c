/* The nip for a given load: P(a) from the stick/slip solution at half-width a is
 * monotone (about a^2, Hertz), so a follows from a safeguarded secant (Dekker/Brent-like:
 * secant steps inside a bracket, bisection when they leave it or stall) on
 * f(ln a) = ln P(a) - ln P, started from the previous a (warm) or the Hertz half-width. */
#include "nip/contact_internal.h"

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

/* Hertz half-width a^2 = 4 P R* / (pi E*) with 1/E* = (H1_11 + H2_11)/2 of the half-planes
 * (Johnson 1985, eq. 4.45); the sheet is left out (it is only a starting guess). */
static double hertz_guess(const rs_nip_contact *nc, double P)
{
  double H1[2][2], H2[2][2];
  if (rs_ortho_halfplane(&nc->roll_c, H1) || rs_ortho_halfplane(&nc->cfg.drum, H2)) {
    rs_error_clear();
    return 1e-3 * fmin(nc->R[0], nc->R[1]);
  }
  double Estar = 2.0 / (H1[0][0] + H2[0][0]);
  return sqrt(4 * P * rs_nipc_rstar(nc) / (3.14159265358979323846 * Estar));
}

rs_status rs_nip_contact_solve_load(rs_nip_contact *nc, double P, double Ti, rs_nip_solution *out)
{
  if (!nc || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!(isfinite(P) && P > 0)) return RS_ERROR(RS_ERR_INPUT, "nip.load must be > 0 (got %g N/m)", P);
  if (!(isfinite(Ti) && Ti >= 0)) return RS_ERROR(RS_ERR_INPUT, "web tension Ti = %g N/m must be >= 0", Ti);
  if (!nc->have_roll) return RS_ERROR(RS_ERR_INPUT, "nip contact: the roll is not set");
  /* The drum's drive carries (1 - share) Ti through friction alone: mu_drum P >= that. */
  double carried = (1.0 - rs_nipc_share(nc)) * Ti;
  if (carried > 0 && nc->cfg.mu_drum * P < carried)
    return RS_ERROR(RS_ERR_INPUT, "nip.friction.drum * nip.load = %g * %g = %g N/m is less than "
                    "the tension the drum must carry by friction (%g N/m of the web tension %g N/m): "
                    "no stick/slip state exists; raise nip.load or nip.friction.drum",
                    nc->cfg.mu_drum, P, nc->cfg.mu_drum * P, carried, Ti);
  const double Rs = rs_nipc_rstar(nc), amax = 0.2 * fmin(nc->R[0], nc->R[1]);
  const double xmax = log(amax), xmin = log(amax * 1e-7), lnP = log(P), tol = nc->cfg.load_rtol;
  double a0, slope = 2.0;
  if (nc->warm_a > 0) {
    double ratio = P / nc->warm_P * Rs / nc->warm_Rs;
    /* the same nip again: start exactly at the previous a (its kernels are cached) */
    a0 = fabs(ratio - 1) <= tol ? nc->warm_a : nc->warm_a * sqrt(ratio);
    if (nc->warm_slope > 0.5 && nc->warm_slope < 4) slope = nc->warm_slope;
  } else {
    a0 = hertz_guess(nc, P);
  }
  if (!(a0 > 0) || !isfinite(a0)) a0 = 1e-3 * amax;
  double x = fmin(fmax(log(a0), xmin), xmax);
  int have_lo = 0, have_hi = 0, evals = 0, solves = 0, stall = 0;
  double lo = 0, flo = 0, hi = 0, fhi = 0, xprev = 0, fprev = 0, fbest = INFINITY;
  for (;;) {
    rs_status st = rs_nipc_solve_fixed(nc, exp(x), Ti, out);
    ++evals;
    solves += out->iterations;
    if (st) return rs_error_wrap("load search for nip.load = %g N/m (try %d)", P, evals);
    if (!(out->load > 0))
      return RS_ERROR(RS_ERR_SOLVER, "load search: P(a = %g m) = %g N/m is not positive", exp(x), out->load);
    double f = log(out->load) - lnP;
    if (fabs(f) <= tol) break;
    if (evals >= 80)
      return RS_ERROR(RS_ERR_SOLVER, "load search for nip.load = %g N/m did not converge in %d "
                      "half-widths (last a = %g m, P(a) = %g N/m)", P, evals, exp(x), out->load);
    if (f < 0) { have_lo = 1; lo = x; flo = f; }
    else { have_hi = 1; hi = x; fhi = f; }
    if (evals > 1 && x != xprev) {
      double s = (f - fprev) / (x - xprev);
      if (s > 0 && isfinite(s)) slope = s;
    }
    stall = fabs(f) > 0.5 * fbest ? stall + 1 : 0;
    fbest = fmin(fbest, fabs(f));
    double xn = x - f / slope;
    if (have_lo && have_hi) {
      if (!(xn > lo && xn < hi) || stall >= 2) {
        xn = 0.5 * (lo + hi);
        stall = 0;
      }
      (void)flo;
      (void)fhi;
    } else if (!have_hi) { /* P too small so far: widen (at most doubling a) */
      if (x >= xmax)
        return RS_ERROR(RS_ERR_INPUT, "nip.load = %g N/m needs a contact half-width beyond "
                        "0.2 min(R1, R2) = %g m (P there is %g N/m): no half-width carries it",
                        P, amax, out->load);
      xn = fmin(fmin(fmax(xn, x + 1e-3), x + log(2.0)), xmax);
    } else { /* P too large so far: narrow */
      if (x <= xmin)
        return RS_ERROR(RS_ERR_INPUT, "nip.load = %g N/m is too small: P(a = %g m) = %g N/m",
                        P, exp(xmin), out->load);
      xn = fmax(fmax(fmin(xn, x - 1e-3), x - log(2.0)), xmin);
    }
    xprev = x;
    fprev = f;
    x = xn;
  }
  out->width_iterations = evals;
  out->total_solves = solves;
  out->E_r = 0;
  nc->warm_a = out->a;
  nc->warm_P = out->load;
  nc->warm_Rs = Rs;
  nc->warm_slope = slope;
  return RS_OK;
}
