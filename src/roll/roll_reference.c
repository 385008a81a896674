/* The reference solution and its reuse (docs/roll-model.md, "Reusing the deep solution"):
 * the last integration from the core (or from a rebased node, rsi_roll_reference_rebase) is
 * the reference; an increment's integration starts from the highest node below which the
 * reference's (w, L) still give the increment within the tolerance, and keeps them there.
 * This file owns the reference (struct roll_reference, roll_internal.h, with its
 * invariant): its books, its shape, where an integration starts and the start's
 * correction for the drift, and the rebasing of a reference from a node above the core
 * (its passes over the nodes in roll_rebase_pass.c). */
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
  if (!roll->prof.on || roll->prof.top < 1) return 32; /* the first-order search */
  /* on a roll long enough for the deeper level, whose references are not O(N) as a rule
   * (they rebase, flush and freeze the nodes above the level; one from the core renews
   * it: roll_reference_renew), more often: the window of nodes every increment works
   * over shrinks with the drift since the reference (docs/performance.md) */
  const int deep = roll->n >= roll->deep.min_nodes;
  const int a = roll->n / (deep ? 1600 : 400), cap = deep ? 128 : 512;
  return a < 32 ? 32 : a > cap ? cap : a;
}

/* the start-node search's block of nodes (rsi_roll_reuse_start) */
enum { RS_SCAN_BLOCK = 64 };

/* rsi_roll_reuse_start's answer: the start lo, or -1 (node 0 alone saves nothing: a new
 * reference); a start found with the second-order bound is corrected for the drift, with a
 * shape to read below it, or it is none */
static int roll_reuse_found(const rs_roll *roll, int lo, int second, double *C)
{
  *C = 0.0;
  if (lo < 1) return -1;
  if (second) {
    if (!(roll->ref.shape_e[lo] > 1e-280)) return -1;
    *C = roll->prof.c;
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
static int roll_reuse_search(rs_roll *roll, int top, double tol, int second, double *C);

/* The prefix maxima of the drift bound (*eps) and of L (*Lmax) over the lazy nodes 0..j:
 * a + |C| b with the lazy zone's (roll_lazy.c); below the deeper level's top (roll_deep)
 * the drift since the last rebase, |c - c_r| b with its scale, and L there up to
 * |B| max|p_L| from its rebased value; above the level, the larger of the level's and the
 * zone's (the zone's maxima start at its bottom) */
static inline void roll_lazy_zone_bound(const rs_roll *roll, int j, double *eps, double *Lmax)
{
  const double *la = roll->lazy.a, *lb = roll->lazy.b, *pl = roll->lazy.Lmax;
  const int D = roll->deep.top;
  const double dC = fabs(roll->deep.c - roll->deep.c_r), dL = fabs(roll->deep.B) * roll->deep.pL_max;
  if (j < D) {
    *eps = dC * lb[j];
    *Lmax = pl[j] + dL;
    return;
  }
  *eps = la[j] + fabs(roll->lazy.c) * lb[j];
  *Lmax = pl[j];
  if (D > 0) {
    *eps = fmax(*eps, dC * lb[D - 1]);
    *Lmax = fmax(*Lmax, pl[D - 1] + dL);
  }
}

/* A reference from the core is due (roll_reference_renew; tol the remainder a rebase may
 * leave, a hundredth of the reuse's): the node the level may be renewed from instead, or
 * -1 (the level dissolved by that reference). The reference then starts at that node
 * with the rebased values there (the level lowered to the node below it first, the nodes
 * above taking its scales and rebase factors: rsi_roll_deep_lower, so that the start and
 * the node its Hermite slope reads are explicit), integrates every node above afresh and
 * leaves the nodes below in the level. Their (w, L) are still the last core reference's,
 * moved by B (p_w, p_L) to first order in the drift since it: what that leaves is second
 * order in the drift since that reference, which the level's nodes' a + |c| b bounds
 * (their E_ref is that reference's, and c continues the zone's scale their a and b were
 * taken in). So the node is the level's top node, or the highest below it, where that
 * bound's second-order error is within tol; and the level is renewed while its rebase
 * factor's remainder is within its bound (roll_deep_factor_ok), the node within top, and
 * the level then within twice its depth at forming below the top (deeper, a reference from
 * it would pass over more nodes than one from a level formed afresh). */
/* roll_deep_renewable's bound at the level's node j (the prefix maxima up to it) */
static inline double roll_deep_renew_bound(const rs_roll *roll, int j, double Ls)
{
  const roll_deep *d = &roll->deep;
  const double eps = roll->lazy.a[j] + fabs(d->c) * roll->lazy.b[j];
  return rsi_roll_profile_bound(eps, roll->lazy.Lmax[j] + fabs(d->B) * d->pL_max, Ls, 1);
}

static int roll_deep_renewable(const rs_roll *roll, int top, double tol)
{
  const roll_deep *d = &roll->deep;
  const int D = d->top;
  if (D < 3 || D - 1 > top || !roll_deep_factor_ok(roll)) return -1;
  const double Ls = roll->L[roll->n - roll->shift];
  int from = D - 1;
  if (!(roll_deep_renew_bound(roll, from, Ls) <= tol)) {
    /* the highest node within it: the bound grows with the node (prefix maxima) */
    int lo = -1, hi = from;
    while (hi - lo > 1) {
      const int mid = lo + (hi - lo) / 2;
      if (roll_deep_renew_bound(roll, mid, Ls) <= tol)
        lo = mid;
      else
        hi = mid;
    }
    from = lo;
  }
  return from >= 2 && roll->n - (from + 1) <= RS_DEEP_RENEW_DEPTH * d->depth0 ? from : -1;
}

/* A reference from the core is due (rsi_roll_reuse_start): on a long roll whose deeper
 * level may be kept (roll_deep_renewable), one from the level's top node instead, or -1
 * (from the core). top: the highest node the reference's books allow a start at. */
static int roll_reference_renew(rs_roll *roll, int top)
{
  const int from = roll_deep_renewable(roll, top, 0.01 * RS_ACCURACY_PER_RTOL * roll->p.rtol);
  if (from < 1 || !(roll->ref.shape_e[from] > 1e-280)) return -1;
  roll->ref.from = from;
  roll->ref.renew = 1;
  return from;
}

int rsi_roll_reuse_start(rs_roll *roll, double *C)
{
  const int n = roll->n;
  *C = 0.0;
  roll->ref.from = -1;
  if (roll->p.reuse == RS_REUSE_OFF || roll->ref.top < 1 || n < 1) return -1;
  /* below the top of the last integration, so the new one (one node higher) has length */
  int top = roll->ref.top < n - roll->shift ? roll->ref.top : n - roll->shift;
  /* the deep part corrected for the drift (roll_profile.c): a start among the nodes that
   * still hold the reference's (w, L) and read the reference's shape, the error bound of
   * second order */
  const int second = roll->prof.on && roll->prof.top >= 1;
  if (second) {
    top = top < roll->prof.top ? top : roll->prof.top;
    top = top < roll->ref.shape_top ? top : roll->ref.shape_top;
  }
  if (roll->ref.age < roll_refresh_age(roll))
    return roll_reuse_search(roll, top, RS_ACCURACY_PER_RTOL * roll->p.rtol, second, C);
  if (!second) return -1;
  if (roll->ref.deep >= roll->ref.deep_max) return roll_reference_renew(roll, top);
  /* A new reference, from the core or from a node above it (rsi_roll_reference_rebase):
   * below that node the reference's (w, L) and shape take their first-order correction
   * for the drift for good and the drift restarts from 0 there, so what the correction
   * leaves, second order, stays: the node is found with the second-order bound at a
   * hundredth of the tolerance, and after RS_REF_DEEP_MAX (4) such references one is
   * from the core, so that the remainders left add up to at most 4 % of it (at a quarter
   * of the tolerance the 1500-layer newsprint roll's core pressure error at rtol 1e-5 is
   * 1.5e-5, at a hundredth 4.4e-6, against 4.0e-6 with every reference from the core;
   * test_roll_profile).
   * And no higher than the last such reference's node: every such reference starts from
   * values the last one from the core left (rebased), not from those of a chain of
   * restarts, each of which adds CVODE's start-up error at its node (measured on
   * Altmann's roll, a constant modulus whose starts are at the top: the hoop stress's
   * error 4.4e-5 -> 1.5e-4 of T0/t with a chain of five) */
  if (roll->ref.deep > 0) top = top < roll->ref.from_last ? top : roll->ref.from_last;
  const int from = roll_reuse_search(roll, top, 0.01 * RS_ACCURACY_PER_RTOL * roll->p.rtol, 1, C);
  *C = 0.0; /* the start is rebased, not corrected for this increment only */
  if (from < 1 || !(roll->ref.shape_e[from] > 1e-280)) return roll_reference_renew(roll, top);
  roll->ref.from = from;
  return from;
}

/* rsi_roll_reuse_start's search: the highest start at or below top whose error bound (first
 * order, or second with second != 0) is within tol, or -1 */
static int roll_reuse_search(rs_roll *roll, int top, double tol, int second, double *C)
{
  const int n = roll->n;
  const double *restrict Er = roll->ode.Er, *restrict Eref = roll->ref.Er, *restrict L = roll->L;
  const double Ls = L[n - roll->shift];
  /* below the lazy frontier F the drift is bounded by a + |C| b (roll_lazy.c) and scan_L
   * holds the prefix maxima of L (L there is fixed until the next reference); the deeper
   * level's nodes and the zone's, each in their own scale (roll_lazy_zone_bound) */
  const int F = roll->lazy.top < top + 1 ? roll->lazy.top : top + 1;
  int lo = -1;
  double me, ml;
  if (F > 0) roll_lazy_zone_bound(roll, F - 1, &me, &ml);
  if (F > 0 && !(rsi_roll_profile_bound(me, ml, Ls, second) <= tol)) {
    int hi = F - 1; /* E(lo) <= tol < E(hi), all lazy: bisection on the stored bounds */
    while (hi - lo > 1) {
      const int mid = lo + (hi - lo) / 2;
      roll_lazy_zone_bound(roll, mid, &me, &ml);
      if (rsi_roll_profile_bound(me, ml, Ls, second) <= tol)
        lo = mid;
      else
        hi = mid;
    }
    return roll_reuse_found(roll, lo, second, C);
  }
  /* from F up, a block at a time: the block's drifts (a vectorised pass), then their running
   * maxima, E only at each block's end, and node by node inside the block where it first
   * exceeds tol: the answer of a bisection over the prefix maxima (E grows with s0), without
   * a chain of dependent max operations through every node. The start is usually a block or
   * two above F: the drifts of the nodes above it are not formed */
  double *restrict eps = roll->ref.scan_eps;
  if (F == 0) {
    me = 0.0;
    ml = -INFINITY;
  }
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
  return roll_reuse_found(roll, lo, second, C);
}

/* The first layer's load on the core (an integration of no length): a reference of the
 * core node alone (too short to start from: rsi_roll_reuse_start), no shape, no profile
 * yet */
void rsi_roll_reference_core(rs_roll *roll)
{
  roll->ref.Er[0] = roll->ode.Er[0];
  roll->ref.top = 0;
  roll->ref.start = 0;
  roll->ref.start_C = 0.0;
  rsi_roll_profile_drop(roll);
  roll->stats.full_integrations++;
}

/* The books of an integration onto node k starting at j0 (-1: from the core, a new
 * reference of nodes 0..k with the modulus it is integrated with), kept once it has been
 * restarted: from a node above the core, the nodes above j0 are about to be overwritten,
 * no longer the reference's (nor its profile's) */
void rsi_roll_reference_begin(rs_roll *roll, int k, int j0)
{
  if (j0 < 0) {
    memcpy(roll->ref.Er, roll->ode.Er, (size_t)(k + 1) * sizeof(double));
    roll->ref.top = k;
    roll->ref.age = 0;
    roll->ref.deep = 0;
    roll->ref.shape_top = -1; /* until its increment is built (rsi_roll_block_increment) */
    rsi_roll_profile_drop(roll); /* likewise its profile */
    roll->stats.full_integrations++;
    return;
  }
  roll->ref.top = j0;
  rsi_roll_profile_clip(roll, j0);
  roll->ref.age++;
  roll->ref.last_start = j0;
}

/* An integration from node first above the core has reached node k: (w, L) above the start
 * now come from this modulus, which is what later increments' drift is measured against
 * there, and they may start as high as this one's top */
void rsi_roll_reference_end(rs_roll *roll, int k, int first)
{
  if (first == 0) return;
  memcpy(roll->ref.Er + first + 1, roll->ode.Er + first + 1, (size_t)(k - first) * sizeof(double));
  roll->ref.top = k;
}

/* ---- the start of an integration ------------------------------------------------------- */

/* The integration about to start at node first (0: the core) from the nodes' (w, L) there;
 * with C != 0 (rsi_roll_reuse_start: a start found with the second-order bound) the start's
 * (w, L) corrected by C times the profile (roll_profile.c), the reference's values kept to
 * be put back once the increment is built (rsi_roll_start_release) */
void rsi_roll_start_set(rs_roll *roll, int first, double C)
{
  roll->ref.start = first;
  if (C == 0.0) return;
  roll->ref.start_C = C;
  roll->ref.start_ref[0] = roll->w[first];
  roll->ref.start_ref[1] = roll->L[first];
  roll->w[first] += roll->ref.start_C * roll->prof.w[first];
  roll->L[first] += roll->ref.start_C * roll->prof.L[first];
}

/* The start node's (w, L) back to the reference's once the increment corrected there is
 * built and committed or has failed (rsi_roll_start_release): a later start there is
 * corrected afresh; no reference is being rebased any more */
void rsi_roll_start_restore(rs_roll *roll)
{
  roll->ref.from = -1;
  roll->ref.renew = 0;
  if (roll->ref.start_C == 0.0) return;
  roll->w[roll->ref.start] = roll->ref.start_ref[0];
  roll->L[roll->ref.start] = roll->ref.start_ref[1];
  roll->ref.start_C = 0.0;
}

/* A rewound roll (rs_roll_restore): the starts of the roll wound since do not apply */
void rsi_roll_reference_restored(rs_roll *roll)
{
  roll->ref.last_start = 0;
  /* the nodes above the restored roll's top are no longer part of the roll: their values
   * are integrated afresh when they are wound again */
  if (roll->ref.top > roll->n) roll->ref.top = roll->n;
}

/* ---- rebasing ------------------------------------------------------------------------- */

/* A new reference from node `from` up (rsi_roll_reuse_start), before it is integrated: below
 * the node the reference's values take their first-order correction for the drift since
 * the last reference, C = prof.c, for good,
 *     (w, L)_j += C (p_w, p_L)_j,   e_j *= exp(C (p_L,j - p_L,from)),   E_ref,j = E_r,j,
 * the shape so that it stays exp(L) up to a constant, and continuous at the node, where the
 * integration's shape joins it (rsi_roll_add_one). The drift there restarts from 0: what the
 * correction leaves is second order (the start-node search bounded it). Every node was
 * taken out of the lazy zone first (rsi_roll_integrate), so that the shape may change. */
void rsi_roll_reference_rebase(rs_roll *roll, int from)
{
  const double C = roll->prof.c, pLf = roll->prof.L[from];
  double *restrict w = roll->w, *restrict L = roll->L, *restrict e = roll->ref.shape_e;
  double *restrict Eref = roll->ref.Er;
  const double *restrict pw = roll->prof.w, *restrict pL = roll->prof.L, *restrict E = roll->ode.Er;
  /* the deeper level's nodes (roll_deep) stay as they are: the level carries the factor
   * (rsi_roll_deep_rebased, called before); in a loop that vectorises where every
   * exponent is within the Taylor sum's range (roll_exp_step's own choice: the same bits) */
  if (rsi_roll_rebase_small(C, pL, pLf, roll->deep.top, from + 1))
    rsi_roll_rebase_nodes(C, pw, pL, pLf, E, w, L, e, Eref, roll->deep.top, from + 1);
  else
    rsi_roll_rebase_nodes_exp(C, pw, pL, pLf, E, w, L, e, Eref, roll->deep.top, from + 1);
  /* |p_L| <= prof.max: the shape's bound grows by at most the factor */
  roll->ref.shape_max *= exp(2.0 * fabs(C) * roll->prof.max);
  /* the drift is in the rebased values now: should this increment fail, the next starts
   * at or below the node, uncorrected (the nodes above hold the last reference's values,
   * whose drift C no longer tells: as rsi_roll_integrate marks them for an integration from
   * the node, but before anything can fail) */
  roll->ref.top = from;
  rsi_roll_profile_rebased(roll, from);
}

/* The deeper level's nodes lo..hi-1 leaving it (roll_lazy.c: all of them when it is
 * dissolved, its two top ones when it is renewed): they take the rebases they were
 * spared, (w, L) += B (p_w, p_L) and e *= A exp(B p_L) (B the sum of the rebases' C,
 * A the product of their exp(-C p_L,from): the factors of rsi_roll_reference_rebase,
 * whose profile there was the same at each); E_ref stays, so the drift there is measured
 * since the level formed, on the safe side of the one since the last rebase. */
void rsi_roll_reference_carry(rs_roll *roll, int lo, int hi, double A, double B)
{
  if (B == 0.0 && A == 1.0) return;
  double *restrict w = roll->w, *restrict L = roll->L, *restrict e = roll->ref.shape_e;
  const double *restrict pw = roll->prof.w, *restrict pL = roll->prof.L;
  if (rsi_roll_rebase_small(B, pL, 0.0, lo, hi))
    rsi_roll_carry_nodes(A, B, pw, pL, w, L, e, lo, hi);
  else
    rsi_roll_carry_nodes_exp(A, B, pw, pL, w, L, e, lo, hi);
}

/* A new reference from node ref.from up, its increment committed: the nodes above it hold
 * this integration's (w, L) and modulus (rsi_roll_integrate), the shape follows it
 * (rsi_roll_add_one, rsi_roll_block_increment); below they were rebased
 * (rsi_roll_reference_rebase). The reference's age starts again; the profile goes on from
 * the node (rsi_roll_profile_extend), as far as the shape followed the integration (not
 * where its scale would overflow). */
void rsi_roll_reference_extend(rs_roll *roll)
{
  const int from = roll->ref.from;
  const int top = roll->ref.top < roll->ref.shape_top ? roll->ref.top : roll->ref.shape_top;
  roll->ref.age = 0;
  if (roll->ref.renew) { /* in place of one from the core: a new chain begins */
    roll->ref.deep = 0;
    roll->ref.renewals++;
  } else {
    roll->ref.deep++;
    roll->ref.deep_references++;
    roll->ref.from_last = from;
  }
  rsi_roll_profile_extend(roll, from, top);
}

/* ---- the shape ------------------------------------------------------------------------ */

/* max(m, |shape_e_j|, and with Hakiel's placement |shape_h_j|) over the nodes [lo, hi]
 * (a NaN gives a NaN: no bound) */
static double roll_shape_bound(const rs_roll *roll, int lo, int hi, double m)
{
  const double *restrict se = roll->ref.shape_e, *restrict sh = roll->ref.shape_h;
  for (int j = lo; j <= hi; ++j) m = fabs(se[j]) > m || se[j] != se[j] ? fabs(se[j]) : m;
  if (!roll->shift)
    for (int j = lo; j <= hi; ++j) m = fabs(sh[j]) > m || sh[j] != sh[j] ? fabs(sh[j]) : m;
  return m;
}

/* A reference's increment (an integration from the core): its shape kept, e (the decays
 * below the block, rsi_roll_block_increment) below node bottom and 1 there (a later start
 * there still reads the shape), with its bound (the decays' own, e_bound, where only
 * shape_e counts) */
void rsi_roll_shape_reference(rs_roll *roll, const double *e, int bottom, double e_bound)
{
  const double *w = roll->w;
  memcpy(roll->ref.shape_e, e, (size_t)bottom * sizeof(double));
  roll->ref.shape_e[bottom] = 1.0;
  if (!roll->shift)
    for (int j = 0; j <= bottom; ++j) roll->ref.shape_h[j] = roll->ref.shape_e[j] * (1.0 + w[j]);
  roll->ref.shape_top = bottom;
  roll->ref.shape_max =
      roll->shift ? fmax(1.0, e_bound) : roll_shape_bound(roll, 0, bottom, 0.0);
}

/* The shape above a start lo follows this integration (the decays e there, bound
 * e_bound), in the reference's scale, so that a later increment may start higher and
 * still read its deep part as c x shape; not where that scale would overflow (then later
 * starts stay below shape_top) */
void rsi_roll_shape_follow(rs_roll *roll, const double *e, int lo, int bottom, double e_bound)
{
  const double *w = roll->w;
  const double scale = roll->ref.shape_e[lo] / e[lo];
  if (!(scale < 1e200)) {
    rsi_roll_shape_cut(roll, lo);
    return;
  }
  for (int j = lo; j < bottom; ++j) roll->ref.shape_e[j] = scale * e[j];
  roll->ref.shape_e[bottom] = scale;
  if (!roll->shift)
    for (int j = lo; j <= bottom; ++j) roll->ref.shape_h[j] = roll->ref.shape_e[j] * (1.0 + w[j]);
  roll->ref.shape_top = bottom;
  roll->ref.shape_max = roll->shift ? fmax(roll->ref.shape_max, fmax(scale, scale * e_bound))
                                    : roll_shape_bound(roll, lo, bottom, roll->ref.shape_max);
}

/* The fused one-layer path's end of rsi_roll_shape_segment (roll_internal.h): the shape's
 * new top node bottom, in scale `scale`, and its bound, the segments' values each at most
 * scale x M s of its segment */
void rsi_roll_shape_followed(rs_roll *roll, int bottom, double scale, const roll_segments *seg)
{
  roll->ref.shape_e[bottom] = scale;
  roll->ref.shape_top = bottom;
  double m = roll->ref.shape_max > scale ? roll->ref.shape_max : scale;
  for (int g = 0; g < seg->count; ++g) {
    const double b = scale * (seg->M[g] * seg->s[g]);
    m = b > m || b != b ? b : m;
  }
  roll->ref.shape_max = m;
}

/* above node lo the shape is stale */
void rsi_roll_shape_cut(rs_roll *roll, int lo) { roll->ref.shape_top = lo; }

/* ---- the component's life -------------------------------------------------------------- */

int rsi_roll_reference_alloc(rs_roll *roll, size_t cap)
{
  roll_reference *r = &roll->ref;
  double **const arrays[] = {&r->Er, &r->scan_eps, &r->shape_e, &r->shape_h};
  r->top = -1;
  r->shape_top = -1;
  r->from = -1;
  r->deep_max = RS_REF_DEEP_MAX;
  return rsi_roll_calloc(arrays, 4, cap + 1);
}

void rsi_roll_reference_free(rs_roll *roll)
{
  free(roll->ref.Er);
  free(roll->ref.scan_eps);
  free(roll->ref.shape_e);
  free(roll->ref.shape_h);
}
