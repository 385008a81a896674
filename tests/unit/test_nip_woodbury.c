/* The rank-k correction of the nip's kept LU (src/nip/contact_woodbury.c) against a fresh
 * factorization of the corrected matrix: B = B0 with k rows replaced, its solve and its
 * transposed solve to ~1e-12, its 1-norm exactly, the Hager-Higham estimate of ||B^-1||_1
 * against LAPACK's dgecon on B's own LU and against the exact norm of the inverse, and the
 * fallback: a singular capacitance matrix (a replaced row equal to a kept one) and more
 * rows than the cache holds are refused (k = 0, the caller refactors). */
#include "check.h"
#include "nip/contact_internal.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double entry(unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return ((double)((*s >> 8) & 0xffff) / 65536.0) - 0.5;
}

typedef struct {
  int n, k;
  double *B0, *LU, *B, *BLU, *colsum;
  lapack_int *ipiv, *bpiv;
  int rows[32];
  rs_nipc_wb wb;
} setup;

/* B0 (pivoting needed: the diagonal no larger than the rest), its LU; B with rows
 * rows[0..k-1] = 3 i + 1 replaced by new random rows; the correction set */
static int make(setup *S, int n, int k, unsigned seed, int cap)
{
  memset(S, 0, sizeof *S);
  S->n = n;
  S->k = k;
  size_t nn = (size_t)n * n;
  S->B0 = malloc(nn * sizeof(double));
  S->LU = malloc(nn * sizeof(double));
  S->B = malloc(nn * sizeof(double));
  S->BLU = malloc(nn * sizeof(double));
  S->colsum = calloc((size_t)n, sizeof(double));
  S->ipiv = malloc((size_t)n * sizeof(lapack_int));
  S->bpiv = malloc((size_t)n * sizeof(lapack_int));
  unsigned s = seed;
  for (int c = 0; c < n; ++c)
    for (int r = 0; r < n; ++r) {
      double v = entry(&s) + (r == c ? 0.5 : 0.0);
      S->B0[(size_t)c * n + r] = v;
      S->colsum[c] += fabs(v);
    }
  memcpy(S->LU, S->B0, nn * sizeof(double));
  memcpy(S->B, S->B0, nn * sizeof(double));
  CHECK(LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, S->LU, n, S->ipiv) == 0);
  CHECK(rs_nipc_wb_alloc(&S->wb, n, cap) == RS_OK);
  for (int i = 0; i < k; ++i) {
    S->rows[i] = (3 * i + 1) % n;
    for (int c = 0; c < n; ++c) S->B[(size_t)c * n + S->rows[i]] = entry(&s) + (c == S->rows[i]);
    if (i < cap) /* the new rows, as the caller writes them (more than cap: refused unread) */
      for (int c = 0; c < n; ++c) rs_nipc_wb_row(&S->wb, i)[c] = S->B[(size_t)c * n + S->rows[i]];
  }
  memcpy(S->BLU, S->B, nn * sizeof(double));
  CHECK(LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, S->BLU, n, S->bpiv) == 0);
  return rs_nipc_wb_set(&S->wb, S->LU, S->ipiv, S->B0, k, S->rows, 1e-8);
}

static void unmake(setup *S)
{
  rs_nipc_wb_free(&S->wb);
  free(S->B0);
  free(S->LU);
  free(S->B);
  free(S->BLU);
  free(S->colsum);
  free(S->ipiv);
  free(S->bpiv);
}

/* largest |x - y| / max |y| of the corrected solve against B's own LU */
static double solve_error(setup *S, char trans, unsigned seed)
{
  const int n = S->n;
  double *x = malloc((size_t)n * sizeof *x), *y = malloc((size_t)n * sizeof *y);
  unsigned s = seed;
  for (int r = 0; r < n; ++r) x[r] = y[r] = entry(&s);
  CHECK(LAPACKE_dgetrs(LAPACK_COL_MAJOR, trans, n, 1, S->BLU, n, S->bpiv, y, n) == 0);
  if (trans == 'N')
    rs_nipc_wb_solve(&S->wb, S->LU, S->ipiv, x);
  else
    rs_nipc_wb_solve_t(&S->wb, S->LU, S->ipiv, x);
  double mx = 0, d = 0;
  for (int r = 0; r < n; ++r) {
    mx = fmax(mx, fabs(y[r]));
    d = fmax(d, fabs(x[r] - y[r]));
  }
  free(x);
  free(y);
  return d / mx;
}

static const int SIZES[][2] = {{5, 1}, {5, 3}, {13, 4}, {64, 1}, {64, 7}, {192, 1}, {192, 4}, {192, 12}, {192, 16}};
enum { NSIZES = sizeof SIZES / sizeof SIZES[0] };

static void solve_against_fresh_lu(void)
{
  double worst = 0, worst_t = 0;
  for (int c = 0; c < NSIZES; ++c) {
    setup S;
    CHECK(make(&S, SIZES[c][0], SIZES[c][1], 777u + (unsigned)c, 16) == 0);
    CHECK(S.wb.k == SIZES[c][1]);
    worst = fmax(worst, solve_error(&S, 'N', 99u + (unsigned)c));
    worst_t = fmax(worst_t, solve_error(&S, 'T', 199u + (unsigned)c));
    /* the cached columns serve a second, different correction of a subset of the rows */
    for (int i = 0; i < S.k / 2 + 1; ++i) {
      double *d = rs_nipc_wb_row(&S.wb, i);
      for (int cc = 0; cc < S.n; ++cc) d[cc] = S.B[(size_t)cc * S.n + S.rows[i]];
    }
    CHECK(rs_nipc_wb_set(&S.wb, S.LU, S.ipiv, S.B0, S.k / 2 + 1, S.rows, 1e-8) == 0);
    CHECK(S.wb.nslots == S.k);
    unmake(&S);
  }
  CHECK_LOG("largest |x - x_fresh| / max |x_fresh|, B x = b", worst);
  CHECK_LOG("largest |x - x_fresh| / max |x_fresh|, B^T x = b", worst_t);
  CHECK_LT(worst, 1e-12);
  CHECK_LT(worst_t, 1e-12);
}

static void norm_and_estimate(void)
{
  double worst_norm = 0, worst_dgecon = 0, worst_over = 0, least_ratio = 1;
  for (int c = 0; c < NSIZES; ++c) {
    setup S;
    const int n = SIZES[c][0];
    CHECK(make(&S, n, SIZES[c][1], 4242u + (unsigned)c, 16) == 0);
    /* ||B||_1 exactly */
    double bn = 0;
    for (int cc = 0; cc < n; ++cc) {
      double s = 0;
      for (int r = 0; r < n; ++r) s += fabs(S.B[(size_t)cc * n + r]);
      bn = fmax(bn, s);
    }
    double wn = rs_nipc_wb_norm1(&S.wb, S.B0, S.colsum);
    worst_norm = fmax(worst_norm, fabs(wn - bn) / bn);
    /* the estimate against dgecon on B's own LU, and against the exact ||B^-1||_1 */
    double *work = malloc((size_t)4 * n * sizeof *work);
    double est = rs_nipc_wb_inv_norm1(&S.wb, S.LU, S.ipiv, work);
    double rc = 0;
    CHECK(LAPACKE_dgecon(LAPACK_COL_MAJOR, '1', n, S.BLU, n, bn, &rc) == 0);
    worst_dgecon = fmax(worst_dgecon, fabs(est * bn * rc - 1));
    double *inv = malloc((size_t)n * n * sizeof *inv);
    memcpy(inv, S.BLU, (size_t)n * n * sizeof *inv);
    CHECK(LAPACKE_dgetri(LAPACK_COL_MAJOR, n, inv, n, S.bpiv) == 0);
    double exact = 0;
    for (int cc = 0; cc < n; ++cc) {
      double s = 0;
      for (int r = 0; r < n; ++r) s += fabs(inv[(size_t)cc * n + r]);
      exact = fmax(exact, s);
    }
    worst_over = fmax(worst_over, est / exact - 1);
    least_ratio = fmin(least_ratio, est / exact);
    free(inv);
    free(work);
    unmake(&S);
  }
  CHECK_LOG("largest |norm1 - ||B||_1| / ||B||_1", worst_norm);
  CHECK_LOG("largest |est / est_dgecon - 1|", worst_dgecon);
  CHECK_LOG("least est / ||B^-1||_1", least_ratio);
  CHECK_LT(worst_norm, 1e-14);
  CHECK_LT(worst_dgecon, 1e-10); /* the same algorithm on the same matrix */
  CHECK_LT(worst_over, 1e-10);   /* a lower bound, up to the solves' rounding */
  CHECK(least_ratio > 0.3);
}

static void fallback_refused(void)
{
  /* a replaced row equal to a row that is kept: B singular, so is C */
  setup S;
  CHECK(make(&S, 64, 3, 31u, 16) == 0);
  const int n = S.n, keep = 0; /* row 0 is not among rows 1, 4, 7 */
  double *d = rs_nipc_wb_row(&S.wb, 1);
  for (int c = 0; c < n; ++c) d[c] = S.B0[(size_t)c * n + keep];
  for (int i = 0; i < 3; ++i)
    if (i != 1) {
      double *e = rs_nipc_wb_row(&S.wb, i);
      for (int c = 0; c < n; ++c) e[c] = S.B[(size_t)c * n + S.rows[i]];
    }
  CHECK(rs_nipc_wb_set(&S.wb, S.LU, S.ipiv, S.B0, 3, S.rows, 1e-8) == 2);
  CHECK(S.wb.k == 0);
  /* refused, the solve is the kept LU's */
  double *x = malloc((size_t)n * sizeof *x), *y = malloc((size_t)n * sizeof *y);
  for (int r = 0; r < n; ++r) x[r] = y[r] = 1.0 / (r + 1);
  rs_nipc_wb_solve(&S.wb, S.LU, S.ipiv, x);
  rs_nipc_lu_solve(n, S.LU, S.ipiv, y);
  double d_max = 0;
  for (int r = 0; r < n; ++r) d_max = fmax(d_max, fabs(x[r] - y[r]));
  CHECK(d_max == 0.0);
  free(x);
  free(y);
  unmake(&S);
  /* more rows than the cache holds */
  CHECK(make(&S, 64, 5, 32u, 4) == 1);
  CHECK(S.wb.k == 0);
  unmake(&S);
  /* after forgetting (a new LU), nothing cached */
  CHECK(make(&S, 64, 2, 33u, 4) == 0);
  rs_nipc_wb_forget(&S.wb);
  CHECK(S.wb.k == 0 && S.wb.nslots == 0);
  unmake(&S);
}

static const check_case cases[] = {{"solve_against_fresh_lu", solve_against_fresh_lu},
                                   {"norm_and_estimate", norm_and_estimate},
                                   {"fallback_refused", fallback_refused}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
