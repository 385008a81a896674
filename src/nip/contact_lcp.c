/* The stick/slip conditions at a fixed half-width as a linear complementarity problem
 * (LCP), solved by Lemke's complementary pivoting (Lemke 1965; Cottle, Pang & Stone 1992,
 * "The linear complementarity problem", sec. 4.4; contact_lemke.c).
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

/* Z = K^-1 E (n x S, column-major): column j is K^-1 e_{M+j} = diag(cs) Kq^-1 (rs_{M+j}
 * e_{M+j}), Kq the equilibrated matrix of the kept factorization; a solve a column
 * (contact_lu.c: LAPACK's dgetrs for the S columns at once takes fewer instructions, but
 * its blocked triangles go through OpenBLAS's work buffer, whose first touch costs ~60
 * page faults of ~12 us each: docs/performance.md) */
static void lcp_stick_response(const rs_nip_contact *nc, double *Z)
{
  const rs_nipc_lin *L = &nc->lin;
  const int M = nc->M, n = nc->n, S = 2 * (M - 1);
  for (int j = 0; j < S; ++j) {
    double *Zj = Z + (size_t)j * n;
    Zj[M + j] = L->rs[M + j];
    rs_nipc_lu_solve(n, L->LU, L->ipiv, Zj);
    for (int i = 0; i < n; ++i) Zj[i] *= L->cs[i];
  }
}

/* The starting tableau of the full-stick state z0 and its response Z (contact_lemke.c): the
 * right-hand side c (m) and the s+ columns U (m x S, column-major), scaled so that the
 * entries are O(1): margins w in units of qs, the largest mu pbar or |q| of the full-stick
 * state; slips in units of us = qs / max |dw/ds| */
static void lcp_fill(const rs_nip_contact *nc, const double *z0, const double *Z, int m, double *c,
                     double *U)
{
  const int M = nc->M, n = nc->n, E = M - 1, S = 2 * E;
  const double mu[2] = {nc->cfg.mu_roll, nc->cfg.mu_drum};
  double qs = 0;
  for (int k = 0; k < 2; ++k)
    for (int e = 0; e < E; ++e)
      qs = fmax(qs, fmax(mu[k] * fabs(pbar_of(M, z0, e)), fabs(z0[COL_Q(k, e)])));
  if (!(qs > 0)) qs = 1;
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
      c[ip] = (p0 - q0) / qs;
      c[im] = (p0 + q0) / qs;
      for (int j = 0; j < S; ++j) {
        const double *Zj = Z + (size_t)j * n;
        double pw = mu[k] * pbar_of(M, Zj, e), qw = Zj[COL_Q(k, e)];
        /* d w / d s+_j, scaled, moved to the left of w = c + Mt u */
        U[(size_t)j * m + ip] = -(pw - qw) * us / qs;
        U[(size_t)j * m + im] = -(pw + qw) * us / qs;
      }
    }
}

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
  double *Z = calloc((size_t)n * S, sizeof *Z), *zz = malloc((size_t)n * sizeof *zz);
  double *c = malloc((size_t)m * sizeof *c), *U = malloc((size_t)m * S * sizeof *U);
  if (!Z || !zz || !c || !U) {
    st = RS_ERROR(RS_ERR_MEMORY, "LCP work space (%d complementarity pairs)", m);
  } else {
    memcpy(zz, nc->z, (size_t)n * sizeof *zz); /* z0, from the solve above */
    lcp_stick_response(nc, Z);
  }
  if (st == RS_OK) {
    lcp_fill(nc, zz, Z, m, c, U);
    const int cap = 20 * m;
    int found = rs_nipc_lemke(m, S, U, c, RS_NIPC_LEMKE_REVISED_MAX(m), cap, state_out, NULL, pivots);
    if (found < 0)
      st = RS_ERROR(RS_ERR_MEMORY, "LCP work space (%d complementarity pairs)", m);
    else if (!found)
      st = RS_ERROR(RS_ERR_SOLVER, "Lemke's method for the stick/slip LCP at a = %g m %s after "
                    "%d pivots (%d complementarity pairs)", a,
                    *pivots > cap ? "hit its pivot cap" : "ended on a secondary ray", *pivots, m);
  }
  free(Z);
  free(zz);
  free(c);
  free(U);
  return st;
}
