/* Radial (stack) modulus laws E_r(P): the tangent modulus of the wound stack in the
 * radial direction at interlayer pressure P (Pa, compression positive). */
#include <math.h>
#include <stdint.h>

#include "util/bracket.h"
#include "util/float_flags.h"
#include "util/vector_clones.h"

#include "reelsim/material.h"
#include "util/error.h"

/* Fritsch & Carlson (1980) monotone cubic slopes: harmonic-mean interior slopes,
 * zero where the data change direction, one-sided three-point ends clipped to keep
 * the interpolant monotone between points. */
static void pchip_slopes(int n, const double *x, const double *y, double *d)
{
  if (n == 1) {
    d[0] = 0.0;
    return;
  }
  if (n == 2) {
    d[0] = d[1] = (y[1] - y[0]) / (x[1] - x[0]);
    return;
  }
  for (int i = 1; i < n - 1; ++i) {
    double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    double s0 = (y[i] - y[i - 1]) / h0, s1 = (y[i + 1] - y[i]) / h1;
    if (s0 * s1 <= 0.0) {
      d[i] = 0.0;
    } else {
      double w0 = 2.0 * h1 + h0, w1 = h1 + 2.0 * h0;
      d[i] = (w0 + w1) / (w0 / s0 + w1 / s1);
    }
  }
  for (int e = 0; e < 2; ++e) {
    int i0 = e == 0 ? 0 : n - 1, i1 = e == 0 ? 1 : n - 2, i2 = e == 0 ? 2 : n - 3;
    double h0 = fabs(x[i1] - x[i0]), h1 = fabs(x[i2] - x[i1]);
    double s0 = (y[i1] - y[i0]) / (x[i1] - x[i0]), s1 = (y[i2] - y[i1]) / (x[i2] - x[i1]);
    double de = ((2.0 * h0 + h1) * s0 - h0 * s1) / (h0 + h1);
    if (de * s0 <= 0.0)
      de = 0.0;
    else if (s0 * s1 <= 0.0 && fabs(de) > fabs(3.0 * s0))
      de = 3.0 * s0;
    d[i0] = de;
  }
}

rs_status rs_radial_law_prepare(rs_radial_law *law)
{
  switch (law->law) {
  case RS_RADIAL_LINEAR:
    if (!(law->E_r > 0.0) || !isfinite(law->E_r))
      return RS_ERROR(RS_ERR_INPUT, "radial.E_r must be a positive modulus (got %g Pa)", law->E_r);
    return RS_OK;
  case RS_RADIAL_PFEIFFER:
    if (!(law->K1 > 0.0) || !isfinite(law->K1))
      return RS_ERROR(RS_ERR_INPUT, "radial.K1 must be > 0 Pa (got %g)", law->K1);
    if (!(law->K2 > 0.0) || !isfinite(law->K2))
      return RS_ERROR(RS_ERR_INPUT, "radial.K2 must be > 0 (got %g)", law->K2);
    return RS_OK;
  case RS_RADIAL_HAKIEL:
    if (law->n_coef < 1 || law->n_coef > RS_HAKIEL_MAX_COEF)
      return RS_ERROR(RS_ERR_INPUT, "radial.C must have 1 to %d coefficients (got %d)",
                      RS_HAKIEL_MAX_COEF, law->n_coef);
    if (!(law->C[0] > 0.0))
      return RS_ERROR(RS_ERR_INPUT, "radial.C[0] (E_r at zero pressure) must be > 0 Pa (got %g)",
                      law->C[0]);
    for (int i = 0; i < law->n_coef; ++i)
      if (!isfinite(law->C[i]))
        return RS_ERROR(RS_ERR_INPUT, "radial.C[%d] is not a finite number", i);
    return RS_OK;
  case RS_RADIAL_TABLE:
    if (law->n_points < 1 || law->n_points > RS_TABLE_MAX)
      return RS_ERROR(RS_ERR_INPUT, "radial.points must have 1 to %d [P, E_r] pairs (got %d)",
                      RS_TABLE_MAX, law->n_points);
    for (int i = 0; i < law->n_points; ++i) {
      if (!(law->P[i] >= 0.0) || !isfinite(law->P[i]))
        return RS_ERROR(RS_ERR_INPUT, "radial.points[%d]: pressure must be >= 0 (got %g)", i,
                        law->P[i]);
      if (!(law->E[i] > 0.0) || !isfinite(law->E[i]))
        return RS_ERROR(RS_ERR_INPUT, "radial.points[%d]: E_r must be > 0 (got %g)", i, law->E[i]);
      if (i > 0 && !(law->P[i] > law->P[i - 1]))
        return RS_ERROR(RS_ERR_INPUT,
                        "radial.points must be sorted by strictly increasing pressure "
                        "(points[%d].P = %g after %g)",
                        i, law->P[i], law->P[i - 1]);
    }
    pchip_slopes(law->n_points, law->P, law->E, law->slope);
    return RS_OK;
  }
  return RS_ERROR(RS_ERR_INPUT, "unknown radial law %d", (int)law->law);
}

/* Pfeiffer's tangent modulus K2 (P + K1) at P >= 0 (a layer never pulls on its
 * neighbour: separation = no stiffness gain) */
static inline double pfeiffer_modulus(double K1, double K2, double P)
{
  return K2 * ((P < 0.0 ? 0.0 : P) + K1);
}

/* The same law over an array: one dispatch, loops that vectorise. */
void rs_radial_modulus_n(const rs_radial_law *law, const double *restrict P, double *restrict E,
                         int n)
{
  switch (law->law) {
  case RS_RADIAL_LINEAR:
    for (int i = 0; i < n; ++i) E[i] = law->E_r;
    return;
  case RS_RADIAL_PFEIFFER: {
    const double K1 = law->K1, K2 = law->K2;
    for (int i = 0; i < n; ++i) E[i] = pfeiffer_modulus(K1, K2, P[i]);
    return;
  }
  case RS_RADIAL_HAKIEL: { /* Horner over the nodes: a plain loop that vectorises */
    const int m = law->n_coef;
    const double *C = law->C;
    if (m == 3) { /* the usual quadratic, in one pass */
      const double c0 = C[0], c1 = C[1], c2 = C[2];
      for (int i = 0; i < n; ++i) {
        const double p = P[i] > 0.0 ? P[i] : 0.0;
        E[i] = c0 + p * (c1 + p * c2);
      }
      return;
    }
    for (int i = 0; i < n; ++i) E[i] = C[m - 1];
    for (int c = m - 2; c >= 0; --c) {
      const double Cc = C[c];
      for (int i = 0; i < n; ++i) E[i] = E[i] * (P[i] > 0.0 ? P[i] : 0.0) + Cc;
    }
    return;
  }
  default:
    for (int i = 0; i < n; ++i) E[i] = rs_radial_modulus(law, P[i]);
    return;
  }
}

/* rs_radial_modulus_n at P = -sigma, checked. The check's flag is read from the moduli's
 * bits (util/float_flags.h), so that the loops vectorise; they are the same operations as
 * rs_radial_modulus_n's, so the same moduli bit for bit. */
RS_VECTOR_CLONES static int modulus_stress_pass(const rs_radial_law *law,
                                               const double *restrict sigma, double *restrict P,
                                               double *restrict E, int n)
{
  uint64_t bad = 0; /* the checks' flags from the moduli's bits: the loops vectorise */
  if (law->law == RS_RADIAL_PFEIFFER) {
    const double K1 = law->K1, K2 = law->K2;
    for (int i = 0; i < n; ++i) {
      const double p = -sigma[i], v = pfeiffer_modulus(K1, K2, p);
      P[i] = p;
      E[i] = v;
      bad |= rs_flag_not_positive_finite(v);
    }
  } else if (law->law == RS_RADIAL_HAKIEL && law->n_coef == 3) {
    const double c0 = law->C[0], c1 = law->C[1], c2 = law->C[2];
    for (int i = 0; i < n; ++i) {
      const double p = -sigma[i], q = p > 0.0 ? p : 0.0, v = c0 + q * (c1 + q * c2);
      P[i] = p;
      E[i] = v;
      bad |= rs_flag_not_positive_finite(v);
    }
  } else {
    for (int i = 0; i < n; ++i) P[i] = -sigma[i];
    rs_radial_modulus_n(law, P, E, n);
    for (int i = 0; i < n; ++i) bad |= rs_flag_not_positive_finite(E[i]);
  }
  for (int i = 0; rs_flag_raised(bad) && i < n; ++i)
    if (!(E[i] > 0.0 && E[i] < INFINITY)) return i;
  return -1;
}

int rs_radial_modulus_stress_n(const rs_radial_law *law, const double *restrict sigma,
                               double *restrict P, double *restrict E, int n)
{
  return modulus_stress_pass(law, sigma, P, E, n);
}

/* E_r(P), Pa:
 *   linear    E_r
 *   pfeiffer  K2 (P + K1)                    (Pfeiffer 1968: P = K1 (exp(K2 eps) - 1))
 *   hakiel    sum_i C_i P^i                  (Hakiel 1987)
 *   table     monotone cubic Hermite through (P_i, E_i), end values held outside. */
double rs_radial_modulus(const rs_radial_law *law, double P)
{
  if (P < 0.0) P = 0.0; /* a layer never pulls on its neighbour: separation = no stiffness gain */
  switch (law->law) {
  case RS_RADIAL_LINEAR: return law->E_r;
  case RS_RADIAL_PFEIFFER: return pfeiffer_modulus(law->K1, law->K2, P);
  case RS_RADIAL_HAKIEL: {
    double e = 0.0;
    for (int i = law->n_coef - 1; i >= 0; --i) e = e * P + law->C[i];
    return e;
  }
  case RS_RADIAL_TABLE: {
    int n = law->n_points;
    if (n == 1 || P <= law->P[0]) return law->E[0];
    if (P >= law->P[n - 1]) return law->E[n - 1];
    int lo = rs_bracket(law->P, n, P), hi = lo + 1;
    double h = law->P[hi] - law->P[lo], s = (P - law->P[lo]) / h;
    double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    return h00 * law->E[lo] + h10 * h * law->slope[lo] + h01 * law->E[hi] + h11 * h * law->slope[hi];
  }
  }
  return NAN;
}

/* The stack's strain at pressure P (compression positive), loaded from zero:
 *     eps(P) = integral over [0, P] of dp / E_r(p)                      (1)
 * the tangent modulus being dP/d eps. What a stack test measures (strain against pressure)
 * and what a layer of the roll at pressure P is compressed by. Gauss-Legendre (8 points)
 * on panels graded geometrically towards 0 (P 2^-k, k = 0..30: the laws' 1/E_r varies
 * most at low pressure), each split at the table's points (the monotone cubic is C^1
 * only there); below P 2^-30 the zero-pressure modulus. Linear: P/E_r exactly. */
/* the 8-point Gauss-Legendre rule on [-1, 1]: the abscissae +-x[i] and their weights w[i] */
static const double gl8_x[4] = {0.18343464249564980, 0.52553240991632899, 0.79666647741362674,
                                0.96028985649753623};
static const double gl8_w[4] = {0.36268378337836198, 0.31370664587788729, 0.22238103445337447,
                                0.10122853629037626};

/* the panel [a, b]'s eight Gauss points, in the pairs c - h x_i, c + h x_i */
static void gl8_points(double a, double b, double pts[8])
{
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  for (int i = 0; i < 4; ++i) {
    pts[2 * i] = c - h * gl8_x[i];
    pts[2 * i + 1] = c + h * gl8_x[i];
  }
}

/* the integral over the panel [a, b] of 1/E_r, from the moduli E at its gl8_points */
static double gl8_sum(double a, double b, const double E[8])
{
  double s = 0.0;
  for (int i = 0; i < 4; ++i) s += gl8_w[i] * (1.0 / E[2 * i] + 1.0 / E[2 * i + 1]);
  return s * (0.5 * (b - a));
}

static double strain_panel(const rs_radial_law *law, double a, double b)
{
  double pts[8], E[8];
  gl8_points(a, b, pts);
  for (int k = 0; k < 8; ++k) E[k] = rs_radial_modulus(law, pts[k]);
  return gl8_sum(a, b, E);
}

double rs_radial_strain_step(const rs_radial_law *law, double a, double b)
{
  if (!(b > a)) return 0.0;
  double eps = 0.0, x = a;
  if (law->law == RS_RADIAL_TABLE)
    for (int i = 0; i < law->n_points; ++i)
      if (law->P[i] > x && law->P[i] < b) {
        eps += strain_panel(law, x, law->P[i]);
        x = law->P[i];
      }
  return eps + strain_panel(law, x, b);
}

/* rs_radial_strain_step a block of steps at a time: their Gauss points' moduli in one call
 * (rs_radial_modulus_n, which gives what rs_radial_modulus gives point by point), then
 * each step's sum in strain_panel's order. A table's steps are split at its points: one
 * by one. */
void rs_radial_strain_steps(const rs_radial_law *law, const double *P, int n, double *d)
{
  enum { STEPS = 64 };
  if (law->law == RS_RADIAL_TABLE) {
    for (int i = 0; i < n; ++i) d[i] = rs_radial_strain_step(law, P[i], P[i + 1]);
    return;
  }
  double pts[8 * STEPS], E[8 * STEPS];
  for (int i0 = 0; i0 < n; i0 += STEPS) {
    const int m = n - i0 < STEPS ? n - i0 : STEPS;
    for (int i = 0; i < m; ++i) gl8_points(P[i0 + i], P[i0 + i + 1], pts + 8 * i);
    rs_radial_modulus_n(law, pts, E, 8 * m);
    for (int i = 0; i < m; ++i) {
      const double a = P[i0 + i], b = P[i0 + i + 1];
      d[i0 + i] = b > a ? 0.0 + gl8_sum(a, b, E + 8 * i) : 0.0;
    }
  }
}

double rs_radial_strain(const rs_radial_law *law, double P)
{
  if (!(P > 0.0)) return 0.0; /* a layer never pulls on its neighbour */
  if (law->law == RS_RADIAL_LINEAR) return P / law->E_r;
  double lo = ldexp(P, -30), eps = lo / rs_radial_modulus(law, 0.0);
  for (int k = 30; k >= 1; --k) eps += rs_radial_strain_step(law, ldexp(P, -k), ldexp(P, -k + 1));
  return eps;
}
