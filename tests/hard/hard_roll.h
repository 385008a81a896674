/* Checks shared by the roll engine's hard cases (test_hard.c: stiffness and size at their
 * extremes; test_hard_load.c: tensions, laws and failures): finiteness, the bounds of a roll
 * wound at constant tension, a profile's distance, convergence in rtol, Altmann's closed
 * form. Needs check.h and roll_helpers.h included first. */
#ifndef RS_TESTS_HARD_ROLL_H
#define RS_TESTS_HARD_ROLL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "roll/roll.h"

static inline int all_finite(const rs_roll *roll)
{
  int n = rs_roll_layers(roll);
  const double *sr = rs_roll_sigma_r(roll), *st = rs_roll_sigma_theta(roll);
  for (int j = 0; j < n; ++j)
    if (!isfinite(sr[j]) || !isfinite(st[j])) return 0;
  return isfinite(rs_roll_core_pressure(roll));
}

/* Bounds of a roll wound at constant tension T (docs/robustness.md derives them from the
 * Riccati form, u = 1 + w: u' = g^2 - u^2, u(x_c) = 1 + kc):
 *  - every increment is compressive, ds = -(T/s) e^(L - L(s)) < 0: the pressure of layer j
 *    is at least its own layer's T/s_j, and the core pressure is > 0;
 *  - with kc >= -1 (a core no softer than rigid with nu < 0 makes it) u stays >= 0, so the
 *    hoop increment ds u is <= 0: sigma_theta_j <= T/t;
 *  - where moreover g >= 1 (E_r <= E_theta) u rises through 1 once and L dips by at most
 *    ln 2 (u >= tanh(x - x_c)), so |ds| <= 2 T/s: P_j <= 2 sum_{k >= j} T/s_k, the same
 *    for the core (`upper` asks for this one; a rigid core nearly reaches the factor 2).
 * The outer layer carries exactly -T/s and T/t. Returns the core pressure / sum_k T/s_k. */
static inline double check_bounds(const rs_roll *roll, const rs_roll_params *p, double T,
                                  int upper)
{
  /* the loads sit at the nodes s_j, j = 1..n (Hakiel) or 0..n-1 (beneath: node 0 is the
   * core, and the outermost layer's outer face is free) */
  const int n = rs_roll_layers(roll), beneath = p->placement == RS_LOAD_BENEATH;
  const double t = p->caliper;
  const double *sr = rs_roll_sigma_r(roll), *st = rs_roll_sigma_theta(roll);
  double sum = 0.0;
  int bad_low = 0, bad_high = 0, bad_hoop = 0;
  for (int j = n - 1; j >= 0; --j) {
    double s = rs_roll_layer_radius(roll, j), P = -sr[j];
    if (beneath && j == n - 1) {
      if (!(P == 0.0)) ++bad_low;
      continue;
    }
    sum += T / s;
    if (!(P >= (T / s) * (1.0 - 1e-12))) ++bad_low;
    if (upper && !(P <= 2.0 * sum)) ++bad_high;
    if (!(st[j] <= (T / t) * (1.0 + 1e-12))) ++bad_hoop;
  }
  if (beneath) sum += T / p->core_radius;
  CHECK(bad_low == 0);
  CHECK(bad_high == 0);
  CHECK(bad_hoop == 0);
  CHECK(rs_roll_core_pressure(roll) > 0.0);
  if (upper) CHECK(rs_roll_core_pressure(roll) <= 2.0 * sum);
  double s = rs_roll_outer_radius(roll);
  if (beneath)
    CHECK(sr[n - 1] == 0.0);
  else
    CHECK_CLOSE(sr[n - 1], -T / s, 1e-14);
  CHECK_CLOSE(st[n - 1], T / t, 1e-14);
  return rs_roll_core_pressure(roll) / sum;
}

/* max over layers of |a - b| / max|b| (sigma_r profiles), and the core pressures */
static inline double profile_diff(const rs_roll *a, const rs_roll *b)
{
  int n = rs_roll_layers(a);
  const double *x = rs_roll_sigma_r(a), *y = rs_roll_sigma_r(b);
  double d = 0.0, m = 0.0;
  for (int j = 0; j < n; ++j) {
    d = fmax(d, fabs(x[j] - y[j]));
    m = fmax(m, fabs(y[j]));
  }
  return d / m;
}

/* Winds the roll again at the two looser rtols: the sigma_r error against `ref` (a much
 * tighter rtol) must fall as rtol does, and be below 1% at the loosest. */
static inline void converges_in_rtol(const rs_roll_params *base, int n, double T,
                                     const double rtols[2], const rs_roll *ref)
{
  rs_roll_params p = *base;
  double err[2];
  for (int i = 0; i < 2; ++i) {
    p.rtol = rtols[i];
    rs_roll *r = wind(&p, n, 1, T);
    if (!r) return;
    err[i] = profile_diff(r, ref);
    printf("  rtol %-8g max |sigma_r - ref| / max|ref| = %.17g\n", rtols[i], err[i]);
    rs_roll_destroy(&r);
  }
  CHECK_LT(err[1], err[0]);
  CHECK_LT(err[0], 1e-2);
}

/* Engine vs Altmann for a linear law, every layer; returns the max relative error of
 * sigma_r (and checks the core pressure to rtol_check). */
static inline double vs_altmann(const rs_roll_params *p, int n, double T, double rtol_check,
                                double *core_engine)
{
  rs_roll *roll = wind(p, n, 1, T);
  if (!roll) return INFINITY;
  double g = sqrt(p->E_theta / p->radial.E_r);
  double kc = (isinf(p->core_stiffness) ? 0.0 : p->E_theta / p->core_stiffness) + p->nu_rtheta - 1;
  double *sr = malloc((size_t)n * sizeof(double)), *st = malloc((size_t)n * sizeof(double)), core;
  altmann_roll(g, kc, p->core_radius, p->caliper, n, T, sr, st, &core, p->placement);
  const double *er = rs_roll_sigma_r(roll), *et = rs_roll_sigma_theta(roll);
  double max_r = 0.0, max_t = 0.0;
  for (int j = 0; j < n; ++j) {
    max_r = fmax(max_r, fabs(er[j] - sr[j]) / fabs(sr[j]));
    max_t = fmax(max_t, fabs(et[j] - st[j]) / (T / p->caliper));
  }
  CHECK_LOG("g", g);
  CHECK_LOG("core pressure, engine (Pa)", rs_roll_core_pressure(roll));
  CHECK_LOG("core pressure, Altmann (Pa)", core);
  CHECK_LOG("max rel error sigma_r", max_r);
  CHECK_LOG("max error sigma_theta / (T/t)", max_t);
  CHECK(all_finite(roll));
  if (core > 1e-300) CHECK_CLOSE(rs_roll_core_pressure(roll), core, rtol_check);
  else CHECK_ABS(rs_roll_core_pressure(roll), core, 1e-300);
  CHECK_LT(max_r, rtol_check);
  CHECK_LT(max_t, rtol_check);
  if (core_engine) *core_engine = rs_roll_core_pressure(roll);
  free(sr);
  free(st);
  rs_roll_destroy(&roll);
  return max_r;
}

#endif
