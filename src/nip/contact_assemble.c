/* The linear system of the discretised nip for one stick/slip active set: assembly of
 * eqs. (12)-(15), (20) and the physical scales its solver equilibrates with. The unknowns
 * and rows are laid out as contact_solve.c describes (COL_P, COL_Q, ROW_STICK in
 * contact_internal.h). Below the solvers (contact_linear.c, contact_lcp.c,
 * contact_solve.c), which all use it. */
#include "nip/contact_internal.h"

#include <math.h>
#include <string.h>

/* col[i] = (c - x[i]) * keep[i] over n entries (keep 1 or 0: a stick row keeps its value
 * exactly, a slip row gets 0) */
static void stick_rsub(int n, double *restrict col, double c, const double *restrict x,
                       const double *restrict keep)
{
  for (int i = 0; i < n; ++i) col[i] = (c - x[i]) * keep[i];
}

/* The right-hand side, the rows' kinds (keep: 1 stick, 0 slip) and the entries of the
 * columns past the shears (delta0, eps0, xi2, T0). */
static void assemble_rest(rs_nip_contact *nc, double a, double Ti, double f, double *keep)
{
  const int M = nc->M, n = nc->n, E = M - 1;
  const double dx = 2 * a / (M - 1), Rs = rs_nipc_rstar(nc);
  const rs_sheet *sh = &nc->cfg.sheet;
  double *b = nc->rhs;
  double *cD = nc->A + (size_t)(3 * M - 4) * n, *cE = cD + n, *cX = cE + n, *cT = cX + n;
  memset(cD, 0, (size_t)4 * n * sizeof *cD);
  for (int i = 0; i < M; ++i) {
    double x = -a + i * dx;
    cD[i] = -1.0;
    cE[i] = -x / Rs;
    b[i] = -x * x / (2 * Rs) + sh->c12 * Ti;
  }
  for (int k = 0; k < 2; ++k)
    for (int e = 0; e < E; ++e) {
      int r = ROW_STICK(k, e), stick = nc->state[k * E + e] == 0;
      keep[e + k * E] = stick ? 1.0 : 0.0;
      b[r] = stick ? -f * Ti : 0.0;
      if (stick && k == 1) cX[r] = 1.0;
      if (stick && k == 0) cT[r] = -f;
    }
  int r1 = 3 * M - 2, r2 = 3 * M - 1;
  cT[r1] = 1.0;
  cT[r2] = 1.0;
  b[r1] = Ti;
  b[r2] = rs_nipc_share(nc) * Ti;
}

/* Assembles A z = rhs (column-major) for the current active set, column by column: every
 * entry is written, the slices along the kernels contiguous. The rows (eqs. (12)-(15),
 * (20)):
 * - indentation (12) at node i, with v_k = -w_k, the corrected eq. (11) and
 *   N(x_i) = Ti + dx sum_{e < i} (q1 + q2):
 *     w1 + w2 + 2h c22 p - c12 N - delta0 - eps0 x / R* = -x^2 / (2 R*);
 * - contact k, element e: stick (13)/(14), imposed at the element's upstream node x_e
 *   (staggered by half a cell from the shear, Kalker-style upwind; docs/nip.md):
 *     c11 <N>_e/(2h) - c12 p_e - eps_k(x_e) + xi_k = 0,
 *   xi_2 an unknown, xi_1 from the wound-on condition (22): the wound sheet (tension T0,
 *   strain c11 T0/(2h) from its unstressed state) moves with the roll surface, whose
 *   circumference the nip shrinks by the mean strain eps1_mean = m P (mass balance over a
 *   revolution), so xi_1 = m dx sum p_j - c11 T0/(2h). (xi_1 = 0 would make the sheet on
 *   the roll run c11 T0/(2h) faster than the roll: forward slip everywhere, NIT = mu P
 *   even for rigid cylinders; docs/nip.md, "Wound-on condition".) <N>_e the mean of N
 *   over the dual cell [x_e - dx/2, x_e + dx/2] (exact): N(x_e) + dx/8 (Q_e - Q_{e-1}),
 *   Q = q1 + q2; or slip (15): q_k,e = mu_k sigma pbar_e, pbar_e = (p_e + p_{e+1})/2;
 * - (20): sheet equilibrium T0 - int (q1 + q2) = Ti; winder torque T0 - int q1 = share Ti. */
void rs_nipc_assemble(rs_nip_contact *nc, double a, double Ti)
{
  const int M = nc->M, n = nc->n, E = M - 1;
  const double dx = 2 * a / (M - 1);
  const rs_sheet *sh = &nc->cfg.sheet;
  const double mu[2] = {nc->cfg.mu_roll, nc->cfg.mu_drum};
  const double f = sh->c11 / (2 * sh->h), c22 = 2 * sh->h * sh->c22, c12dx = sh->c12 * dx;
  const double rms = nc->roll_mean_strain * dx;
  double *keep = nc->keep; /* 2E: the stick rows of contact 0, then 1 */
  assemble_rest(nc, a, Ti, f, keep);
  const double *pu0 = nc->ker[0][KP].pu, *pu1 = nc->ker[1][KP].pu;
  /* pressure columns */
  for (int j = 1; j < M - 1; ++j) {
    double *col = nc->A + (size_t)COL_P(j) * n;
    const double *u0 = pu0 + (M - 1 - j), *u1 = pu1 + (M - 1 - j);
    for (int i = 0; i < M; ++i) col[i] = u0[i] + u1[i];
    col[j] += c22;
    for (int k = 0; k < 2; ++k) {
      double *st = col + M + k * E;
      const double *pe = nc->ker[k][KP].pe + (M - 1 - j), *kp = keep + k * E;
      /* -pe (+ eps1_mean's m dx on the roll's rows) */
      if (k == 0) stick_rsub(E, st, rms, pe, kp);
      else stick_rsub(E, st, 0.0, pe, kp);
      if (kp[j] != 0.0) st[j] = k == 0 ? -pe[j] - sh->c12 + rms : -pe[j] - sh->c12;
      /* slip rows e = j (p_e) and e = j - 1 (p_{e+1}): -mu sigma / 2 */
      for (int e = j - 1; e <= j && e < E; ++e)
        if (kp[e] == 0.0) st[e] = -0.5 * mu[k] * nc->state[k * E + e];
    }
    col[3 * M - 2] = col[3 * M - 1] = 0.0;
  }
  /* shear columns */
  for (int kk = 0; kk < 2; ++kk) {
    const double *qu = nc->ker[kk][KQU].qu;
    for (int ee = 0; ee < E; ++ee) {
      double *col = nc->A + (size_t)COL_Q(kk, ee) * n;
      const double *u = qu + (M - 1 - ee);
      for (int i = 0; i <= ee; ++i) col[i] = u[i];
      for (int i = ee + 1; i < M; ++i) col[i] = u[i] - c12dx;
      for (int k = 0; k < 2; ++k) {
        double *st = col + M + k * E;
        const double *kp = keep + k * E;
        if (k == kk) {
          /* stick row e: f dx w - qe_k(e - ee), w = 0 (e < ee), 1/8, 7/8, 1 */
          const double *qe = nc->ker[k][KQE].qe + (M - 1 - ee);
          stick_rsub(ee, st, 0.0, qe, kp);
          if (ee < E) st[ee] = (f * dx * 0.125 - qe[ee]) * kp[ee];
          if (ee + 1 < E) st[ee + 1] = (f * dx * 0.875 - qe[ee + 1]) * kp[ee + 1];
          if (ee + 2 < E) stick_rsub(E - ee - 2, st + ee + 2, f * dx, qe + ee + 2, kp + ee + 2);
          if (kp[ee] == 0.0) st[ee] = 1.0; /* slip: q_k,e = ... */
        } else {
          for (int e = 0; e < ee; ++e) st[e] = 0.0;
          if (ee < E) st[ee] = f * dx * 0.125 * kp[ee];
          if (ee + 1 < E) st[ee + 1] = f * dx * 0.875 * kp[ee + 1];
          for (int e = ee + 2; e < E; ++e) st[e] = f * dx * kp[e];
        }
      }
      col[3 * M - 2] = -dx;
      col[3 * M - 1] = kk == 0 ? -dx : 0.0;
    }
  }
}

/* Physical scales of the unknowns and rows: the raw entries mix m/Pa (~1e-11), 1/Pa,
 * m/m and N/m, so plain equilibration (dgeequ) can let the pressure vanish against the
 * delta0 column. Reference values: indentation w_ref = a^2/(2R*), pressure p_ref giving
 * w_ref through the local compliance, strain s_ref = p_ref * the largest local strain
 * compliance, load P_ref = 2 a p_ref. */
void rs_nipc_scales(const rs_nip_contact *nc, double a, double *col, double *row)
{
  const int M = nc->M, n = nc->n, E = M - 1;
  const double dx = 2 * a / (M - 1), Rs = rs_nipc_rstar(nc);
  const rs_sheet *sh = &nc->cfg.sheet;
  const int d0 = rs_kernel_index(M, 0), d1 = rs_kernel_index(M, 1);
  double w_ref = a * a / (2 * Rs);
  double c_loc = fabs(nc->ker[0][KP].pu[d0]) + fabs(nc->ker[1][KP].pu[d0]) + 2 * sh->h * sh->c22;
  double p_ref = w_ref / c_loc;
  double e_loc = fmax(fmax(fabs(nc->ker[0][KP].pe[d0]), fabs(nc->ker[1][KP].pe[d0])),
                      fmax(fabs(nc->ker[0][KQE].qe[d1]), fabs(nc->ker[1][KQE].qe[d1])));
  e_loc = fmax(e_loc, fmax(sh->c11 * dx / (2 * sh->h), fabs(sh->c12)));
  double s_ref = p_ref * e_loc, P_ref = 2 * a * p_ref;
  for (int c = 0; c < n - 4; ++c) col[c] = p_ref;
  col[n - 4] = w_ref;
  col[n - 3] = w_ref * Rs / a;
  col[n - 2] = s_ref;
  col[n - 1] = P_ref;
  for (int r = 0; r < M; ++r) row[r] = w_ref;
  for (int r = M; r < M + 2 * E; ++r) row[r] = nc->state[r - M] ? p_ref : s_ref;
  row[n - 2] = row[n - 1] = P_ref;
}
