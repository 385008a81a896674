/* The rank-k correction of the kept LU (contact_woodbury.h): Woodbury's identity with the
 * columns of W = B0^-1 E_K cached per row, the capacitance matrix C = I + D W factored and
 * screened by its condition number, and Hager-Higham's 1-norm estimate of the inverse. */
#include "nip/contact_woodbury.h"

#include "nip/contact_internal.h"
#include "util/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

rs_status rs_nipc_wb_alloc(rs_nipc_wb *w, int n, int cap)
{
  memset(w, 0, sizeof *w);
  w->n = n;
  w->cap = cap;
  if (cap < 1) cap = 1; /* cap 0: no correction, every rs_nipc_wb_set with k > 0 refused */
  w->rows = malloc((size_t)cap * sizeof *w->rows);
  w->slot = malloc((size_t)n * sizeof *w->slot);
  w->Wc = malloc((size_t)cap * n * sizeof *w->Wc);
  w->D = malloc((size_t)cap * n * sizeof *w->D);
  w->C = malloc((size_t)cap * cap * sizeof *w->C);
  w->cpiv = malloc((size_t)cap * sizeof *w->cpiv);
  w->s = malloc((size_t)cap * sizeof *w->s);
  w->t = malloc((size_t)cap * sizeof *w->t);
  w->v = malloc((size_t)n * sizeof *w->v);
  w->cwork = malloc((size_t)4 * cap * sizeof *w->cwork);
  w->ciwork = malloc((size_t)cap * sizeof *w->ciwork);
  if (!w->rows || !w->slot || !w->Wc || !w->D || !w->C || !w->cpiv || !w->s || !w->t || !w->v ||
      !w->cwork || !w->ciwork)
    return RS_ERROR(RS_ERR_MEMORY, "nip rank-k correction work space (n = %d, k <= %d)", n, cap);
  rs_nipc_wb_forget(w);
  return RS_OK;
}

void rs_nipc_wb_free(rs_nipc_wb *w)
{
  free(w->rows);
  free(w->slot);
  free(w->Wc);
  free(w->D);
  free(w->C);
  free(w->cpiv);
  free(w->s);
  free(w->t);
  free(w->v);
  free(w->cwork);
  free(w->ciwork);
  memset(w, 0, sizeof *w);
}

void rs_nipc_wb_forget(rs_nipc_wb *w)
{
  for (int r = 0; r < w->n; ++r) w->slot[r] = -1;
  w->nslots = 0;
  w->k = 0;
}

/* the cached column B0^-1 e_r, made on first use; NULL when the cache is full */
static const double *wcol(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, int r)
{
  if (w->slot[r] < 0) {
    if (w->nslots >= w->cap) return NULL;
    double *c = w->Wc + (size_t)w->nslots * w->n;
    memset(c, 0, (size_t)w->n * sizeof *c);
    c[r] = 1;
    rs_nipc_lu_solve(w->n, LU, ipiv, c);
    w->slot[r] = w->nslots++;
  }
  return w->Wc + (size_t)w->slot[r] * w->n;
}

static double dot(int n, const double *restrict a, const double *restrict b)
{
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int n4 = n & ~3, i = 0;
  for (; i < n4; i += 4) {
    s0 += a[i] * b[i];
    s1 += a[i + 1] * b[i + 1];
    s2 += a[i + 2] * b[i + 2];
    s3 += a[i + 3] * b[i + 3];
  }
  for (; i < n; ++i) s0 += a[i] * b[i];
  return (s0 + s1) + (s2 + s3);
}

int rs_nipc_wb_set(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, const double *B0, int k,
                   const int *rows, double rcond_min)
{
  const int n = w->n, ld = w->cap;
  w->k = 0;
  if (k > w->cap) return 1;
  const double *Wk[k > 0 ? k : 1];
  for (int i = 0; i < k; ++i) {
    Wk[i] = wcol(w, LU, ipiv, rows[i]);
    if (!Wk[i]) return 1;
    double *d = rs_nipc_wb_row(w, i);
    for (int c = 0; c < n; ++c) d[c] -= B0[(size_t)c * n + rows[i]];
    w->rows[i] = rows[i];
  }
  if (k == 0) return 0;
  /* C = I + D W, its 1-norm, LU and condition */
  double cnorm = 0;
  for (int j = 0; j < k; ++j) {
    double sum = 0;
    for (int i = 0; i < k; ++i) {
      double cij = (i == j) + dot(n, rs_nipc_wb_row(w, i), Wk[j]);
      w->C[(size_t)j * ld + i] = cij;
      sum += fabs(cij);
    }
    cnorm = fmax(cnorm, sum);
  }
  lapack_int K = (lapack_int)k, LD = (lapack_int)ld;
  if (!isfinite(cnorm) || LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, K, K, w->C, LD, w->cpiv) != 0) return 2;
  double rc = 0;
  if (LAPACKE_dgecon_work(LAPACK_COL_MAJOR, '1', K, w->C, LD, cnorm, &rc, w->cwork, w->ciwork) != 0 ||
      !(rc >= rcond_min))
    return 2;
  w->k = k;
  return 0;
}

/* the column of W of correction row i */
static inline const double *wcol_of(const rs_nipc_wb *w, int i)
{
  return w->Wc + (size_t)w->slot[w->rows[i]] * (size_t)w->n;
}

/* s <- C^-1 s ('N') or C^-T s ('T') with dgetrf's factors of C (k is small: no blocking) */
static void cap_solve(rs_nipc_wb *w, char trans, double *s)
{
  const int k = w->k;
  const size_t ld = (size_t)w->cap;
  const double *C = w->C;
  if (trans == 'N') {
    for (int i = 0; i < k; ++i) {
      int p = (int)w->cpiv[i] - 1;
      double t = s[i];
      s[i] = s[p];
      s[p] = t;
    }
    for (int j = 0; j < k; ++j)
      for (int i = j + 1; i < k; ++i) s[i] -= C[j * ld + i] * s[j];
    for (int j = k - 1; j >= 0; --j) {
      s[j] /= C[j * ld + j];
      for (int i = 0; i < j; ++i) s[i] -= C[j * ld + i] * s[j];
    }
    return;
  }
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < j; ++i) s[j] -= C[j * ld + i] * s[i];
    s[j] /= C[j * ld + j];
  }
  for (int j = k - 2; j >= 0; --j)
    for (int i = j + 1; i < k; ++i) s[j] -= C[j * ld + i] * s[i];
  for (int i = k - 1; i >= 0; --i) {
    int p = (int)w->cpiv[i] - 1;
    double t = s[i];
    s[i] = s[p];
    s[p] = t;
  }
}

/* x <- B^-1 x = y - W C^-1 D y, y = B0^-1 x */
void rs_nipc_wb_solve(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, double *x)
{
  const int n = w->n, k = w->k;
  rs_nipc_lu_solve(n, LU, ipiv, x);
  if (!k) return;
  int i = 0;
  for (; i + 4 <= k; i += 4)
    rs_nipc_dot4(n, x, rs_nipc_wb_row(w, i), rs_nipc_wb_row(w, i + 1), rs_nipc_wb_row(w, i + 2),
                 rs_nipc_wb_row(w, i + 3), w->s + i);
  for (; i < k; ++i) w->s[i] = dot(n, rs_nipc_wb_row(w, i), x);
  cap_solve(w, 'N', w->s);
  for (i = 0; i + 4 <= k; i += 4)
    rs_nipc_sub4(n, x, w->s[i], w->s[i + 1], w->s[i + 2], w->s[i + 3], wcol_of(w, i), wcol_of(w, i + 1),
                 wcol_of(w, i + 2), wcol_of(w, i + 3));
  for (; i < k; ++i) {
    const double *c = wcol_of(w, i), si = w->s[i];
    for (int r = 0; r < n; ++r) x[r] -= si * c[r];
  }
}

/* x <- B^-T x = B0^-T (x - D^T C^-T W^T x) */
void rs_nipc_wb_solve_t(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, double *x)
{
  const int n = w->n, k = w->k;
  if (k) {
    int i = 0;
    for (; i + 4 <= k; i += 4)
      rs_nipc_dot4(n, x, wcol_of(w, i), wcol_of(w, i + 1), wcol_of(w, i + 2), wcol_of(w, i + 3), w->s + i);
    for (; i < k; ++i) w->s[i] = dot(n, wcol_of(w, i), x);
    cap_solve(w, 'T', w->s);
    for (i = 0; i + 4 <= k; i += 4)
      rs_nipc_sub4(n, x, w->s[i], w->s[i + 1], w->s[i + 2], w->s[i + 3], rs_nipc_wb_row(w, i),
                   rs_nipc_wb_row(w, i + 1), rs_nipc_wb_row(w, i + 2), rs_nipc_wb_row(w, i + 3));
    for (; i < k; ++i) {
      const double *d = rs_nipc_wb_row(w, i), si = w->s[i];
      for (int c = 0; c < n; ++c) x[c] -= si * d[c];
    }
  }
  rs_nipc_lu_solve_t(n, LU, ipiv, x);
}

double rs_nipc_wb_norm1(const rs_nipc_wb *w, const double *B0, const double *colsum)
{
  const int n = w->n;
  double m = 0;
  for (int c = 0; c < n; ++c) {
    double s = colsum[c];
    for (int i = 0; i < w->k; ++i) {
      double b0 = B0[(size_t)c * n + w->rows[i]];
      s += fabs(b0 + w->D[(size_t)i * n + c]) - fabs(b0);
    }
    m = s > m ? s : m;
  }
  return m;
}

static double norm1v(int n, const double *x)
{
  double s = 0;
  for (int i = 0; i < n; ++i) s += fabs(x[i]);
  return s;
}

static int argmax_abs(int n, const double *x)
{
  int j = 0;
  for (int i = 1; i < n; ++i)
    if (fabs(x[i]) > fabs(x[j])) j = i;
  return j;
}

/* Hager (1984), "Condition estimates", SIAM J. Sci. Stat. Comput. 5, 311-316; Higham (1988),
 * ACM TOMS 14, 381-396, Algorithm 4.1: from x = (1/n, ..), alternate y = B^-1 x and
 * z = B^-T sign(y), move x to the unit vector of the largest |z| until the signs repeat, the
 * estimate stops growing or five steps; then the test vector x_i = (-1)^i (1 + i/(n-1)),
 * whose 2 ||B^-1 x||_1 / (3 n) guards against the method's rare underestimates. */
double rs_nipc_wb_inv_norm1(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, double *work)
{
  const int n = w->n;
  double *x = work, *sg = work + n;
  for (int i = 0; i < n; ++i) x[i] = 1.0 / n;
  rs_nipc_wb_solve(w, LU, ipiv, x);
  double est = norm1v(n, x);
  if (n == 1) return est;
  for (int i = 0; i < n; ++i) x[i] = sg[i] = x[i] >= 0 ? 1.0 : -1.0;
  rs_nipc_wb_solve_t(w, LU, ipiv, x);
  int j = argmax_abs(n, x);
  for (int iter = 2; iter <= 5; ++iter) {
    memset(x, 0, (size_t)n * sizeof *x);
    x[j] = 1;
    rs_nipc_wb_solve(w, LU, ipiv, x);
    double old = est;
    est = norm1v(n, x);
    int same = 1;
    for (int i = 0; i < n && same; ++i) same = (x[i] >= 0 ? 1.0 : -1.0) == sg[i];
    if (same || est <= old) {
      est = fmax(est, old);
      break;
    }
    for (int i = 0; i < n; ++i) x[i] = sg[i] = x[i] >= 0 ? 1.0 : -1.0;
    rs_nipc_wb_solve_t(w, LU, ipiv, x);
    int jlast = j;
    j = argmax_abs(n, x);
    if (fabs(x[jlast]) == fabs(x[j])) break;
  }
  for (int i = 0; i < n; ++i) x[i] = (i % 2 ? -1.0 : 1.0) * (1.0 + (double)i / (n - 1));
  rs_nipc_wb_solve(w, LU, ipiv, x);
  double alt = 2 * norm1v(n, x) / (3.0 * n);
  return alt > est ? alt : est;
}
