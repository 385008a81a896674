/* The increment ODE of the roll engine (docs/roll-model.md): in x = ln r,
 *     w' = g^2 - 1 - 2 w - w^2,   L' = w,     g^2(x) = E_theta / E_r(P(x)),
 * with ln g^2 a C^1 cubic Hermite between the layer nodes, E_r frozen at the pressures
 * before the increment. The right-hand side and CVODE's error weights (the exact Jacobian,
 * which only CVODE's own Newton iteration needs, is the fallback corrector's:
 * roll_corrector.c). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "roll/roll_corrector.h"
#include "roll/roll_internal.h"
#include "roll/vector2.h"
#include "util/error.h"
#include "util/float_flags.h"
#include "util/log_vec.h"
#include "util/sundials_compat.h"
#include "util/vector_clones.h"

/* ln g^2 at node j: from the pass over the integration's nodes (rsi_roll_lg2_range), or else
 * formed when first needed in an epoch. A neighbour's value is usually
 * there already (an interval needs nodes j-1..j+2, and the steps move up the roll): then
 *     ln g_j^2 = ln g_k^2 + ln(E_k / E_j) = ln g_k^2 + 2 atanh(z),  z = (E_k - E_j)/(E_k + E_j),
 * by the series to z^9 (relative error below z^10 / 11 < 1e-19 for |z| < 0.015, a 3 %
 * change of the modulus between layers): five multiply-adds and a division where log()
 * costs ~20 ns; log() otherwise. */
static inline double roll_lg2(rs_roll *roll, int j)
{
  if (roll->ode.lg2_range_epoch == roll->ode.epoch && j >= roll->ode.lg2_lo && j <= roll->ode.lg2_hi)
    return roll->ode.lg2[j];
  if (roll->ode.lg2_epoch[j] != roll->ode.epoch) {
    const unsigned long long ep = roll->ode.epoch;
    const int k = j > 0 && roll->ode.lg2_epoch[j - 1] == ep ? j - 1
                  : j + 1 < roll->ode.nodes_in_use && roll->ode.lg2_epoch[j + 1] == ep ? j + 1
                                                                              : -1;
    const double z = k >= 0 ? (roll->ode.Er[k] - roll->ode.Er[j]) / (roll->ode.Er[k] + roll->ode.Er[j]) : 1.0;
    if (fabs(z) < 0.015) {
      roll->ode.lg2[j] = roll->ode.lg2[k] + roll_log_ratio_small(z);
    } else {
      roll->ode.lg2[j] = log(roll->p.E_theta / roll->ode.Er[j]);
    }
    roll->ode.lg2_epoch[j] = ep;
  }
  return roll->ode.lg2[j];
}

/* r = e^x near the anchor as r_anchor e^(x - x_anchor) by a Taylor sum (relative error
 * below 1e-16 for |x - x_anchor| < 0.02); the anchor itself is always an exact exp(), so
 * nothing accumulates. CVODE evaluates within a step or two of where it was. */
static inline double roll_radius_at(rs_roll *roll, double x)
{
  const double d = x - roll->ode.x_anchor;
  if (!(fabs(d) < 0.02)) {
    roll->ode.x_anchor = x;
    roll->ode.r_anchor = exp(x);
    return roll->ode.r_anchor;
  }
  return roll->ode.r_anchor * roll_exp_small_estrin(d);
}

/* g^2 at x = ln r: a cubic Hermite in ln g^2 between the nodes (Catmull-Rom slopes), in
 * the layer coordinate *xi = (r - r_c)/t, and d(g^2)/dx = g^2 v'(xi) r/t (continuous: the
 * interpolant is C^1), which the node interpolation needs. hc holds the interval's cubic,
 * formed afresh when x is in another one. */
static double roll_g2_eval(rs_roll *roll, roll_g2_cubic *hc, double x, double *dg2, double *xi_out)
{
  const double r = roll_radius_at(roll, x);
  double inv_p = roll->inv_caliper; /* 1 / the pitch of the interval r is in */
  const double xi = roll->air.geom ? rsi_roll_air_coord(roll, r, &inv_p) : (r - roll->p.core_radius) * inv_p;
  *xi_out = xi;
  const int last = roll->ode.nodes_in_use - 1;
  int j = xi <= 0.0 ? -1 : (int)xi;
  /* at the end nodes themselves (an integration starts at the core and stops at its top
   * node; r = e^x there within rounding) the slope is the inner interval's, one-sided:
   * the step's jet there must be the one its quintic interpolates, or the step's defect
   * says 1e4 - 1e5 tolerances that are not there (docs/roll-model.md) */
  if (last > 0 && ((j < 0 && xi > -1e-7) || (j >= last && xi < last + 1e-7)))
    j = j < 0 ? 0 : last - 1;
  if (j < 0 || j >= last) {
    *dg2 = 0.0;
    return roll->p.E_theta / roll->ode.Er[j < 0 ? 0 : last];
  }
  double f = xi - j;
  if (j != hc->j || hc->epoch != roll->ode.epoch) {
    const double y0 = roll_lg2(roll, j), y1 = roll_lg2(roll, j + 1);
    const double m0 = j > 0 ? 0.5 * (y1 - roll_lg2(roll, j - 1)) : y1 - y0;
    const double m1 = j + 1 < last ? 0.5 * (roll_lg2(roll, j + 2) - y0) : y1 - y0;
    /* the cubic as y0 + f (m0 + f (c2 + f c3)): three dependent multiply-adds a call */
    hc->y0 = y0;
    hc->m0 = m0;
    hc->c2 = 3.0 * (y1 - y0) - 2.0 * m0 - m1;
    hc->c3 = 2.0 * (y0 - y1) + m0 + m1;
    hc->g0 = roll->p.E_theta / roll->ode.Er[j]; /* = e^y0 */
    hc->j = j;
    hc->epoch = roll->ode.epoch;
  }
  const double m0 = hc->m0, c2 = hc->c2, c3 = hc->c3;
  /* e^v = g^2 at the node times e^(v - y0), a change of ln g^2 within one layer: the
   * Taylor sum where it is small (a tenth of the cost of exp(), a right-hand side at a time) */
  const double dv0 = f * (m0 + f * (c2 + f * c3));
  double g2 = fabs(dv0) < 0.03 ? hc->g0 * roll_exp_small_estrin(dv0) : exp(hc->y0 + dv0);
  const double dv = m0 + f * (2.0 * c2 + 3.0 * c3 * f);
  *dg2 = g2 * dv * (r * inv_p);
  return g2;
}

/* (r - r_c)/t at x = ln r: the layer coordinate g^2 was last evaluated at when x is that
 * point (the end of the step just taken: rsi_roll_integrate looks for its nodes there), else
 * from the anchored radius; either way without an exp() */
double rsi_roll_layer_coord_at(rs_roll *roll, double x)
{
  if (x == roll->ode.gx && roll->ode.gepoch == roll->ode.epoch) return roll->ode.gxi;
  if (roll->air.geom) {
    double inv_p;
    return rsi_roll_air_coord(roll, roll_radius_at(roll, x), &inv_p);
  }
  return (roll_radius_at(roll, x) - roll->p.core_radius) * roll->inv_caliper;
}

/* ln g^2 at the nodes [lo, hi] in one pass that vectorises (an integration over a short
 * span looks at most of them: RS_LG2_RANGE_MAX). rs_log_positive holds for positive normal
 * numbers; a g^2 outside them (a modulus the law left beyond 1e308 times E_theta, or
 * below 2.2e-308 of it) takes log() instead, as the lazy path does: an infinite g^2 gives
 * the right-hand side the infinity that makes CVODE say so (the flag read from g^2's bits:
 * util/float_flags.h) */
RS_VECTOR_CLONES static void roll_lg2_pass(rs_roll *roll, int lo, int hi)
{
  double *restrict lg = roll->ode.lg2;
  const double *restrict E = roll->ode.Er, Eth = roll->p.E_theta;
  uint64_t odd = 0;
  for (int j = lo; j <= hi; ++j) {
    const double g2 = Eth / E[j];
    odd |= rs_flag_not_positive_normal(g2);
    lg[j] = rs_log_positive(g2);
  }
  for (int j = lo; rs_flag_raised(odd) && j <= hi; ++j) {
    const double g2 = Eth / E[j];
    if (!(g2 >= DBL_MIN && g2 <= DBL_MAX)) lg[j] = log(g2);
  }
  roll->ode.lg2_lo = lo;
  roll->ode.lg2_hi = hi;
  roll->ode.lg2_range_epoch = roll->ode.epoch;
}

void rsi_roll_lg2_range(rs_roll *roll, int lo, int hi)
{
  roll_lg2_pass(roll, lo, hi);
}

/* g^2 at x for the error correction's look inside a step, on a copy of the right-hand
 * side's interval cubic: what it and the step's end keep stay as they were, as the next
 * step starts where this one ended */
double rsi_roll_g2_probe(rs_roll *roll, double x)
{
  roll_g2_cubic hc = roll->ode.g2c;
  double dg2, xi;
  return roll_g2_eval(roll, &hc, x, &dg2, &xi);
}

/* roll_g2_eval at x, kept for the next call at the same x (dg2 may be NULL) */
double rsi_roll_g2_at(rs_roll *roll, double x, double *dg2)
{
  if (x != roll->ode.gx || roll->ode.gepoch != roll->ode.epoch) {
    roll->ode.g2x = roll_g2_eval(roll, &roll->ode.g2c, x, &roll->ode.dg2x, &roll->ode.gxi);
    roll->ode.gx = x;
    roll->ode.gepoch = roll->ode.epoch;
  }
  if (dg2) *dg2 = roll->ode.dg2x;
  return roll->ode.g2x;
}

/* f(x, [w, L]) = [g^2 - 1 - 2w - w^2, w],  x = ln r */
int rsi_roll_rhs(sunrealtype x, N_Vector yv, N_Vector ydot, void *user)
{
  rs_roll *roll = user;
  const sunrealtype *y = NV_DATA_S(yv); /* the macro: the library's getter is a call */
  sunrealtype *f = NV_DATA_S(ydot);
  double g2 = rsi_roll_g2_at(roll, x, NULL), w = y[0];
  f[0] = g2 - 1.0 - 2.0 * w - w * w;
  f[1] = w;
  return isfinite(f[0]) ? 0 : 1; /* recoverable: CVODE retries with a smaller step */
}

/* CVODE's error weights 1/(rtol |y_i| + atol), as CVodeSStolerances would form them, in
 * one function instead of five vector operations */
int rsi_roll_ewt(N_Vector yv, N_Vector ewt, void *user)
{
  const rs_roll *roll = user;
  const sunrealtype *y = NV_DATA_S(yv);
  sunrealtype *e = NV_DATA_S(ewt);
  const double rtol = roll->p.rtol, atol = roll->p.atol;
  const double d0 = rtol * fabs(y[0]) + atol, d1 = rtol * fabs(y[1]) + atol;
  if (!(d0 > 0.0 && d1 > 0.0)) return -1;
  e[0] = 1.0 / d0;
  e[1] = 1.0 / d1;
  return 0;
}

/* P_node = the pressures (Pa, compression positive) at the nodes lazy_top..k before the
 * increment, plus add[j] where add != NULL; the layers being wound carry none yet. Nodes
 * below the lazy frontier are not read (roll_lazy.c). Plain loops: they vectorise. */
void rsi_roll_gather_pressure(rs_roll *roll, int k, const double *add)
{
  double *restrict P = roll->ode.P_node;
  const int n = roll->n < k ? roll->n : k, F = roll->lazy.top;
  if (F == 0) P[0] = -roll->core_sigma;
  for (int j = F > 1 ? F : 1; j <= n; ++j) P[j] = -roll->sigma_r[j - 1];
  for (int j = n + 1 > F ? n + 1 : F; j <= k; ++j) P[j] = 0.0;
  if (add)
    for (int j = F; j <= k; ++j) P[j] += add[j];
}

/* the error for node j, whose modulus (roll->ode.Er, at roll->ode.P_node) is not positive and finite */
static rs_status roll_modulus_refused(const rs_roll *roll, int j)
{
  return RS_ERROR(RS_ERR_SOLVER,
                  "radial modulus E_r = %g Pa at r = %.6g m (pressure %g Pa) is not positive: "
                  "the radial law is outside its range",
                  roll->ode.Er[j], roll_node_radius(roll, j), roll->ode.P_node[j]);
}

/* E_r at the nodes [lo, hi) from P_node, checked: positive and finite; with entrained air
 * the film at each node in series (roll_air.c) */
static rs_status roll_modulus_range(rs_roll *roll, int lo, int hi)
{
  if (hi <= lo) return RS_OK;
  rs_radial_modulus_n(&roll->p.radial, roll->ode.P_node + lo, roll->ode.Er + lo, hi - lo);
  /* linear and Pfeiffer moduli are positive and finite at every finite P >= 0 (K1, K2,
   * E_r > 0 checked at load; the pressures are finite: rsi_roll_commit); a polynomial or a
   * table can leave its range: one vectorised pass, the node looked for only then */
  const rs_radial_kind law = roll->p.radial.law;
  if (law != RS_RADIAL_LINEAR && law != RS_RADIAL_PFEIFFER) {
    const double *restrict E = roll->ode.Er;
    uint64_t bad = 0;
    for (int j = lo; j < hi; ++j) bad |= rs_flag_not_positive_finite(E[j]);
    for (int j = lo; rs_flag_raised(bad) && j < hi; ++j)
      if (!(E[j] > 0.0 && E[j] < INFINITY))
        return roll_modulus_refused(roll, j);
  }
  if (roll->p.air_film) rsi_roll_air_series(roll, roll->ode.P_node, roll->ode.Er, lo, hi);
  return RS_OK;
}

/* P_node and E_r at the nodes [lo, hi), all holding their stresses explicitly (none lazy),
 * from the stresses in one pass (rs_radial_modulus_stress_n, checked as it goes); the nodes
 * above the n layers wound (the layers being wound) carry no pressure yet. With entrained
 * air the film at each node in series (roll_air.c). */
static rs_status roll_modulus_stress_range(rs_roll *roll, int lo, int hi)
{
  const rs_radial_law *law = &roll->p.radial;
  double *restrict P = roll->ode.P_node, *restrict E = roll->ode.Er;
  const int n = roll->n < hi - 1 ? roll->n : hi - 1;
  if (hi <= lo) return RS_OK;
  int bad = -1;
  if (lo == 0) bad = rs_radial_modulus_stress_n(law, &roll->core_sigma, P, E, 1);
  const int j1 = lo > 1 ? lo : 1, j2 = n + 1 > lo ? n + 1 : lo;
  if (bad < 0 && j1 <= n) {
    const int b = rs_radial_modulus_stress_n(law, roll->sigma_r + j1 - 1, P + j1, E + j1, n + 1 - j1);
    if (b >= 0) bad = j1 + b;
  }
  if (bad < 0 && j2 < hi) {
    for (int j = j2; j < hi; ++j) P[j] = 0.0;
    rs_radial_modulus_n(law, P + j2, E + j2, hi - j2);
    for (int j = j2; bad < 0 && j < hi; ++j)
      if (!(E[j] > 0.0 && E[j] < INFINITY)) bad = j;
  }
  if (bad >= 0)
    return roll_modulus_refused(roll, bad);
  if (roll->p.air_film) rsi_roll_air_series(roll, P, E, lo, hi);
  return RS_OK;
}

/* The moduli of the nodes 0..k are the integration's from now: a new epoch (ln g^2 and the
 * interpolation's caches are formed again: over a long integration only where CVODE's
 * steps look, a few nodes per step, rather than a log at every node at every increment;
 * over a short one in a vectorised pass, rsi_roll_lg2_range) */
static rs_status roll_modulus_epoch(rs_roll *roll, int k, rs_status st)
{
  if (st) return st;
  roll->ode.epoch++;
  roll->ode.nodes_in_use = k + 1;
  return RS_OK;
}

/* rsi_roll_gather_pressure (nothing added) and rsi_roll_set_modulus in one pass over the nodes:
 * the predictor's modulus, at the pressures before the increment */
rs_status rsi_roll_set_modulus_stress(rs_roll *roll, int k)
{
  return roll_modulus_epoch(roll, k, roll_modulus_stress_range(roll, roll->lazy.top, k + 1));
}

/* The pressures and moduli of the nodes [lo, hi) that have just left the lazy zone
 * (rsi_roll_integrate, when an integration starts below the frontier): same epoch */
rs_status rsi_roll_prepare_nodes(rs_roll *roll, int lo, int hi)
{
  return roll_modulus_stress_range(roll, lo, hi); /* flushed: none of them lazy */
}

/* E_r(P) at the nodes lazy_top..k, P from roll->ode.P_node: the modulus an integration sees
 * (g^2 = E_theta / E_r, and ln g^2, are formed by rsi_roll_lg2_range or where the steps look:
 * roll_lg2). */
rs_status rsi_roll_set_modulus(rs_roll *roll, int k)
{
  return roll_modulus_epoch(roll, k, roll_modulus_range(roll, roll->lazy.top, k + 1));
}

/* The moduli Ep (with entrained air its film in series) at the pressures Pp = 1.001 P + 1 Pa,
 * a little above the pressures P, at the nodes [lo, hi): d ln E_r / dP by the forward
 * difference (Ep - E) / (E (Pp - P)), to ~1e-3. One formula for the lazy zone's drift
 * bound (roll_lazy.c) and the drift profile's forcing (roll_profile.c). */
void rsi_roll_modulus_probe(const rs_roll *roll, const double *restrict P, double *restrict Pp,
                            double *restrict Ep, int lo, int hi)
{
  for (int j = lo; j < hi; ++j) Pp[j] = P[j] * 1.001 + 1.0;
  rs_radial_modulus_n(&roll->p.radial, Pp + lo, Ep + lo, hi - lo);
  if (roll->p.air_film) rsi_roll_air_series(roll, Pp, Ep, lo, hi);
}

/* ---- the workspace's life ---------------------------------------------------------------- */

/* The workspace's arrays for a roll of cap layers (nodes 0..cap), zeroed; 0 when one could
 * not be allocated (rsi_roll_ode_free frees what was) */
int rsi_roll_ode_alloc(rs_roll *roll, size_t cap)
{
  roll_ode *o = &roll->ode;
  double **const arrays[] = {&o->P_node, &o->Er, &o->lg2};
  o->lg2_range_max = RS_LG2_RANGE_MAX;
  o->lg2_hi = -1; /* no range yet */
  o->lg2_epoch = calloc(cap + 1, sizeof *o->lg2_epoch);
  return rsi_roll_calloc(arrays, 3, cap + 1) && o->lg2_epoch;
}

/* CVODE for the roll: BDF on the 2-vector (w, L) with its fused and specialised
 * operations (vector2.c), the engine's right-hand side and error weights, the exact
 * corrector or CVODE's Newton iteration (roll_corrector.c); 0 on success */
int rsi_roll_ode_create(rs_roll *roll)
{
  roll_ode *o = &roll->ode;
  if (rs_sundials_context_create(&o->sunctx) != 0) return -1;
  o->y = N_VNew_Serial(2, o->sunctx);
  if (!o->y) return -1;
  /* fused vector kernels: fewer calls per step, and steps are what this engine is made of */
  if (N_VEnableFusedOps_Serial(o->y, SUNTRUE) != 0) return -1;
  /* and the hot ones as straight-line 2-component code (src/roll/vector2.c) */
  if (rsi_roll_vector2_specialise(o->y) != 0) return -1;
  N_VConst(0.0, o->y);
  o->cvode = CVodeCreate(CV_BDF, o->sunctx);
  if (!o->cvode) return -1;
  if (rs_sundials_cvode_messages(o->cvode, o->sunctx, &o->cvode_msg) != 0) return -1;
  if (CVodeInit(o->cvode, rsi_roll_rhs, log(roll->p.core_radius), o->y) != CV_SUCCESS) return -1;
  if (CVodeWFtolerances(o->cvode, rsi_roll_ewt) != CV_SUCCESS) return -1;
  if (CVodeSetUserData(o->cvode, roll) != CV_SUCCESS) return -1;
  /* the corrector equations solved exactly (roll_corrector.c, vector2.c) */
  if (rsi_roll_corrector_attach(o->sunctx, o->cvode, o->y, &o->NLS, &o->fallback_LS,
                                &o->fallback_A) != 0)
    return -1;
  /* one CVode call = one step here; the per-increment budget is counted by the engine */
  if (CVodeSetMaxNumSteps(o->cvode, 10) != CV_SUCCESS) return -1;
  /* CVODE keeps its step (and its order) while the step it could take is within a band of
   * the current one, [0, 1.5] by default: it never shrinks a step until one fails its error
   * test. Near the surface, where every step must be ~10 % shorter than the last, one step
   * in five would fail. [0.8, 1.05]: it shrinks a step before it fails, and moves up to order 5
   * on the way up from a restart in the smooth interior, where a partial integration starts
   * (docs/performance.md has the measurements). */
  if (CVodeSetEtaFixedStepBounds(o->cvode, 0.8, 1.05) != CV_SUCCESS) return -1;
  return 0;
}

void rsi_roll_ode_free(rs_roll *roll)
{
  roll_ode *o = &roll->ode;
  if (o->cvode) CVodeFree(&o->cvode);
  if (o->NLS) SUNNonlinSolFree(o->NLS); /* CVODE does not free a solver it was given */
  if (o->fallback_LS) SUNLinSolFree(o->fallback_LS);
  if (o->fallback_A) SUNMatDestroy(o->fallback_A);
  if (o->y) N_VDestroy(o->y);
  if (o->sunctx) SUNContext_Free(&o->sunctx);
  free(o->P_node);
  free(o->Er);
  free(o->lg2);
  free(o->lg2_epoch);
}

/* CVODE restarted at x0 (the start node's ln r) from y = (w0, L0); r = e^x anchored afresh
 * at the start (its radii do not depend on where the last integration ended). 0, or -1
 * when CVODE refuses (its message in cvode_msg) */
int rsi_roll_ode_restart(rs_roll *roll, double x0, double w0, double L0)
{
  roll_ode *o = &roll->ode;
  sunrealtype *y = N_VGetArrayPointer(o->y);
  y[0] = w0;
  y[1] = L0;
  o->cvode_msg[0] = '\0';
  o->x_anchor = x0;
  o->r_anchor = exp(x0);
  return CVodeReInit(o->cvode, x0, o->y) == CV_SUCCESS ? 0 : -1;
}
