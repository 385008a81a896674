/* The stress increment of a block of layers from one integration's (w, ln y), by the
 * one-layer decays down the roll, and its commit to the roll's stresses (both load
 * placements; docs/roll-model.md). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "roll/roll_internal.h"
#include "util/float_flags.h"
#include "util/vector_clones.h"
#include "util/error.h"

/* The decay over one layer is exp(d), d = L_j - L_{j+1} = -int w dx, |d| ~ w t / r, small:
 * the Taylor sum to d^7 (relative error d^8/8! < 2e-17 for |d| < 0.03) costs 8 flops where
 * exp() costs ~20 ns, and the product down the roll carries ~N x 1e-16 of rounding (1e-12
 * for 10,000 layers). A larger step (a very soft web, g t / r > 0.03) takes exp()
 * (roll_exp_step). */

/* e[lo..hi) *= s, what falls below 1e-290 cleared (a plain loop: it vectorises) */
static inline void roll_scale_clear(double *restrict e, int lo, int hi, double s)
{
  for (int j = lo; j < hi; ++j) e[j] = roll_decay_clear(e[j] * s);
}

/* e_j = y(r_j)/y(r_top) for j = top-1 .. lo, into e[lo..top): the products, from the top
 * down, of the one-layer decays exp(L_j - L_{j+1}) (roll_exp_step: the Taylor sums in a
 * plain loop that vectorises, exp() where a decay is large). A running product is a chain
 * of dependent multiplications (its latency, not its flops, set the time: a sixth of a
 * 100,000-layer film's run), so a long range is cut into four segments whose products run
 * side by side, each then to be scaled by the product of the segments above it: left in e
 * unscaled, with the segments' bounds, scales and largest products in *seg (the scaling
 * may then be fused with what uses e: roll_layer.c). A range under 256 nodes is one
 * segment, final (seg->count = 0). Below 1e-290 a product is 0: no subnormals. */
RS_VECTOR_CLONES static void roll_decays_pass(const double *restrict L, double *restrict e,
                                              int lo, int top, roll_segments *seg)
{
  /* |d| >= 0.03 gives a value outside [e^-0.03, e^0.03] = [0.97045, 1.03045] (the sum is
   * increasing everywhere: its derivative is the sum to d^6, positive): exp() there. A sum
   * outside (0.9705, 1.0304) has |d| > 0.02994, so the flag looks at |d| (three vector
   * operations, not five) and the pass that follows at the sums. The flag is read from
   * |d|'s bits (util/float_flags.h), so that the loop vectorises on any x86-64 */
  uint64_t bad = 0;
  const uint64_t limit = rs_double_bits(0.0299);
  for (int j = lo; j < top; ++j) {
    const double d = L[j] - L[j + 1];
    bad |= rs_flag_not_below(d, limit);
    e[j] = roll_exp_small(d);
  }
  if (rs_flag_raised(bad))
    for (int j = lo; j < top; ++j)
      if (!(e[j] > 0.9705 && e[j] < 1.0304)) e[j] = roll_exp_step(L[j] - L[j + 1]);
  const int n = top - lo;
  if (n < 256) {
    double p = 1.0, M = 0.0;
    for (int j = top - 1; j >= lo; --j) {
      p = p > 1e-290 ? p * e[j] : 0.0;
      M = p > M ? p : M;
      e[j] = p;
    }
    seg->count = 0;
    seg->M[0] = M;
    return;
  }
  /* segments [b0, b1), [b1, b2), [b2, b3), [b3, top): the top one takes the remainder. The
   * chains test for underflow every 64 factors only (off the chain's critical path); the
   * largest product of each (a NaN is not one: it ends as 0) bounds the increment there */
  const int q = n / 4, b0 = lo, b1 = lo + q, b2 = lo + 2 * q, b3 = lo + 3 * q;
  double p0 = 1.0, p1 = 1.0, p2 = 1.0, p3 = 1.0;
  double M0 = 0.0, M1 = 0.0, M2 = 0.0, M3 = 0.0;
  for (int j = top - 1; j >= b3 + q; --j) {
    p3 = p3 > 1e-290 ? p3 * e[j] : 0.0;
    M3 = p3 > M3 ? p3 : M3;
    e[j] = p3;
  }
  for (int i = q - 1; i >= 0; --i) {
    p0 *= e[b0 + i];
    p1 *= e[b1 + i];
    p2 *= e[b2 + i];
    p3 *= e[b3 + i];
    e[b0 + i] = p0;
    e[b1 + i] = p1;
    e[b2 + i] = p2;
    e[b3 + i] = p3;
    M0 = p0 > M0 ? p0 : M0;
    M1 = p1 > M1 ? p1 : M1;
    M2 = p2 > M2 ? p2 : M2;
    M3 = p3 > M3 ? p3 : M3;
    if ((i & 63) == 0) {
      p0 = p0 > 1e-290 ? p0 : 0.0;
      p1 = p1 > 1e-290 ? p1 : 0.0;
      p2 = p2 > 1e-290 ? p2 : 0.0;
      p3 = p3 > 1e-290 ? p3 : 0.0;
    }
  }
  /* each segment is scaled by the product of those above it (e[b3] = p3, ...) */
  *seg = (roll_segments){4, {b0, b1, b2, b3, top}, {0.0, 0.0, p3, 1.0}, {M0, M1, M2, M3}};
  seg->s[1] = seg->s[2] * p2;
  seg->s[0] = seg->s[1] * p1;
}

void rsi_roll_decays_raw(const double *restrict L, double *restrict e, int lo, int top,
                         roll_segments *seg)
{
  roll_decays_pass(L, e, lo, top, seg);
}

/* rsi_roll_decays_raw, each segment then scaled and what fell below 1e-290 cleared; returns a
 * bound of the e_j written (the segments' largest products times their scales) */
static double roll_decays(const double *restrict L, double *restrict e, int lo, int top)
{
  roll_segments seg;
  rsi_roll_decays_raw(L, e, lo, top, &seg);
  double bound = seg.count == 0 ? seg.M[0] : 0.0;
  for (int g = seg.count - 1; g >= 0; --g) {
    roll_scale_clear(e, seg.b[g], seg.b[g + 1], seg.s[g]);
    bound = fmax(bound, seg.M[g] * seg.s[g]);
  }
  return bound;
}

/* The deep part's scales below a start lo, for c = ds(lo) / shape_e(lo): c and 0 as read
 * from the reference's shape, or, the start corrected for the drift (start_C, roll_profile.c),
 * c e exp(C (p_L - p_L(lo))), to first order c (1 - C p_L(lo)) e + c C e p_L: returns the
 * first scale, *c2 the second */
double rsi_roll_deep_scales(const rs_roll *roll, int lo, double c, double *c2)
{
  const double C = roll->ref.start_C;
  if (C == 0.0) {
    *c2 = 0.0;
    return c;
  }
  *c2 = c * C;
  return c * (1.0 - C * roll->prof.L[lo]);
}

/* The block's own nodes bottom..bottom + m - 1 (rsi_roll_block_increment): dsr, dsh and,
 * with mean, the mean pressure seen; returns S (the sum at the block's bottom), *V the
 * mean's sum there */
static double roll_block_nodes(rs_roll *roll, int bottom, int m, const double *T0, double *mean,
                               double *Vout)
{
  const double *L = roll->L, *w = roll->w;
  double S = 0.0, V = 0.0; /* V_b = sum_{i >= b} (m - 1 - i) T_i/s_i exp(L_b - L(s_i)) */
  for (int b = m - 1; b >= 0; --b) {
    const int j = bottom + b;
    const double decay = b == m - 1 ? 0.0 : exp(L[j] - L[j + 1]);
    const double above = S * decay, c = T0[b] / roll_node_radius(roll, j);
    S = above + c;
    roll->dsr[j] = -S;
    roll->dsh[j] = -above * (1.0 + w[j]); /* Hakiel's hoop accounting (unused beneath) */
    if (mean) {
      V = V * decay + (m - 1 - b) * c;
      mean[j] = V / (m - b);
    }
  }
  *Vout = V;
  return S;
}

/* The increment of a block of m layers wound onto k_old, from one integration's (w, L).
 * Block layer i loads node q_i = k_old + 1 + i - shift (radius s_i: its own outer radius
 * for Hakiel, the outer radius of the layer beneath it by default: then that layer's hoop
 * stress takes the load too, and the new outermost layer's outer face stays traction
 * free), and its sub-increment is exactly
 *     ds_i(r_j) = -(T_i / s_i) exp(L_j - L(s_i)),     j <= q_i,
 * because y, integrated from the core, does not depend on where the load is applied.
 * Summed from the top of the block down, S_b = T_b/s_b + exp(L_b - L_{b+1}) S_{b+1}: every
 * exponent is a decay over one layer or from a node to the bottom of the block, so nothing
 * overflows. Fills dsr = sum of ds_i at each node, dsh = sum over the layers strictly above
 * it of ds_i (1 + w) (= ds_i + r ds_i'; with the load beneath a layer, the sub-increments
 * at or above it: that layer is part of the loaded body). With mean != NULL also the mean,
 * over the sub-increments that reach a node, of the pressure the block has added there
 * before each:
 *     mean_j = (1/n_j) sum_i sum_{i' < i} -ds_i'(r_j)
 * (n_j = m below the block, m - b at block node b, which exists from sub-increment b on).
 * Below the block ds_j = -S e_j, e_j = y(r_j)/y(s_b), from the one-layer decays down to the
 * integration's start node lo, and below it c_deep times the reference's shape (deep_lo,
 * c_deep, c2_deep; rsi_roll_commit). For m = 1 these are the single-layer formulas of
 * Hakiel accretion, operation for operation. */
void rsi_roll_block_increment(rs_roll *roll, int k_old, int m, const double *T0, double *mean)
{
  const double *w = roll->w;
  const int shift = roll->shift, bottom = k_old + 1 - shift;
  double V;
  const double S = roll_block_nodes(roll, bottom, m, T0, mean, &V);
  if (shift) /* the outermost layer: no load above it */
    roll->dsr[k_old + m] = 0.0;
  double *restrict dsr = roll->dsr, *restrict dsh = roll->dsh;
  const int j0 = roll->ref.start;
  int lo = j0 >= 1 && j0 <= roll->ref.shape_top && roll->ref.shape_e[j0] > 1e-280 ? j0 : 0;
  /* an increment computed node by node from the core adds to the stored values of nodes
   * that are lazy: their drift bound would not see it, so they are brought up to date */
  if (lo == 0 && roll->lazy.top > 0) rsi_roll_lazy_flush(roll, 0);
  const double e_bound = roll_decays(roll->L, dsr, lo, bottom);
  if (j0 == 0) { /* a reference's increment: its shape, and its profile for the drift to come */
    rsi_roll_shape_reference(roll, dsr, bottom, e_bound);
    if (roll->prof.on && !mean) rsi_roll_wstep_store(roll, bottom); /* the profile reads w */
    rsi_roll_profile_reference(roll, bottom, S, mean != NULL);
  }
  roll->deep_lo = lo;
  roll->c_deep = lo > 0 ? -S * dsr[lo] / roll->ref.shape_e[lo] : 0.0;
  roll->c2_deep = 0.0;
  if (lo > 0 && lo == j0) roll->c_deep = rsi_roll_deep_scales(roll, lo, roll->c_deep, &roll->c2_deep);
  if (j0 == 0 && !mean && roll->lazy.ok && roll->lazy.top == 0 && roll->ref.last_start > 2 &&
      roll->ref.last_start <= bottom) {
    /* a reference's increment is -S times its own shape everywhere below the block: the
     * nodes well below where the last partial integration started can take it lazily at
     * once (their drift is zero now: the modulus was just integrated), so the next
     * increment does not gather, evaluate and scan the whole roll again */
    rsi_roll_lazy_freeze(roll, roll->ref.last_start - 1);
    if (roll->lazy.top > 0) {
      roll->deep_lo = lo = roll->lazy.top;
      roll->c_deep = -S;
    }
  }
  if (lo > 0 && dsr[lo] > 1e-280) rsi_roll_shape_follow(roll, dsr, lo, bottom, e_bound);
  if (mean) {
    for (int j = lo; j < bottom; ++j) mean[j] = V * dsr[j] / m;
    const double cm = lo > 0 ? V * dsr[lo] / (m * roll->ref.shape_e[lo]) : 0.0;
    for (int j = 0; j < lo; ++j) mean[j] = cm * roll->ref.shape_e[j];
  }
  for (int j = lo; j < bottom; ++j) dsr[j] *= -S;
  if (!shift)
    for (int j = lo; j < bottom; ++j) dsh[j] = dsr[j] * (1.0 + w[j]);
}

/* RS_OK when ds[0..k] and dh[0..k] (an increment's radial and hoop stress at the nodes)
 * are all finite; else the error naming the lowest node that is not. */
static rs_status roll_check_increment(const rs_roll *roll, const double *ds, const double *dh, int k)
{
  /* the nodes below deep_lo are c_deep times the reference's shape, which is finite (its
   * own increment passed this check): c_deep and the shape's bound say for them. Above,
   * x - x is 0 for a finite x and NaN for an infinite or NaN one: one sum says whether all
   * are finite (four sums, independent, so that the compiler can vectorise them: a
   * floating-point sum's order is otherwise fixed) */
  if (!isfinite(roll->c_deep) || !isfinite(roll->c2_deep))
    return RS_ERROR(RS_ERR_SOLVER, "non-finite stress increment at the core (outer radius %.9g m)",
                    roll_node_radius(roll, k));
  /* below deep_lo, c_deep times the shape: finite where |c_deep| times the shape's bound
   * is (a tension near the largest double overflows there: the node is looked for) */
  const int lo = roll->deep_lo;
  const double c = roll->c_deep, c2 = roll->c2_deep;
  if (lo > 0 && !roll_deep_bounded(roll, c, c2))
    for (int j = 0; j < lo; ++j)
      if (!isfinite(c * roll->ref.shape_e[j]) || (!roll->shift && !isfinite(c * roll->ref.shape_h[j])) ||
          (c2 != 0.0 && !isfinite(roll->ref.shape_e[j] * (c + c2 * roll->prof.L[j]))))
        return j == 0 ? RS_ERROR(RS_ERR_SOLVER,
                                 "non-finite stress increment at the core (outer radius %.9g m)",
                                 roll_node_radius(roll, k))
                      : RS_ERROR(RS_ERR_SOLVER,
                                 "non-finite stress increment at r = %.9g m (layer %d)", roll_node_radius(roll, j), j);
  double z0 = 0.0, z1 = 0.0, z2 = 0.0, z3 = 0.0;
  int j = roll->deep_lo;
  for (; j + 3 <= k; j += 4) {
    z0 += (ds[j] - ds[j]) + (dh[j] - dh[j]);
    z1 += (ds[j + 1] - ds[j + 1]) + (dh[j + 1] - dh[j + 1]);
    z2 += (ds[j + 2] - ds[j + 2]) + (dh[j + 2] - dh[j + 2]);
    z3 += (ds[j + 3] - ds[j + 3]) + (dh[j + 3] - dh[j + 3]);
  }
  for (; j <= k; ++j) z0 += (ds[j] - ds[j]) + (dh[j] - dh[j]);
  const int bad = (z0 + z1) + (z2 + z3) != 0.0;
  for (j = roll->deep_lo; bad && j <= k; ++j)
    if (!isfinite(ds[j]) || !isfinite(dh[j]))
      return j == 0 ? RS_ERROR(RS_ERR_SOLVER,
                               "non-finite stress increment at the core (outer radius %.9g m)",
                               roll_node_radius(roll, k))
                    : RS_ERROR(RS_ERR_SOLVER, "non-finite stress increment at r = %.9g m (layer %d)",
                               roll_node_radius(roll, j), j);
  return RS_OK;
}

/* Adds dsr (and with Hakiel's placement dsh) to the roll; the block's own layers start
 * from their own share. */
rs_status rsi_roll_commit(rs_roll *roll, int m, const double *T0)
{
  const int k_old = roll->n, k = roll->n + m;
  const double t = roll->p.caliper;
  const double *restrict ds = roll->dsr, *restrict dh = roll->dsh;
  rs_status st = roll_check_increment(roll, ds, roll->shift ? ds : dh, k);
  if (st) return st;
  /* below deep_lo the increment is c_deep times the reference's shape (rsi_roll_block_increment):
   * the lazy nodes take it in their common scale */
  const int lo = roll->deep_lo;
  const double c = roll->c_deep, c2 = roll->c2_deep;
  const double *restrict sh = roll->ref.shape_h;
  double *restrict sr = roll->sigma_r, *restrict sth = roll->sigma_theta;
  const int j0 = rsi_roll_commit_deep(roll, lo, c, c2, ds[0]);
  rsi_roll_profile_commit(roll, lo, c); /* the drift scale of the reference's nodes */
  const int j1 = lo > 1 ? lo : 1;
  for (int j = j1; j <= k_old; ++j) sr[j - 1] += ds[j];
  for (int j = k_old + 1; j <= k; ++j) sr[j - 1] = ds[j];
  if (roll->shift) { /* the hoop stresses follow from the radial ones */
    roll->hoop_stale = 1; /* derived when asked for: rs_roll_sigma_theta */
    return RS_OK;
  }
  for (int j = j0; j < lo; ++j) sth[j - 1] += c * sh[j];
  for (int j = j1; j <= k_old; ++j) sth[j - 1] += dh[j];
  for (int j = k_old + 1; j <= k; ++j) sth[j - 1] = T0[j - k_old - 1] / t + dh[j];
  return RS_OK;
}

/* With the load beneath each layer, a layer's hoop stress is its mean over the turn, i.e.
 * its tension per unit width over t, and the turn's equilibrium gives it exactly from the
 * radial stresses on its two faces:
 *     sigma_theta_j = (s_j sigma_r(s_j) - s_{j-1} sigma_r(s_{j-1})) / t,
 * because every increment satisfies sigma_theta = d(r sigma_r)/dr (the integral of its hoop
 * stress over the turn is [r ds]) and the layer joined at T0_j/t while pressing T0_j on
 * the face beneath it (docs/roll-model.md). The outermost layer, whose outer face is free,
 * gets T0/t. A point value at s_j would differ from the mean by a first-order-in-t amount
 * that, for g ~ 60, is of the size of the hoop stress itself deep in the roll. Layers
 * 1..k (arrays 0..k-1); node 0 is the core. Each layer on its own (no running sum), so
 * that the loop vectorises; derived only when the hoop stresses are read (the reel reads
 * them at history stages and at the end), not at every increment. */
void rsi_roll_hoop_from_equilibrium(double *restrict sth, const double *restrict sr, double core_sigma,
                                double rc, double t, int k)
{
  const double inv_t = 1.0 / t;
  if (k < 1) return;
  sth[0] = ((rc + t) * sr[0] - rc * core_sigma) * inv_t;
  for (int j = 2; j <= k; ++j)
    sth[j - 1] = ((rc + j * t) * sr[j - 1] - (rc + (j - 1) * t) * sr[j - 2]) * inv_t;
}

/* rsi_roll_hoop_from_equilibrium with the nodes at the radii R[0..k] (entrained air: the turn
 * and the film beneath it carry the radial stresses on their faces; the film no hoop force,
 * so the web's is [R sigma_r] over the turn, its stress that over t) */
void rsi_roll_hoop_from_equilibrium_at(double *restrict sth, const double *restrict sr, double core_sigma,
                                   const double *restrict R, double t, int k)
{
  const double inv_t = 1.0 / t;
  if (k < 1) return;
  sth[0] = (R[1] * sr[0] - R[0] * core_sigma) * inv_t;
  for (int j = 2; j <= k; ++j) sth[j - 1] = (R[j] * sr[j - 1] - R[j - 1] * sr[j - 2]) * inv_t;
}
