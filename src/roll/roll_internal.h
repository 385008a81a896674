/* The roll engine's private state and the interface between its parts (src/roll):
 *   roll.c            the roll: parameters, create/destroy, rs_roll_add_layers, queries
 *   roll_ode.c        the ODE workspace: CVODE, the increment ODE (g^2(x) between the
 *                     nodes, right-hand side, Jacobian, error weights), the modulus an
 *                     increment sees
 *   roll_integrate.c  one integration across the roll with CVODE (nodes by quintic
 *                     interpolation inside each step, the integration's error corrected)
 *   roll_reference.c  the reference solution: where an integration may start, its books,
 *                     its shape, the start's correction, rebasing
 *   roll_increment.c  the stress increment of a block from (w, ln y), committed to the roll
 *   roll_layer.c      the same for one layer over the nodes above a reused start, in one pass
 *   roll_state.c      saving and restoring a roll's stresses
 *   roll_lazy.c       the deep part's stresses kept lazy (a scale times the reference's shape),
 *                     and on a long roll a deeper lazy level that references leave alone
 *   roll_profile.c    the reused deep part's first-order correction for the modulus drift
 *   roll_air.c        entrained air: the film under each layer in series with the stack
 *   vector2.c         CVODE's vector operations and the exact corrector for the 2-component
 *                     state
 *   roll_corrector.c  which corrector CVODE gets: the exact one after its self-test passed
 *   roll_check.c      the components' invariants, checked
 * docs/roll-model.md has the model and the derivations. */
#ifndef REELSIM_ROLL_INTERNAL_H
#define REELSIM_ROLL_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>

#include "roll/roll.h"
#include "util/huge_pages.h"
#include "util/sundials_compat.h"

enum { RS_CVODE_MSG_LEN = RS_SUNDIALS_MSG_LEN };
/* references from a node above the core between two from the core (rsi_roll_reuse_start) */
enum { RS_REF_DEEP_MAX = 4 };
/* The deeper lazy level (roll_deep): a reference from a node above the core keeps the
 * nodes more than twice as far below the top as its node in a level of their own when
 * they are at least RS_DEEP_MIN_NODES (where it pays: a long roll) */
enum { RS_DEEP_MIN_NODES = 50000 };
/* ... and renews it in place of a reference from the core while it lies within this many
 * times its depth at forming below the top (roll_reference_renew) */
enum { RS_DEEP_RENEW_DEPTH = 2 };
/* An integration whose top is at most this many nodes above its start forms ln g^2 at
 * all of them (and the one below the start) in one vectorised pass before CVODE starts,
 * instead of when a step first looks (rsi_roll_lg2_range: the right-hand side then never
 * waits on log(); beyond ~1024 nodes the pass forms more than the steps look at:
 * docs/performance.md) */
enum { RS_LG2_RANGE_MAX = 1024 };

/* One CVODE step's quintic of w in s = (x - a) inv_h (roll_integrate.c), for its nodes
 * [lo, hi]: w there is evaluated when read */
typedef struct roll_wstep {
  double a, inv_h, c[6];
  int lo, hi;
} roll_wstep;

/* ln g^2 in one interval between layer nodes: its index j, the epoch it belongs to, and
 * ln g^2 = y0 + f (m0 + f (c2 + f c3)); g0 = e^y0 = g^2 at its lower node */
typedef struct roll_g2_cubic {
  int j;
  unsigned long long epoch;
  double y0, m0, c2, c3, g0;
} roll_g2_cubic;

/* The roll's state is a few components, each a struct below, each written by the one file
 * that owns it (its functions; the others read it or call them), each with its invariant
 * stated where it is declared. The invariants hold between increments (after
 * rs_roll_create, after every rs_roll_add_layers that returned RS_OK; rs_roll_restore
 * keeps them) and are checked by rsi_roll_check_invariants (roll_check.c, one check per
 * component) after every increment in builds with RS_ROLL_CHECKS and in test_roll_check.
 * Besides the components the roll holds its parameters and stresses (roll.c; the commit
 * of an increment, roll_increment.c, roll_layer.c, and the lazy zone's moves,
 * roll_lazy.c, add to the stresses), the integration's nodes (w, L, wstep, xnode:
 * roll_integrate.c; xnode placed by roll_air.c, the reference's nodes rebased by
 * roll_reference.c), the last increment (dsr, dsh, deep_lo, c_deep, c2_deep, P_mean:
 * roll_increment.c, roll_layer.c), the work counters (stats: whichever part does the work
 * counts it) and a scratch block that no component owns. */

/* The ODE workspace (roll_ode.c; the corrector's handles made by roll_corrector.c and
 * stored here by roll_ode.c): CVODE and its vector, the nodes' pressures and moduli the
 * increment's ODE sees, ln g^2 at the nodes and the interpolation's caches.
 * Invariant: cvode, y and sunctx exist; exactly one of NLS (the exact corrector) and
 * fallback_LS with fallback_A (CVODE's Newton iteration) is set; 0 <= nodes_in_use <=
 * max_layers + 1 (the nodes an integration may look at); lg2_range_max >= 0; a cache's epoch is never
 * ahead of the moduli's (g2c.epoch, gepoch, lg2_range_epoch <= epoch). Er over the nodes an
 * integration looks at is the modulus at P_node there. */
typedef struct roll_ode {
  SUNContext sunctx;
  void *cvode;
  N_Vector y;
  SUNNonlinearSolver NLS;      /* the exact corrector, or NULL: CVODE's own Newton with */
  SUNLinearSolver fallback_LS; /* a dense linear solver (roll_corrector.c) */
  SUNMatrix fallback_A;
  char cvode_msg[RS_CVODE_MSG_LEN];
  double *P_node;       /* [cap + 1] pressure that sets the increment's modulus at each node, Pa */
  double *Er;           /* [cap + 1] E_r at the nodes for the current increment; g^2 = E_theta/E_r */
  double *lg2;          /* ln g^2: in one pass over a short integration's nodes, else
                           when the interpolation first needs it */
  unsigned long long *lg2_epoch, epoch; /* lg2[j] is current when lg2_epoch[j] == epoch, */
  int lg2_lo, lg2_hi;   /* or when lg2_lo <= j <= lg2_hi and lg2_range_epoch == epoch */
  unsigned long long lg2_range_epoch;
  int lg2_range_max;    /* an integration whose top is at most this many nodes above its
                           start forms them in one pass (RS_LG2_RANGE_MAX; 0: never) */
  int nodes_in_use;     /* nodes the RHS may look at (k + 1) */
  /* the Hermite cubic of the interval the right-hand side last evaluated (CVODE's calls
   * cluster) */
  roll_g2_cubic g2c;
  /* g^2 and d(g^2)/dx at the x last evaluated: a step's corrector and the jet at its end
   * all look at the same x */
  double gx, g2x, dg2x, gxi; /* gxi: the layer coordinate (r - r_c)/t at gx */
  unsigned long long gepoch;
  double x_anchor, r_anchor; /* r_anchor = exp(x_anchor) exactly, near where CVODE is */
} roll_ode;

/* The reference solution (roll_reference.c): the last integration from the core (or from
 * a rebased node) is the reference; below the node an integration starts from, (w, L)
 * stay the reference's, and the increment there is c times the reference's shape.
 * Invariant: -1 <= top <= n and Er > 0 over nodes 0..top; 0 <= start <= n; between
 * increments from = -1, renew = 0 and start_C = 0 (rsi_roll_start_release); -1 <= shape_top <=
 * max_layers, and over the shape's nodes 0 <= shape_e <= shape_max (and |shape_h| <=
 * shape_max with Hakiel's placement). */
typedef struct roll_reference {
  double *Er;           /* [cap + 1] the modulus the reference was integrated with */
  double *scan_eps;     /* [cap + 1] |E_r / Er - 1| at the nodes the start search looks at */
  int top;              /* w, L at the nodes 0..top are still the reference's; -1: none */
  int age;              /* integrations since the reference */
  int start;            /* node the last integration started from (0: the core) */
  int last_start;       /* the last start above the core (where a reference's increment
                           may be kept lazy from: rsi_roll_block_increment) */
  int from;             /* > 0: this increment's integration is a new reference from that
                           node up, the nodes below rebased (rsi_roll_reference_rebase) */
  int deep;             /* references from a node above the core since the last from it */
  int deep_max;         /* how many there may be (RS_REF_DEEP_MAX; 0: every one from it) */
  long deep_references; /* references from a node above the core so far */
  int from_last;        /* the node the last of them started from */
  int renew;            /* 1: this increment's reference (from `from`) renews the deeper
                           level in place of one from the core (roll_reference_renew) */
  long renewals;        /* references that renewed the level so far */
  double start_C;       /* the drift scale this increment's start was corrected with, 0: none */
  double start_ref[2];  /* the reference's (w, L) at that start (rsi_roll_start_release) */
  /* Below the start node the increment's shape is the reference's: e_j = y(r_j)/y(r_A) and
   * e_j (1 + w_j) of the reference's own increment (A its block's bottom node), kept for
   * nodes 0..shape_top; -1: none. An increment that starts at j0 <= shape_top is
   *   ds_j = c e_j,  ds_j + r ds_j' = c e_j (1 + w_j),   c = ds_{j0} / e_{j0}    (j < j0),
   * two multiplications a node (rsi_roll_block_increment, rsi_roll_commit). */
  double *shape_e, *shape_h;
  int shape_top;
  /* a bound on |shape_e| (and |shape_h| with Hakiel's placement) over the shape's nodes:
   * when |c_deep| times it is finite, so is the increment below deep_lo (rsi_roll_commit) */
  double shape_max;
} roll_reference;

/* The drift profile (roll_profile.c; docs/roll-model.md, "The deep part corrected for
 * the drift"). Nodes 0..top still hold the reference's (w, L): every integration since the
 * reference started at or above them. The pressure added there since is -c shape_e (to
 * first order), and the reference's solution with the modulus moved by it is
 * (w, L) + c (w, L)_profile. top -1: no profile (the start-node search bounds the drift
 * at first order).
 * Invariant: a profile (top >= 0) lies within the reference's nodes (top <= ref.top),
 * |L| <= max, w finite, over its nodes; between increments no reference's profile waits
 * (next = -1); c is finite. */
typedef struct roll_profile {
  int on;               /* the roll corrects its deep part (load beneath, one layer, reuse) */
  int top;
  double c;             /* the drift scale C since the reference */
  int next;             /* a reference's profile (its top), in use once its increment is
                           committed, with c_next its drift scale */
  double c_next;
  double max;           /* max |L| over the profile's nodes (the finiteness bound) */
  double *w, *L;        /* [cap + 1] */
} roll_profile;

/* The lazy deep part (roll_lazy.c): nodes deep.top..top-1 (below them the deeper level,
 * roll_deep; deep.top is 0 without one) hold stored values, their true stresses being
 * stored + c x shape (e, and h for Hakiel's hoop stress), plus c2 x e x profile L for the
 * radial stress with the deep part corrected.
 * Invariant: an empty zone (top = deep.top) has c = c2 = 0; a zone lies within the nodes
 * that existed when its scale started (top <= limit <= n), is allowed and covered by the
 * reference's shape (top - 1 <= ref.shape_top); over it a, b and Lmax are prefix maxima
 * (never decreasing up the roll) from deep.top; c and c2 are finite. */
typedef struct roll_lazy {
  int top;
  int ok;               /* this increment may freeze nodes (one layer: no corrector) */
  int limit;            /* nodes below it existed when c last started from 0 */
  int allowed;          /* the law's ln E_r is concave: the lazy part's bound holds */
  double c, c2;         /* true = stored + c e + c2 e L_profile (sigma_r) */
  double *a, *b;        /* [cap + 1] prefix maxima of the drift bound's a_j and b_j */
  double *Lmax;         /* [cap + 1] max over nodes 0..j of L (the start search's) */
  double *view_r, *view_theta; /* [cap] the stresses in full, for readers (roll_lazy_view) */
} roll_lazy;

/* The deeper lazy level (roll_lazy.c; docs/roll-model.md, "The deeper lazy level"). On a
 * long roll a reference from a node above the core leaves the nodes 0..top-1, far below
 * its node, alone: their stresses are stored + e_j (c + c2 p_L,j), e and p_L as they were
 * when the level formed; the reference's rebasing leaves their w, L, shape e and E_ref as
 * they are, and the shape's rebase factor since, A exp(B p_L,j) (A the product of
 * exp(-C p_L,from), B the sum of C, over the rebases), is carried in the scales to first
 * order: an increment c' + c2' p_L of the current shape adds A c' to c and A (B c' + c2')
 * to c2. Dissolved (the scales into the stored stresses, the rebase factors into w, L and
 * e: rsi_roll_reference_carry) when a start or a reference reaches below top, at a
 * reference from the core, a lumped block or a restore. Where a reference from the core
 * is due, a level that may be kept is renewed instead (roll_reference_renew): the
 * reference starts at its top node, or at the highest below it where the second-order
 * bound of the drift since that reference (a + |c| b with the zone's a and b of when they
 * froze: their E_ref is still that reference's) is within a hundredth of tol, the nodes
 * above leaving the level (rsi_roll_deep_lower), and the nodes below keep the core
 * reference's (w, L) with the rebase factors carried; while the level lies within twice
 * its depth at forming below the top (depth0: n - top then; deeper, it is dissolved and the reference is from the core,
 * after which a level forms afresh). Over nodes 0..top-1 the lazy
 * zone's a, b and Lmax are the level's own prefix maxima (in the scale c continues); the
 * lazy zone proper is top..lazy.top-1, its maxima starting afresh at top.
 * Invariant: an empty level (top = 0) has c = c2 = B = 0 and A = 1; a level lies within
 * the lazy zone (top <= lazy.top <= lazy.limit), with the load beneath the layer and
 * covered by the reference's shape (top - 1 <= ref.shape_top); A > 0, and c, c2, B finite;
 * min_nodes >= 1, span > 0; over its nodes the a, b and Lmax are prefix maxima; a level
 * has a depth at forming, 0 < depth0 <= n (an empty one 0). */
typedef struct roll_deep {
  int top;
  int min_nodes;        /* the fewest nodes a level forms with (RS_DEEP_MIN_NODES; tests
                           lower it: the level is then used on short rolls too) */
  double span;          /* a level keeps the nodes more than span x (n - from) below a
                           reference's node `from` (1; tests lower it) */
  double c, c2;         /* true = stored + e (c + c2 p_L) */
  double c_r;           /* c at the last rebase: the drift since is at most |c - c_r| b_j */
  double A, B;          /* the shape's rebase factor since the level formed, A exp(B p_L) */
  double pL_max;        /* max |p_L| over the level's nodes */
  double c_form, c2_form; /* c and c2 when it formed */
  double eP_max;        /* max e_j / P_j over its nodes when it formed (the pressure gained
                           since, relative to the pressure: roll_deep_factor_ok) */
  int depth0;           /* n - top when it formed (0: no level) */
  long formed;          /* levels formed so far (a work counter) */
} roll_deep;

/* Entrained air at its radius (roll_air.c): with films (and the load beneath) the nodes
 * sit at the real radii node_r (p.air_radius as each node was created), from the first
 * node with a film beneath it (geom = 1; before, node_r[j] = r_c + j t, the same
 * arithmetic). Node j's interval [j, j + 1] has pitch p_j = node_r[j + 1] - node_r[j]
 * (the newest node: t); inv_pitch = 1/p_j, pitch_sq = (p_j / t)^2.
 * Invariant: without arrays geom = 0; with them node_r rises strictly over nodes 0..n,
 * and inv_pitch > 0 and pitch_sq > 0 there. */
typedef struct roll_air {
  int geom;
  int geom_j;           /* the interval the layer coordinate was last found in */
  double kc0;           /* the core condition of the film-free roll */
  double *node_r, *inv_pitch, *pitch_sq; /* [cap + 1]; NULL without air */
} roll_air;

struct rs_roll {
  rs_roll_params p;
  double kc;            /* core condition r y'/y at r_c */
  int shift;            /* 1: a layer's load on the node beneath it (RS_LOAD_BENEATH), 0:
                           at its own outer radius (Hakiel): layer k loads node k - shift */
  int n;                /* layers wound; 0 <= n <= p.max_layers */
  /* the stresses (finite), as stored: below lazy.top the lazy zone adds its part */
  double core_sigma;    /* sigma_r at r_c, Pa (compression negative) */
  double *sigma_r;      /* [cap] per layer at s_j */
  double *sigma_theta;  /* [cap] */
  int hoop_stale;       /* load beneath: sigma_theta is derived from sigma_r when read */
  double inv_caliper;   /* 1 / p.caliper: the layer coordinate by a multiplication */
  /* the integration's nodes 0..n (roll_integrate.c) */
  double *w, *L;        /* (w, ln y) at the nodes */
  /* With one layer wound and its load beneath it only a start node reads w: the last
   * integration's w is kept as its steps' quintics (nodes wstep[0].lo.. of its steps), and
   * an integration evaluates the nodes at and below its start before it overwrites the
   * rest. wstep_n <= wstep_cap. */
  roll_wstep *wstep;
  int wstep_n, wstep_cap;
  int w_lazy;           /* this increment's integrations keep w as their steps' quintics */
  double *xnode;        /* ln r_j: CVODE's independent variable at the nodes */
  /* the last increment (roll_increment.c, fused for one layer in roll_layer.c) */
  double *P_mean;       /* [cap + 1] corrected lumping: mean pressure increment seen, Pa */
  double *dsr, *dsh;    /* [cap + 1] the increment's ds and ds + r ds' at the nodes */
  /* the last increment's nodes below deep_lo are c_deep (shape_e, shape_h), plus, with the
   * deep part corrected, c2_deep shape_e prof.L */
  int deep_lo;
  double c_deep, c2_deep;
  rs_roll_stats stats;
  roll_ode ode;
  roll_reference ref;
  roll_profile prof;
  roll_lazy lazy;
  roll_deep deep;
  roll_air air;
  /* Scratch [cap + 1] each, owned by no component: a function may use it for values that
   * do not survive the call (the drift profile's coefficients, roll_profile.c; the moduli
   * a little above the pressures of nodes that join the lazy zone, roll_lazy.c). No
   * component's array is ever used as scratch. */
  struct {
    double *u, *d, *q, *c, *a, *b;
  } scratch;
};

/* *arrays[i] = count zeroed doubles each (i < n), from 4 MiB advised into huge pages; 0
 * when one could not be allocated (the others are still allocated: the owner's free frees
 * them) */
static inline int rsi_roll_calloc(double **const arrays[], size_t n, size_t count)
{
  int ok = 1;
  for (size_t i = 0; i < n; ++i) {
    ok &= (*arrays[i] = calloc(count, sizeof(double))) != NULL;
    (void)rs_huge_pages_advise(*arrays[i], count * sizeof(double)); /* a long roll's */
  }
  return ok;
}

/* node j's radius (m): r_c + j t, or with entrained air its real radius */
static inline double roll_node_radius(const rs_roll *roll, int j)
{
  return roll->air.geom ? roll->air.node_r[j] : roll->p.core_radius + j * roll->p.caliper;
}

/* a decay's product v scaled into place, 0 below 1e-290 (no subnormals): the one rule of
 * the block path (roll_increment.c) and the fused one-layer pass (roll_layer.c) */
static inline double roll_decay_clear(double v) { return v > 1e-290 ? v : 0.0; }

/* whether an increment's deep part, c x shape + c2 x shape x profile L below its start, is
 * finite by the bounds of the shape and the profile (else the nodes are looked at one by
 * one: rsi_roll_commit) */
static inline int roll_deep_bounded(const rs_roll *roll, double c, double c2)
{
  return fabs(c) * roll->ref.shape_max < INFINITY &&
         (c2 == 0.0 || fabs(c2) * roll->ref.shape_max * roll->prof.max < INFINITY);
}

/* Whether the deeper level's rebase factor A exp(B p_L), carried in its scales to first
 * order, is still within its bound: the truncation is (B p_L)^2/2 of the pressure its
 * nodes gained since it formed, e_j (c - c_form + (c2 - c2_form) p_L,j), at most
 * (|B| pL_max)^2/2 (|c - c_form| + |c2 - c2_form| pL_max) max(e_j/P_j) of a node's pressure
 * P_j (which only grows), and is held to 1 % of tol; and |B| pL_max <= 0.1, where the
 * series is dominated by its first terms. */
static inline int roll_deep_factor_ok(const rs_roll *roll)
{
  const roll_deep *d = &roll->deep;
  const double f = fabs(d->B) * d->pL_max;
  if (f == 0.0) return 1;
  const double gain = (fabs(d->c - d->c_form) + fabs(d->c2 - d->c2_form) * d->pL_max) * d->eP_max;
  return f <= 0.1 && 0.5 * f * f * gain <= 0.01 * RS_ACCURACY_PER_RTOL * roll->p.rtol;
}

/* e^d by its Taylor sum to d^7: relative error below d^8/8! (2e-17 at |d| = 0.03) */
static inline double roll_exp_small(double d)
{
  return 1.0 + d * (1.0 + d * (1.0 / 2 + d * (1.0 / 6 + d * (1.0 / 24 + d * (1.0 / 120 +
         d * (1.0 / 720 + d * (1.0 / 5040)))))));
}

/* the same sum by Estrin's scheme: four dependent multiply-adds instead of seven, for
 * the right-hand side, which CVODE waits for (a loop over an array takes roll_exp_small:
 * there the throughput counts, and Horner's form has fewer operations) */
static inline double roll_exp_small_estrin(double d)
{
  const double d2 = d * d, d4 = d2 * d2;
  const double a = 1.0 + d, b = 1.0 / 2 + d * (1.0 / 6), c = 1.0 / 24 + d * (1.0 / 120),
               e = 1.0 / 720 + d * (1.0 / 5040);
  return (a + d2 * b) + d4 * (c + d2 * e);
}

/* e^d: the Taylor sum where it holds (|d| < 0.03: a layer's decay, a change of ln g^2 within
 * a layer), exp() beyond */
static inline double roll_exp_step(double d)
{
  return fabs(d) >= 0.03 ? exp(d) : roll_exp_small(d);
}

/* ln(a/b) = 2 atanh(z), z = (a - b)/(a + b), by its series to z^9: relative error below
 * z^10/11 < 1e-19 for |z| < 0.015 (two neighbouring nodes' moduli), five multiply-adds
 * where log() costs ~20 ns */
static inline double roll_log_ratio_small(double z)
{
  const double z2 = z * z;
  return 2.0 * z * (1.0 + z2 * (1.0 / 3 + z2 * (1.0 / 5 + z2 * (1.0 / 7 + z2 * (1.0 / 9)))));
}

/* roll_lazy.c */
void rsi_roll_deep_maxima(const double *pL, const double *e, const double *sr, double core_sigma,
                          double c, double c2, int D, double *m, double *q);
void rsi_roll_shape_add(rs_roll *roll, int lo, int hi, double c, double c2);
void rsi_roll_lazy_flush(rs_roll *roll, int from);
int rsi_roll_lazy_flush_core(rs_roll *roll);
void rsi_roll_lazy_freeze(rs_roll *roll, int to);
double rsi_roll_lazy_sigma(const rs_roll *roll, int j);
const double *rsi_roll_lazy_view_r(rs_roll *roll);
const double *rsi_roll_lazy_view_theta(rs_roll *roll);
int rsi_roll_lazy_allowed(const rs_roll_params *p);
int rsi_roll_commit_deep(rs_roll *roll, int lo, double c, double c2, double ds0);
void rsi_roll_lazy_configure(rs_roll *roll, int m);
void rsi_roll_lazy_clear(rs_roll *roll);
int rsi_roll_deep_keep(rs_roll *roll, int from);
void rsi_roll_deep_rebased(rs_roll *roll, double C, double pL_from);
void rsi_roll_deep_lower(rs_roll *roll, int to);
int rsi_roll_lazy_alloc(rs_roll *roll, size_t cap);
void rsi_roll_lazy_free(rs_roll *roll);

/* roll_ode.c */
double rsi_roll_g2_at(rs_roll *roll, double x, double *dg2);
double rsi_roll_g2_probe(rs_roll *roll, double x);
void rsi_roll_lg2_range(rs_roll *roll, int lo, int hi);
double rsi_roll_layer_coord_at(rs_roll *roll, double x);
int rsi_roll_rhs(sunrealtype x, N_Vector yv, N_Vector ydot, void *user);
int rsi_roll_ewt(N_Vector yv, N_Vector ewt, void *user);
void rsi_roll_gather_pressure(rs_roll *roll, int k, const double *add);
rs_status rsi_roll_set_modulus(rs_roll *roll, int k);
rs_status rsi_roll_set_modulus_stress(rs_roll *roll, int k);
rs_status rsi_roll_prepare_nodes(rs_roll *roll, int lo, int hi);
int rsi_roll_ode_alloc(rs_roll *roll, size_t cap);
int rsi_roll_ode_create(rs_roll *roll);
void rsi_roll_ode_free(rs_roll *roll);
int rsi_roll_ode_restart(rs_roll *roll, double x0, double w0, double L0);
void rsi_roll_modulus_probe(const rs_roll *roll, const double *P, double *Pp, double *Ep, int lo,
                            int hi);

/* roll_profile.c */
int rsi_roll_profile_build(rs_roll *roll, int from, int top);
double rsi_roll_profile_bound(double eps_max, double L_max, double Ls, int second);
void rsi_roll_profile_configure(rs_roll *roll, int on);
void rsi_roll_profile_drop(rs_roll *roll);
void rsi_roll_profile_clip(rs_roll *roll, int top);
void rsi_roll_profile_reference(rs_roll *roll, int bottom, double S, int block);
void rsi_roll_profile_commit(rs_roll *roll, int lo, double c);
void rsi_roll_profile_rebased(rs_roll *roll, int from);
void rsi_roll_profile_extend(rs_roll *roll, int from, int top);
int rsi_roll_profile_alloc(rs_roll *roll, size_t cap);
void rsi_roll_profile_free(rs_roll *roll);

/* roll_air.c */
void rsi_roll_air_series(const rs_roll *roll, const double *P, double *E, int lo, int hi);
rs_status rsi_roll_air_alloc(rs_roll *roll);
void rsi_roll_air_free(rs_roll *roll);
rs_status rsi_roll_air_nodes(rs_roll *roll, int k_old, int k);
double rsi_roll_air_coord(rs_roll *roll, double r, double *inv_pitch);

/* roll_integrate.c */
rs_status rsi_roll_integrate(rs_roll *roll, int k);
void rsi_roll_wstep_store(rs_roll *roll, int hi);
void rsi_roll_start_release(rs_roll *roll, rs_status st);


/* roll_increment.c */
typedef struct roll_segments {
  int count;            /* 4, or 0: the products are final (a short range) */
  int b[5];             /* segment g is the nodes [b[g], b[g + 1]) */
  double s[4];          /* its scale: the product of the segments above it */
  double M[4];          /* its largest unscaled product */
} roll_segments;
void rsi_roll_decays_raw(const double *L, double *e, int lo, int top, roll_segments *seg);
void rsi_roll_hoop_from_equilibrium(double *sigma_theta, const double *sigma_r, double core_sigma,
                                double rc, double t, int k);
void rsi_roll_hoop_from_equilibrium_at(double *sigma_theta, const double *sigma_r, double core_sigma,
                                   const double *radius, double t, int k);
double rsi_roll_deep_scales(const rs_roll *roll, int lo, double c, double *c2);
void rsi_roll_block_increment(rs_roll *roll, int k_old, int m, const double *T0, double *mean);
rs_status rsi_roll_commit(rs_roll *roll, int m, const double *T0);

/* roll_reference.c */
int rsi_roll_reuse_start(rs_roll *roll, double *C);
void rsi_roll_reference_core(rs_roll *roll);
void rsi_roll_reference_begin(rs_roll *roll, int k, int j0);
void rsi_roll_reference_end(rs_roll *roll, int k, int first);
void rsi_roll_reference_extend(rs_roll *roll);
void rsi_roll_reference_rebase(rs_roll *roll, int from);
void rsi_roll_reference_carry(rs_roll *roll, int lo, int hi, double A, double B);
/* 1 when |s (pL_j - p0)| < 0.03 at every node of [lo, hi), none NaN: roll_exp_step is then
 * the Taylor sum at each, and the rebase's and the carry's node loops below that vectorise
 * (exp by roll_exp_small) give the bits of those node by node (_exp: roll_exp_step) */
int rsi_roll_rebase_small(double s, const double *pL, double p0, int lo, int hi);
void rsi_roll_rebase_nodes(double C, const double *pw, const double *pL, double pLf,
                           const double *E, double *w, double *L, double *e, double *Eref,
                           int lo, int hi);
void rsi_roll_carry_nodes(double A, double B, const double *pw, const double *pL, double *w,
                          double *L, double *e, int lo, int hi);
void rsi_roll_rebase_nodes_exp(double C, const double *pw, const double *pL, double pLf,
                               const double *E, double *w, double *L, double *e, double *Eref,
                               int lo, int hi);
void rsi_roll_carry_nodes_exp(double A, double B, const double *pw, const double *pL, double *w,
                              double *L, double *e, int lo, int hi);
void rsi_roll_reference_restored(rs_roll *roll);
void rsi_roll_start_set(rs_roll *roll, int first, double C);
void rsi_roll_start_restore(rs_roll *roll);
void rsi_roll_shape_reference(rs_roll *roll, const double *e, int bottom, double e_bound);
void rsi_roll_shape_follow(rs_roll *roll, const double *e, int lo, int bottom, double e_bound);
void rsi_roll_shape_followed(rs_roll *roll, int bottom, double scale, const roll_segments *seg);
void rsi_roll_shape_cut(rs_roll *roll, int lo);
int rsi_roll_reference_alloc(rs_roll *roll, size_t cap);
void rsi_roll_reference_free(rs_roll *roll);
/* The one-layer path's pass over a segment of the decays (rsi_roll_add_one): the decays of
 * [lo, hi), scaled by s, cleared below 1e-290 (as roll_decays), committed as ds = -S e (sr
 * holds layer j at j - 1); with se != NULL (the reference's shape_e) the shape follows,
 * in the reference's scale. The reference's code (its other writers of the shape are in
 * roll_reference.c), inline here so that the pass stays one loop over the nodes. */
static inline void rsi_roll_shape_segment(const double *restrict e, double *restrict sr,
                                          double *restrict se, int lo, int hi, double s,
                                          double mS, double scale)
{
  if (se)
    for (int j = lo; j < hi; ++j) {
      const double ev = roll_decay_clear(e[j] * s);
      se[j] = scale * ev;
      sr[j - 1] += ev * mS;
    }
  else
    for (int j = lo; j < hi; ++j) {
      const double ev = roll_decay_clear(e[j] * s);
      sr[j - 1] += ev * mS;
    }
}

/* roll_check.c */
const char *rsi_roll_check_invariants(const rs_roll *roll, int full);

/* roll_layer.c */
rs_status rsi_roll_add_one(rs_roll *roll, double T0);

#endif
