/* Linear solves of the nip system A z = b (contact_solve.c assembles A, unscaled).
 *
 * A factorization is kept between solves: consecutive systems differ either by a few
 * stick/slip rows (the active-set passes) or by a small drift of all kernel entries (the
 * next trial half-width, the next layer: relative changes 1e-5..1e-3). Both make
 * M^-1 A a low-rank or small perturbation of the identity, M the kept LU, so GMRES
 * preconditioned with M (right preconditioning, the true residual is what it minimises)
 * converges in a few iterations at O(n^2) each instead of a new O(n^3) LU. It stops on
 * the residual of the equilibrated system, checked explicitly at the end; a new LU is made
 * when that fails, stagnates, or too many rows changed (Saad 2003, "Iterative methods for
 * sparse linear systems", ch. 6 and 9).
 *
 * Scaling: physical scales of the unknowns and rows (the raw entries span 1e-11 m/Pa to
 * N/m; plain equilibration let the pressure vanish against the delta0 column), then row
 * and column equilibration as dgeequ does; both are frozen with the factorization. */
#include "nip/contact_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { GMRES_MAX = 40, GMRES_MAX_ROWS = 16 };
static const double GMRES_RTOL = 1e-14; /* ||b - A x|| / ||b||, equilibrated system */

rs_status rs_nipc_lin_alloc(rs_nip_contact *nc)
{
  const size_t n = (size_t)nc->n, m = GMRES_MAX;
  rs_nipc_lin *L = &nc->lin;
  L->LU = malloc(n * n * sizeof(double));
  L->ipiv = malloc(n * sizeof(lapack_int));
  L->rs = malloc(n * sizeof(double));
  L->cs = malloc(n * sizeof(double));
  L->state = malloc((size_t)(nc->M - 1) * 2);
  L->V = malloc((m + 1) * n * sizeof(double));
  L->H = malloc((m + 1) * m * sizeof(double));
  L->work = malloc(7 * n * sizeof(double) + 4 * (m + 1) * sizeof(double));
  L->iwork = malloc(n * sizeof(lapack_int));
  L->valid = 0;
  if (!L->LU || !L->ipiv || !L->rs || !L->cs || !L->state || !L->V || !L->H || !L->work || !L->iwork)
    return RS_ERROR(RS_ERR_MEMORY, "nip linear solver work space (n = %d)", nc->n);
  return RS_OK;
}

void rs_nipc_lin_free(rs_nip_contact *nc)
{
  rs_nipc_lin *L = &nc->lin;
  free(L->LU);
  free(L->ipiv);
  free(L->rs);
  free(L->cs);
  free(L->state);
  free(L->V);
  free(L->H);
  free(L->work);
  free(L->iwork);
  memset(L, 0, sizeof *L);
}

/* y = A x, A column-major n x n; sweeps over columns (vectorised at -O2: restrict and a
 * trip count visible as a multiple of 4, plus the tail) */
static void axpy_col(int n, double *restrict y, double s, const double *restrict a)
{
  int n4 = n & ~3;
  for (int i = 0; i < n4; ++i) y[i] += s * a[i];
  for (int i = n4; i < n; ++i) y[i] += s * a[i];
}

static void matvec(int n, const double *A, const double *x, double *y)
{
  memset(y, 0, (size_t)n * sizeof *y);
  for (int c = 0; c < n; ++c)
    if (x[c] != 0) axpy_col(n, y, x[c], A + (size_t)c * n);
}

/* y = diag(rs) A diag(cs) x */
static void scaled_matvec(const rs_nip_contact *nc, const double *rs, const double *x, double *y,
                          double *tmp)
{
  const int n = nc->n;
  for (int c = 0; c < n; ++c) tmp[c] = nc->lin.cs[c] * x[c];
  matvec(n, nc->A, tmp, y);
  for (int r = 0; r < n; ++r) y[r] *= rs[r];
}

static rs_status lu_solve(rs_nip_contact *nc, double *x)
{
  lapack_int N = (lapack_int)nc->n;
  lapack_int info = LAPACKE_dgetrs_work(LAPACK_COL_MAJOR, 'N', N, 1, nc->lin.LU, N, nc->lin.ipiv, x, N);
  if (info != 0) return RS_ERROR(RS_ERR_INTERNAL, "dgetrs info %d", (int)info);
  return RS_OK;
}

static double norm2(int n, const double *x)
{
  double s = 0;
  for (int i = 0; i < n; ++i) s += x[i] * x[i];
  return sqrt(s);
}

/* A new factorization of the current matrix: scales, equilibration, dgetrf. */
rs_status rs_nipc_lin_refactor(rs_nip_contact *nc, double a)
{
  const int n = nc->n;
  rs_nipc_lin *L = &nc->lin;
  double *col = L->work, *row = L->work + n;
  rs_nipc_scales(nc, a, col, row);
  double *B = L->LU;
  for (int c = 0; c < n; ++c)
    for (int r = 0; r < n; ++r) B[(size_t)c * n + r] = nc->A[(size_t)c * n + r] * (col[c] / row[r]);
  /* equilibration as dgeequ: rows to max 1, then columns to max 1 */
  double *er = L->rs, *ec = L->cs;
  for (int r = 0; r < n; ++r) er[r] = 0;
  for (int c = 0; c < n; ++c)
    for (int r = 0; r < n; ++r) er[r] = fmax(er[r], fabs(B[(size_t)c * n + r]));
  for (int r = 0; r < n; ++r) {
    if (!(er[r] > 0) || !isfinite(er[r])) {
      L->valid = 0;
      return RS_ERROR(RS_ERR_SOLVER, "nip system has an empty or non-finite row %d", r + 1);
    }
    er[r] = 1 / er[r];
  }
  double anorm = 0;
  for (int c = 0; c < n; ++c) {
    double *Bc = B + (size_t)c * n, m = 0;
    for (int r = 0; r < n; ++r) m = fmax(m, fabs(Bc[r]) * er[r]);
    if (!(m > 0) || !isfinite(m)) {
      L->valid = 0;
      return RS_ERROR(RS_ERR_SOLVER, "nip system has an empty or non-finite column %d", c + 1);
    }
    ec[c] = 1 / m;
    double s = 0;
    for (int r = 0; r < n; ++r) {
      Bc[r] *= er[r] * ec[c];
      s += fabs(Bc[r]);
    }
    anorm = fmax(anorm, s);
  }
  for (int r = 0; r < n; ++r) er[r] /= row[r];
  for (int c = 0; c < n; ++c) ec[c] *= col[c];
  L->anorm = anorm;
  L->rcond = -1;
  L->a = a;
  memcpy(L->state, nc->state, (size_t)(nc->M - 1) * 2);
  lapack_int N = (lapack_int)n;
  lapack_int info = LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, N, N, B, N, L->ipiv);
  ++nc->stats_lu;
  if (info != 0) {
    L->valid = 0;
    if (info < 0) return RS_ERROR(RS_ERR_INTERNAL, "dgetrf argument %d", (int)-info);
    return RS_ERROR(RS_ERR_SOLVER, "nip system is singular (dgetrf: zero pivot %d of %d)", (int)info, n);
  }
  /* cheap singularity screen for the passes before the last (dgecon runs on the final
   * state only): the pivots bound the condition number from below */
  double umin = INFINITY, umax = 0;
  for (int i = 0; i < n; ++i) {
    double u = fabs(B[(size_t)i * n + i]);
    umin = fmin(umin, u);
    umax = fmax(umax, u);
  }
  if (!(umin > 1e3 * 2.2e-16 * umax)) {
    L->valid = 0;
    return RS_ERROR(RS_ERR_SOLVER, "nip system is numerically singular (pivot ratio %.3g)", umin / umax);
  }
  L->valid = 1;
  return RS_OK;
}

/* GMRES on diag(rs') A diag(cs) x = diag(rs') b, right-preconditioned with the kept LU,
 * started from x0 = LU^-1 b. Returns 1 on success (solution in nc->z), 0 to refactor. */
static int gmres(rs_nip_contact *nc, int changed_rows)
{
  const int n = nc->n, m = GMRES_MAX;
  rs_nipc_lin *L = &nc->lin;
  double *rsc = L->work, *b = L->work + n, *x = L->work + 2 * n, *w = L->work + 3 * n;
  double *tmp = L->work + 4 * n, *u = L->work + 5 * n, *r = L->work + 6 * n;
  double *g = L->work + 7 * n, *cg = g + (m + 1), *sg = cg + (m + 1), *y = sg + (m + 1);
  double *V = L->V, *H = L->H;
#define HH(i, j) H[(size_t)(j) * (m + 1) + (i)]
  /* row scales: the factorization's, fresh ones for the rows whose stick/slip state changed */
  const int M = nc->M, E = M - 1;
  memcpy(rsc, L->rs, (size_t)n * sizeof *rsc);
  if (changed_rows)
    for (int k = 0; k < 2 * E; ++k) {
      if (nc->state[k] == L->state[k]) continue;
      int row = M + k;
      double mx = 0;
      for (int c = 0; c < n; ++c) mx = fmax(mx, fabs(nc->A[(size_t)c * n + row] * L->cs[c]));
      if (!(mx > 0)) return 0;
      rsc[row] = 1 / mx;
    }
  for (int i = 0; i < n; ++i) b[i] = rsc[i] * nc->rhs[i];
  double bnorm = norm2(n, b);
  memcpy(x, b, (size_t)n * sizeof *x);
  if (lu_solve(nc, x)) return 0;
  scaled_matvec(nc, rsc, x, w, tmp);
  for (int i = 0; i < n; ++i) r[i] = b[i] - w[i];
  double beta = norm2(n, r), tol = GMRES_RTOL * bnorm;
  int k = 0;
  if (beta > tol) {
    for (int i = 0; i < n; ++i) V[i] = r[i] / beta;
    memset(g, 0, (size_t)(m + 1) * sizeof *g);
    g[0] = beta;
    double res = beta;
    for (k = 0; k < m; ++k) {
      double *vk = V + (size_t)k * n, *vn = V + (size_t)(k + 1) * n;
      memcpy(u, vk, (size_t)n * sizeof *u);
      if (lu_solve(nc, u)) return 0;
      scaled_matvec(nc, rsc, u, w, tmp);
      /* modified Gram-Schmidt, twice (keeps V orthogonal to round-off) */
      for (int j = 0; j <= k; ++j) HH(j, k) = 0;
      for (int pass = 0; pass < 2; ++pass)
        for (int j = 0; j <= k; ++j) {
          const double *vj = V + (size_t)j * n;
          double h = 0;
          for (int i = 0; i < n; ++i) h += vj[i] * w[i];
          for (int i = 0; i < n; ++i) w[i] -= h * vj[i];
          HH(j, k) += h;
        }
      double hn = norm2(n, w);
      HH(k + 1, k) = hn;
      if (hn > 0)
        for (int i = 0; i < n; ++i) vn[i] = w[i] / hn;
      /* Givens rotations keep H upper triangular; |g[k+1]| is the residual norm */
      for (int j = 0; j < k; ++j) {
        double h1 = HH(j, k), h2 = HH(j + 1, k);
        HH(j, k) = cg[j] * h1 + sg[j] * h2;
        HH(j + 1, k) = -sg[j] * h1 + cg[j] * h2;
      }
      double h1 = HH(k, k), h2 = HH(k + 1, k), d = hypot(h1, h2);
      if (!(d > 0)) return 0;
      cg[k] = h1 / d;
      sg[k] = h2 / d;
      HH(k, k) = d;
      HH(k + 1, k) = 0;
      g[k + 1] = -sg[k] * g[k];
      g[k] = cg[k] * g[k];
      res = fabs(g[k + 1]);
      if (res <= tol || hn == 0) {
        ++k;
        break;
      }
      /* stagnation (a large change of the matrix): a new LU is cheaper */
      if (k == 9 && res > 1e-4 * beta) return 0;
      if (k + 1 >= m) return 0;
    }
    /* y = H^-1 g, u = V y, x += LU^-1 u */
    for (int i = k - 1; i >= 0; --i) {
      double s = g[i];
      for (int j = i + 1; j < k; ++j) s -= HH(i, j) * y[j];
      y[i] = s / HH(i, i);
    }
    memset(u, 0, (size_t)n * sizeof *u);
    for (int j = 0; j < k; ++j) axpy_col(n, u, y[j], V + (size_t)j * n);
    if (lu_solve(nc, u)) return 0;
    for (int i = 0; i < n; ++i) x[i] += u[i];
    /* the true residual, not the recurrence's */
    scaled_matvec(nc, rsc, x, w, tmp);
    for (int i = 0; i < n; ++i) r[i] = b[i] - w[i];
    if (!(norm2(n, r) <= 10 * tol)) return 0;
  }
#undef HH
  for (int c = 0; c < n; ++c) nc->z[c] = L->cs[c] * x[c];
  nc->stats_gmres_it += k;
  L->solved_state_differs = changed_rows > 0;
  return 1;
}

/* Solves nc->A z = nc->rhs into nc->z, with the kept factorization when it serves. */
rs_status rs_nipc_lin_solve(rs_nip_contact *nc, double a)
{
  const int n = nc->n, E = nc->M - 1;
  rs_nipc_lin *L = &nc->lin;
  if (L->valid && fabs(a / L->a - 1) < 0.1) {
    int changed = 0;
    for (int k = 0; k < 2 * E; ++k) changed += nc->state[k] != L->state[k];
    if (changed <= GMRES_MAX_ROWS && gmres(nc, changed)) {
      L->fresh = 0;
      for (int c = 0; c < n; ++c)
        if (!isfinite(nc->z[c])) return RS_ERROR(RS_ERR_SOLVER, "nip solution is not finite");
      return RS_OK;
    }
  }
  rs_status st = rs_nipc_lin_refactor(nc, a);
  if (st) return st;
  double *x = nc->z;
  for (int r = 0; r < n; ++r) x[r] = L->rs[r] * nc->rhs[r];
  st = lu_solve(nc, x);
  if (st) return st;
  for (int c = 0; c < n; ++c) {
    x[c] *= L->cs[c];
    if (!isfinite(x[c])) return RS_ERROR(RS_ERR_SOLVER, "nip solution is not finite");
  }
  L->solved_state_differs = 0;
  L->fresh = 1;
  return RS_OK;
}

/* 1-norm condition number estimate (dgecon) of the equilibrated matrix of the last solve:
 * of its own factorization, or of the kept one when the last solve refined from it with
 * the same stick/slip rows (then the matrices differ by the small kernel drift that the
 * GMRES convergence bounds); rows that changed get a factorization of their own first.
 * RS_ERR_SOLVER if numerically singular. */
rs_status rs_nipc_lin_cond(rs_nip_contact *nc, double a, double *cond)
{
  rs_nipc_lin *L = &nc->lin;
  if (!L->valid || L->solved_state_differs) {
    rs_status st = rs_nipc_lin_refactor(nc, a);
    if (st) return st;
    L->solved_state_differs = 0;
  }
  if (L->rcond < 0) {
    lapack_int N = (lapack_int)nc->n;
    lapack_int info = LAPACKE_dgecon_work(LAPACK_COL_MAJOR, '1', N, L->LU, N, L->anorm, &L->rcond,
                                          L->work, L->iwork);
    if (info != 0) return RS_ERROR(RS_ERR_INTERNAL, "dgecon info %d", (int)info);
  }
  *cond = L->rcond > 0 ? 1.0 / L->rcond : INFINITY;
  if (!(L->rcond > 1e3 * 2.2e-16))
    return RS_ERROR(RS_ERR_SOLVER, "nip system is numerically singular (condition number %.3g)", *cond);
  return RS_OK;
}
