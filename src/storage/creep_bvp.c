/* The elastic boundary value problem of the creep model (docs/storage.md, "Creep"): the
 * stress rates of the roll whose turns creep at given strain rates.
 *
 * Turn j (faces s_{j-1}, s_j, mid-radius m_j, caliper t) has uniform stresses
 *     R_j = (sigma_r(j-1) + sigma_r(j)) / 2,   H_j = (s_j sigma_r(j) - s_{j-1} sigma_r(j-1)) / t
 * (H_j: the turn's equilibrium, d(r sigma_r)/dr = sigma_theta, exactly), and uniform strains
 *     eps_r = R_j / E_r,j - nu H_j / E_theta + c_r,j,
 *     eps_theta = (H_j - nu R_j) / E_theta + c_theta,j,
 * met by the radial displacements of its faces: u_j - u_{j-1} = t eps_r and
 * (u_j + u_{j-1}) / 2 = m_j eps_theta (a box scheme: second order in t). So turn j's faces
 * move by u_j = m_j eps_theta + (t/2) eps_r and u_{j-1} = m_j eps_theta - (t/2) eps_r, and
 * the rates of sigma_r at the faces 0..n-1 are fixed by
 *     face j = 1..n-1:  both turns give face j the same displacement (compatibility)
 *     face 0 (core):    u_0 = r_c sigma_r(0) / E_c      (rigid: 0; the core does not creep)
 *     face n (outside): sigma_r(n) = 0                  (free)
 * a tridiagonal system. Every equation is multiplied by t E_theta so that its coefficients
 * are O(s^2) (m, s in m). It is an M-matrix (off-diagonals negative, rows dominated by
 * t (1/E_r - 1/E_theta) > 0) except the core row, and elimination runs from the core
 * outwards, the direction in which the discrete Riccati recursion of the pivots is stable
 * (the continuum's w = r y'/y integrated outwards, docs/roll-model.md). */
#include <math.h>

#include "storage/creep.h"

/* turn j's face displacements (times t E_theta) as a_lo sigma(j-1) + a_hi sigma(j) + e */
typedef struct creep_turn {
  double up_lo, up_hi, up_e; /* outer face s_j */
  double dn_lo, dn_hi, dn_e; /* inner face s_{j-1} */
} creep_turn;

static creep_turn creep_turn_make(const rs_creep_params *p, int j, double E_r, double c_r,
                                  double c_theta)
{
  const double t = p->caliper, h = 0.5 * t, nu = p->nu_rtheta, E = p->E_theta;
  const double s0 = p->core_radius + (j - 1) * t, s1 = s0 + t, m = s0 + h;
  const double rho = E / E_r;
  /* eps_r t E = al sigma(j-1) + be sigma(j) + t E c_r; eps_theta t E = ga sigma(j-1) + de sigma(j) + ... */
  const double al = h * rho + nu * s0, be = h * rho - nu * s1;
  const double ga = -s0 - h * nu, de = s1 - h * nu;
  const double er = t * E * c_r, et = t * E * c_theta;
  return (creep_turn){m * ga + h * al, m * de + h * be, m * et + h * er,
                      m * ga - h * al, m * de - h * be, m * et - h * er};
}

void rs_creep_bvp(const rs_creep_params *p, const double *E_r, const double *c_r,
                  const double *c_theta, double *ds, double *work)
{
  const int n = p->n_layers;
  const double t = p->caliper, E = p->E_theta;
  const double core = isinf(p->core_stiffness) ? 0.0 : t * E * p->core_radius / p->core_stiffness;
  double *cp = work; /* Thomas: the eliminated super-diagonal; ds holds the eliminated rhs */
  creep_turn lo = creep_turn_make(p, 1, E_r[0], c_r[0], c_theta[0]);
  /* face 0: -(Dn_1) + core sigma(0) = Dn_1's eigenstrain part */
  double b = -lo.dn_lo + core, c = -lo.dn_hi, d = lo.dn_e;
  cp[0] = c / b;
  ds[0] = d / b;
  for (int j = 1; j < n; ++j) {
    const creep_turn hi = creep_turn_make(p, j + 1, E_r[j], c_r[j], c_theta[j]);
    const double a = lo.up_lo;
    b = lo.up_hi - hi.dn_lo;
    c = -hi.dn_hi;
    d = hi.dn_e - lo.up_e;
    const double piv = b - a * cp[j - 1];
    cp[j] = c / piv;
    ds[j] = (d - a * ds[j - 1]) / piv;
    lo = hi;
  }
  for (int j = n - 2; j >= 0; --j) ds[j] -= cp[j] * ds[j + 1];
}
