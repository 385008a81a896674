/* Linear solves of the nip system A z = b (contact_solve.c assembles A, unscaled).
 *
 * A factorization is kept between solves: consecutive systems differ either by a few
 * stick/slip rows (the active-set passes) or by a small drift of all kernel entries (the
 * next trial half-width, the next layer: relative changes 1e-5..1e-3). Both make
 * M^-1 A a low-rank or small perturbation of the identity, M the kept LU, so GMRES
 * preconditioned with M (right preconditioning, the true residual is what it minimises)
 * converges in a few iterations at O(n^2) each instead of a new O(n^3) LU (Saad 2003,
 * "Iterative methods for sparse linear systems", ch. 6 and 9). The GMRES is SUNDIALS'
 * SPGMR (SUNLinSol_SPGMR, modified Gram-Schmidt) on the equilibrated system, with the
 * matrix-vector product and the LU solve as its callbacks, in cycles of KRYLOV_MAXL
 * iterations restarted from the last iterate. It stops on the residual of the equilibrated
 * system, checked explicitly at the end; a new LU is made when that fails, when the first
 * cycle leaves more than 1e-4 of the initial residual (stagnation: the matrix moved too
 * far), or when too many rows changed. SPGMR replaced a hand-written GMRES with the same
 * stopping rules, iterations and answers; it costs 4 % more instructions per warm nip
 * solve (its vector operations go through the N_Vector table) and 1.3 % on the 6054-layer
 * contact reel (docs/performance.md, "The GMRES").
 *
 * The factorization a solve makes for itself is in single precision (sgetrf on a float copy
 * of the equilibrated matrix, its factors then kept in double): half dgetrf's work, and a
 * preconditioner as good for GMRES, which refines every solve, a fresh one too, to the
 * same residual (1e-14): on the contact reel 68 more GMRES iterations (701 instead of
 * 633) against 18 M fewer instructions in the 15 factorizations (docs/performance.md). A
 * refinement from a single-precision LU that fails (a system too ill-conditioned for it:
 * its error is ~1e-7 of the condition number) falls back to dgetrf, for good on that
 * handle. The LCP's
 * responses and a condition estimate that needs a new LU take one in double
 * (rs_nipc_lin_refactor).
 *
 * Scaling: physical scales of the unknowns and rows (the raw entries span 1e-11 m/Pa to
 * N/m; plain equilibration let the pressure vanish against the delta0 column), then row
 * and column equilibration as dgeequ does; both are frozen with the factorization. */
#include "nip/contact_internal.h"
#include "util/error.h"
#include "util/sundials_compat.h"
#include "util/vector_clones.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_spgmr.h>

/* up to 4 cycles of 10 iterations (the hand-written GMRES: 40, stagnation test at 10) */
enum { KRYLOV_MAXL = 10, KRYLOV_CYCLES = 4, KRYLOV_MAX_ROWS = 32 };
/* the kept LU serves while the half-width is within this fraction of its own */
static const double KRYLOV_MAX_DRIFT = 0.05;
static const double KRYLOV_RTOL = 1e-14; /* ||b - A x|| / ||b||, equilibrated system */
/* the least reciprocal condition number of the rank-k correction's capacitance matrix */
static const double WB_RCOND_MIN = 1e-8;
enum { WB_MAX_NODES = 1024 };

static int krylov_atimes(void *data, N_Vector v, N_Vector z);
static int krylov_psolve(void *data, N_Vector r, N_Vector z, sunrealtype tol, int lr);

rs_status rs_nipc_lin_alloc(rs_nip_contact *nc)
{
  const size_t n = (size_t)nc->n;
  rs_nipc_lin *L = &nc->lin;
  L->LU = malloc(n * n * sizeof(double));
  L->ipiv = malloc(n * sizeof(lapack_int));
  L->rs = malloc(n * sizeof(double));
  L->cs = malloc(n * sizeof(double));
  L->gm_rs = malloc(n * sizeof(double));
  L->state = malloc((size_t)(nc->M - 1) * 2);
  L->work = malloc(5 * n * sizeof(double)); /* dgecon needs 4 n */
  L->iwork = malloc(n * sizeof(lapack_int));
  /* the rank-k correction keeps a copy of the equilibrated matrix: up to M = 1024 nodes
   * (75 MB); beyond, GMRES refines from the kept LU alone */
  L->B0 = n <= 3 * WB_MAX_NODES ? malloc(n * n * sizeof(double)) : NULL;
  L->colsum = malloc(n * sizeof(double));
  L->krows = malloc(n * sizeof(int));
  L->LUs = malloc(n * n * sizeof(float));
  L->valid = 0;
  if (!L->LU || !L->ipiv || !L->rs || !L->cs || !L->gm_rs || !L->state || !L->work || !L->iwork ||
      (!L->B0 && n <= 3 * WB_MAX_NODES) || !L->colsum || !L->krows || !L->LUs)
    return RS_ERROR(RS_ERR_MEMORY, "nip linear solver work space (n = %d)", nc->n);
  if (rs_nipc_wb_alloc(&L->wb, nc->n, L->B0 ? KRYLOV_MAX_ROWS : 0)) return RS_ERR_MEMORY;
  if (rs_sundials_context_create(&L->sunctx) != 0)
    return RS_ERROR(RS_ERR_MEMORY, "nip linear solver: SUNContext_Create failed");
  L->nx = N_VNew_Serial((sunindextype)n, L->sunctx);
  L->nb = L->nx ? N_VClone(L->nx) : NULL;
  L->spgmr = L->nx ? SUNLinSol_SPGMR(L->nx, SUN_PREC_RIGHT, KRYLOV_MAXL, L->sunctx) : NULL;
  if (!L->nb || !L->spgmr)
    return RS_ERROR(RS_ERR_MEMORY, "nip linear solver: SPGMR work space (n = %d)", nc->n);
  if (SUNLinSol_SPGMRSetMaxRestarts(L->spgmr, 0) || SUNLinSolSetATimes(L->spgmr, nc, krylov_atimes) ||
      SUNLinSolSetPreconditioner(L->spgmr, nc, NULL, krylov_psolve) ||
      SUNLinSolInitialize(L->spgmr))
    return RS_ERROR(RS_ERR_INTERNAL, "nip linear solver: SPGMR set-up failed");
  return RS_OK;
}

void rs_nipc_lin_free(rs_nip_contact *nc)
{
  rs_nipc_lin *L = &nc->lin;
  free(L->LU);
  free(L->ipiv);
  free(L->rs);
  free(L->cs);
  free(L->gm_rs);
  free(L->state);
  free(L->work);
  free(L->iwork);
  free(L->B0);
  free(L->colsum);
  free(L->krows);
  free(L->LUs);
  rs_nipc_wb_free(&L->wb);
  if (L->spgmr) SUNLinSolFree(L->spgmr);
  if (L->nb) N_VDestroy(L->nb);
  if (L->nx) N_VDestroy(L->nx);
  if (L->sunctx) SUNContext_Free(&L->sunctx);
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

/* y += A(:, c..c+3) x(c..c+3): four columns a sweep, so y is loaded and stored once for
 * four (the product is ~half of a GMRES iteration's work) */
RS_VECTOR_CLONES static void axpy4_col(int n, double *restrict y, const double *restrict x,
                                        const double *restrict a0, const double *restrict a1,
                                        const double *restrict a2, const double *restrict a3)
{
  const double x0 = x[0], x1 = x[1], x2 = x[2], x3 = x[3];
  int n4 = n & ~3;
  for (int i = 0; i < n4; ++i) y[i] += (x0 * a0[i] + x1 * a1[i]) + (x2 * a2[i] + x3 * a3[i]);
  for (int i = n4; i < n; ++i) y[i] += (x0 * a0[i] + x1 * a1[i]) + (x2 * a2[i] + x3 * a3[i]);
}

static void matvec(int n, const double *A, const double *x, double *y)
{
  memset(y, 0, (size_t)n * sizeof *y);
  int c = 0;
  for (; c + 4 <= n; c += 4) {
    const double *a = A + (size_t)c * n;
    axpy4_col(n, y, x + c, a, a + n, a + 2 * (size_t)n, a + 3 * (size_t)n);
  }
  for (; c < n; ++c)
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

/* x <- the kept LU's inverse, with the rank-k correction of the changed rows when set */
static rs_status lu_solve(rs_nip_contact *nc, double *x)
{
  rs_nipc_wb_solve(&nc->lin.wb, nc->lin.LU, nc->lin.ipiv, x);
  return RS_OK;
}

static double norm2(int n, const double *x)
{
  double s = 0;
  for (int i = 0; i < n; ++i) s += x[i] * x[i];
  return sqrt(s);
}

/* fmax(a, b) without the library call (the same result, NaN included: a NaN is ignored) */
static inline double max_of(double a, double b)
{
  return b > a || isnan(a) ? b : a;
}

/* max_r |b_r| w_r (w >= 0; a NaN product is passed over, as max_of does): four partial
 * maxima, so the sweep vectorises; the largest is the same in any order */
static double col_max(int n, const double *restrict b, const double *restrict w)
{
  double m[4] = {0, 0, 0, 0};
  int n4 = n & ~3;
  for (int r = 0; r < n4; r += 4)
    for (int k = 0; k < 4; ++k) {
      double v = fabs(b[r + k]) * w[r + k];
      m[k] = v > m[k] ? v : m[k];
    }
  for (int r = n4; r < n; ++r) {
    double v = fabs(b[r]) * w[r];
    m[0] = v > m[0] ? v : m[0];
  }
  return max_of(max_of(m[0], m[1]), max_of(m[2], m[3]));
}

/* B <- the LU factors of B (n x n, column-major) by sgetrf on the float copy F; returns
 * sgetrf's info (> 0: a zero pivot in single precision, B left as it was) */
static lapack_int getrf_single(int n, double *B, float *F, lapack_int *ipiv)
{
  const size_t nn = (size_t)n * (size_t)n;
  for (size_t i = 0; i < nn; ++i) F[i] = (float)B[i];
  lapack_int N = (lapack_int)n;
  lapack_int info = LAPACKE_sgetrf_work(LAPACK_COL_MAJOR, N, N, F, N, ipiv);
  if (info == 0)
    for (size_t i = 0; i < nn; ++i) B[i] = (double)F[i];
  return info;
}

/* A new factorization of the current matrix: scales, equilibration, dgetrf (or sgetrf when
 * single and the single-precision factorization finds no zero pivot). */
static rs_status refactor(rs_nip_contact *nc, double a, int single)
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
    for (int r = 0; r < n; ++r) er[r] = max_of(er[r], fabs(B[(size_t)c * n + r]));
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
    m = col_max(n, Bc, er);
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
    if (L->B0) memcpy(L->B0 + (size_t)c * n, Bc, (size_t)n * sizeof *Bc);
    L->colsum[c] = s;
    anorm = fmax(anorm, s);
  }
  for (int r = 0; r < n; ++r) er[r] /= row[r];
  for (int c = 0; c < n; ++c) ec[c] *= col[c];
  L->anorm = anorm;
  L->rcond = -1;
  L->a = a;
  rs_nipc_wb_forget(&L->wb);
  memcpy(L->state, nc->state, (size_t)(nc->M - 1) * 2);
  lapack_int N = (lapack_int)n;
  L->single = single && getrf_single(n, B, L->LUs, L->ipiv) == 0;
  lapack_int info = L->single ? 0 : LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, N, N, B, N, L->ipiv);
  ++nc->stats_lu;
  nc->stats_lu_single += L->single;
  if (info != 0) {
    L->valid = 0;
    if (info < 0) return RS_ERROR(RS_ERR_INTERNAL, "dgetrf argument %d", (int)-info);
    return RS_ERROR(RS_ERR_SOLVER, "nip system is singular (dgetrf: zero pivot %d of %d)", (int)info, n);
  }
  /* cheap singularity screen for the passes before the last (the estimate runs on the final
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

rs_status rs_nipc_lin_refactor(rs_nip_contact *nc, double a)
{
  return refactor(nc, a, 0);
}

/* SPGMR's callbacks: z = diag(rs') A diag(cs) v (rs' = gm_rs), and z = LU^-1 r. A failed
 * LU solve is "recoverable" for SPGMR (it returns), and then refactors here. */
static int krylov_atimes(void *data, N_Vector v, N_Vector z)
{
  rs_nip_contact *nc = data;
  scaled_matvec(nc, nc->lin.gm_rs, NV_DATA_S(v), NV_DATA_S(z), nc->lin.work);
  return 0;
}

static int krylov_psolve(void *data, N_Vector r, N_Vector z, sunrealtype tol, int lr)
{
  (void)tol;
  (void)lr;
  rs_nip_contact *nc = data;
  memcpy(NV_DATA_S(z), NV_DATA_S(r), (size_t)nc->n * sizeof(double));
  return lu_solve(nc, NV_DATA_S(z)) ? 1 : 0;
}

/* GMRES (SPGMR) on diag(rs') A diag(cs) x = diag(rs') b, right-preconditioned with the kept
 * LU, started from x0 = LU^-1 b. Returns 1 on success (solution in nc->z), 0 to refactor. */
static int krylov(rs_nip_contact *nc, int changed_rows)
{
  const int n = nc->n;
  rs_nipc_lin *L = &nc->lin;
  double *rsc = L->gm_rs, *w = L->work + n, *r = L->work + 2 * n, *x0 = L->work + 3 * n;
  double *b = NV_DATA_S(L->nb), *x = NV_DATA_S(L->nx);
  /* row scales: the factorization's, fresh ones for the rows whose stick/slip state changed */
  const int M = nc->M, E = M - 1;
  memcpy(rsc, L->rs, (size_t)n * sizeof *rsc);
  int nk = 0;
  if (changed_rows)
    for (int k = 0; k < 2 * E; ++k) {
      if (nc->state[k] == L->state[k]) continue;
      int row = M + k;
      double mx = 0;
      for (int c = 0; c < n; ++c) mx = max_of(mx, fabs(nc->A[(size_t)c * n + row] * L->cs[c]));
      if (!(mx > 0)) return 0;
      rsc[row] = 1 / mx;
      if (!L->B0) continue;
      double *d = rs_nipc_wb_row(&L->wb, nk);
      for (int c = 0; c < n; ++c) d[c] = rsc[row] * (nc->A[(size_t)c * n + row] * L->cs[c]);
      L->krows[nk++] = row;
    }
  /* the preconditioner: the kept LU corrected for these rows (rank nk) */
  if (L->B0 && rs_nipc_wb_set(&L->wb, L->LU, L->ipiv, L->B0, nk, L->krows, WB_RCOND_MIN)) return 0;
  for (int i = 0; i < n; ++i) b[i] = rsc[i] * nc->rhs[i];
  double tol = KRYLOV_RTOL * norm2(n, b);
  memcpy(x, b, (size_t)n * sizeof *x);
  if (lu_solve(nc, x)) return 0;
  memcpy(x0, x, (size_t)n * sizeof *x0);
  if (SUNLinSolSetZeroGuess(L->spgmr, SUNFALSE)) return 0;
  long it = 0;
  int flag = SUNLS_CONV_FAIL;
  for (int cycle = 0; cycle < KRYLOV_CYCLES; ++cycle) {
    flag = SUNLinSolSolve(L->spgmr, NULL, L->nx, L->nb, tol);
    it += SUNLinSolNumIters(L->spgmr);
    if (flag != SUNLS_RES_REDUCED) break;
    if (cycle == 0) { /* stagnation (a large change of the matrix): a new LU is cheaper */
      scaled_matvec(nc, rsc, x0, w, L->work);
      for (int i = 0; i < n; ++i) r[i] = b[i] - w[i];
      if (SUNLinSolResNorm(L->spgmr) > 1e-4 * norm2(n, r)) return 0;
    }
  }
  if (flag != SUNLS_SUCCESS) return 0;
  /* the true residual, not the recurrence's */
  scaled_matvec(nc, rsc, x, w, L->work);
  for (int i = 0; i < n; ++i) r[i] = b[i] - w[i];
  if (!(norm2(n, r) <= 10 * tol)) return 0;
  for (int c = 0; c < n; ++c) nc->z[c] = L->cs[c] * x[c];
  nc->stats_gmres_it += it;
  L->solved_state_differs = changed_rows > 0;
  return 1;
}

/* Solves nc->A z = nc->rhs into nc->z, with the kept factorization when it serves. */
rs_status rs_nipc_lin_solve(rs_nip_contact *nc, double a)
{
  const int n = nc->n, E = nc->M - 1;
  rs_nipc_lin *L = &nc->lin;
  if (L->valid && fabs(a / L->a - 1) < KRYLOV_MAX_DRIFT) {
    int changed = 0;
    for (int k = 0; k < 2 * E; ++k) changed += nc->state[k] != L->state[k];
    if (changed <= KRYLOV_MAX_ROWS && krylov(nc, changed)) {
      L->fresh = 0;
      for (int c = 0; c < n; ++c)
        if (!isfinite(nc->z[c])) return RS_ERROR(RS_ERR_SOLVER, "nip solution is not finite");
      return RS_OK;
    }
  }
  rs_status st = refactor(nc, a, !L->double_only && !L->want_double);
  if (st) return st;
  if (L->single) { /* a preconditioner: GMRES from it to the same residual */
    if (krylov(nc, 0)) {
      L->fresh = 1;
      for (int c = 0; c < n; ++c)
        if (!isfinite(nc->z[c])) return RS_ERROR(RS_ERR_SOLVER, "nip solution is not finite");
      return RS_OK;
    }
    L->double_only = 1;
    st = refactor(nc, a, 0);
    if (st) return st;
  }
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

/* the least reciprocal condition number of a system solved: 1e3 roundoffs */
static const double RCOND_MIN = 1e3 * 2.2e-16;

/* 1-norm condition number estimate of the equilibrated matrix of the last solve: of its
 * own factorization (dgecon's estimator on its solves), or of the kept one when the last
 * solve refined from it with the same stick/slip rows (then the matrices differ by the small kernel drift that the
 * GMRES convergence bounds), or, when rows changed and the kept LU carries their rank-k
 * correction, of the corrected matrix (contact_woodbury.c); other changed rows get a
 * factorization of their own first. RS_ERR_SOLVER if numerically singular. */
rs_status rs_nipc_lin_cond(rs_nip_contact *nc, double a, double *cond)
{
  rs_nipc_lin *L = &nc->lin;
  int ok;
  if (L->valid && L->solved_state_differs && L->wb.k > 0) {
    /* the kept LU with its rank-k correction for the changed rows */
    double anorm = rs_nipc_wb_norm1(&L->wb, L->B0, L->colsum);
    double ainv = rs_nipc_wb_inv_norm1(&L->wb, L->LU, L->ipiv, L->work);
    *cond = anorm * ainv;
    ok = isfinite(*cond) && *cond < 1 / RCOND_MIN;
  } else {
    if (!L->valid || L->solved_state_differs) {
      rs_status st = rs_nipc_lin_refactor(nc, a);
      if (st) return st;
      L->solved_state_differs = 0;
    }
    if (L->rcond < 0 && L->wb.k == 0) {
      /* dgecon's estimator (Hager-Higham) on the solves of contact_lu.c: OpenBLAS's dgecon
       * solves the triangles by dlatrs, 0.52 M instructions an estimate against ~0.2 M */
      double ainv = rs_nipc_wb_inv_norm1(&L->wb, L->LU, L->ipiv, L->work);
      L->rcond = L->anorm > 0 && ainv > 0 ? 1.0 / (L->anorm * ainv) : 0.0;
      if (isnan(L->rcond)) L->rcond = 0.0;
    } else if (L->rcond < 0) {
      lapack_int N = (lapack_int)nc->n;
      lapack_int info = LAPACKE_dgecon_work(LAPACK_COL_MAJOR, '1', N, L->LU, N, L->anorm, &L->rcond,
                                            L->work, L->iwork);
      if (info != 0) return RS_ERROR(RS_ERR_INTERNAL, "dgecon info %d", (int)info);
    }
    *cond = L->rcond > 0 ? 1.0 / L->rcond : INFINITY;
    ok = L->rcond > RCOND_MIN;
  }
  if (!ok)
    return RS_ERROR(RS_ERR_SOLVER, "nip system is numerically singular (condition number %.3g)", *cond);
  return RS_OK;
}
