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
 * integrated by 8-point Gauss-Legendre on each piece; the remainders are summed from
 * ln(sin x / x) = -sum_k zeta(2k) (x/pi)^(2k) / k, x = u/2. */
#include "cylinder/internal.h"

#include <math.h>

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

/* zeta(2k)/k and zeta(2k)/(k (2k+1)), k = 1..KMAX, filled once (thread-safe: every
 * thread writes the same values; the flag is set last). */
enum { KMAX = 200 };
static double coef_g[KMAX + 1], coef_G[KMAX + 1];
static volatile int coef_ready = 0;

static void coef_init(void)
{
  if (coef_ready) return;
  for (int k = 1; k <= KMAX; ++k) {
    coef_g[k] = zeta2k(k) / k;
    coef_G[k] = coef_g[k] / (2 * k + 1);
  }
  coef_ready = 1;
}

/* The smooth remainders at u (|u| <= 5 pi/4): g for the cos sums (mask 1), c and G for
 * the sin sums (mask 2). */
static void smooth_parts(double u, unsigned mask, double *g, double *c, double *G)
{
  double x = 0.5 * u, y2 = (x / RS_PI) * (x / RS_PI);
  double sg = 0, sc = 0, sG = 0, pw = 1;
  for (int k = 1; k <= KMAX; ++k) {
    double tc = zeta2k(k) * pw; /* zeta(2k) y2^(k-1) */
    pw *= y2;
    sc += tc;
    sg += coef_g[k] * pw; /* zeta(2k) y2^k / k */
    sG += coef_G[k] * pw;
    if (tc < 1e-18 * sc) break;
  }
  if (mask & 1) *g = -sg;
  if (mask & 2) {
    *c = -x / (RS_PI * RS_PI) * sc;
    *G = -2 * x * sG;
  }
}

static const double gl_x[8] = {-0.96028985649753623168, -0.79666647741362673959,
                               -0.52553240991632898582, -0.18343464249564980494,
                               0.18343464249564980494,  0.52553240991632898582,
                               0.79666647741362673959,  0.96028985649753623168};
static const double gl_w[8] = {0.10122853629037625915, 0.22238103445337447054,
                               0.31370664587788728734, 0.36268378337836198297,
                               0.36268378337836198297, 0.31370664587788728734,
                               0.22238103445337447054, 0.10122853629037625915};

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
  if (basis == RS_BASIS_HAT) {
    if (n == 0) return w / (2 * RS_PI);
    double y = 0.5 * (double)n * w, sc = sin(y) / y;
    return w / RS_PI * sc * sc;
  }
  if (n == 0) return w / RS_PI;
  return 2.0 / (RS_PI * (double)n) * sin((double)n * w);
}

int rs_cyl_closed_sums_part(rs_basis basis, double w, double t, unsigned mask, double out[6])
{
  coef_init();
  t = remainder(t, 2 * RS_PI);
  pieces P = make_pieces(basis, w);
  double snap = 1e-10 * w;
  double I[K_COUNT] = {0};
  double jumpsum = 0; /* coefficient of ln|0| in the 1/u kernel */
  double gsm[3] = {0, 0, 0};
  for (int k = 0; k < P.np; ++k) {
    double uhi = t - P.b[k], ulo = t - P.b[k + 1];
    if (fabs(uhi) < snap) uhi = 0;
    if (fabs(ulo) < snap) ulo = 0;
    double A = P.v[k] + P.s[k] * (t - P.b[k]);
    double P0h[K_COUNT], P1h[K_COUNT], P0l[K_COUNT], P1l[K_COUNT];
    antider(uhi, mask, P0h, P1h);
    antider(ulo, mask, P0l, P1l);
    static const int jc[4] = {K_LOG, K_ABS, K_ONE, K_U2}, js[4] = {K_INV, K_ULOG, K_SGN, K_U};
    for (int f = 0; f < 2; ++f) {
      if (!(mask & (1u << f))) continue;
      const int *js_ = f ? js : jc;
      for (int i = 0; i < 4; ++i) {
        int j = js_[i];
        I[j] += A * (P0h[j] - P0l[j]) - P.s[k] * (P1h[j] - P1l[j]);
      }
    }
    /* f at u = 0 from this piece, with the sign of its ln|u| term */
    if (uhi == 0) jumpsum += A;
    if (ulo == 0) jumpsum -= A;
    /* smooth remainders by Gauss-Legendre in t' */
    double h = 0.5 * (P.b[k + 1] - P.b[k]), m = 0.5 * (P.b[k + 1] + P.b[k]);
    for (int q = 0; q < 8; ++q) {
      double tp = m + h * gl_x[q];
      double f = (P.v[k] + P.s[k] * (tp - P.b[k])) * h * gl_w[q];
      double g = 0, c = 0, G = 0;
      smooth_parts(t - tp, mask, &g, &c, &G);
      gsm[0] += f * g;
      gsm[1] += f * c;
      gsm[2] += f * G;
    }
  }
  double ip = 1 / RS_PI;
  if (mask & 1) {
    /* f(t) (mean of the one-sided limits on a jump) and a_0 */
    double ft;
    if (basis == RS_BASIS_HAT) {
      ft = fmax(0.0, 1 - fabs(t) / w);
    } else {
      double e = fabs(t) - w;
      ft = fabs(e) < snap ? 0.5 : (e < 0 ? 1.0 : 0.0);
    }
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

int rs_cyl_closed_sums(rs_basis basis, double w, double t, double out[6])
{
  return rs_cyl_closed_sums_part(basis, w, t, 3u, out);
}
