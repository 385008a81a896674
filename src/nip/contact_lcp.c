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

/* The whole method in one function, as the textbooks give it (set up the tableau from the
 * full-stick solve, then pivot: entering variable, ratio test, pivot, complement), longer
 * than the project's 80 lines because split it reads worse: the tableau, the basis and the
 * pivot rule are one piece of state that every step reads and changes. */
rs_status rs_nipc_lcp(rs_nip_contact *nc, double a, double Ti, signed char *state_out, int *pivots)
{
  const int M = nc->M, n = nc->n, E = M - 1, S = 2 * E, m = 2 * S;
  const double mu[2] = {nc->cfg.mu_roll, nc->cfg.mu_drum};
  *pivots = 0;
  if (m > 1024) /* the dense tableau is m x (m + S + 2) */
    return RS_ERROR(RS_ERR_SOLVER, "LCP fallback not run: %d complementarity pairs (M = %d > 257 "
                    "nodes) is too large for its dense tableau", m, M);
  /* full stick: K and b, and its factorization */
  memset(nc->state, 0, (size_t)S);
  rs_nipc_assemble(nc, a, Ti);
  rs_status st = rs_nipc_lin_solve(nc, a);
  if (st) return rs_error_wrap("LCP: full-stick system at a = %g m", a);
  const rs_nipc_lin *L = &nc->lin;
  if (!L->valid) return RS_ERROR(RS_ERR_INTERNAL, "LCP: no factorization");
  /* Z = K^-1 E: column j is K^-1 e_{M+j} = diag(cs) Kq^-1 (rs_{M+j} e_{M+j}), Kq the
   * equilibrated matrix that is factored (nc->lin). Unless the solve just factored K, the
   * kept factorization is of an older matrix (GMRES refined from it): factor K itself. */
  if (!L->fresh) {
    st = rs_nipc_lin_refactor(nc, a);
    if (st) return rs_error_wrap("LCP: full-stick system at a = %g m", a);
  }
  double *Z = calloc((size_t)n * S, sizeof *Z);
  const int W = (m + S + 2 + 3) & ~3; /* tableau row length, padded (see row_update) */
  double *T = malloc((size_t)m * W * sizeof *T);
  int *basis = malloc((size_t)m * sizeof *basis);
  double *zz = malloc((size_t)n * sizeof *zz);
  if (!Z || !T || !basis || !zz) {
    free(Z);
    free(T);
    free(basis);
    free(zz);
    return RS_ERROR(RS_ERR_MEMORY, "LCP work space (%d complementarity pairs)", m);
  }
  memcpy(zz, nc->z, (size_t)n * sizeof *zz); /* z0, from the solve above */
  for (int j = 0; j < S; ++j) Z[(size_t)j * n + M + j] = L->rs[M + j];
  lapack_int N = (lapack_int)n;
  lapack_int info = LAPACKE_dgetrs_work(LAPACK_COL_MAJOR, 'N', N, (lapack_int)S, L->LU, N, L->ipiv, Z, N);
  if (info != 0) {
    st = RS_ERROR(RS_ERR_INTERNAL, "dgetrs info %d", (int)info);
    goto done;
  }
  for (int j = 0; j < S; ++j)
    for (int i = 0; i < n; ++i) Z[(size_t)j * n + i] *= L->cs[i];
  /* scales, so that the tableau entries are O(1): margins w in units of qs, the largest
   * mu pbar or |q| of the full-stick state; slips in units of us = qs / max |dw/ds| */
  double qs = 0;
  for (int k = 0; k < 2; ++k)
    for (int e = 0; e < E; ++e)
      qs = fmax(qs, fmax(mu[k] * fabs(pbar_of(M, zz, e)), fabs(zz[COL_Q(k, e)])));
  if (!(qs > 0)) qs = 1;
  /* Tableau rows i = 0..m-1: w_i - sum_j Mt_ij u_j - t = c_i. Variables: w_i (i < m),
   * s+_j (m + j), s-_j (m + S + j), t (VT). Stored columns: w (m), s+ (S), t, rhs; the
   * column of s-_j is minus that of s+_j in any basis (row operations keep the linear
   * relation), so it is not stored. */
  const int VT = 2 * m, CT = m + S, CR = m + S + 1;
#define TT(i, j) T[(size_t)(i) * W + (j)]
  memset(T, 0, (size_t)m * W * sizeof *T);
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
      double p0 = mu[k] * pbar_of(M, zz, e), q0 = zz[COL_Q(k, e)];
      TT(ip, ip) = 1;
      TT(im, im) = 1;
      TT(ip, CR) = (p0 - q0) / qs;
      TT(im, CR) = (p0 + q0) / qs;
      TT(ip, CT) = -1;
      TT(im, CT) = -1;
      for (int j = 0; j < S; ++j) {
        const double *Zj = Z + (size_t)j * n;
        double pw = mu[k] * pbar_of(M, Zj, e), qw = Zj[COL_Q(k, e)];
        /* d w / d s+_j, scaled, moved to the left of w = c + Mt u */
        TT(ip, m + j) = -(pw - qw) * us / qs;
        TT(im, m + j) = -(pw + qw) * us / qs;
      }
    }
  for (int i = 0; i < m; ++i) basis[i] = i;
  /* stored column and sign of a variable */
#define COLOF(v) ((v) == VT ? CT : (v) < m ? (v) : (v) < m + S ? (v) : (v) - S)
#define SGNOF(v) ((v) >= m + S && (v) < VT ? -1.0 : 1.0)
  /* start: c >= 0 is the full-stick solution */
  int r = 0;
  for (int i = 1; i < m; ++i)
    if (TT(i, CR) < TT(r, CR)) r = i;
  int found = TT(r, CR) >= 0;
  int enter = VT, cap = 20 * m;
  while (!found) {
    /* pivot on (r, enter) */
    const int ce = COLOF(enter);
    const double se = SGNOF(enter);
    double pv = se * TT(r, ce);
    for (int j = 0; j < W; ++j) TT(r, j) /= pv;
    for (int i = 0; i < m; ++i) {
      if (i == r) continue;
      double f = se * TT(i, ce);
      if (f == 0) continue;
      row_update(W, T + (size_t)i * W, f, T + (size_t)r * W);
    }
    int leaving = basis[r];
    basis[r] = enter;
    if (++*pivots > cap) break;
    if (leaving == VT) {
      found = 1;
      break;
    }
    /* the complement of the leaving variable enters */
    enter = leaving < m ? leaving + m : leaving - m;
    /* ratio test: rows where the entering column is positive (rhs stays >= 0); ties: the
     * row of t first (ends), then the smallest index */
    const int cn = COLOF(enter);
    const double sn = SGNOF(enter);
    r = -1;
    double best = INFINITY;
    for (int i = 0; i < m; ++i) {
      double col = sn * TT(i, cn);
      if (!(col > 1e-12)) continue;
      double ratio = fmax(TT(i, CR), 0.0) / col, tie = 1e-12 * fmax(1.0, best);
      if (r < 0 || ratio < best - tie || (ratio <= best + tie && basis[i] == VT)) {
        best = ratio;
        r = i;
      }
    }
    if (r < 0) break; /* secondary ray */
  }
#undef COLOF
#undef SGNOF
#undef TT
  if (found) {
    memset(state_out, 0, (size_t)S);
    for (int i = 0; i < m; ++i) {
      int v = basis[i];
      if (v < m || v == 2 * m) continue; /* w or t */
      double val = T[(size_t)i * W + CR];
      if (!(val > 0)) continue;
      int j = v - m; /* u index: s+ for j < S, s- otherwise */
      state_out[j < S ? j : j - S] = j < S ? 1 : -1;
    }
  } else {
    st = RS_ERROR(RS_ERR_SOLVER, "Lemke's method for the stick/slip LCP at a = %g m %s after %d "
                  "pivots (%d complementarity pairs)", a,
                  *pivots > cap ? "hit its pivot cap" : "ended on a secondary ray", *pivots, m);
  }
done:
  free(Z);
  free(T);
  free(basis);
  free(zz);
  return st;
}
