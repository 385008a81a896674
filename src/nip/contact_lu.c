/* The solve with the kept LU factors of the nip system (dgetrf's P A = L U, column-major),
 * what LAPACK's dgetrs does for one right-hand side, with the triangles swept four columns
 * at a time: x is read and written once per four columns instead of once per column
 * (OpenBLAS's dgetrs took ~72 k instructions per solve at n = 192, this ~25 k; it is the
 * preconditioner of every GMRES iteration, docs/performance.md). The same arithmetic up
 * to the order of the sums. */
#include "nip/contact_internal.h"
#include "util/vector_clones.h"

/* y(0..m-1) -= a0 x0 + a1 x1 + a2 x2 + a3 x3 (vectorised: restrict, a multiple of 4 first) */
RS_VECTOR_CLONES static void nipc_sub4_pass(int m, double *restrict y, double x0, double x1,
                                             double x2, double x3, const double *restrict a0,
                                             const double *restrict a1,
                                             const double *restrict a2,
                                             const double *restrict a3)
{
  int m4 = m & ~3;
  for (int i = 0; i < m4; ++i) y[i] -= (a0[i] * x0 + a1[i] * x1) + (a2[i] * x2 + a3[i] * x3);
  for (int i = m4; i < m; ++i) y[i] -= (a0[i] * x0 + a1[i] * x1) + (a2[i] * x2 + a3[i] * x3);
}

void rs_nipc_sub4(int m, double *restrict y, double x0, double x1, double x2, double x3,
                 const double *restrict a0, const double *restrict a1, const double *restrict a2,
                 const double *restrict a3)
{
  nipc_sub4_pass(m, y, x0, x1, x2, x3, a0, a1, a2, a3);
}

void rs_nipc_lu_solve(int n, const double *LU, const lapack_int *ipiv, double *x)
{
#define COLUMN(j) (LU + (size_t)(j) * (size_t)n)
  for (int i = 0; i < n; ++i) { /* the row interchanges, in dgetrf's order */
    int p = (int)ipiv[i] - 1;
    if (p != i) {
      double t = x[i];
      x[i] = x[p];
      x[p] = t;
    }
  }
  /* L y = x, L unit lower triangular: a block of four columns solves its own 4 x 4
   * triangle, then updates the rows below it */
  int j = 0;
  for (; j + 4 <= n; j += 4) {
    const double *c0 = COLUMN(j), *c1 = COLUMN(j + 1), *c2 = COLUMN(j + 2), *c3 = COLUMN(j + 3);
    double x0 = x[j];
    double x1 = x[j + 1] - c0[j + 1] * x0;
    double x2 = x[j + 2] - c0[j + 2] * x0 - c1[j + 2] * x1;
    double x3 = x[j + 3] - c0[j + 3] * x0 - c1[j + 3] * x1 - c2[j + 3] * x2;
    x[j + 1] = x1;
    x[j + 2] = x2;
    x[j + 3] = x3;
    int k = j + 4;
    rs_nipc_sub4(n - k, x + k, x0, x1, x2, x3, c0 + k, c1 + k, c2 + k, c3 + k);
  }
  for (; j < n; ++j) {
    const double *c = COLUMN(j);
    for (int i = j + 1; i < n; ++i) x[i] -= c[i] * x[j];
  }
  /* U z = y, U upper triangular: the columns beyond the last whole block first, one by
   * one, then blocks of four from the end, each its 4 x 4 triangle and the rows above */
  int r = n % 4;
  for (j = n - 1; j >= n - r; --j) {
    const double *c = COLUMN(j);
    x[j] /= c[j];
    for (int i = 0; i < j; ++i) x[i] -= c[i] * x[j];
  }
  for (j = n - r - 4; j >= 0; j -= 4) {
    const double *c0 = COLUMN(j), *c1 = COLUMN(j + 1), *c2 = COLUMN(j + 2), *c3 = COLUMN(j + 3);
    double x3 = x[j + 3] / c3[j + 3];
    double x2 = (x[j + 2] - c3[j + 2] * x3) / c2[j + 2];
    double x1 = (x[j + 1] - c2[j + 1] * x2 - c3[j + 1] * x3) / c1[j + 1];
    double x0 = (x[j] - c1[j] * x1 - c2[j] * x2 - c3[j] * x3) / c0[j];
    x[j] = x0;
    x[j + 1] = x1;
    x[j + 2] = x2;
    x[j + 3] = x3;
    rs_nipc_sub4(j, x, x0, x1, x2, x3, c0, c1, c2, c3);
  }
#undef COLUMN
}

/* d[m] = sum_i c_m[i] x[i] for four columns c_0..c_3: x is loaded once for four, each sum
 * in four partial sums (lanes), so the sweep vectorises */
RS_VECTOR_CLONES static void nipc_dot4_pass(int len, const double *restrict x,
                                             const double *restrict c0, const double *restrict c1,
                                             const double *restrict c2, const double *restrict c3,
                                             double d[4])
{
  double s0[4] = {0, 0, 0, 0}, s1[4] = {0, 0, 0, 0}, s2[4] = {0, 0, 0, 0}, s3[4] = {0, 0, 0, 0};
  int m4 = len & ~3;
  for (int i = 0; i < m4; i += 4)
    for (int l = 0; l < 4; ++l) {
      s0[l] += c0[i + l] * x[i + l];
      s1[l] += c1[i + l] * x[i + l];
      s2[l] += c2[i + l] * x[i + l];
      s3[l] += c3[i + l] * x[i + l];
    }
  for (int i = m4; i < len; ++i) {
    s0[0] += c0[i] * x[i];
    s1[0] += c1[i] * x[i];
    s2[0] += c2[i] * x[i];
    s3[0] += c3[i] * x[i];
  }
  d[0] = (s0[0] + s0[1]) + (s0[2] + s0[3]);
  d[1] = (s1[0] + s1[1]) + (s1[2] + s1[3]);
  d[2] = (s2[0] + s2[1]) + (s2[2] + s2[3]);
  d[3] = (s3[0] + s3[1]) + (s3[2] + s3[3]);
}

void rs_nipc_dot4(int len, const double *restrict x, const double *restrict c0, const double *restrict c1,
                 const double *restrict c2, const double *restrict c3, double d[4])
{
  nipc_dot4_pass(len, x, c0, c1, c2, c3, d);
}

static double dot1(int len, const double *restrict c, const double *restrict x)
{
  double s = 0;
  for (int i = 0; i < len; ++i) s += c[i] * x[i];
  return s;
}

/* x <- A^-T x: U^T y = x (forward), L^T z = y (backward), then the interchanges in reverse;
 * the rows of U^T and L^T are columns of the factors, so four of them are one sweep of dot
 * products (dot4) and a 4 x 4 triangle */
void rs_nipc_lu_solve_t(int n, const double *LU, const lapack_int *ipiv, double *x)
{
#define COLUMN(j) (LU + (size_t)(j) * (size_t)n)
  double d[4];
  int j = 0;
  for (; j + 4 <= n; j += 4) {
    const double *c0 = COLUMN(j), *c1 = COLUMN(j + 1), *c2 = COLUMN(j + 2), *c3 = COLUMN(j + 3);
    rs_nipc_dot4(j, x, c0, c1, c2, c3, d);
    double x0 = (x[j] - d[0]) / c0[j];
    double x1 = (x[j + 1] - d[1] - c1[j] * x0) / c1[j + 1];
    double x2 = (x[j + 2] - d[2] - c2[j] * x0 - c2[j + 1] * x1) / c2[j + 2];
    double x3 = (x[j + 3] - d[3] - c3[j] * x0 - c3[j + 1] * x1 - c3[j + 2] * x2) / c3[j + 3];
    x[j] = x0;
    x[j + 1] = x1;
    x[j + 2] = x2;
    x[j + 3] = x3;
  }
  for (; j < n; ++j) x[j] = (x[j] - dot1(j, COLUMN(j), x)) / COLUMN(j)[j];
  int r = n % 4;
  for (j = n - 4; j >= r; j -= 4) {
    const double *c0 = COLUMN(j), *c1 = COLUMN(j + 1), *c2 = COLUMN(j + 2), *c3 = COLUMN(j + 3);
    int k = j + 4;
    rs_nipc_dot4(n - k, x + k, c0 + k, c1 + k, c2 + k, c3 + k, d);
    double x3 = x[j + 3] - d[3];
    double x2 = x[j + 2] - d[2] - c2[j + 3] * x3;
    double x1 = x[j + 1] - d[1] - c1[j + 2] * x2 - c1[j + 3] * x3;
    double x0 = x[j] - d[0] - c0[j + 1] * x1 - c0[j + 2] * x2 - c0[j + 3] * x3;
    x[j] = x0;
    x[j + 1] = x1;
    x[j + 2] = x2;
    x[j + 3] = x3;
  }
  for (j = r - 1; j >= 0; --j) x[j] -= dot1(n - j - 1, COLUMN(j) + j + 1, x + j + 1);
  for (int i = n - 1; i >= 0; --i) { /* the row interchanges, in reverse order */
    int p = (int)ipiv[i] - 1;
    if (p != i) {
      double t = x[i];
      x[i] = x[p];
      x[p] = t;
    }
  }
#undef COLUMN
}
