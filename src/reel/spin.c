/* The centrifugal load of a spinning roll (docs/roll-model.md, "Centrifugal load").
 *
 * Turn j, a <= r <= b, is a cylindrically orthotropic plane-stress annulus (E_r its tangent
 * stack modulus, E_theta, nu) under the body force c r, c = rho omega^2 (Pa/m^2). With
 * equilibrium d(r sigma_r)/dr - sigma_theta + c r^2 = 0 and compatibility
 * eps_r = d(r eps_theta)/dr for the compliance of src/storage/elastic.c, F = r sigma_r obeys
 *     r^2 F'' + r F' - g^2 F = -(3 + nu) c r^3,        g^2 = E_theta / E_r
 * (Lekhnitskii 1968): F = A r^g + B r^-g + F_p with the particular solution, zero at r = a,
 *     F_p = (3 + nu) c (r^3 - a^(3-g) r^g) / (g^2 - 9)
 *         = -(3 + nu) c r^3 l E((g - 3) l) / (g + 3),   l = ln(r/a), E(z) = expm1(z)/z
 * (finite at g = 3: no special case). Its faces: sr_p(a) = 0, sr_p(b) = F_p(b)/b, hoop
 * st_p = F_p' + c r^2; u/r = (st - nu sr)/E_theta. The homogeneous part carries the face
 * stresses (sr_a, sr_b - sr_p(b)) with elastic.c's face compliances (a1, a2, b1, b2), so
 *     u_a/a = a1 sr_a + a2 sr_b + c a0,    u_b/b = b1 sr_a + b2 sr_b + c b0,
 * continuity of u at every face and the core u = r_c E_c_inv sr_0 give a tridiagonal
 * system in the face stresses, the outer face free. A turn's mean hoop stress is its
 * equilibrium: ([r sr]_a^b + c (b^3 - a^3)/3) / (b - a). */
#include "reel/spin.h"

#include <math.h>
#include <stdlib.h>

#include "reel/result_internal.h"
#include "reelsim/core.h"
#include "reelsim/material.h"
#include "reelsim/recipe.h"
#include "util/error.h"

static double expm1_over(double z) { return fabs(z) < 1e-300 ? 1.0 : expm1(z) / z; }

typedef struct spin_turn {
  double a1, a2, a0; /* u_a/a = a1 sr_a + a2 sr_b + c a0 */
  double b1, b2, b0; /* u_b/b = b1 sr_a + b2 sr_b + c b0 */
} spin_turn;

static void spin_turn_coef(double a, double b, double E_r, double E_t, double nu, spin_turn *t)
{
  const double g = sqrt(E_t / E_r), L = log1p((b - a) / a);
  const double P = exp((g - 1.0) * L), Q = exp(-(g + 1.0) * L);
  const double D = Q * expm1(2.0 * g * L), S = P + Q, R = exp(-2.0 * L), gD = g / D;
  t->a1 = -(gD * S + nu) / E_t;
  t->a2 = 2.0 * gD / E_t;
  t->b1 = -2.0 * gD * R / E_t;
  t->b2 = (gD * S - nu) / E_t;
  /* the particular solution per unit c */
  const double Ep = L * expm1_over((g - 3.0) * L), k = (3.0 + nu) / (g + 3.0);
  const double srb = -k * b * b * Ep, stb = b * b * (1.0 - k * (1.0 + g * Ep));
  t->a0 = a * a * (g - nu) / ((g + 3.0) * E_t) - t->a2 * srb;
  t->b0 = (stb - nu * srb) / E_t - t->b2 * srb;
}

/* Solves the faces for the body forces c[0..n-1] given the turns' compliances. */
static rs_status spin_solve(int n, const double *s, const spin_turn *tc, double E_c_inv,
                            const double *c, double *dsr, double *dst, double *work)
{
  double *cp = work, *dp = work + (n + 1);
  for (int k = 0; k < n; ++k) {
    const spin_turn *above = &tc[k], *below = k ? &tc[k - 1] : NULL;
    const double sub = below ? below->b1 : 0.0;
    const double diag = below ? below->b2 - above->a1 : E_c_inv - above->a1;
    const double rhs = c[k] * above->a0 - (below ? c[k - 1] * below->b0 : 0.0);
    const double den = diag - (k ? sub * cp[k - 1] : 0.0);
    if (!(fabs(den) > 0.0) || !isfinite(den))
      return RS_ERROR(RS_ERR_SOLVER, "centrifugal load: the system is singular at face %d", k);
    cp[k] = -above->a2 / den;
    dp[k] = (rhs - (k ? sub * dp[k - 1] : 0.0)) / den;
  }
  dsr[n] = 0.0;
  dsr[n - 1] = dp[n - 1];
  for (int k = n - 2; k >= 0; --k) dsr[k] = dp[k] - cp[k] * dsr[k + 1];
  for (int k = 0; k < n; ++k) {
    const double a = s[k], b = s[k + 1];
    dst[k] = (b * dsr[k + 1] - a * dsr[k]) / (b - a) + c[k] * (a * a + a * b + b * b) / 3.0;
  }
  for (int k = 0; k <= n; ++k)
    if (!isfinite(dsr[k]))
      return RS_ERROR(RS_ERR_SOLVER, "centrifugal load: the stress is not finite at r = %g m", s[k]);
  return RS_OK;
}

static rs_status spin_coefs(int n, const double *s, const double *E_r, double E_theta, double nu,
                            spin_turn *tc)
{
  for (int k = 0; k < n; ++k) {
    if (!(E_r[k] > 0.0))
      return RS_ERROR(RS_ERR_SOLVER, "centrifugal load: layer %d at r = %g m has E_r = %g Pa",
                      k + 1, s[k + 1], E_r[k]);
    spin_turn_coef(s[k], s[k + 1], E_r[k], E_theta, nu, &tc[k]);
  }
  return RS_OK;
}

rs_status rs_spin_field(int n, const double *s, const double *E_r, double E_theta, double nu,
                        double E_c_inv, const double *c, double *dsr, double *dst, double *work)
{
  if (n < 1) return RS_OK;
  spin_turn *tc = malloc((size_t)n * sizeof *tc);
  if (!tc) return RS_ERROR(RS_ERR_MEMORY, "centrifugal load: out of memory (%d layers)", n);
  rs_status st = spin_coefs(n, s, E_r, E_theta, nu, tc);
  if (!st) st = spin_solve(n, s, tc, E_c_inv, c, dsr, dst, work);
  free(tc);
  return st;
}

/* The spin part, exact for linear layers with frozen moduli: layer j arrives at its own
 * omega_j = V(s_j) / s_j as a free spinning ring (hoop c_j r^2, no face load: its tension's
 * rho t V^2 is what it does not press with); as the roll grows it slows, a change of body
 * force on the roll wound so far, applied at `updates` checkpoints to each turn by the
 * difference between the new omega^2 and the one it last had; the stop takes the last
 * omega^2 off the whole roll. */
rs_status rs_spin_wound(const rs_problem *pb, rs_reel_result *res, int updates)
{
  const int n = res->n_layers;
  if (n < 1) return RS_OK;
  const rs_material *m = &pb->material;
  const double rho = m->density, Ec = rs_core_stiffness(&pb->core);
  const double E_c_inv = isfinite(Ec) ? 1.0 / Ec : 0.0, nu = m->nu_rtheta;
  const size_t N = (size_t)n + 1;
  double *buf = malloc(10 * N * sizeof(double));
  spin_turn *tc = malloc((size_t)n * sizeof *tc);
  res->at_speed_sigma_r = malloc((size_t)n * sizeof(double));
  res->at_speed_sigma_theta = malloc((size_t)n * sizeof(double));
  rs_status st = RS_OK;
  if (!buf || !tc || !res->at_speed_sigma_r || !res->at_speed_sigma_theta) {
    st = RS_ERROR(RS_ERR_MEMORY, "centrifugal load: out of memory (%d layers)", n);
    goto done;
  }
  double *s = buf, *Er = buf + N, *lev = buf + 2 * N, *c = buf + 3 * N, *Sr = buf + 4 * N,
         *St = buf + 5 * N, *dsr = buf + 6 * N, *dst = buf + 7 * N, *work = buf + 8 * N;
  s[0] = res->core_radius;
  for (int j = 0; j < n; ++j) s[j + 1] = res->radius[j];
  for (int j = 0; j < n; ++j) {
    const double lo = j ? res->sigma_r[j - 1] : -res->core_pressure, hi = res->sigma_r[j];
    Er[j] = rs_radial_modulus(&m->radial, fmax(0.0, -0.5 * (lo + hi)));
    /* entrained air: the film under the turn in series with its stack, over the turn's
     * real thickness s[j+1] - s[j] (the caliper and the film) */
    if (res->air_film_entrained)
      Er[j] = rs_air_series_modulus(Er[j], m->caliper, res->air_film_entrained[j],
                                    fmax(0.0, -0.5 * (lo + hi)), pb->air.pressure) *
              ((s[j + 1] - s[j]) / m->caliper);
  }
  if ((st = spin_coefs(n, s, Er, m->E_theta, nu, tc))) goto done;
  for (int j = 0; j <= n; ++j) Sr[j] = St[j] = 0.0;
  const int every = updates > 0 ? (n + updates - 1) / updates : (n + 255) / 256;
  int done_to = 0; /* layers that have arrived */
  while (done_to < n) {
    const int k = done_to + every < n ? done_to + every : n;
    for (int j = done_to; j < k; ++j) { /* arrivals: free rings at their own speed */
      const double w = rs_recipe_eval(&pb->speed, s[j + 1]) / s[j + 1], a = s[j], b = s[j + 1];
      lev[j] = rho * w * w;
      St[j] += lev[j] * (a * a + a * b + b * b) / 3.0;
    }
    done_to = k;
    /* the roll of k layers slows to the omega the next layer arrives at (the last: its own) */
    const double sk = k < n ? s[k + 1] : s[n], w = rs_recipe_eval(&pb->speed, sk) / sk;
    const double target = rho * w * w;
    int any = 0;
    for (int j = 0; j < k; ++j) {
      c[j] = target - lev[j];
      any |= c[j] != 0.0;
      lev[j] = target;
    }
    if (!any) continue;
    if ((st = spin_solve(k, s, tc, E_c_inv, c, dsr, dst, work))) goto done;
    for (int j = 0; j <= k; ++j) Sr[j] += dsr[j];
    for (int j = 0; j < k; ++j) St[j] += dst[j];
  }
  for (int j = 0; j < n; ++j) {
    res->at_speed_sigma_r[j] = res->sigma_r[j] + Sr[j + 1];
    res->at_speed_sigma_theta[j] = res->sigma_theta[j] + St[j];
  }
  res->at_speed_core_pressure = res->core_pressure - Sr[0];
  /* the stop: every turn's omega^2 (now the last layer's) goes to 0 */
  for (int j = 0; j < n; ++j) c[j] = -lev[j];
  if (lev[0] != 0.0 && (st = spin_solve(n, s, tc, E_c_inv, c, dsr, dst, work))) goto done;
  if (lev[0] == 0.0)
    for (int j = 0; j <= n; ++j) dsr[j] = dst[j] = 0.0;
  for (int j = 0; j < n; ++j) {
    res->sigma_r[j] = res->at_speed_sigma_r[j] + dsr[j + 1];
    res->sigma_theta[j] = res->at_speed_sigma_theta[j] + dst[j];
  }
  res->core_pressure = res->at_speed_core_pressure - dsr[0];
done:
  free(buf);
  free(tc);
  return st;
}
