/* The correction of the integration's global error (src/roll/roll_integrate.c,
 * roll_correction_step; docs/roll-model.md, "Correcting the integration's error"), against
 * independent references:
 *   altmann_exact     constant E_r: every stress against Altmann's closed form summed over
 *                     the increments, with and without the correction, at rtol 1e-5 (the
 *                     first-order reuse, every start at the top): the corrected errors at
 *                     least 30x smaller; the default reuse's within 0.1, 1 and 3x its
 *                     tolerance (core, sigma_r, sigma_theta)
 *   pfeiffer_tight    the Pfeiffer newsprint roll (1500 layers) against an rtol 1e-10
 *                     reference without the correction, both placements: every increment
 *                     from the core at rtol 1e-4 and 1e-3, the corrected core pressure,
 *                     sigma_r and sigma_theta at least 50x closer (measured 80 - 1400x:
 *                     the estimate is the integration's error to a percent or two); with
 *                     the default reuse at rtol 1e-5 and 1e-4, at least 30x (10x for
 *                     sigma_theta) closer and the core pressure within 3x the reuse's
 *                     tolerance (its error is what is left)
 *   innermost_hoop    the same roll at a scene's defaults (rtol 1e-3, atol = rtol, the reuse
 *                     and the correction) against an rtol 1e-10 reference without the
 *                     correction: the hoop stress error of the ten innermost layers (where
 *                     each integration from the core starts) no larger than the rest's, and
 *                     the largest under 5e-5 of T0/t
 *   vanishes          at rtol 1e-10 the correction changes the stresses by less than 1e-8
 *                     of the core pressure (it is an estimate of errors that vanish) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "roll_helpers.h"

typedef struct errs {
  double core, sr, st; /* relative; sigma_theta against T0/t */
} errs;

static errs compare(const rs_roll *a, const double *sr, const double *st, double core, int n,
                    double T0, double t)
{
  errs e = {fabs(rs_roll_core_pressure(a) - core) / core, 0.0, 0.0};
  const double *ar = rs_roll_sigma_r(a), *at = rs_roll_sigma_theta(a);
  for (int j = 0; j < n; ++j) {
    if (sr[j] != 0.0) e.sr = fmax(e.sr, fabs(ar[j] - sr[j]) / fabs(sr[j]));
    e.st = fmax(e.st, fabs(at[j] - st[j]) * t / T0);
  }
  return e;
}

static void report(const char *what, errs off, errs on)
{
  printf("  %-34s core %.3e -> %.3e   sigma_r %.3e -> %.3e   sigma_theta %.3e -> %.3e\n",
         what, off.core, on.core, off.sr, on.sr, off.st, on.st);
}

static void altmann_exact(void)
{
  const int n = 2000;
  const double rc = 0.05, t = 100e-6, Et = 5e9, Er = 5e7, T = 300.0;
  static double sr[2000], st[2000];
  double core = 0.0;
  const double kc = -1.0, g = sqrt(Et / Er); /* rigid core, nu = 0 */
  altmann_roll(g, kc, rc, t, n, T, sr, st, &core, RS_LOAD_BENEATH);
  rs_roll_params p = linear_params(rc, t, Et, Er, INFINITY, n);
  p.rtol = 1e-5;
  /* the integrations the first-order reuse makes: each from a start at the top (a
   * constant modulus never drifts), so that the comparison is the correction's alone */
  p.reuse = RS_REUSE_FIRST_ORDER;
  p.correction = RS_CORRECTION_OFF;
  rs_roll *off = wind(&p, n, 1, T);
  p.correction = RS_CORRECTION_ON;
  rs_roll *on = wind(&p, n, 1, T);
  /* the default (the corrected reuse: its starts stay at or below the last one within a
   * reference's service, so its integrations are longer) no less accurate */
  p.reuse = RS_REUSE_ON;
  rs_roll *dflt = wind(&p, n, 1, T);
  if (!off || !on || !dflt) goto out;
  errs a = compare(off, sr, st, core, n, T, t), b = compare(on, sr, st, core, n, T, t);
  errs c = compare(dflt, sr, st, core, n, T, t);
  report("Altmann, rtol 1e-5", a, b);
  report("Altmann, rtol 1e-5, the default", b, c);
  CHECK_LT(30.0 * b.core, a.core);
  CHECK_LT(30.0 * b.sr, a.sr);
  CHECK_LT(30.0 * b.st, a.st);
  const double tol = RS_ACCURACY_PER_RTOL * p.rtol;
  CHECK_LT(c.core, 0.1 * tol); /* measured 0.01, 0.5 and 1.6 tol: a constant modulus */
  CHECK_LT(c.sr, tol);          /* never drifts, and its starts stay near the top */
  CHECK_LT(c.st, 3.0 * tol);
out:
  rs_roll_destroy(&off);
  rs_roll_destroy(&on);
  rs_roll_destroy(&dflt);
}

static void pfeiffer_case(rs_load_placement placement)
{
  const int n = 1500;
  const double T = 682.5, t = 70e-6;
  rs_roll_params p = pfeiffer_params(0.0762, t, 3.5e9, 5e3, 60, 1e9, n);
  p.placement = placement;
  p.rtol = 1e-10;
  p.reuse = RS_REUSE_OFF;
  p.correction = RS_CORRECTION_OFF;
  rs_roll *ref = wind(&p, n, 1, T);
  if (!ref) return;
  double *sr = malloc(2 * n * sizeof *sr), *st = sr + n;
  if (!sr) {
    rs_roll_destroy(&ref);
    return;
  }
  for (int j = 0; j < n; ++j) {
    sr[j] = rs_roll_sigma_r(ref)[j];
    st[j] = rs_roll_sigma_theta(ref)[j];
  }
  const double core = rs_roll_core_pressure(ref);
  const double rtols[] = {1e-4, 1e-3, 1e-5, 1e-4};
  for (int i = 0; i < 4; ++i) {
    const int reuse = i >= 2; /* every increment from the core, then the default reuse */
    p.rtol = rtols[i];
    p.reuse = reuse ? RS_REUSE_ON : RS_REUSE_OFF;
    p.correction = RS_CORRECTION_OFF;
    rs_roll *off = wind(&p, n, 1, T);
    p.correction = RS_CORRECTION_ON;
    rs_roll *on = wind(&p, n, 1, T);
    if (off && on) {
      errs a = compare(off, sr, st, core, n, T, t), b = compare(on, sr, st, core, n, T, t);
      char what[80];
      snprintf(what, sizeof what, "Pfeiffer, %s, %s, rtol %.0e",
               placement == RS_LOAD_BENEATH ? "beneath" : "hakiel",
               reuse ? "reuse" : "from the core", rtols[i]);
      report(what, a, b);
      if (!reuse) {
        CHECK_LT(50.0 * b.core, a.core); /* measured 660 - 1400x; sigma_theta at 1e-3 80x */
        CHECK_LT(50.0 * b.sr, a.sr);
        CHECK_LT(50.0 * b.st, a.st);
      } else {
        CHECK_LT(30.0 * b.core, a.core);
        CHECK_LT(30.0 * b.sr, a.sr);
        CHECK_LT(10.0 * b.st, a.st);
        CHECK_LT(b.core, 3.0 * RS_ACCURACY_PER_RTOL * rtols[i]);
      }
    }
    rs_roll_destroy(&off);
    rs_roll_destroy(&on);
  }
  free(sr);
  rs_roll_destroy(&ref);
}

static void pfeiffer_tight(void)
{
  pfeiffer_case(RS_LOAD_BENEATH);
  pfeiffer_case(RS_LOAD_HAKIEL);
}

static void vanishes(void)
{
  const int n = 600;
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, n);
  p.rtol = 1e-10;
  p.correction = RS_CORRECTION_OFF;
  rs_roll *off = wind(&p, n, 1, 682.5);
  p.correction = RS_CORRECTION_ON;
  rs_roll *on = wind(&p, n, 1, 682.5);
  if (off && on) {
    const double core = rs_roll_core_pressure(off);
    double d = fabs(rs_roll_core_pressure(on) - core);
    for (int j = 0; j < n; ++j)
      d = fmax(d, fabs(rs_roll_sigma_r(on)[j] - rs_roll_sigma_r(off)[j]));
    CHECK_LOG("max stress change / core pressure", d / core);
    CHECK_LT(d / core, 1e-8);
    CHECK(d > 0.0); /* the correction did act */
  }
  rs_roll_destroy(&off);
  rs_roll_destroy(&on);
}

/* max over layers [lo, hi) of |sigma_theta - ref| t / T0 */
static double hoop_error(const rs_roll *a, const rs_roll *ref, int lo, int hi, double T0, double t)
{
  double e = 0.0;
  for (int j = lo; j < hi; ++j)
    e = fmax(e, fabs(rs_roll_sigma_theta(a)[j] - rs_roll_sigma_theta(ref)[j]) * t / T0);
  return e;
}

static void innermost_hoop(void)
{
  const int n = 1500;
  const double T = 682.5, t = 70e-6;
  rs_roll_params p = pfeiffer_params(0.0762, t, 3.5e9, 5e3, 60, 1e9, n);
  p.rtol = 1e-10;
  p.reuse = RS_REUSE_ON; /* at rtol 1e-10: within 1e-10 T0/s of every increment from the core */
  p.correction = RS_CORRECTION_OFF;
  rs_roll *ref = wind(&p, n, 1, T);
  p.rtol = 1e-3;
  p.atol = 0.0; /* a scene's default: atol = rtol */
  p.correction = RS_CORRECTION_ON;
  rs_roll *dflt = wind(&p, n, 1, T);
  if (ref && dflt) {
    const double inner = hoop_error(dflt, ref, 0, 10, T, t), bulk = hoop_error(dflt, ref, 10, n, T, t);
    CHECK_LOG("sigma_theta error, layers 0 - 9", inner);
    CHECK_LOG("sigma_theta error, layers 10 - n", bulk);
    CHECK_LT(inner, bulk);
    CHECK_LT(fmax(inner, bulk), 5e-5);
  }
  rs_roll_destroy(&ref);
  rs_roll_destroy(&dflt);
}

static const check_case cases[] = {{"altmann_exact", altmann_exact},
                                   {"pfeiffer_tight", pfeiffer_tight},
                                   {"innermost_hoop", innermost_hoop},
                                   {"vanishes", vanishes}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
