/* The deep part of the roll kept lazy (docs/roll-model.md, "The lazy deep part"): below the
 * node an increment's integration starts from, the increment is c times the reference's
 * shape e_j (rsi_roll_block_increment). Nodes below the lazy frontier F are not touched at
 * every increment: their stresses are
 *     sigma_r(r_j) = stored_j + C e_j,    (Hakiel placement: sigma_theta_j = stored + C h_j)
 * with C the sum of the increments' c since the nodes were frozen. The start-node search
 * (rsi_roll_reuse_start) needs their modulus drift eps_j = |E_r/E_ref - 1|; to first order in
 * the pressure added since freezing, -dC e_j, it is at most
 *     eps_j ~ a_j + |C| b_j,   b_j = |d ln E_r / dP| e_j,   a_j = eps_j(freeze) - |C_f| b_j
 * (C only grows in magnitude: every increment compresses; ln E_r is concave in P for the
 * stack laws, so the first-order change of ln E_r is an upper bound of it, and the relative
 * change exceeds that by (b dC)^2 / 2, negligible at the drifts the search accepts), and
 * the search takes the prefix maxima of a and b.
 * So an increment costs work over the nodes from the frontier up, not over the whole roll.
 * Readers get the full values in separate arrays (roll_lazy_view_*): reading never moves
 * the frontier. */
#include <math.h>
#include <stdlib.h>

#include "roll/roll_internal.h"
#include "util/vector_clones.h"

/* sr[j - 1] += e_j (c + c2 p_L,j) for the nodes [lo, hi), lo >= 1 (c e_j alone where c2 is
 * 0: an uncorrected deep part): arrays passed as such, so that it vectorises */
static void roll_shape_add_n(double *restrict sr, const double *restrict e,
                             const double *restrict pL, int lo, int hi, double c, double c2)
{
  if (c2 != 0.0)
    for (int j = lo; j < hi; ++j) sr[j - 1] += e[j] * (c + c2 * pL[j]);
  else
    for (int j = lo; j < hi; ++j) sr[j - 1] += c * e[j];
}

/* the radial stresses of the nodes [lo, hi) (lo >= 1) take c x shape + c2 x shape x prof_L:
 * a deep part below an increment's start, or nodes leaving or joining the lazy zone */
RS_VECTOR_CLONES static void roll_shape_add_pass(rs_roll *roll, int lo, int hi, double c,
                                                 double c2)
{
  roll_shape_add_n(roll->sigma_r, roll->ref.shape_e, roll->prof.L, lo, hi, c, c2);
}

void rsi_roll_shape_add(rs_roll *roll, int lo, int hi, double c, double c2)
{
  roll_shape_add_pass(roll, lo, hi, c, c2);
}

/* stored += scale x shape (+ scale2 x shape x prof_L) over the nodes [lo, hi) (node 0: the
 * core; Hakiel's placement also the hoop stresses): how nodes leave (scales C, C2) and join
 * (-C, -C2) the lazy zone */
static void roll_lazy_shift(rs_roll *roll, int lo, int hi, double scale, double scale2)
{
  if (lo == 0) roll->core_sigma += scale * roll->ref.shape_e[0]; /* prof_L is 0 at the core */
  rsi_roll_shape_add(roll, lo > 1 ? lo : 1, hi, scale, scale2);
  if (!roll->shift) {
    const double *restrict h = roll->ref.shape_h;
    double *restrict sth = roll->sigma_theta;
    for (int j = lo > 1 ? lo : 1; j < hi; ++j) sth[j - 1] += scale * h[j];
  }
}

/* The deeper level dissolved (roll_deep, roll_internal.h): with stresses != 0 its scales
 * go into the stored stresses (with the shape as it was when the level formed), then with
 * carry != 0 its rebase factors into the nodes' w, L and shape (rsi_roll_reference_carry);
 * the lazy zone above it must be empty. Every node below the old frontier is explicit
 * after. */
static void roll_deep_dissolve(rs_roll *roll, int stresses, int carry)
{
  roll_deep *d = &roll->deep;
  if (d->top == 0) return;
  if (stresses) roll_lazy_shift(roll, 0, d->top, d->c, d->c2);
  if (carry) rsi_roll_reference_carry(roll, 0, d->top, d->A, d->B);
  roll->lazy.top = 0;
  d->top = 0;
  d->depth0 = 0;
  d->c = d->c2 = d->c_r = d->B = 0.0;
  d->A = 1.0;
}

/* Nodes [from, F) back to explicit stresses (their true values); F = from. Below the
 * deeper level's top (roll_deep) the whole level is dissolved: F = 0. */
void rsi_roll_lazy_flush(rs_roll *roll, int from)
{
  const int F = roll->lazy.top, D = roll->deep.top;
  if (from < 0) from = 0;
  if (from >= F) return;
  if (F > D) roll_lazy_shift(roll, from > D ? from : D, F, roll->lazy.c, roll->lazy.c2);
  roll->lazy.top = from > D ? from : D;
  if (roll->lazy.top == D) roll->lazy.c = roll->lazy.c2 = 0.0;
  if (from < D) roll_deep_dissolve(roll, 1, 1);
}

/* Every node back to explicit stresses before a reference from the core, which integrates
 * every node's (w, L) and makes the shape afresh: the deeper level's rebase factors are
 * not carried into them (a pass with an exponential a node, for nothing). Returns 1 when a
 * level held nodes: their shape is then stale until the reference's increment makes it. */
int rsi_roll_lazy_flush_core(rs_roll *roll)
{
  if (roll->deep.top == 0) {
    rsi_roll_lazy_flush(roll, 0);
    return 0;
  }
  rsi_roll_lazy_flush(roll, roll->deep.top);
  roll_deep_dissolve(roll, 1, 0);
  return 1;
}

/* each node's a_j and b_j (the drift bound's, before the prefix maxima) from its modulus E,
 * the reference's Eref, and Ep at the pressure Pp a little above P: a loop over arrays
 * passed as such, that vectorises (two divisions a node) */
static void roll_lazy_bounds(int lo, int hi, double aC, const double *restrict P,
                             const double *restrict Pp, const double *restrict E,
                             const double *restrict Ep, const double *restrict Eref,
                             const double *restrict e, double *restrict la, double *restrict lb)
{
  for (int j = lo; j < hi; ++j) {
    const double kappa = fabs(Ep[j] - E[j]) / (E[j] * (Pp[j] - P[j])); /* d ln E / dP to 1e-3 */
    const double b = kappa * e[j], bb = b == b ? b : INFINITY; /* a NaN slope bounds nothing */
    lb[j] = bb;
    la[j] = fabs(E[j] - Eref[j]) / Eref[j] - aC * bb;
  }
}

/* rsi_roll_lazy_freeze's block of nodes: its ten arrays' blocks fit the first-level cache */
enum { RS_FREEZE_BLOCK = 256 };

/* Nodes [F, to) become lazy; their modulus E_r (roll->ode.Er) and the reference's (Er_ref) are
 * current, and the reference's shape covers them. */
RS_VECTOR_CLONES static void roll_lazy_freeze_pass(rs_roll *roll, int to)
{
  const int F = roll->lazy.top, D = roll->deep.top;
  /* C sums the increments since it was last 0. A node wound after that was above some of
   * them: c e_j of those is no stress (e_j = exp(L_j - shape_L) grows up the roll, by
   * orders of magnitude on a very soft web) and stored = true - C e_j would cancel
   * catastrophically. So only nodes that existed when C started are frozen. */
  if (F == D && roll->lazy.c == 0.0) roll->lazy.limit = roll->n;
  if (to > roll->lazy.limit) to = roll->lazy.limit;
  if (to <= F) return;
  const double C = roll->lazy.c, aC = fabs(C);
  const double *restrict e = roll->ref.shape_e, *restrict E = roll->ode.Er, *restrict Eref = roll->ref.Er;
  double *restrict Pp = roll->scratch.c, *restrict Ep = roll->scratch.q;
  double *restrict la = roll->lazy.a, *restrict lb = roll->lazy.b, *restrict sl = roll->lazy.Lmax;
  const double *restrict P = roll->ode.P_node, *restrict L = roll->L;
  /* the zone's maxima start afresh above the deeper level (whose own are below it) */
  double pa = F > D ? la[F - 1] : -INFINITY, pb = F > D ? lb[F - 1] : 0.0;
  double pl = F > D ? sl[F - 1] : -INFINITY; /* and the prefix maxima of L */
  /* a block at a time, so that what one pass writes the next reads from the first-level
   * cache (at a reference the whole roll freezes: nine arrays of it, streamed once each,
   * not three times) */
  for (int b0 = F; b0 < to; b0 += RS_FREEZE_BLOCK) {
    const int b1 = to - b0 > RS_FREEZE_BLOCK ? b0 + RS_FREEZE_BLOCK : to;
    /* d ln E_r / dP by a forward difference (the drift profile's: roll_ode.c) */
    rsi_roll_modulus_probe(roll, P, Pp, Ep, b0, b1);
    /* each node's a and b in a pass that vectorises (into the arrays, over Pp and Ep), then
     * the three running maxima side by side */
    roll_lazy_bounds(b0, b1, aC, P, Pp, E, Ep, Eref, e, la, lb);
    for (int j = b0; j < b1; ++j) {
      pa = la[j] > pa ? la[j] : pa;
      pb = lb[j] > pb ? lb[j] : pb;
      pl = L[j] > pl ? L[j] : pl;
      la[j] = pa;
      lb[j] = pb;
      sl[j] = pl;
    }
  }
  if (C != 0.0 || roll->lazy.c2 != 0.0) roll_lazy_shift(roll, F, to, -C, -roll->lazy.c2);
  roll->lazy.top = to;
}

void rsi_roll_lazy_freeze(rs_roll *roll, int to)
{
  roll_lazy_freeze_pass(roll, to);
}

/* sigma_r at node j (0: the core), lazy (in the zone or the deeper level) or not */
double rsi_roll_lazy_sigma(const rs_roll *roll, int j)
{
  const double s = j == 0 ? roll->core_sigma : roll->sigma_r[j - 1];
  if (j >= roll->lazy.top) return s;
  if (j < roll->deep.top)
    return s + roll->ref.shape_e[j] * (roll->deep.c + roll->deep.c2 * roll->prof.L[j]);
  return s + roll->ref.shape_e[j] * (roll->lazy.c + roll->lazy.c2 * roll->prof.L[j]);
}

/* The stresses in full for a reader, without touching the lazy state (so that reading a
 * roll never changes how it winds on: a run with history stages or entrained air winds
 * bit for bit as one without) */
static const double *roll_lazy_view(const rs_roll *roll, const double *restrict stored,
                                    const double *restrict shape, double C2,
                                    double *restrict v)
{
  const int F = roll->lazy.top, n = roll->n;
  const double C = roll->lazy.c, *restrict pL = roll->prof.L;
  const int lazy_end = F - 1 < n ? F - 1 : n; /* layers 0..F-2 sit on lazy nodes 1..F-1 */
  /* the deeper level's nodes 1..deep.top-1 (layers 0..deep.top-2; sigma_r only: the level
   * needs the load beneath, whose hoop stresses are derived from the radial ones) */
  const int deep_end = roll->deep.top - 1 < lazy_end ? roll->deep.top - 1 : lazy_end;
  int j0 = 0;
  if (deep_end > 0) {
    const double Cd = roll->deep.c, Cd2 = roll->deep.c2;
    for (int j = 0; j < deep_end; ++j) v[j] = stored[j] + shape[j + 1] * (Cd + Cd2 * pL[j + 1]);
    j0 = deep_end;
  }
  if (C2 != 0.0)
    for (int j = j0; j < lazy_end; ++j) v[j] = stored[j] + shape[j + 1] * (C + C2 * pL[j + 1]);
  else
    for (int j = j0; j < lazy_end; ++j) v[j] = stored[j] + C * shape[j + 1];
  for (int j = lazy_end > 0 ? lazy_end : 0; j < n; ++j) v[j] = stored[j];
  return v;
}

const double *rsi_roll_lazy_view_r(rs_roll *roll)
{
  return roll_lazy_view(roll, roll->sigma_r, roll->ref.shape_e, roll->lazy.c2, roll->lazy.view_r);
}

const double *rsi_roll_lazy_view_theta(rs_roll *roll)
{
  return roll_lazy_view(roll, roll->sigma_theta, roll->ref.shape_h, 0.0, roll->lazy.view_theta);
}

/* Whether the lazy deep part may be used: when ln E_r(P) is concave over P >= 0, the drift
 * a lazy node's first-order bound predicts from its slope when frozen bounds the change of
 * ln E_r to come. Pfeiffer's and a constant law are concave; a polynomial or a table is
 * checked on a logarithmic grid of pressures from 1 Pa to 1 GPa (the slopes of ln E_r
 * between grid points must not rise). A law that is not (a table flat below its first
 * point, then steep: slope 0 when frozen, a jump later) keeps every node explicit. The
 * stack law's alone, also with air films (their series compliance falls with P: there the
 * bound is an estimate, like the rest of the criterion), so that a roll whose films are all
 * cut off winds as one without air, bit for bit. */
int rsi_roll_lazy_allowed(const rs_roll_params *p)
{
  if (p->radial.law == RS_RADIAL_LINEAR || p->radial.law == RS_RADIAL_PFEIFFER) return 1;
  enum { NG = 400 };
  double lnE[NG], P[NG];
  for (int i = 0; i < NG; ++i) {
    P[i] = pow(10.0, 9.0 * i / (NG - 1));
    lnE[i] = log(rs_radial_modulus(&p->radial, P[i]));
  }
  for (int i = 1; i + 1 < NG; ++i) {
    /* the slope falls (or stays) from one interval to the next */
    const double s0 = (lnE[i] - lnE[i - 1]) / (P[i] - P[i - 1]);
    const double s1 = (lnE[i + 1] - lnE[i]) / (P[i + 1] - P[i]);
    if (!(s1 <= s0 * (1.0 + 1e-9) + 1e-300)) return 0;
  }
  return 1;
}

/* The deep part of an increment committed: below node lo (> 0) it is c x shape + c2 x shape
 * x prof_L (rsi_roll_block_increment), which the lazy nodes take in their common scales
 * and the nodes from the lazy frontier (or 1) to lo explicitly; the core takes c x shape_e
 * there (prof_L is 0 at the core), or ds0 for an increment computed node by node (lo = 0).
 * Returns the lowest node with its own stored value (1, or the lazy frontier). Shared by
 * rsi_roll_commit and rsi_roll_add_one: one formula. The lazy zone's, since it moves its
 * scales. */
int rsi_roll_commit_deep(rs_roll *roll, int lo, double c, double c2, double ds0)
{
  int j0 = 1;
  if (lo > 0 && roll->lazy.top > 0) {
    roll_deep *d = &roll->deep;
    if (d->top > 0) { /* the current shape is A exp(B p_L) times the level's: first order */
      d->c += d->A * c;
      d->c2 += d->A * (d->B * c + c2);
    }
    if (roll->lazy.top > d->top) {
      roll->lazy.c += c;
      roll->lazy.c2 += c2;
    }
    j0 = roll->lazy.top;
  } else {
    roll->core_sigma += lo > 0 ? c * roll->ref.shape_e[0] : ds0;
  }
  rsi_roll_shape_add(roll, j0, lo, c, c2);
  return j0;
}

/* whether this increment, of m layers, may freeze nodes (one layer: no corrector reads the
 * pressures at every node) */
void rsi_roll_lazy_configure(rs_roll *roll, int m) { roll->lazy.ok = m == 1 && roll->lazy.allowed; }

/* The zone emptied without applying its scales: the stored stresses were just set in full
 * (rs_roll_restore) */
void rsi_roll_lazy_clear(rs_roll *roll)
{
  roll_deep_dissolve(roll, 0, 1); /* the nodes' w, L and shape take the rebase factors */
  roll->lazy.top = 0;
  roll->lazy.c = roll->lazy.c2 = 0.0;
}

/* one node of rsi_roll_deep_maxima (below): `stored` its stored stress, *m and *q the
 * maxima of its chain */
static inline void deep_maxima_node(double stored, double e, double pL, double c, double c2,
                                    double *m, double *q)
{
  const double P = -(stored + e * (c + c2 * pL));
  const double r = P > 0.0 ? e / P : INFINITY, a = fabs(pL);
  *m = a > *m ? a : *m;
  *q = r > *q || r != r ? r : *q;
}

/* max |p_L,j| (*m) and max e_j / P_j (*q) over the nodes [0, D) (rsi_roll_deep_keep), P_j
 * the node's pressure now, -(stored + e_j (c + c2 p_L,j)) (sr[j - 1] stored, core_sigma at
 * node 0: its true stress, in the zone: the level continues the zone's scales); a node not
 * under pressure bounds nothing (INFINITY), a NaN is kept for good. Each maximum as four
 * running ones side by side, merged by the same rule: a maximum is the same whatever the
 * order it is taken in (of numbers >= +0, or a NaN kept), so the chains' latency is shared
 * out without a bit changing. */
void rsi_roll_deep_maxima(const double *restrict pL, const double *restrict e,
                          const double *restrict sr, double core_sigma, double c, double c2,
                          int D, double *m, double *q)
{
  double mm[4] = {0.0, 0.0, 0.0, 0.0}, qq[4] = {0.0, 0.0, 0.0, 0.0};
  if (D > 0) deep_maxima_node(core_sigma, e[0], pL[0], c, c2, &mm[0], &qq[0]);
  int j = 1;
  for (; j + 3 < D; j += 4)
    for (int k = 0; k < 4; ++k)
      deep_maxima_node(sr[j + k - 1], e[j + k], pL[j + k], c, c2, &mm[k], &qq[k]);
  for (; j < D; ++j) deep_maxima_node(sr[j - 1], e[j], pL[j], c, c2, &mm[0], &qq[0]);
  for (int k = 1; k < 4; ++k) {
    mm[0] = mm[k] > mm[0] ? mm[k] : mm[0];
    qq[0] = qq[k] > qq[0] || qq[k] != qq[k] ? qq[k] : qq[0];
  }
  *m = mm[0];
  *q = qq[0];
}

/* A reference from node `from` above the core is about to rebase the nodes below it
 * (rsi_roll_reference_rebase): the node from which the nodes must leave the lazy zone, the
 * deeper level's top, or 0 (every node: the level dissolved by the flush). A level kept
 * stays while it lies below the node and its rebase factor's first-order remainder is
 * negligible (roll_deep_factor_ok: at most 1 % of tol of its nodes' pressures). One
 * forms, when none exists, of the lazy nodes more than span x (n - from) below the node
 * (twice as far below the top: later references from a node above the core start at or
 * below it, rsi_roll_reuse_start), if they are at least min_nodes. Its scales are the
 * zone's, which it continues; its bounds the zone's below it, b_j (|d ln E_r/dP| e_j)
 * bounding its drift since the last rebase with |c - c_r|. */
int rsi_roll_deep_keep(rs_roll *roll, int from)
{
  roll_deep *d = &roll->deep;
  if (d->top > 0) return d->top < from && roll_deep_factor_ok(roll) ? d->top : 0;
  int D = from - (int)(d->span * (roll->n - from));
  if (D > from - 1) D = from - 1; /* the start's Hermite slope reads node from - 1 */
  if (D > roll->lazy.top) D = roll->lazy.top;
  if (!roll->shift || D < d->min_nodes) return 0;
  rsi_roll_deep_maxima(roll->prof.L, roll->ref.shape_e, roll->sigma_r, roll->core_sigma,
                       roll->lazy.c, roll->lazy.c2, D, &d->pL_max, &d->eP_max);
  d->top = D;
  d->depth0 = roll->n - D;
  d->c = d->c_r = d->c_form = roll->lazy.c;
  d->c2 = d->c2_form = roll->lazy.c2;
  d->A = 1.0;
  d->B = 0.0;
  d->formed++;
  return D;
}

/* A reference from node `from` above the core is about to rebase the nodes from the
 * deeper level's top up by exp(C (p_L,j - p_L,from)) (rsi_roll_reference_rebase; C the
 * drift scale, p_L,from the profile at the node): the level carries the factor */
void rsi_roll_deep_rebased(rs_roll *roll, double C, double pL_from)
{
  roll_deep *d = &roll->deep;
  if (d->top == 0) return;
  d->A *= exp(-C * pL_from);
  d->B += C;
  d->c_r = d->c; /* the drift since the last rebase is measured from here */
}

/* The level renewed (roll_reference_renew, roll_reference.c): the lazy zone above it
 * flushed, and its nodes from `to` up leave it, taking its scales into their stored
 * stresses (with the shape as it was when the level formed) and its rebase factors into
 * their w, L and shape (rsi_roll_reference_carry); the level's top and the zone's are
 * then `to`. */
void rsi_roll_deep_lower(rs_roll *roll, int to)
{
  roll_deep *d = &roll->deep;
  const int D = d->top;
  rsi_roll_lazy_flush(roll, D);
  roll_lazy_shift(roll, to, D, d->c, d->c2);
  rsi_roll_reference_carry(roll, to, D, d->A, d->B);
  d->top = to;
  roll->lazy.top = to;
}

int rsi_roll_lazy_alloc(rs_roll *roll, size_t cap)
{
  roll_lazy *z = &roll->lazy;
  double **const node_arrays[] = {&z->a, &z->b, &z->Lmax};
  double **const layer_arrays[] = {&z->view_r, &z->view_theta};
  z->allowed = rsi_roll_lazy_allowed(&roll->p);
  roll->deep.A = 1.0;
  roll->deep.min_nodes = RS_DEEP_MIN_NODES;
  roll->deep.span = 1.0;
  return rsi_roll_calloc(node_arrays, 3, cap + 1) & rsi_roll_calloc(layer_arrays, 2, cap);
}

void rsi_roll_lazy_free(rs_roll *roll)
{
  free(roll->lazy.a);
  free(roll->lazy.b);
  free(roll->lazy.Lmax);
  free(roll->lazy.view_r);
  free(roll->lazy.view_theta);
}
