/* The reference solution and its reuse (docs/roll-model.md, "Reusing the deep solution"):
 * the last integration from the core (or from a rebased node, rsi_roll_reference_rebase) is
 * the reference; an increment's integration starts from the highest node below which the
 * reference's (w, L) still give the increment within the tolerance, and keeps them there.
 * This file owns the reference's bookkeeping (ref_top, ref_age, Er_ref, start, start_C,
 * ref_from; struct rs_roll, roll_internal.h, states their invariants). */
#include <math.h>
#include <string.h>

#include "roll/roll_internal.h"

/* Integrations from the core between two references. Accuracy does not need a refresh
 * (rsi_roll_reuse_start bounds the error whatever the reference's age); cost does: the start
 * node sinks as the modulus drifts, and an integration from the core crosses the whole
 * roll where a partial one crosses the nodes above the start. With the first-order search
 * a reference serves 32 increments. With the deep part corrected for the drift the start
 * sinks with the drift's square, so a reference serves longer, the longer the roll (an
 * integration from the core costs more): n/400 increments, 32 to 512 (the choice measured
 * in docs/performance.md). */
static int roll_refresh_age(const rs_roll *roll)
{
  if (!roll->prof_on || roll->prof_top < 1) return 32; /* the first-order search */
  const int a = roll->n / 400;
  return a < 32 ? 32 : a > 512 ? 512 : a;
}

/* the start-node search's block of nodes (rsi_roll_reuse_start) */
enum { RS_SCAN_BLOCK = 64 };

/* rsi_roll_reuse_start's answer: the start lo, or -1 (node 0 alone saves nothing: a new
 * reference); a start found with the second-order bound is corrected for the drift, with a
 * shape to read below it, or it is none */
static int roll_reuse_found(rs_roll *roll, int lo, int second)
{
  if (lo < 1) return -1;
  if (second) {
    if (!(roll->shape_e[lo] > 1e-280)) return -1;
    roll->start_C = roll->ref_c;
  }
  return lo;
}

/* The node to start the integration of an increment onto k from, keeping the reference's
 * (w, L) below it, or -1: from the core, as a new reference.
 *
 * Node j's reference (w, L) solves the Riccati equation with E_ref instead of E_r. The
 * equation relaxes to w = g - 1 at rate 2g, so a relative change eps of g^2 = E_theta/E_r
 * moves w by ~ (w + 1) eps / 2: the increment below a start node s0 is off by a relative
 * ~ (eps / 2) (L(s0) - L_j), and above it by ~ eps / 4 (the start value's error, relaxing).
 * The increment itself is (T0/s) exp(L_j - L_s) there. So the error in units of T0/s is
 * at most ~ E(s0) = max_{j <= s0} eps_j x exp(max_{j <= s0} L_j - L_s) x (at most e^-1 / 2
 * from the factor u e^-u of the nodes below): the start node is the highest with E(s0) <=
 * tol = RS_ACCURACY_PER_RTOL x rtol, the accuracy the corrected integrations deliver. E
 * grows with s0 (both maxima do), so it is found by bisection. L_s is the top of the last
 * increment (L[n - shift]), one increment below the new one: the bound is on the safe side.
 *
 * The error has one sign (pressures only grow, so E_r drifts one way) and adds up to ~1.3
 * tol over a reel: with the integrations corrected it is most of what is left (newsprint-
 * rider at rtol 1e-3: core pressure 2.9e-5 from a tight run, 6.8e-6 with every increment
 * from the core; docs/roll-model.md). */
static int roll_reuse_search(rs_roll *roll, int top, double tol, int second);

int rsi_roll_reuse_start(rs_roll *roll)
{
  const int n = roll->n;
  roll->start_C = 0.0;
  roll->ref_from = -1;
  if (roll->p.reuse == RS_REUSE_OFF || roll->ref_top < 1 || n < 1) return -1;
  /* below the top of the last integration, so the new one (one node higher) has length */
  int top = roll->ref_top < n - roll->shift ? roll->ref_top : n - roll->shift;
  /* the deep part corrected for the drift (roll_profile.c): a start among the nodes that
   * still hold the reference's (w, L) and read the reference's shape, the error bound of
   * second order */
  const int second = roll->prof_on && roll->prof_top >= 1;
  if (second) {
    top = top < roll->prof_top ? top : roll->prof_top;
    top = top < roll->shape_top ? top : roll->shape_top;
  }
  if (roll->ref_age < roll_refresh_age(roll))
    return roll_reuse_search(roll, top, RS_ACCURACY_PER_RTOL * roll->p.rtol, second);
  if (!second || roll->ref_deep >= roll->ref_deep_max) return -1;
  /* A new reference, from the core or from a node above it (rsi_roll_reference_rebase):
   * below that node the reference's (w, L) and shape take their first-order correction
   * for the drift for good and the drift restarts from 0 there, so what the correction
   * leaves, second order, stays: the node is found with the second-order bound at a
   * hundredth of the tolerance, and after RS_REF_DEEP_MAX (4) such references one is
   * from the core, so that the remainders left add up to at most 4 % of it (measured:
   * at a quarter of the tolerance the 1500-layer newsprint roll's core pressure error
   * grew from 4.0e-6 to 1.5e-5 at rtol 1e-5, at a hundredth 4.4e-6; test_roll_profile).
   * And no higher than the last such reference's node: every such reference starts from
   * values the last one from the core left (rebased), not from those of a chain of
   * restarts, each of which adds CVODE's start-up error at its node (measured on
   * Altmann's roll, a constant modulus whose starts are at the top: the hoop stress's
   * error 4.4e-5 -> 1.5e-4 of T0/t with a chain of five) */
  if (roll->ref_deep > 0) top = top < roll->ref_from_last ? top : roll->ref_from_last;
  const int from = roll_reuse_search(roll, top, 0.01 * RS_ACCURACY_PER_RTOL * roll->p.rtol, 1);
  roll->start_C = 0.0; /* the start is rebased, not corrected for this increment only */
  if (from < 1 || !(roll->shape_e[from] > 1e-280)) return -1;
  roll->ref_from = from;
  return from;
}

/* rsi_roll_reuse_start's search: the highest start at or below top whose error bound (first
 * order, or second with second != 0) is within tol, or -1 */
static int roll_reuse_search(rs_roll *roll, int top, double tol, int second)
{
  const int n = roll->n;
  const double *restrict Er = roll->Er, *restrict Eref = roll->Er_ref, *restrict L = roll->L;
  const double Ls = L[n - roll->shift];
  /* below the lazy frontier F the drift is bounded by a + |C| b (roll_lazy.c) and scan_L
   * holds the prefix maxima of L (L there is fixed until the next reference) */
  const int F = roll->lazy_top < top + 1 ? roll->lazy_top : top + 1;
  const double aC = fabs(roll->lazy_c), *restrict la = roll->lazy_a, *restrict lb = roll->lazy_b;
  const double *restrict pl = roll->scan_L;
  int lo = -1;
  if (F > 0 && !(rsi_roll_profile_bound(la[F - 1] + aC * lb[F - 1], pl[F - 1], Ls, second) <= tol)) {
    int hi = F - 1; /* E(lo) <= tol < E(hi), all lazy: bisection on the stored bounds */
    while (hi - lo > 1) {
      const int mid = lo + (hi - lo) / 2;
      if (rsi_roll_profile_bound(la[mid] + aC * lb[mid], pl[mid], Ls, second) <= tol)
        lo = mid;
      else
        hi = mid;
    }
    return roll_reuse_found(roll, lo, second);
  }
  /* from F up, a block at a time: the block's drifts (a vectorised pass), then their running
   * maxima, E only at each block's end, and node by node inside the block where it first
   * exceeds tol: the answer of a bisection over the prefix maxima (E grows with s0), without
   * a chain of dependent max operations through every node. The start is usually a block or
   * two above F: the drifts of the nodes above it are not formed */
  double *restrict eps = roll->scan_eps;
  double me = F > 0 ? la[F - 1] + aC * lb[F - 1] : 0.0, ml = F > 0 ? pl[F - 1] : -INFINITY;
  lo = F - 1;
  for (int b0 = F; b0 <= top; b0 += RS_SCAN_BLOCK) {
    const int b1 = b0 + RS_SCAN_BLOCK - 1 < top ? b0 + RS_SCAN_BLOCK - 1 : top;
    for (int j = b0; j <= b1; ++j) eps[j] = fabs(Er[j] - Eref[j]) / Eref[j];
    double e4[4] = {me, me, me, me}, l4[4] = {ml, ml, ml, ml};
    int j = b0;
    for (; j + 3 <= b1; j += 4)
      for (int q = 0; q < 4; ++q) {
        e4[q] = eps[j + q] > e4[q] ? eps[j + q] : e4[q];
        l4[q] = L[j + q] > l4[q] ? L[j + q] : l4[q];
      }
    for (; j <= b1; ++j) {
      e4[0] = eps[j] > e4[0] ? eps[j] : e4[0];
      l4[0] = L[j] > l4[0] ? L[j] : l4[0];
    }
    const double be = fmax(fmax(e4[0], e4[1]), fmax(e4[2], e4[3]));
    const double bl = fmax(fmax(l4[0], l4[1]), fmax(l4[2], l4[3]));
    if (rsi_roll_profile_bound(be, bl, Ls, second) <= tol) { /* the whole block qualifies */
      me = be;
      ml = bl;
      lo = b1;
      continue;
    }
    for (j = b0; j <= b1; ++j) { /* the first node past tol is in this block */
      me = eps[j] > me ? eps[j] : me;
      ml = L[j] > ml ? L[j] : ml;
      if (!(rsi_roll_profile_bound(me, ml, Ls, second) <= tol)) break;
      lo = j;
    }
    break;
  }
  return roll_reuse_found(roll, lo, second);
}

/* The first layer's load on the core (an integration of no length): a reference of the
 * core node alone (too short to start from: rsi_roll_reuse_start), no shape, no profile
 * yet */
void rsi_roll_reference_core(rs_roll *roll)
{
  roll->Er_ref[0] = roll->Er[0];
  roll->ref_top = 0;
  roll->start = 0;
  roll->start_C = 0.0;
  roll->prof_top = -1;
  roll->stats.full_integrations++;
}

/* The books of an integration onto node k starting at j0 (-1: from the core, a new
 * reference of nodes 0..k with the modulus it is integrated with), kept once it has been
 * restarted: from a node above the core, the nodes above j0 are about to be overwritten,
 * no longer the reference's (nor its profile's) */
void rsi_roll_reference_begin(rs_roll *roll, int k, int j0)
{
  if (j0 < 0) {
    memcpy(roll->Er_ref, roll->Er, (size_t)(k + 1) * sizeof(double));
    roll->ref_top = k;
    roll->ref_age = 0;
    roll->ref_deep = 0;
    roll->shape_top = -1; /* until its increment is built (rsi_roll_block_increment) */
    roll->prof_top = -1;  /* likewise its profile */
    roll->stats.full_integrations++;
    return;
  }
  roll->ref_top = j0;
  roll->prof_top = roll->prof_top < j0 ? roll->prof_top : j0;
  roll->ref_age++;
  roll->last_start = j0;
}

/* An integration from node first above the core has reached node k: (w, L) above the start
 * now come from this modulus, which is what later increments' drift is measured against
 * there, and they may start as high as this one's top */
void rsi_roll_reference_end(rs_roll *roll, int k, int first)
{
  if (first == 0) return;
  memcpy(roll->Er_ref + first + 1, roll->Er + first + 1, (size_t)(k - first) * sizeof(double));
  roll->ref_top = k;
}
