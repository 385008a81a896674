/* Buckling of the wound stack as rings on springs (docs/defects.md, section 2 (b)): every
 * layer j a thin ring of bending stiffness D_j (N m per unit width) at its mid radius rho_j
 * carrying the hoop force N_j (N/m, compression positive; a layer in tension stiffens),
 * each joined to the one beneath by the interface's radial spring k_j (Pa/m: E_r / t),
 * the first to the core by k_0 (the core and the first interface in series), the last
 * free. In the mode w_j cos(m theta) the energy per radian is
 *   1/2 sum_j rho_j [D_j (m^2-1)^2 / rho_j^4 - lambda N_j (m^2-1) / rho_j^2] w_j^2
 *   + 1/2 sum_j r_j k_j (w_j - w_(j-1))^2          (w_(-1) = 0, r_j the spring's radius)
 * (the ring on a foundation of Brush & Almroth 1975, layer by layer); the stack buckles at
 * the least load factor lambda that makes this form singular. One ring on one spring gives
 * back N_cr(m) = D (m^2-1)/R^2 + k R^2/(m^2-1). The form is affine in lambda, so the
 * lambdas where it is positive definite are an interval from 0: bisection on the LDL^T
 * pivots of the tridiagonal matrix is exact. */
#include <math.h>
#include <stdlib.h>

#include "reelsim/defects.h"

/* The form at x = m^2 - 1 and load factor lambda: its diagonal a_j and its off-diagonal
 * b_j (between rings j and j + 1), the one formula assemble and definite share. */
static inline double diagonal(const rs_ring_stack *s, int j, double x, double lambda)
{
  const double r2 = s->rho[j] * s->rho[j];
  double a = s->rho[j] * (s->D[j] * x * x / (r2 * r2) - lambda * s->N[j] * x / r2) +
             s->r_spring[j] * s->k[j];
  if (j + 1 < s->n) a += s->r_spring[j + 1] * s->k[j + 1];
  return a;
}

static inline double off_diagonal(const rs_ring_stack *s, int j)
{
  return -s->r_spring[j + 1] * s->k[j + 1];
}

/* Diagonal a_j and off-diagonal b_j (between j and j+1) of the form at (m, lambda). */
static void assemble(const rs_ring_stack *s, double m, double lambda, double *a, double *b)
{
  const double x = m * m - 1.0;
  for (int j = 0; j < s->n; ++j) {
    a[j] = diagonal(s, j, x, lambda);
    if (j + 1 < s->n) b[j] = off_diagonal(s, j);
  }
}

/* 1 when the form at (m, lambda) is positive definite (every LDL^T pivot > 0). The form is
 * built as the pivots go, so that a form found indefinite at layer j costs j layers, not n
 * (most of the bisections' tests, and most of the whole reel's defect assessment). */
static int definite(const rs_ring_stack *s, double m, double lambda)
{
  const double x = m * m - 1.0;
  double d = diagonal(s, 0, x, lambda);
  if (!(d > 0.0)) return 0;
  for (int j = 1; j < s->n; ++j) {
    const double b = off_diagonal(s, j - 1);
    d = diagonal(s, j, x, lambda) - b * b / d;
    if (!(d > 0.0)) return 0;
  }
  return 1;
}

/* The critical load factor of mode m, below `cap` (returns cap when none below it), to
 * the relative tolerance rtol. */
static double mode_factor(const rs_ring_stack *s, double m, double cap, double rtol)
{
  if (definite(s, m, cap)) return cap;
  double lo = 0.0, hi = cap;
  for (int it = 0; it < 200 && hi - lo > rtol * hi; ++it) {
    double mid = 0.5 * (lo + hi);
    if (definite(s, m, mid)) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

/* Inverse iteration just below the critical factor: the mode's shape, its peak layer. */
static int mode_peak(const rs_ring_stack *s, double m, double lambda, double *a, double *b)
{
  const int n = s->n;
  double *x = malloc((size_t)n * sizeof *x), *c = malloc((size_t)n * sizeof *c);
  int peak = 0;
  if (!x || !c) goto done;
  assemble(s, m, lambda * (1.0 - 1e-6), a, b);
  for (int j = 0; j < n; ++j) x[j] = s->N[j] > 0.0 ? 1.0 : 0.0;
  for (int it = 0; it < 6; ++it) { /* Thomas: (a, b) x_new = x */
    c[0] = b && n > 1 ? b[0] / a[0] : 0.0;
    x[0] /= a[0];
    for (int j = 1; j < n; ++j) {
      double den = a[j] - b[j - 1] * c[j - 1];
      c[j] = j + 1 < n ? b[j] / den : 0.0;
      x[j] = (x[j] - b[j - 1] * x[j - 1]) / den;
    }
    for (int j = n - 2; j >= 0; --j) x[j] -= c[j] * x[j + 1];
    double big = 0.0;
    for (int j = 0; j < n; ++j)
      if (fabs(x[j]) > big) big = fabs(x[j]), peak = j;
    if (big > 0.0)
      for (int j = 0; j < n; ++j) x[j] /= big;
  }
done:
  free(x);
  free(c);
  return peak;
}

/* A bound X(lambda) on x = m^2 - 1 above which the form is positive definite at every
 * load factor up to lambda, so that the scan need not test those modes (a mode of short
 * wavelength is held by its rings' bending alone; most of the scan's grid). Row j's
 * diagonal exceeds the sum of its off-diagonals by its ring term
 *   rho_j x (D_j x / rho_j^4 - lambda N_j / rho_j^2)
 * (the springs' terms cancel; the core's spring only adds to row 0); a form whose every
 * row has that margin positive is diagonally dominant, hence positive definite, and its
 * LDL^T pivots computed in floating point stay above the off-diagonals as long as the
 * margin is well above rounding: here at least 1e-6 of the row's terms,
 *   A_j x^2 - B_j x - C_j > 0,  A_j = (1 - eps) D_j / rho_j^3,
 *   B_j = lambda max(N_j + eps |N_j|, 0) / rho_j,  C_j = eps (r_j k_j + r_(j+1) k_(j+1)),
 * true for x above the larger root (a layer in tension counted as unloaded: X then grows
 * with lambda, and a bound made at a larger lambda still holds). So a skipped mode is one
 * definite() would pass: the same scan, the same bits. Infinity when some row has no
 * bending to rely on. */
static double bending_bound(const rs_ring_stack *s, double lambda)
{
  const double eps = 1e-6;
  double X = 0.0;
  for (int j = 0; j < s->n; ++j) {
    const double rho = s->rho[j], A = (1.0 - eps) * s->D[j] / (rho * rho * rho);
    const double B = lambda * fmax(s->N[j] + eps * fabs(s->N[j]), 0.0) / rho;
    double C = s->r_spring[j] * s->k[j];
    if (j + 1 < s->n) C += s->r_spring[j + 1] * s->k[j + 1];
    C *= eps;
    const double x = (B + sqrt(B * B + 4.0 * A * C)) / (2.0 * A);
    if (!(A > 0.0 && rho > 0.0 && C >= 0.0 && isfinite(x))) return INFINITY;
    if (x > X) X = x;
  }
  return X;
}

/* mode_factor on the scan's grid, below the least factor found so far: `best` itself
 * when the mode is above the bending bound (*X, made at *X_at >= best: made again at best
 * only when the older one does not settle the mode) */
static double scan_factor(const rs_ring_stack *s, double m, double best, double *X,
                          double *X_at)
{
  const double x = m * m - 1.0;
  if (x > *X) return best;
  if (*X_at != best) {
    *X = bending_bound(s, best);
    *X_at = best;
    if (x > *X) return best;
  }
  return mode_factor(s, m, best, 1e-4);
}

/* 1 when no ring is in compression (every N_j <= 0, none NaN) */
static int no_compression(const rs_ring_stack *s)
{
  for (int j = 0; j < s->n; ++j)
    if (!(s->N[j] <= 0.0)) return 0;
  return 1;
}

double rs_defect_ring_stack_critical(const rs_ring_stack *s, int *mode, int *peak)
{
  const double cap = 1e12;
  if (mode) *mode = 0;
  if (peak) *peak = 0;
  if (!s || s->n < 1) return cap;
  /* No ring in compression: every entry of the diagonal is then non-decreasing in the load
   * factor and in x = m^2 - 1 (each operation rounds monotonically), and an LDL^T pivot
   * d_j = a_j - b_j^2 / d_(j-1) does not fall as a_j and d_(j-1) rise: a form definite at
   * m = 2, lambda = 0 is definite at every mode and factor the scan would test, which then
   * finds none below the cap: the same answer without the scan's passes. */
  if (no_compression(s) && definite(s, 2.0, 0.0)) return cap;
  double *a = malloc((size_t)s->n * sizeof *a), *b = malloc((size_t)s->n * sizeof *b);
  if (!a || !b) {
    free(a);
    free(b);
    return NAN;
  }
  /* scan m on a grid (every integer to 32, then 4 % steps) to 1e-4, keep the least,
   * look at the integers between its grid neighbours, then bisect the best to 1e-12 */
  double best = cap, prev = 2.0, bm = 0.0, lo_m = 2.0, hi_m = 2.0, X = INFINITY, X_at = NAN;
  for (double m = 2.0; m < 2e6; m = m < 32.0 ? m + 1.0 : floor(m * 1.04)) {
    double f = scan_factor(s, m, best, &X, &X_at);
    if (f < best) {
      best = f;
      bm = m;
      lo_m = prev;
    }
    if (bm == prev) hi_m = m;
    prev = m;
  }
  if (hi_m < bm) hi_m = bm;
  for (double m = lo_m; bm > 0.0 && m <= hi_m; m += 1.0) {
    double f = scan_factor(s, m, best, &X, &X_at);
    if (f < best) best = f, bm = m;
  }
  if (bm > 0.0) best = mode_factor(s, bm, best * (1.0 + 1e-3), 1e-13);
  if (bm > 0.0) {
    if (mode) *mode = (int)bm;
    if (peak) *peak = mode_peak(s, bm, best, a, b);
  }
  free(a);
  free(b);
  return best;
}
