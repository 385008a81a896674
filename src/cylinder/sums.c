/* Closed forms of the subtracted parts of the accelerated series: for a basis function f
 * (hat or box) with cosine coefficients a_n on the circle,
 *   sum_{n>=1} a_n cos(n t) / n^k  and  sum_{n>=1} a_n sin(n t) / n^k,  k = 0, 1, 2,
 * are (1/pi) int f(t') K(t - t') dt' with the classical sums (|u| < 2 pi, u != 0;
 * Abramowitz & Stegun 1964, 4.3.70 and 27.8):
 *   sum cos(nu)      = pi delta(u) - 1/2        sum sin(nu)      = cot(u/2)/2
 *   sum cos(nu)/n    = -ln|2 sin(u/2)|          sum sin(nu)/n    = (pi sgn u - u)/2
 *   sum cos(nu)/n^2  = pi^2/6 - pi|u|/2 + u^2/4 sum sin(nu)/n^2  = Cl2(u) = u - u ln|u| - G(u)
 * Each kernel is split into a part with elementary antiderivatives against the linear
 * pieces of f (1/u, ln|u|, u ln|u|, |u|, sgn u, powers) and a smooth remainder
 *   g(u) = ln(sin(u/2)/(u/2)),  c(u) = cot(u/2)/2 - 1/u,  G(u) = int_0^u g,
 * power series in z = u/(2 pi) from ln(sin x / x) = -sum_k zeta(2k) (x/pi)^(2k) / k,
 * x = u/2 (Abramowitz & Stegun 4.3.71):
 *   g = -sum zeta(2k)/k z^2k,  c = -(1/pi) sum zeta(2k) z^(2k-1),
 *   G = -2 pi sum zeta(2k)/(k (2k+1)) z^(2k+1),
 * whose antiderivatives against 1 and u are integrated term by term, so the remainders
 * against the linear pieces of f are exact sums too (they were 8-point Gauss-Legendre,
 * which agrees to round-off: the integrands are polynomials of degree < 16 to 1e-18 for
 * |u| < 0.4, and 8 times the work). */
#include "cylinder/internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/error.h"

/* zeta(2k), k = 1..30 (for k > 30, 1 + 4^-k + 9^-k is exact in double) */
static const double zeta_even[30] = {
  1.6449340668482264365,
  1.0823232337111381915,
  1.0173430619844491397,
  1.0040773561979443394,
  1.0009945751278180853,
  1.0002460865533080483,
  1.0000612481350587048,
  1.0000152822594086519,
  1.0000038172932649998,
  1.0000009539620338728,
  1.0000002384505027277,
  1.0000000596081890513,
  1.0000000149015548284,
  1.0000000037253340248,
  1.0000000009313274324,
  1.0000000002328311834,
  1.0000000000582077209,
  1.0000000000145519219,
  1.0000000000036379795,
  1.0000000000009094948,
  1.0000000000002273737,
  1.0000000000000568434,
  1.0000000000000142109,
  1.0000000000000035527,
  1.0000000000000008882,
  1.000000000000000222,
  1.0000000000000000555,
  1.0000000000000000139,
  1.0000000000000000035,
  1.0000000000000000009
};

static double zeta2k(int k)
{
  if (k <= 30) return zeta_even[k - 1];
  return 1 + pow(4.0, -k) + pow(9.0, -k);
}

/* The series' coefficients, k = 1..KMAX, filled once (thread-safe: every thread writes
 * the same values; the flag is set last): zeta(2k)/k, zeta(2k)/(k (2k+1)), and those of
 * the antiderivatives (smooth_antider). */
enum { KMAX = 200 };
static double coef_g[KMAX + 1], coef_G[KMAX + 1];
static double coef_g1[KMAX + 1], coef_c1[KMAX + 1], coef_G0[KMAX + 1], coef_G1[KMAX + 1];
static volatile int coef_ready = 0;

static void coef_init(void)
{
  if (coef_ready) return;
  for (int k = 1; k <= KMAX; ++k) {
    coef_g[k] = zeta2k(k) / k;
    coef_G[k] = coef_g[k] / (2 * k + 1);
    coef_g1[k] = coef_g[k] / (2 * k + 2);
    coef_c1[k] = zeta2k(k) / (2 * k + 1);
    coef_G0[k] = coef_G[k] / (2 * k + 2);
    coef_G1[k] = coef_G[k] / (2 * k + 3);
  }
  coef_ready = 1;
}

/* Antiderivatives of the smooth remainders (zero at u = 0), z = u/(2 pi), Z = z^2:
 *   mask 1: out[0] = int g du   = -2 pi    sum zeta(2k)/(k (2k+1)) z^(2k+1)
 *           out[1] = int u g du = -(2 pi)^2 sum zeta(2k)/(k (2k+2)) z^(2k+2)
 *   mask 2: out[2] = int c du   = -sum zeta(2k)/k z^(2k)
 *           out[3] = int u c du = -4 pi sum zeta(2k)/(2k+1) z^(2k+1)
 *           out[4] = int G du   = -(2 pi)^2 sum zeta(2k)/(k (2k+1) (2k+2)) z^(2k+2)
 *           out[5] = int u G du = -(2 pi)^3 sum zeta(2k)/(k (2k+1) (2k+3)) z^(2k+3)
 * The coefficients fall with k, so the sums stop when Z^k is below 1e-18 of the first
 * term's Z (|u| <= 5 pi/4: Z <= 0.4, at most ~45 terms; a nip's |u| < 0.1: 5 - 9). */
static void smooth_antider(double u, unsigned mask, double out[6])
{
  const double tp = 2 * RS_PI;
  double z = u / tp, Z = z * z, pw = Z;
  double g0 = 0, g1 = 0, c0 = 0, c1 = 0, G0 = 0, G1 = 0;
  for (int k = 1; k <= KMAX; ++k) {
    if (mask & 1) {
      g0 += coef_G[k] * pw;
      g1 += coef_g1[k] * pw;
    }
    if (mask & 2) {
      c0 += coef_g[k] * pw;
      c1 += coef_c1[k] * pw;
      G0 += coef_G0[k] * pw;
      G1 += coef_G1[k] * pw;
    }
    if (!(pw >= 1e-18 * Z)) break; /* also u = 0 */
    pw *= Z;
  }
  if (mask & 1) {
    out[0] = -tp * z * g0;
    out[1] = -tp * tp * Z * g1;
  }
  if (mask & 2) {
    out[2] = -c0;
    out[3] = -2 * tp * z * c1;
    out[4] = -tp * tp * Z * G0;
    out[5] = -tp * tp * tp * z * Z * G1;
  }
}

/* Antiderivatives P0 = int K, P1 = int u K for the elementary kernels; mask 1: the kernels
 * of the cos sums (ln|u|, 1, |u|, u^2), mask 2: those of the sin sums (1/u, sgn u, u,
 * u ln|u|). u^p ln|u| is 0 at u = 0. */
enum { K_INV, K_LOG, K_ULOG, K_ABS, K_SGN, K_ONE, K_U, K_U2, K_COUNT };

static void antider(double u, unsigned mask, double P0[K_COUNT], double P1[K_COUNT])
{
  double au = fabs(u), u2 = u * u, lg = u == 0 ? 0 : log(au);
  double ul = u * lg, u2l = u2 * lg, u3l = u2 * ul; /* u^p ln|u| */
  if (mask & 1) {
    P0[K_LOG] = ul - u;
    P1[K_LOG] = 0.5 * u2l - 0.25 * u2;
    P0[K_ABS] = 0.5 * u * au;
    P1[K_ABS] = au * au * au / 3;
    P0[K_ONE] = u;
    P1[K_ONE] = 0.5 * u2;
    P0[K_U2] = u2 * u / 3;
    P1[K_U2] = 0.25 * u2 * u2;
  }
  if (mask & 2) {
    P0[K_INV] = lg; /* finite part; jumps are checked by the caller */
    P1[K_INV] = u;
    P0[K_ULOG] = 0.5 * u2l - 0.25 * u2;
    P1[K_ULOG] = u3l / 3 - u2 * u / 9;
    P0[K_SGN] = au;
    P1[K_SGN] = 0.5 * u * au;
    P0[K_U] = 0.5 * u2;
    P1[K_U] = u2 * u / 3;
  }
}

typedef struct pieces {
  int np;
  double b[3];     /* breakpoints */
  double v[2], s[2]; /* f = v[k] + s[k] (t' - b[k]) on [b[k], b[k+1]] */
} pieces;

static pieces make_pieces(rs_basis basis, double w)
{
  pieces P;
  if (basis == RS_BASIS_HAT) {
    P.np = 2;
    P.b[0] = -w; P.b[1] = 0; P.b[2] = w;
    P.v[0] = 0; P.s[0] = 1 / w;
    P.v[1] = 1; P.s[1] = -1 / w;
  } else {
    P.np = 1;
    P.b[0] = -w; P.b[1] = w; P.b[2] = 0;
    P.v[0] = 1; P.s[0] = 0;
    P.v[1] = 0; P.s[1] = 0;
  }
  return P;
}

double rs_cyl_basis_coef(rs_basis basis, double w, long n)
{
  if (n == 0) return basis == RS_BASIS_HAT ? w / (2 * RS_PI) : w / RS_PI;
  const double y = basis == RS_BASIS_HAT ? 0.5 * (double)n * w : (double)n * w;
  return rs_cyl_basis_coef_sin(basis, w, n, sin(y));
}

/* What a piece boundary at u contributes: the elementary antiderivatives (antider) and
 * the smooth remainders' (smooth_antider), at u = t - b. */
typedef struct sum_point {
  double P0[K_COUNT], P1[K_COUNT], S[6];
} sum_point;

static void point_eval(double u, unsigned mask, sum_point *pt)
{
  antider(u, mask, pt->P0, pt->P1);
  smooth_antider(u, mask, pt->S);
}

/* The sums at t from the pieces' boundary values: at[k] the point u[k] = t - b[k] (k <=
 * np; snapped to 0 within round-off of a breakpoint), ua[k] the same unsnapped, for the
 * piece's value there. ft = f(t) (the mean of the one-sided limits on a jump). */
static int combine(const pieces *P, rs_basis basis, double w, double ft, const double *u,
                   const double *ua, const sum_point *const *at, unsigned mask, double out[6])
{
  double I[K_COUNT] = {0};
  double jumpsum = 0; /* coefficient of ln|0| in the 1/u kernel */
  double gsm[3] = {0, 0, 0};
  static const int jc[4] = {K_LOG, K_ABS, K_ONE, K_U2}, js[4] = {K_INV, K_ULOG, K_SGN, K_U};
  for (int k = 0; k < P->np; ++k) {
    const sum_point *h = at[k], *l = at[k + 1];
    double uhi = u[k], ulo = u[k + 1];
    double A = P->v[k] + P->s[k] * ua[k];
    for (int f = 0; f < 2; ++f) {
      if (!(mask & (1u << f))) continue;
      const int *js_ = f ? js : jc;
      for (int i = 0; i < 4; ++i) {
        int j = js_[i];
        I[j] += A * (h->P0[j] - l->P0[j]) - P->s[k] * (h->P1[j] - l->P1[j]);
      }
    }
    /* f at u = 0 from this piece, with the sign of its ln|u| term */
    if (uhi == 0) jumpsum += A;
    if (ulo == 0) jumpsum -= A;
    /* the smooth remainders against f = A - s u, term by term */
    if (mask & 1) gsm[0] += A * (h->S[0] - l->S[0]) - P->s[k] * (h->S[1] - l->S[1]);
    if (mask & 2) {
      gsm[1] += A * (h->S[2] - l->S[2]) - P->s[k] * (h->S[3] - l->S[3]);
      gsm[2] += A * (h->S[4] - l->S[4]) - P->s[k] * (h->S[5] - l->S[5]);
    }
  }
  double ip = 1 / RS_PI;
  if (mask & 1) {
    out[0] = ft - rs_cyl_basis_coef(basis, w, 0);
    out[1] = ip * (-I[K_LOG] - gsm[0]);
    out[2] = ip * (RS_PI * RS_PI / 6 * I[K_ONE] - 0.5 * RS_PI * I[K_ABS] + 0.25 * I[K_U2]);
  }
  if (mask & 2) {
    out[3] = ip * (I[K_INV] + gsm[1]);
    out[4] = ip * (0.5 * RS_PI * I[K_SGN] - 0.5 * I[K_U]);
    out[5] = ip * (I[K_U] - I[K_ULOG] - gsm[2]);
    if (fabs(jumpsum) > 1e-12) {
      out[3] = copysign(INFINITY, -jumpsum);
      return -1;
    }
  }
  return 0;
}

int rs_cyl_closed_sums_part(rs_basis basis, double w, double t, unsigned mask, double out[6])
{
  coef_init();
  t = rs_cyl_wrap(t);
  pieces P = make_pieces(basis, w);
  double snap = 1e-10 * w, u[3], ua[3];
  sum_point pt[3];
  const sum_point *at[3] = {&pt[0], &pt[1], &pt[2]};
  /* a piece's upper end is the one before's lower end (t - b[k]), evaluated once */
  for (int k = 0; k <= P.np; ++k) {
    ua[k] = u[k] = t - P.b[k];
    if (fabs(u[k]) < snap) u[k] = 0;
    point_eval(u[k], mask, &pt[k]);
  }
  double ft;
  if (basis == RS_BASIS_HAT) {
    ft = fmax(0.0, 1 - fabs(t) / w);
  } else {
    double e = fabs(t) - w;
    ft = fabs(e) < snap ? 0.5 : (e < 0 ? 1.0 : 0.0);
  }
  return combine(&P, basis, w, ft, u, ua, at, mask, out);
}

rs_status rs_cyl_closed_sums_grid(rs_basis basis, double w, int nk, const long *h2,
                                  unsigned mask, double (*out)[6])
{
  coef_init();
  if (nk <= 0) return RS_OK;
  pieces P = make_pieces(basis, w);
  /* the grid's unit: half a cell, the breakpoints +-2, 0 (hat) or +-1 (box) units */
  const long step = basis == RS_BASIS_HAT ? 2 : 1;
  const double unit = basis == RS_BASIS_HAT ? 0.5 * w : w;
  long lo = h2[0], hi = h2[0];
  for (int i = 1; i < nk; ++i) {
    lo = h2[i] < lo ? h2[i] : lo;
    hi = h2[i] > hi ? h2[i] : hi;
  }
  lo -= step;
  hi += step;
  size_t np = (size_t)(hi - lo + 1);
  sum_point *pts = malloc(np * sizeof *pts);
  unsigned char *done = calloc(np, 1);
  if (!pts || !done) {
    free(pts);
    free(done);
    return RS_ERROR(RS_ERR_MEMORY, "closed sums at %d offsets", nk);
  }
  for (int i = 0; i < nk; ++i) {
    double u[3];
    const sum_point *at[3];
    for (int k = 0; k <= P.np; ++k) {
      long j = h2[i] - (k == 0 ? -step : k == P.np ? step : 0);
      u[k] = (double)j * unit;
      size_t q = (size_t)(j - lo);
      if (!done[q]) {
        point_eval(u[k], mask, &pts[q]);
        done[q] = 1;
      }
      at[k] = &pts[q];
    }
    long ah = labs(h2[i]);
    double ft = basis == RS_BASIS_HAT ? (ah < 2 ? 1 - 0.5 * (double)ah : 0.0)
                                      : (ah < 1 ? 1.0 : ah == 1 ? 0.5 : 0.0);
    combine(&P, basis, w, ft, u, u, at, mask, out[i]);
  }
  free(pts);
  free(done);
  return RS_OK;
}

int rs_cyl_closed_sums(rs_basis basis, double w, double t, double out[6])
{
  return rs_cyl_closed_sums_part(basis, w, t, 3u, out);
}
