/* The increment ODE of the roll engine (docs/roll-model.md): in x = ln r,
 *     w' = g^2 - 1 - 2 w - w^2,   L' = w,     g^2(x) = E_theta / E_r(P(x)),
 * with ln g^2 a C^1 cubic Hermite between the layer nodes, E_r frozen at the pressures
 * before the increment. The right-hand side, its exact Jacobian and CVODE's error weights. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "roll/roll_internal.h"
#include "util/error.h"
#include "util/log_vec.h"

/* ln g^2 at node j: from the pass over the integration's nodes (rsi_roll_lg2_range), or else
 * formed when first needed in an epoch. A neighbour's value is usually
 * there already (an interval needs nodes j-1..j+2, and the steps move up the roll): then
 *     ln g_j^2 = ln g_k^2 + ln(E_k / E_j) = ln g_k^2 + 2 atanh(z),  z = (E_k - E_j)/(E_k + E_j),
 * by the series to z^9 (relative error below z^10 / 11 < 1e-19 for |z| < 0.015, a 3 %
 * change of the modulus between layers): five multiply-adds and a division where log()
 * costs ~20 ns; log() otherwise. */
static inline double roll_lg2(rs_roll *roll, int j)
{
  if (roll->lg2_range_epoch == roll->epoch && j >= roll->lg2_lo && j <= roll->lg2_hi)
    return roll->lg2[j];
  if (roll->lg2_epoch[j] != roll->epoch) {
    const unsigned long long ep = roll->epoch;
    const int k = j > 0 && roll->lg2_epoch[j - 1] == ep ? j - 1
                  : j + 1 < roll->nodes_in_use && roll->lg2_epoch[j + 1] == ep ? j + 1
                                                                              : -1;
    const double z = k >= 0 ? (roll->Er[k] - roll->Er[j]) / (roll->Er[k] + roll->Er[j]) : 1.0;
    if (fabs(z) < 0.015) {
      roll->lg2[j] = roll->lg2[k] + roll_log_ratio_small(z);
    } else {
      roll->lg2[j] = log(roll->p.E_theta / roll->Er[j]);
    }
    roll->lg2_epoch[j] = ep;
  }
  return roll->lg2[j];
}

/* r = e^x near the anchor as r_anchor e^(x - x_anchor) by a Taylor sum (relative error
 * below 1e-16 for |x - x_anchor| < 0.02); the anchor itself is always an exact exp(), so
 * nothing accumulates. CVODE evaluates within a step or two of where it was. */
static inline double roll_radius_at(rs_roll *roll, double x)
{
  const double d = x - roll->x_anchor;
  if (!(fabs(d) < 0.02)) {
    roll->x_anchor = x;
    roll->r_anchor = exp(x);
    return roll->r_anchor;
  }
  return roll->r_anchor * roll_exp_small_estrin(d);
}

/* g^2 at x = ln r: a cubic Hermite in ln g^2 between the nodes (Catmull-Rom slopes), in
 * the layer coordinate *xi = (r - r_c)/t, and d(g^2)/dx = g^2 v'(xi) r/t (continuous: the
 * interpolant is C^1), which the node interpolation needs. hc holds the interval's cubic,
 * formed afresh when x is in another one. */
static double roll_g2_eval(rs_roll *roll, roll_g2_cubic *hc, double x, double *dg2, double *xi_out)
{
  const double r = roll_radius_at(roll, x);
  double inv_p = roll->inv_caliper; /* 1 / the pitch of the interval r is in */
  const double xi = roll->geom ? rsi_roll_air_coord(roll, r, &inv_p) : (r - roll->p.core_radius) * inv_p;
  *xi_out = xi;
  const int last = roll->nodes_in_use - 1;
  int j = xi <= 0.0 ? -1 : (int)xi;
  /* at the end nodes themselves (an integration starts at the core and stops at its top
   * node; r = e^x there within rounding) the slope is the inner interval's, one-sided:
   * the step's jet there must be the one its quintic interpolates, or the step's defect
   * says 1e4 - 1e5 tolerances that are not there (docs/roll-model.md) */
  if (last > 0 && ((j < 0 && xi > -1e-7) || (j >= last && xi < last + 1e-7)))
    j = j < 0 ? 0 : last - 1;
  if (j < 0 || j >= last) {
    *dg2 = 0.0;
    return roll->p.E_theta / roll->Er[j < 0 ? 0 : last];
  }
  double f = xi - j;
  if (j != hc->j || hc->epoch != roll->epoch) {
    const double y0 = roll_lg2(roll, j), y1 = roll_lg2(roll, j + 1);
    const double m0 = j > 0 ? 0.5 * (y1 - roll_lg2(roll, j - 1)) : y1 - y0;
    const double m1 = j + 1 < last ? 0.5 * (roll_lg2(roll, j + 2) - y0) : y1 - y0;
    /* the cubic as y0 + f (m0 + f (c2 + f c3)): three dependent multiply-adds a call */
    hc->y0 = y0;
    hc->m0 = m0;
    hc->c2 = 3.0 * (y1 - y0) - 2.0 * m0 - m1;
    hc->c3 = 2.0 * (y0 - y1) + m0 + m1;
    hc->g0 = roll->p.E_theta / roll->Er[j]; /* = e^y0 */
    hc->j = j;
    hc->epoch = roll->epoch;
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
  if (x == roll->gx && roll->gepoch == roll->epoch) return roll->gxi;
  if (roll->geom) {
    double inv_p;
    return rsi_roll_air_coord(roll, roll_radius_at(roll, x), &inv_p);
  }
  return (roll_radius_at(roll, x) - roll->p.core_radius) * roll->inv_caliper;
}

/* ln g^2 at the nodes [lo, hi] in one pass that vectorises (an integration over a short
 * span looks at most of them: RS_LG2_RANGE_MAX). rs_log_positive holds for positive normal
 * numbers; a g^2 outside them (a modulus the law left beyond 1e308 times E_theta, or
 * below 2.2e-308 of it) takes log() instead, as the lazy path does: an infinite g^2 gives
 * the right-hand side the infinity that makes CVODE say so (the flag is a compare mask as
 * wide as a double: it stays in the vector registers) */
void rsi_roll_lg2_range(rs_roll *roll, int lo, int hi)
{
  double *restrict lg = roll->lg2;
  const double *restrict E = roll->Er, Eth = roll->p.E_theta;
  int64_t odd = 0;
  for (int j = lo; j <= hi; ++j) {
    const double g2 = Eth / E[j];
    odd |= (int64_t)!(g2 >= DBL_MIN) | (int64_t)(g2 > DBL_MAX);
    lg[j] = rs_log_positive(g2);
  }
  for (int j = lo; odd && j <= hi; ++j) {
    const double g2 = Eth / E[j];
    if (!(g2 >= DBL_MIN && g2 <= DBL_MAX)) lg[j] = log(g2);
  }
  roll->lg2_lo = lo;
  roll->lg2_hi = hi;
  roll->lg2_range_epoch = roll->epoch;
}

/* g^2 at x for the error correction's look inside a step, on a copy of the right-hand
 * side's interval cubic: what it and the step's end keep stay as they were, as the next
 * step starts where this one ended */
double rsi_roll_g2_probe(rs_roll *roll, double x)
{
  roll_g2_cubic hc = roll->g2c;
  double dg2, xi;
  return roll_g2_eval(roll, &hc, x, &dg2, &xi);
}

/* roll_g2_eval at x, kept for the next call at the same x (dg2 may be NULL) */
double rsi_roll_g2_at(rs_roll *roll, double x, double *dg2)
{
  if (x != roll->gx || roll->gepoch != roll->epoch) {
    roll->g2x = roll_g2_eval(roll, &roll->g2c, x, &roll->dg2x, &roll->gxi);
    roll->gx = x;
    roll->gepoch = roll->epoch;
  }
  if (dg2) *dg2 = roll->dg2x;
  return roll->g2x;
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

/* J = df/d(w, L) = [[-(2 + 2w), 0], [1, 0]] */
int rsi_roll_jac(double x, const double y[2], double J[2][2], void *user)
{
  (void)x;
  (void)user;
  J[0][0] = -(2.0 + 2.0 * y[0]);
  J[0][1] = 0.0;
  J[1][0] = 1.0;
  J[1][1] = 0.0;
  return 0;
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
  double *restrict P = roll->P_node;
  const int n = roll->n < k ? roll->n : k, F = roll->lazy_top;
  if (F == 0) P[0] = -roll->core_sigma;
  for (int j = F > 1 ? F : 1; j <= n; ++j) P[j] = -roll->sigma_r[j - 1];
  for (int j = n + 1 > F ? n + 1 : F; j <= k; ++j) P[j] = 0.0;
  if (add)
    for (int j = F; j <= k; ++j) P[j] += add[j];
}

/* the error for node j, whose modulus (roll->Er, at roll->P_node) is not positive and finite */
static rs_status roll_modulus_refused(const rs_roll *roll, int j)
{
  return RS_ERROR(RS_ERR_SOLVER,
                  "radial modulus E_r = %g Pa at r = %.6g m (pressure %g Pa) is not positive: "
                  "the radial law is outside its range",
                  roll->Er[j], roll_node_radius(roll, j), roll->P_node[j]);
}

/* E_r at the nodes [lo, hi) from P_node, checked: positive and finite; with entrained air
 * the film at each node in series (roll_air.c) */
static rs_status roll_modulus_range(rs_roll *roll, int lo, int hi)
{
  if (hi <= lo) return RS_OK;
  rs_radial_modulus_n(&roll->p.radial, roll->P_node + lo, roll->Er + lo, hi - lo);
  /* linear and Pfeiffer moduli are positive and finite at every finite P >= 0 (K1, K2,
   * E_r > 0 checked at load; the pressures are finite: rsi_roll_commit); a polynomial or a
   * table can leave its range: one vectorised pass, the node looked for only then */
  const rs_radial_kind law = roll->p.radial.law;
  if (law != RS_RADIAL_LINEAR && law != RS_RADIAL_PFEIFFER) {
    const double *restrict E = roll->Er;
    int64_t bad = 0; /* a double's width: the OR stays in the vector registers */
    for (int j = lo; j < hi; ++j) bad |= (int64_t)!(E[j] > 0.0) | (int64_t)!(E[j] < INFINITY);
    for (int j = lo; bad && j < hi; ++j)
      if (!(E[j] > 0.0 && E[j] < INFINITY))
        return roll_modulus_refused(roll, j);
  }
  if (roll->p.air_film) rsi_roll_air_series(roll, roll->P_node, roll->Er, lo, hi);
  return RS_OK;
}

/* P_node and E_r at the nodes [lo, hi), all holding their stresses explicitly (none lazy),
 * from the stresses in one pass (rs_radial_modulus_stress_n, checked as it goes); the nodes
 * above the n layers wound (the layers being wound) carry no pressure yet. With entrained
 * air the film at each node in series (roll_air.c). */
static rs_status roll_modulus_stress_range(rs_roll *roll, int lo, int hi)
{
  const rs_radial_law *law = &roll->p.radial;
  double *restrict P = roll->P_node, *restrict E = roll->Er;
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
  roll->epoch++;
  roll->nodes_in_use = k + 1;
  return RS_OK;
}

/* rsi_roll_gather_pressure (nothing added) and rsi_roll_set_modulus in one pass over the nodes:
 * the predictor's modulus, at the pressures before the increment */
rs_status rsi_roll_set_modulus_stress(rs_roll *roll, int k)
{
  return roll_modulus_epoch(roll, k, roll_modulus_stress_range(roll, roll->lazy_top, k + 1));
}

/* The pressures and moduli of the nodes [lo, hi) that have just left the lazy zone
 * (rsi_roll_integrate, when an integration starts below the frontier): same epoch */
rs_status rsi_roll_prepare_nodes(rs_roll *roll, int lo, int hi)
{
  return roll_modulus_stress_range(roll, lo, hi); /* flushed: none of them lazy */
}

/* E_r(P) at the nodes lazy_top..k, P from roll->P_node: the modulus an integration sees
 * (g^2 = E_theta / E_r, and ln g^2, are formed by rsi_roll_lg2_range or where the steps look:
 * roll_lg2). */
rs_status rsi_roll_set_modulus(rs_roll *roll, int k)
{
  return roll_modulus_epoch(roll, k, roll_modulus_range(roll, roll->lazy_top, k + 1));
}
