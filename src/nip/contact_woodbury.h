/* A rank-k correction of a kept LU (Sherman-Morrison-Woodbury), for the nip's stick/slip
 * rows: the kept factors are of B0 (dgetrf: P B0 = L U); the system to solve has k rows of
 * B0 replaced, rows K = {r_1..r_k}:
 *
 *     B = B0 + E_K D,   D = B[K,:] - B0[K,:] (k x n),   E_K = [e_r1 .. e_rk] (n x k),
 *     B^-1 = B0^-1 - W C^-1 D B0^-1,   W = B0^-1 E_K,   C = I_k + D W (the capacitance),
 *     B^-T = B0^-T - B0^-T D^T C^-T W^T
 *
 * (Woodbury 1950; Golub & Van Loan, "Matrix computations", 4th ed., sec. 2.1.4 and 9.1).
 * The columns of W depend only on the rows, not on their new values, and are kept per row
 * until the LU changes; C is factored (LAPACK) and refused when its reciprocal condition
 * number is below WB_RCOND_MIN (the update would lose the accuracy the kept LU has):
 * the caller then refactors. Private to src/nip. */
#ifndef RS_NIP_CONTACT_WOODBURY_H
#define RS_NIP_CONTACT_WOODBURY_H

#include <lapacke.h>

#include "reelsim/status.h"

typedef struct rs_nipc_wb {
  int n, cap;        /* order; most rows a correction and the column cache hold */
  int k;             /* rows of the current correction (0: none, B = B0) */
  int *rows;         /* cap: the replaced rows */
  int *slot;         /* n: the cache slot of row r's column of W, -1 none */
  int nslots;
  double *Wc;        /* cap columns of n: B0^-1 e_r, by slot */
  double *D;         /* cap rows of n, each contiguous: B[r,:] - B0[r,:] */
  double *C;         /* cap x cap (leading dimension cap): the LU of C */
  lapack_int *cpiv;
  double *s, *t;     /* cap */
  double *v;         /* n */
  double *cwork;     /* 4 cap (dgecon) */
  lapack_int *ciwork;
} rs_nipc_wb;

rs_status rs_nipc_wb_alloc(rs_nipc_wb *w, int n, int cap);
void rs_nipc_wb_free(rs_nipc_wb *w);

/* The kept LU changed: the cached columns of W are void, no correction. */
void rs_nipc_wb_forget(rs_nipc_wb *w);

/* Row i (< cap) of D, to be filled with the new row B[r_i,:] before rs_nipc_wb_set. */
static inline double *rs_nipc_wb_row(rs_nipc_wb *w, int i)
{
  return w->D + (size_t)i * (size_t)w->n;
}

/* Sets the correction: k rows rows[0..k-1] whose new values are in rs_nipc_wb_row(w, i);
 * B0 is the matrix the LU (LU, ipiv) was made of (column-major n x n). Returns 0, or 1 when
 * k exceeds the cache, 2 when the capacitance matrix is singular or its reciprocal condition
 * number is below rcond_min: then no correction is set (k = 0) and the caller refactors. */
int rs_nipc_wb_set(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, const double *B0, int k,
                   const int *rows, double rcond_min);

/* x <- B^-1 x and x <- B^-T x with the kept LU and the correction (k = 0: the LU's solve). */
void rs_nipc_wb_solve(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, double *x);
void rs_nipc_wb_solve_t(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, double *x);

/* ||B||_1 from B0 and the column sums of |B0| (colsum, n) and the correction's rows. */
double rs_nipc_wb_norm1(const rs_nipc_wb *w, const double *B0, const double *colsum);

/* Estimate of ||B^-1||_1 by Hager's method as refined by Higham (the algorithm of LAPACK's
 * dlacn2 that dgecon uses), with the corrected solves; work: 3 n. */
double rs_nipc_wb_inv_norm1(rs_nipc_wb *w, const double *LU, const lapack_int *ipiv, double *work);

#endif
