/* The linear system of the discretised nip for one stick/slip active set: assembly of
 * eqs. (12)-(15), (20) and the physical scales its solver equilibrates with. The unknowns
 * and rows are laid out as contact_solve.c describes (COL_P, COL_Q, ROW_STICK in
 * contact_internal.h). Below the solvers (contact_linear.c, contact_lcp.c,
 * contact_solve.c), which all use it. */
#include "nip/contact_internal.h"

#include <math.h>
#include <string.h>

/* Assembles A z = rhs (column-major) for the current active set. */
void rs_nipc_assemble(rs_nip_contact *nc, double a, double Ti)
{
  const int M = nc->M, n = nc->n, E = M - 1;
  const double dx = 2 * a / (M - 1), Rs = rs_nipc_rstar(nc);
  const rs_sheet *sh = &nc->cfg.sheet;
  const double mu[2] = {nc->cfg.mu_roll, nc->cfg.mu_drum};
  double *A = nc->A, *b = nc->rhs;
  const int cD = 3 * M - 4, cE = 3 * M - 3, cX = 3 * M - 2, cT = 3 * M - 1;
#define AT(r, c) A[(size_t)(c) * n + (r)]
  /* Every entry this assembly leaves untouched is zero. The rows' pattern of nonzeros
   * depends only on their stick/slip kind, so the whole matrix is zeroed once, and after
   * that only the rows whose kind changed since the last assembly (nc->A_state) are
   * cleared; the others are overwritten entry for entry. */
  if (!nc->A_valid) {
    memset(A, 0, (size_t)n * n * sizeof *A);
    nc->A_valid = 1;
  } else {
    for (int k = 0; k < 2 * E; ++k)
      if ((nc->state[k] == 0) != (nc->A_state[k] == 0))
        for (int c = 0; c < n; ++c) AT(M + k, c) = 0.0;
  }
  memcpy(nc->A_state, nc->state, (size_t)2 * E);
  /* indentation (12) at node i, with v_k = -w_k, the corrected eq. (11) and
   * N(x_i) = Ti + dx sum_{e < i} (q1 + q2):
   *   w1 + w2 + 2h c22 p - c12 N - delta0 - eps0 x / R* = -x^2 / (2 R*) */
  for (int i = 0; i < M; ++i) {
    double x = -a + i * dx;
    for (int j = 1; j < M - 1; ++j) {
      int d = rs_kernel_index(M, i - j);
      AT(i, COL_P(j)) = nc->ker[0][KP].pu[d] + nc->ker[1][KP].pu[d];
    }
    if (i > 0 && i < M - 1) AT(i, COL_P(i)) += 2 * sh->h * sh->c22;
    for (int k = 0; k < 2; ++k)
      for (int e = 0; e < E; ++e) {
        int d = rs_kernel_index(M, i - e);
        AT(i, COL_Q(k, e)) = nc->ker[k][KQU].qu[d] - (e < i ? sh->c12 * dx : 0.0);
      }
    AT(i, cD) = -1.0;
    AT(i, cE) = -x / Rs;
    b[i] = -x * x / (2 * Rs) + sh->c12 * Ti;
  }
  /* contact k, element e: stick (13)/(14), imposed at the element's upstream node x_e
   * (staggered by half a cell from the shear, Kalker-style upwind; docs/nip.md):
   *   c11 <N>_e/(2h) - c12 p_e - eps_k(x_e) + xi_k = 0,
   * xi_2 an unknown, xi_1 from the wound-on condition (22): the wound sheet (tension T0,
   * strain c11 T0/(2h) from its unstressed state) moves with the roll surface, whose
   * circumference the nip shrinks by the mean strain eps1_mean = m P (mass balance over a
   * revolution), so xi_1 = m dx sum p_j - c11 T0/(2h). (xi_1 = 0 would make the sheet on the
   * roll run c11 T0/(2h) faster than the roll: forward slip everywhere, NIT = mu P even for
   * rigid cylinders; docs/nip.md, "Wound-on condition".)
   * <N>_e the mean of N over the dual cell [x_e - dx/2, x_e + dx/2] (exact):
   *   N(x_e) + dx/8 (Q_e - Q_{e-1}), Q = q1 + q2;
   * or slip (15): q_k,e = mu_k sigma pbar_e, pbar_e = (p_e + p_{e+1})/2 */
  for (int k = 0; k < 2; ++k)
    for (int e = 0; e < E; ++e) {
      int r = ROW_STICK(k, e);
      signed char s = nc->state[k * E + e];
      if (s == 0) {
        for (int j = 1; j < M - 1; ++j) AT(r, COL_P(j)) = -nc->ker[k][KP].pe[rs_kernel_index(M, e - j)];
        if (e >= 1) AT(r, COL_P(e)) -= sh->c12;
        double f = sh->c11 / (2 * sh->h);
        for (int kk = 0; kk < 2; ++kk)
          for (int ee = 0; ee <= e; ++ee)
            AT(r, COL_Q(kk, ee)) = f * dx * (ee == e ? 0.125 : ee == e - 1 ? 0.875 : 1.0);
        for (int ee = 0; ee <= e; ++ee) AT(r, COL_Q(k, ee)) -= nc->ker[k][KQE].qe[rs_kernel_index(M, e - ee)];
        for (int ee = e + 1; ee < E; ++ee) AT(r, COL_Q(k, ee)) = 0.0 - nc->ker[k][KQE].qe[rs_kernel_index(M, e - ee)];
        if (k == 1) AT(r, cX) = 1.0;
        if (k == 0) {
          AT(r, cT) = -f;
          for (int j = 1; j < M - 1; ++j) AT(r, COL_P(j)) += nc->roll_mean_strain * dx;
        }
        b[r] = -f * Ti;
      } else {
        AT(r, COL_Q(k, e)) = 1.0;
        double m = -0.5 * mu[k] * s;
        if (e >= 1) AT(r, COL_P(e)) = m;
        if (e + 1 <= M - 2) AT(r, COL_P(e + 1)) = m;
        b[r] = 0.0;
      }
    }
  /* (20): sheet equilibrium T0 - int (q1 + q2) = Ti; winder torque T0 - int q1 = share Ti */
  int r1 = 3 * M - 2, r2 = 3 * M - 1;
  for (int e = 0; e < E; ++e) {
    AT(r1, COL_Q(0, e)) = -dx;
    AT(r1, COL_Q(1, e)) = -dx;
    AT(r2, COL_Q(0, e)) = -dx;
  }
  AT(r1, cT) = 1.0;
  AT(r2, cT) = 1.0;
  b[r1] = Ti;
  b[r2] = rs_nipc_share(nc) * Ti;
#undef AT
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
