/* The elastic response of a wound roll to free (thermal, hygroscopic, creep) strains
 * (docs/storage.md, "Every turn an annulus").
 *
 * Turn k, a <= r <= b, is a cylindrically orthotropic plane-stress annulus with constants
 * E_r (the stack's tangent modulus), E_theta, nu and uniform free strains e_r, e_theta:
 *     eps_theta = (sigma_theta - nu sigma_r) / E_theta + e_theta,
 *     eps_r     = sigma_r / E_r - nu sigma_theta / E_theta + e_r,
 * equilibrium sigma_theta = d(r sigma_r)/dr, compatibility eps_r = d(r eps_theta)/dr. With
 * F = r sigma_r: r^2 F'' + r F' - g^2 F = E_theta r (e_r - e_theta), g^2 = E_theta / E_r, so
 * (Lekhnitskii 1968 plus a particular solution; x = r/a, d = e_r - e_theta)
 *     sigma_r     = A x^(g-1) + B x^(-g-1) + E_theta d psi(x),
 *     sigma_theta = g (A x^(g-1) - B x^(-g-1)) + E_theta d (psi(x) + x^(g-1) / (g + 1)),
 *     psi(x) = (x^(g-1) - 1) / (g^2 - 1)   (-> ln(x) / 2 as g -> 1: no special case),
 *     u = r (eps_theta).
 * Given the radial stresses on both faces, A and B follow and with them u/r on both faces:
 *     u_a/a = [-(g S/D + nu) sr_a + (2g/D) sr_b] / E_theta + d c_a + e_theta
 *     u_b/b = [-(2g R/D) sr_a + (g S/D - nu) sr_b] / E_theta + d c_b + e_theta
 * with P = x_b^(g-1), Q = x_b^(-g-1), D = P - Q, S = P + Q, R = P Q, psi_b = psi(x_b),
 *     c_a = 1/(g + 1) - 2 g psi_b / D,   c_b = psi_b + P/(g + 1) - g S psi_b / D.
 * The faces' displacements are continuous; the core's u(r_c) = r_c (sr_0 / E_c + e_c); the
 * outer face is free (sr_n = 0 in the change). One equation a face in the face stresses:
 * a tridiagonal system, diagonally dominant (its off-diagonals negative, the excess of the
 * diagonal (P - 1)(1 - Q) g/D >= 0 for g >= 1), solved by elimination without pivoting.
 * Unlike shooting from the core, nothing grows like (r/r_c)^(g-1). */
#include <math.h>

#include "storage/storage_internal.h"
#include "util/error.h"
#include "storage/storage_result.h"

/* expm1(z)/z, 1 at z = 0 */
static double expm1_over(double z) { return fabs(z) < 1e-300 ? 1.0 : expm1(z) / z; }

typedef struct turn_coef {
  double a1, a2, a0; /* u_a/a = a1 sr_a + a2 sr_b + a0 */
  double b1, b2, b0; /* u_b/b = b1 sr_a + b2 sr_b + b0 */
} turn_coef;

static void turn(double a, double b, double E_r, double E_t, double nu, double e_r, double e_t,
                 turn_coef *c)
{
  const double g = sqrt(E_t / E_r), L = log1p((b - a) / a);
  const double P = exp((g - 1.0) * L), Q = exp(-(g + 1.0) * L);
  const double D = Q * expm1(2.0 * g * L), S = P + Q, R = exp(-2.0 * L);
  /* psi_b = (P - 1)/(g^2 - 1) = L expm1((g-1)L)/((g-1)L) / (g + 1) */
  const double psi = L * expm1_over((g - 1.0) * L) / (g + 1.0);
  const double gD = g / D, d = e_r - e_t;
  c->a1 = -(gD * S + nu) / E_t;
  c->a2 = 2.0 * gD / E_t;
  c->a0 = d * (1.0 / (g + 1.0) - 2.0 * gD * psi) + e_t;
  c->b1 = -2.0 * gD * R / E_t;
  c->b2 = (gD * S - nu) / E_t;
  c->b0 = d * (psi + P / (g + 1.0) - gD * S * psi) + e_t;
}

rs_status rs_storage_elastic(rs_storage_roll *roll, const rs_storage_load *ld, double *dsr,
                             double *dst)
{
  const int n = roll->n;
  const rs_material *m = &roll->problem->material;
  const double nu = m->nu_rtheta, *s = roll->s;
  double *cp = roll->work, *dp = roll->work + (n + 1);
  turn_coef below = {0}, above;
  ++roll->solves;
  /* face k (0..n-1): u_b/b of the turn below (the core's for k = 0) = u_a/a of turn k+1:
   *   b1 sr_{k-1} + (b2 - a1) sr_k - a2 sr_{k+1} = a0 - b0 */
  for (int k = 0; k < n; ++k) {
    const double E_r = ld->E_r[k], E_t = ld->E_theta ? ld->E_theta[k] : m->E_theta;
    const double e_r = (ld->de_r ? ld->de_r[k] : 0.0) + ld->de_r_all;
    const double e_t = (ld->de_theta ? ld->de_theta[k] : 0.0) + ld->de_theta_all;
    if (!(E_r > 0.0) || !(E_t > 0.0))
      return RS_ERROR(RS_ERR_SOLVER,
                      "storage: layer %d at r = %g m has a radial modulus E_r = %g Pa (pressure "
                      "%g Pa): not positive", k + 1, s[k + 1], E_r,
                      -0.5 * (roll->sr[k] + roll->sr[k + 1]));
    turn(s[k], s[k + 1], E_r, E_t, nu, e_r, e_t, &above);
    double sub, diag, rhs;
    if (k == 0) {
      sub = 0.0;
      diag = roll->E_c_inv - above.a1;
      rhs = above.a0 - ld->de_core;
    } else {
      sub = below.b1;
      diag = below.b2 - above.a1;
      rhs = above.a0 - below.b0;
    }
    const double super = -above.a2; /* the coefficient of sr_{k+1}; sr_n = 0 drops it */
    const double den = diag - (k ? sub * cp[k - 1] : 0.0);
    if (!(fabs(den) > 0.0) || !isfinite(den))
      return RS_ERROR(RS_ERR_SOLVER, "storage: the elastic system is singular at face %d", k);
    cp[k] = super / den;
    dp[k] = (rhs - (k ? sub * dp[k - 1] : 0.0)) / den;
    below = above;
  }
  dsr[n] = 0.0;
  dsr[n - 1] = dp[n - 1];
  for (int k = n - 2; k >= 0; --k) dsr[k] = dp[k] - cp[k] * dsr[k + 1];
  const double t = m->caliper;
  for (int k = 1; k <= n; ++k) dst[k - 1] = (s[k] * dsr[k] - s[k - 1] * dsr[k - 1]) / t;
  for (int k = 0; k <= n; ++k)
    if (!isfinite(dsr[k]))
      return RS_ERROR(RS_ERR_SOLVER, "storage: the stress change is not finite at r = %g m", s[k]);
  return RS_OK;
}
