/* The stick/slip conditions at a fixed half-width as a linear complementarity problem
 * (LCP), solved by Lemke's complementary pivoting (Lemke 1965; Cottle, Pang & Stone 1992,
 * "The linear complementarity problem", sec. 4.4).
 *
 * Each element e of contact k has a slip rate s = s+ - s- (s+, s- >= 0, per unit speed)
 * and friction margins w+ = mu pbar - q >= 0, w- = mu pbar + q >= 0 (q the friction on
 * the cylinder). Coulomb's law is s+ w+ = 0 and s- w- = 0: slip forward only at q = +mu
 * pbar, backward only at q = -mu pbar, stick (s = 0) with |q| <= mu pbar. The rest of the
 * system is linear: with the full-stick matrix K (every stick row of contact_solve.c reads
 * "slip rate = 0"), the state with slip rates s solves K z = b + E s (E puts s into the
 * stick rows), so z = z0 + Z s and
 *   w = c + Mt u,  u = (s+, s-),  Mt = [[W+, -W+], [W-, -W-]],  W+- = (mu Pbar -+ Q) Z,
 * c = (mu Pbar -+ Q) z0. Lemke's method either ends at a solution (u, w >= 0, u.w = 0) or
 * on a secondary ray; it is finite without cycling under nondegeneracy (ties broken by the
 * smallest index, with a pivot cap as the guard). A ray is not a proof that no solution
 * exists unless Mt is copositive-plus (docs/nip.md discusses when it is); the caller reports
 * it. The result is used only as an active set: contact_solve.c re-solves and checks it. */
#include "nip/contact_internal.h"
#include "util/error.h"
#include "util/vector_clones.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* pbar_e and q_ke of a vector y of unknowns */
static double pbar_of(int M, const double *y, int e)
{
  double s = 0;
  if (e >= 1) s += y[COL_P(e)];
  if (e + 1 <= M - 2) s += y[COL_P(e + 1)];
  return 0.5 * s;
}

/* x -= f y over a padded row (n a multiple of 4: -O2 vectorises it) */
RS_VECTOR_CLONES static void row_update(int n, double *restrict x, double f,
                                        const double *restrict y)
{
  n &= ~3;
  for (int j = 0; j < n; ++j) x[j] -= f * y[j];
}

/* Lemke's tableau: rows i = 0..m-1 read w_i - sum_j Mt_ij u_j - t = c_i. Variables: w_i
 * (i < m), s+_j (m + j), s-_j (m + S + j), t (vt = 2 m). Stored columns: w (m), s+ (S), t
 * (ct), rhs (cr); the column of s-_j is minus that of s+_j in any basis (row operations keep
 * the linear relation), so it is not stored. basis[i] is the variable of row i. */
typedef struct lcp_tableau {
  double *T;
  int *basis;
  int m, S, W, vt, ct, cr;
} lcp_tableau;

#define TT(tb, i, j) ((tb)->T[(size_t)(i) * (tb)->W + (j)])

/* stored column and sign of variable v */
static int lcp_col(const lcp_tableau *tb, int v)
{
  return v == tb->vt ? tb->ct : v < tb->m + tb->S ? v : v - tb->S;
}
static double lcp_sign(const lcp_tableau *tb, int v)
{
  return v >= tb->m + tb->S && v < tb->vt ? -1.0 : 1.0;
}

/* Z = K^-1 E (n x S, column-major): column j is K^-1 e_{M+j} = diag(cs) Kq^-1 (rs_{M+j}
 * e_{M+j}), Kq the equilibrated matrix of the kept factorization */
static rs_status lcp_stick_response(const rs_nip_contact *nc, double *Z)
{
  const rs_nipc_lin *L = &nc->lin;
  const int M = nc->M, n = nc->n, S = 2 * (M - 1);
  for (int j = 0; j < S; ++j) Z[(size_t)j * n + M + j] = L->rs[M + j];
  lapack_int N = (lapack_int)n;
  lapack_int info = LAPACKE_dgetrs_work(LAPACK_COL_MAJOR, 'N', N, (lapack_int)S, L->LU, N, L->ipiv, Z, N);
  if (info != 0) return RS_ERROR(RS_ERR_INTERNAL, "dgetrs info %d", (int)info);
  for (int j = 0; j < S; ++j)
    for (int i = 0; i < n; ++i) Z[(size_t)j * n + i] *= L->cs[i];
  return RS_OK;
}

/* The tableau of the full-stick state z0 and its response Z, scaled so that its entries are
 * O(1): margins w in units of qs, the largest mu pbar or |q| of the full-stick state; slips
 * in units of us = qs / max |dw/ds| */
static void lcp_fill(const rs_nip_contact *nc, const double *z0, const double *Z, lcp_tableau *tb)
{
  const int M = nc->M, n = nc->n, E = M - 1, S = tb->S, m = tb->m;
  const double mu[2] = {nc->cfg.mu_roll, nc->cfg.mu_drum};
  double qs = 0;
  for (int k = 0; k < 2; ++k)
    for (int e = 0; e < E; ++e)
      qs = fmax(qs, fmax(mu[k] * fabs(pbar_of(M, z0, e)), fabs(z0[COL_Q(k, e)])));
  if (!(qs > 0)) qs = 1;
  memset(tb->T, 0, (size_t)m * tb->W * sizeof *tb->T);
  double us = 0; /* u scale: the slip that changes a margin by qs */
  for (int k = 0; k < 2; ++k)
    for (int e = 0; e < E; ++e) {
      for (int j = 0; j < S; ++j) {
        const double *Zj = Z + (size_t)j * n;
        double pw = mu[k] * pbar_of(M, Zj, e), qw = Zj[COL_Q(k, e)];
        us = fmax(us, fabs(pw - qw));
        us = fmax(us, fabs(pw + qw));
      }
    }
  us = us > 0 ? qs / us : 1.0;
  for (int k = 0; k < 2; ++k)
    for (int e = 0; e < E; ++e) {
      int ip = k * E + e, im = S + ip; /* rows of w+ and w- */
      double p0 = mu[k] * pbar_of(M, z0, e), q0 = z0[COL_Q(k, e)];
      TT(tb, ip, ip) = 1;
      TT(tb, im, im) = 1;
      TT(tb, ip, tb->cr) = (p0 - q0) / qs;
      TT(tb, im, tb->cr) = (p0 + q0) / qs;
      TT(tb, ip, tb->ct) = -1;
      TT(tb, im, tb->ct) = -1;
      for (int j = 0; j < S; ++j) {
        const double *Zj = Z + (size_t)j * n;
        double pw = mu[k] * pbar_of(M, Zj, e), qw = Zj[COL_Q(k, e)];
        /* d w / d s+_j, scaled, moved to the left of w = c + Mt u */
        TT(tb, ip, m + j) = -(pw - qw) * us / qs;
        TT(tb, im, m + j) = -(pw + qw) * us / qs;
      }
    }
  for (int i = 0; i < m; ++i) tb->basis[i] = i;
}

/* Pivots on (r, enter); returns the variable that left the basis */
static int lcp_pivot(lcp_tableau *tb, int r, int enter)
{
  const int ce = lcp_col(tb, enter), W = tb->W;
  const double se = lcp_sign(tb, enter);
  double pv = se * TT(tb, r, ce);
  for (int j = 0; j < W; ++j) TT(tb, r, j) /= pv;
  for (int i = 0; i < tb->m; ++i) {
    if (i == r) continue;
    double f = se * TT(tb, i, ce);
    if (f == 0) continue;
    row_update(W, tb->T + (size_t)i * W, f, tb->T + (size_t)r * W);
  }
  int leaving = tb->basis[r];
  tb->basis[r] = enter;
  return leaving;
}

/* The ratio test for the entering variable: the row where its column is positive whose
 * rhs bounds it first (rhs stays >= 0); ties: the row of t first (ends), then the smallest
 * index. -1: none (a secondary ray). */
static int lcp_ratio_test(const lcp_tableau *tb, int enter)
{
  const int cn = lcp_col(tb, enter);
  const double sn = lcp_sign(tb, enter);
  int r = -1;
  double best = INFINITY;
  for (int i = 0; i < tb->m; ++i) {
    double col = sn * TT(tb, i, cn);
    if (!(col > 1e-12)) continue;
    double ratio = fmax(TT(tb, i, tb->cr), 0.0) / col, tie = 1e-12 * fmax(1.0, best);
    if (r < 0 || ratio < best - tie || (ratio <= best + tie && tb->basis[i] == tb->vt)) {
      best = ratio;
      r = i;
    }
  }
  return r;
}

/* Lemke's pivoting from the full-stick tableau: 1 at a solution, 0 on a secondary ray or
 * past the pivot cap (*pivots > cap) */
static int lcp_lemke(lcp_tableau *tb, int cap, int *pivots)
{
  int r = 0; /* start: c >= 0 is the full-stick solution */
  for (int i = 1; i < tb->m; ++i)
    if (TT(tb, i, tb->cr) < TT(tb, r, tb->cr)) r = i;
  if (TT(tb, r, tb->cr) >= 0) return 1;
  for (int enter = tb->vt;;) {
    int leaving = lcp_pivot(tb, r, enter);
    if (++*pivots > cap) return 0;
    if (leaving == tb->vt) return 1;
    /* the complement of the leaving variable enters */
    enter = leaving < tb->m ? leaving + tb->m : leaving - tb->m;
    if ((r = lcp_ratio_test(tb, enter)) < 0) return 0;
  }
}

/* The stick/slip state of the solution: slip forward (1) or backward (-1) where s+ or s- is
 * basic and positive, stick (0) elsewhere */
static void lcp_state(const lcp_tableau *tb, signed char *state_out)
{
  const int m = tb->m, S = tb->S;
  memset(state_out, 0, (size_t)S);
  for (int i = 0; i < m; ++i) {
    int v = tb->basis[i];
    if (v < m || v == tb->vt) continue; /* w or t */
    if (!(TT(tb, i, tb->cr) > 0)) continue;
    int j = v - m; /* u index: s+ for j < S, s- otherwise */
    state_out[j < S ? j : j - S] = j < S ? 1 : -1;
  }
}

#undef TT

rs_status rs_nipc_lcp(rs_nip_contact *nc, double a, double Ti, signed char *state_out, int *pivots)
{
  const int M = nc->M, n = nc->n, E = M - 1, S = 2 * E, m = 2 * S;
  *pivots = 0;
  if (m > 1024) /* the dense tableau is m x (m + S + 2) */
    return RS_ERROR(RS_ERR_SOLVER, "LCP fallback not run: %d complementarity pairs (M = %d > 257 "
                    "nodes) is too large for its dense tableau", m, M);
  /* full stick: K and b, and its factorization */
  memset(nc->state, 0, (size_t)S);
  rs_nipc_assemble(nc, a, Ti);
  nc->lin.want_double = 1; /* Z below solves with its factors */
  rs_status st = rs_nipc_lin_solve(nc, a);
  nc->lin.want_double = 0;
  if (st) return rs_error_wrap("LCP: full-stick system at a = %g m", a);
  if (!nc->lin.valid) return RS_ERROR(RS_ERR_INTERNAL, "LCP: no factorization");
  /* Unless the solve just factored K in double precision, the kept factorization is of an
   * older matrix (GMRES refined from it) or a single-precision one: factor K itself */
  if (!nc->lin.fresh || nc->lin.single) {
    st = rs_nipc_lin_refactor(nc, a);
    if (st) return rs_error_wrap("LCP: full-stick system at a = %g m", a);
  }
  lcp_tableau tb = {.m = m, .S = S, .W = (m + S + 2 + 3) & ~3, /* padded: see row_update */
                    .vt = 2 * m, .ct = m + S, .cr = m + S + 1};
  double *Z = calloc((size_t)n * S, sizeof *Z), *zz = malloc((size_t)n * sizeof *zz);
  tb.T = malloc((size_t)m * tb.W * sizeof *tb.T);
  tb.basis = malloc((size_t)m * sizeof *tb.basis);
  if (!Z || !tb.T || !tb.basis || !zz) {
    st = RS_ERROR(RS_ERR_MEMORY, "LCP work space (%d complementarity pairs)", m);
  } else {
    memcpy(zz, nc->z, (size_t)n * sizeof *zz); /* z0, from the solve above */
    st = lcp_stick_response(nc, Z);
  }
  if (st == RS_OK) {
    lcp_fill(nc, zz, Z, &tb);
    const int cap = 20 * m;
    if (lcp_lemke(&tb, cap, pivots))
      lcp_state(&tb, state_out);
    else
      st = RS_ERROR(RS_ERR_SOLVER, "Lemke's method for the stick/slip LCP at a = %g m %s after "
                    "%d pivots (%d complementarity pairs)", a,
                    *pivots > cap ? "hit its pivot cap" : "ended on a secondary ray", *pivots, m);
  }
  free(Z);
  free(tb.T);
  free(tb.basis);
  free(zz);
  return st;
}
