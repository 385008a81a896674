/* The reused deep part corrected to first order for the modulus drift (docs/roll-model.md,
 * "The deep part corrected for the drift").
 *
 * Below an increment's start node the engine keeps the reference's (w, L), integrated with
 * the modulus E_ref of the reference's time. Since then each increment has added c e_j to
 * the radial stress there (e the reference's shape, rsi_roll_block_increment), so the pressure
 * is P_ref - C e_j, C = ref_c the sum of those c, and g^2 = E_theta/E_r has moved by
 *     dg^2_j = -g^2_ref (dE_r/dP / E_ref) (-C e_j) = C beta_j,   beta_j = g^2_ref kappa_j e_j,
 * kappa = d ln E_r / dP at P_ref (first order in the drift eps = E_r/E_ref - 1). The
 * reference's solution moves, to first order, by C (p_w, p_L), the solution of the Riccati
 * pair linearised about it, from the core (where w = kc and L = 0 are fixed):
 *     p_w' = beta(x) - 2 (1 + w) p_w,    p_L' = p_w,    p_w = p_L = 0 at r_c.
 * An increment that starts at j0 then starts from (w, L) + C (p_w, p_L) there, and its
 * part below j0 is c e_j exp(C (p_L,j - p_L,j0)) = c (1 - C p_L,j0) e_j + c C e_j p_L,j to
 * first order: two scales, so the deep part stays lazy (roll_lazy.c). What is left is
 * second order in the drift (the curvature of 1/E_r, the Riccati term -p_w^2 C^2, the
 * pressure the correction itself adds, the exponential's), so the start-node search holds
 * eps^2 rather than eps to the tolerance (rsi_roll_profile_bound), and the start stays near the
 * surface however many increments the reference serves: the nodes that must be integrated
 * again at every increment are those the last increment's own drift reaches, not the
 * ones the drift since the reference does. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "roll/roll_internal.h"
#include "util/float_flags.h"
#include "util/vector_clones.h"

/* the profile's block of nodes (its moduli a block at a time) */
enum { RS_PROFILE_BLOCK = 256 };

/* e^-z, phi_m = int_0^1 e^(-z (1 - s)) s^m ds and psi_m = int_0^1 s^m (1 - e^(-z (1 - s)))/z ds
 * (m = 0, 1, 2): by their Taylor sums (truncation below z^5/720 relative for |z| < 0.03: a
 * thin layer, z ~ 2 g t / r) when series != 0, else in closed form, psi_m = (1/(m+1) -
 * phi_m)/z */
static inline void roll_profile_weights(double z, int series, double *q, double phi[3],
                                        double psi[3])
{
  if (series) {
    *q = 1.0 - z * (1.0 - z * (1.0 / 2 - z * (1.0 / 6 - z * (1.0 / 24 - z * (1.0 / 120)))));
    phi[0] = 1.0 - z * (1.0 / 2 - z * (1.0 / 6 - z * (1.0 / 24 - z * (1.0 / 120))));
    phi[1] = 1.0 / 2 - z * (1.0 / 6 - z * (1.0 / 24 - z * (1.0 / 120 - z * (1.0 / 720))));
    phi[2] = 1.0 / 3 - z * (1.0 / 12 - z * (1.0 / 60 - z * (1.0 / 360 - z * (1.0 / 2520))));
    psi[0] = 1.0 / 2 - z * (1.0 / 6 - z * (1.0 / 24 - z * (1.0 / 120 - z * (1.0 / 720))));
    psi[1] = 1.0 / 6 - z * (1.0 / 24 - z * (1.0 / 120 - z * (1.0 / 720 - z * (1.0 / 5040))));
    psi[2] = 1.0 / 12 - z * (1.0 / 60 - z * (1.0 / 360 - z * (1.0 / 2520 - z * (1.0 / 20160))));
  } else {
    *q = exp(-z);
    phi[0] = (1.0 - *q) / z;
    phi[1] = (1.0 - phi[0]) / z;
    phi[2] = (1.0 - 2.0 * phi[1]) / z;
    psi[0] = (1.0 - phi[0]) / z;
    psi[1] = (1.0 / 2 - phi[1]) / z;
    psi[2] = (1.0 / 3 - phi[2]) / z;
  }
}

/* Layer j's coefficients of the recurrence (rsi_roll_profile_build): over the layer
 * p_w(end) = Q p_w(start) + Cf and int p_w dx = A p_w(start) + B, from its length h in x
 * and z = (2 + w_j + w_j+1) h, g^2 at its ends (g0, g1) and e^(v - ln g^2_j) at its middle
 * (ex), d ln g^2 / dC at its ends (u0, u1) and the slopes of that cubic there (um, up).
 * The one formula of every layer (the inner layers' vectorised pass and the others alike);
 * the Taylor sums of the weights when series != 0 (|z| < 0.03), else the closed forms. */
static inline void roll_profile_coef(double h, double z, int series, double g0, double g1,
                                     double ex, double u0, double u1, double um, double up,
                                     double *Q, double *Cf, double *A, double *B)
{
  const double gm = g0 * ex;
  const double b0 = g0 * u0, b1 = g1 * u1;
  const double bm = gm * (0.5 * (u0 + u1) + 0.125 * (um - up));
  const double a1 = -3.0 * b0 + 4.0 * bm - b1, a2 = 2.0 * (b0 - 2.0 * bm + b1);
  double phi[3], psi[3];
  roll_profile_weights(z, series, Q, phi, psi);
  *Cf = h * (b0 * phi[0] + a1 * phi[1] + a2 * phi[2]);
  *A = h * phi[0];
  *B = h * h * (b0 * psi[0] + a1 * psi[1] + a2 * psi[2]);
}

/* Layer j's coefficients (roll_profile_coef) at any layer: d holds the differences of
 * ln g^2 between neighbours, u the nodes' d ln g^2 / dC, nodes 0..top; the cubics at the
 * middle, v - ln g^2_j = d_j/2 + (m0 - m1)/8, the slopes' difference m0 - m1 =
 * (d_{j-1} - d_{j+1})/2 inside and 0 at an end interval (one-sided slopes); exp() where
 * the Taylor sums do not hold */
static inline void roll_profile_layer(int j, int top, const double *restrict d,
                                      const double *restrict u, const double *restrict E,
                                      const double *restrict w, const double *restrict x,
                                      double Eth, double *Q, double *Cf, double *A, double *B)
{
  const double dm = j > 0 ? d[j - 1] : d[j], dp = j + 1 < top ? d[j + 1] : d[j];
  const double um = j > 0 ? 0.5 * (u[j + 1] - u[j - 1]) : u[j + 1] - u[j];
  const double up = j + 1 < top ? 0.5 * (u[j + 2] - u[j]) : u[j + 1] - u[j];
  const double dv = 0.5 * d[j] + 0.0625 * (dm - dp);
  const double h = x[j + 1] - x[j], z = (2.0 + (w[j] + w[j + 1])) * h;
  roll_profile_coef(h, z, fabs(z) < 0.03, Eth / E[j], Eth / E[j + 1], roll_exp_step(dv), u[j],
                    u[j + 1], um, up, Q, Cf, A, B);
}

/* roll_profile_layer for the layers in..top-2 (in >= 1: both neighbours' slopes centred)
 * where the Taylor sums hold, in a loop over arrays passed as such, that vectorises;
 * returns a flag raised (rs_flag_raised) when some layer's sums do not hold (the caller does
 * those again) */
RS_VECTOR_CLONES static uint64_t roll_profile_inner(int in, int top, const double *restrict d,
                                                   const double *restrict u,
                                                   const double *restrict E,
                                                   const double *restrict w,
                                                   const double *restrict x, double Eth,
                                                   double *restrict Q, double *restrict Cf,
                                                   double *restrict A, double *restrict B)
{
  uint64_t wide = 0; /* from the bits (util/float_flags.h): the loop vectorises */
  const uint64_t limit = rs_double_bits(0.03);
  for (int j = in; j + 1 < top; ++j) {
    const double h = x[j + 1] - x[j], z = (2.0 + (w[j] + w[j + 1])) * h;
    const double dv = 0.5 * d[j] + 0.0625 * (d[j - 1] - d[j + 1]);
    wide |= rs_flag_not_below(z, limit) | rs_flag_not_below(dv, limit); /* NaN: prof.top -1 */
    double q, cf, a, b; /* locals, stored after: the loop vectorises */
    roll_profile_coef(h, z, 1, Eth / E[j], Eth / E[j + 1], roll_exp_small(dv), u[j], u[j + 1],
                      0.5 * (u[j + 1] - u[j - 1]), 0.5 * (u[j + 2] - u[j]), &q, &cf, &a, &b);
    Q[j] = q;
    Cf[j] = cf;
    A[j] = a;
    B[j] = b;
  }
  return wide;
}

/* p_w and p_L at the nodes 0..top (returns top, or -1 if the profile is not finite), from
 * the reference just integrated: its (w, L) and
 * modulus (Er_ref) at the nodes, the pressures it was integrated with (P_node), its shape
 * (shape_e, nodes 0..top). The forcing is the derivative of the engine's own g^2(x) =
 * exp(v(x)), v the Hermite cubic of ln g^2 between the nodes (Catmull-Rom slopes, as
 * roll_g2_eval's): d g^2 / dC = g^2 u(x), u the same cubic of the nodes' d ln g^2 / dC =
 * kappa_j e_j. Per layer it is taken quadratic through its values at the nodes and at the
 * middle (where v and u are the cubics' values, v from the differences of ln g^2 between
 * neighbours), w constant (the nodes' mean), and the linear equation integrated exactly
 * for that:
 *     p_w(j+1) = q p_w(j) + h (beta_0 phi_0 + a_1 phi_1 + a_2 phi_2),
 *     p_L(j+1) = p_L(j) + h phi_0 p_w(j) + h^2 (beta_0 psi_0 + a_1 psi_1 + a_2 psi_2),
 * beta(s) = beta_0 + a_1 s/h + a_2 (s/h)^2, p_L the exact integral of that p_w. Near the
 * surface, where P and so ln g^2 change by tens of per cent over a layer, a forcing linear
 * between the nodes would be 2 % off. Each layer's coefficients in a pass that vectorises (the
 * Taylor sums, the layers that need exp() or log() done again after), then the recurrence:
 * two multiply-adds a node on the critical path, the two chains side by side. */
RS_VECTOR_CLONES static int roll_profile_pass(rs_roll *roll, int from, int top)
{
  double *restrict pw = roll->prof.w, *restrict pL = roll->prof.L;
  const double *restrict w = roll->w, *restrict x = roll->xnode, *restrict e = roll->ref.shape_e;
  const double *restrict E = roll->ref.Er, *restrict P = roll->ode.P_node, Eth = roll->p.E_theta;
  /* the roll's scratch: u and d; the moduli a little above P, then in the same arrays the
   * coefficients Q and Cf (so not restrict), A and B */
  double *restrict u = roll->scratch.u, *restrict d = roll->scratch.d;
  double *Q = roll->scratch.q, *Cf = roll->scratch.c;
  double *restrict A = roll->scratch.a, *restrict B = roll->scratch.b;
  const int lo = from > 0 ? from - 1 : 0; /* the first layer's slopes read its neighbour */
  for (int b0 = lo; b0 <= top; b0 += RS_PROFILE_BLOCK) {
    const int nb = top + 1 - b0 < RS_PROFILE_BLOCK ? top + 1 - b0 : RS_PROFILE_BLOCK;
    double *Pp = Cf, *Ep = Q;
    /* d ln E_r / dP by the forward difference the lazy part's bound uses (roll_ode.c) */
    rsi_roll_modulus_probe(roll, P, Pp, Ep, b0, b0 + nb);
    for (int j = b0; j < b0 + nb; ++j) u[j] = (Ep[j] - E[j]) / (E[j] * (Pp[j] - P[j])) * e[j];
  }
  /* |dE| >= 0.015 (E_j + E_j+1) as the difference's sign (it is not -0: |dE| is not) */
  uint64_t wide = 0;
  for (int j = lo; j < top; ++j) {
    wide |= rs_flag_not_below_zero(fabs(E[j] - E[j + 1]) - 0.015 * (E[j] + E[j + 1]));
    d[j] = roll_log_ratio_small((E[j] - E[j + 1]) / (E[j] + E[j + 1]));
  }
  for (int j = lo; rs_flag_raised(wide) && j < top; ++j)
    if (!(fabs(E[j] - E[j + 1]) < 0.015 * (E[j] + E[j + 1]))) d[j] = log(E[j] / E[j + 1]);
  /* the layers inside (their neighbours' slopes both centred) in a loop that vectorises,
   * the end layers on their own; then the layers whose Taylor sums do not hold */
  const int in = from > 1 ? from : 1;
  wide = roll_profile_inner(in, top, d, u, E, w, x, Eth, Q, Cf, A, B);
  if (from == 0 && top > 0) roll_profile_layer(0, top, d, u, E, w, x, Eth, Q, Cf, A, B);
  if (top - 1 > 0 && top - 1 >= from)
    roll_profile_layer(top - 1, top, d, u, E, w, x, Eth, Q + top - 1, Cf + top - 1,
                       A + top - 1, B + top - 1);
  for (int j = in; rs_flag_raised(wide) && j + 1 < top; ++j) {
    const double z = (2.0 + (w[j] + w[j + 1])) * (x[j + 1] - x[j]);
    if (!(fabs(z) < 0.03 && fabs(0.5 * d[j] + 0.0625 * (d[j - 1] - d[j + 1])) < 0.03))
      roll_profile_layer(j, top, d, u, E, w, x, Eth, Q + j, Cf + j, A + j, B + j);
  }
  /* from the core, where p = 0; or on from the profile's values at from (a reference that
   * keeps the nodes below it, rsi_roll_reference_extend) */
  if (from == 0) {
    pw[0] = 0.0;
    pL[0] = 0.0;
  }
  /* the chains in registers: through the arrays each node would wait for its store; the
   * bound over nodes 0..top beside them, off their critical path (the nodes below from
   * keep theirs, within prof_max) */
  double pwj = pw[from], pLj = pL[from];
  double m = from > 0 ? roll->prof.max : 0.0;
  int64_t nan = 0;
  for (int j = from; j < top; ++j) {
    pLj += A[j] * pwj + B[j];
    pwj = Q[j] * pwj + Cf[j];
    pL[j + 1] = pLj;
    pw[j + 1] = pwj;
    m = fabs(pLj) > m ? fabs(pLj) : m;
    nan |= -(int64_t)(pLj != pLj);
  }
  if (nan || m != m) m = NAN;
  roll->prof.max = m;
  return isfinite(m) ? top : -1; /* a profile that is not finite corrects nothing */
}

int rsi_roll_profile_build(rs_roll *roll, int from, int top)
{
  return roll_profile_pass(roll, from, top);
}

/* The start-node search's error bound for a start s0 (rsi_roll_reuse_start), in units of T0/s,
 * from the largest drift eps_max = |E_r/E_ref - 1| of the nodes at and below s0 and their
 * largest L: at first order eps_max exp(L_max - Ls); with the deep part corrected, the
 * second order's eps_max^2 / 4 exp(L_max - Ls), but only where the drift is small enough
 * for the series in it to be dominated by that term (eps_max <= 0.1: else no bound).
 * The 1/4 calibrates both alike: where w relaxes to g - 1, a relative change eps of g^2
 * moves 1 + w by g (sqrt(1 + eps) - 1) = g (eps/2 - eps^2/8 + ...), so the term the first
 * bound holds as eps is eps/2, and the one the second holds is eps^2/8 = (eps^2/4)/2
 * (measured on a Pfeiffer roll: the remainder is 0.135 eps^2 against the first-order
 * term's eps, test_roll_profile.profile_first_order). */
double rsi_roll_profile_bound(double eps_max, double L_max, double Ls, int second)
{
  if (!second) return eps_max * exp(L_max - Ls);
  return eps_max <= 0.1 ? 0.25 * eps_max * eps_max * exp(L_max - Ls) : INFINITY;
}

/* ---- the profile's books ---------------------------------------------------------------- */

/* whether the roll's increments correct their deep part (one layer, its load beneath, the
 * deep reuse: rs_roll_add_layers) */
void rsi_roll_profile_configure(rs_roll *roll, int on) { roll->prof.on = on; }

/* no profile: the nodes it covered no longer hold the reference's values */
void rsi_roll_profile_drop(rs_roll *roll) { roll->prof.top = -1; }

/* the nodes above top no longer hold the reference's values */
void rsi_roll_profile_clip(rs_roll *roll, int top)
{
  roll->prof.top = roll->prof.top < top ? roll->prof.top : top;
}

/* A reference's increment (an integration from the core, its shape just kept, the
 * increment below its block -S times it): its profile built for the drift to come, in use
 * once the increment is committed (rsi_roll_profile_commit); not for a lumped block's
 * predictor. w stored up to node bottom: the caller (rsi_roll_block_increment). */
void rsi_roll_profile_reference(rs_roll *roll, int bottom, double S, int block)
{
  roll->prof.top = -1;
  roll->prof.next = -1;
  if (roll->prof.on && !block) {
    roll->prof.next = rsi_roll_profile_build(roll, 0, bottom);
    roll->prof.c_next = -S;
  }
}

/* An increment committed whose deep part below node lo is c x shape (lo = 0: none): the
 * pressure the reference-valued nodes carry since the reference, -c e (first order),
 * grows by it; a reference's own increment is -S e below its block (its profile in use
 * from now); an increment that was not c x shape below its start ends the profile's use */
void rsi_roll_profile_commit(rs_roll *roll, int lo, double c)
{
  if (roll->ref.start > 0) {
    roll->prof.c += c;
    if (lo == 0) roll->prof.top = -1;
  } else if (roll->prof.next >= 0) {
    roll->prof.top = roll->prof.next;
    roll->prof.c = roll->prof.c_next;
  }
  roll->prof.next = -1;
}

/* The reference rebased below node from (rsi_roll_reference_rebase): the drift is in its
 * values now and restarts from 0 */
void rsi_roll_profile_rebased(rs_roll *roll, int from)
{
  roll->prof.c = 0.0;
  rsi_roll_profile_clip(roll, from);
}

/* A new reference from node from up, committed (rsi_roll_reference_extend), the shape
 * following it up to node top: the profile goes on from the node. To first order the
 * drift to come below it is, as before, C times the shape's forcing, so p there is what it
 * was; the drift since is this increment's own deep scale. */
void rsi_roll_profile_extend(rs_roll *roll, int from, int top)
{
  if (!(from > 0 && from <= roll->prof.top && top > from)) {
    roll->prof.top = -1;
    return;
  }
  roll->prof.top = rsi_roll_profile_build(roll, from, top); /* w stored to top: the caller */
  roll->prof.c = roll->c_deep;
}

int rsi_roll_profile_alloc(rs_roll *roll, size_t cap)
{
  double **const arrays[] = {&roll->prof.w, &roll->prof.L};
  roll->prof.top = -1;
  roll->prof.next = -1;
  return rsi_roll_calloc(arrays, 2, cap + 1);
}

void rsi_roll_profile_free(rs_roll *roll)
{
  free(roll->prof.w);
  free(roll->prof.L);
}
