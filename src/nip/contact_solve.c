/* The discretised nip at a fixed half-width: the active-set (Panagiotopoulos-type)
 * iteration over the stick/slip states of eqs. (12)-(15), (20).
 *
 * Unknowns z (column index):  p_1..p_{M-2}         [0, M-2)
 *                             q1_0..q1_{M-2}        [M-2, 2M-3)   roll traction, +x
 *                             q2_0..q2_{M-2}        [2M-3, 3M-4)  drum traction, +x
 *                             delta0, eps0, xi2, T0 [3M-4, 3M)
 * q1 = -tau+, q2 = +tau- are the friction tractions on the cylinders (nip/nip_contact.h).
 * Rows: indentation at node i [0, M); upper contact at midpoint e [M, 2M-1); lower
 * [2M-1, 3M-2); sheet equilibrium; winder torque. The system itself: contact_assemble.c. */
#include "nip/contact_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/cancel.h"
#include "util/error.h"

void rs_nip_solution_free(rs_nip_solution *s)
{
  if (!s) return;
  free(s->x);
  free(s->pressure);
  free(s->x_shear);
  free(s->shear_upper);
  free(s->shear_lower);
  free(s->slip_rate_upper);
  free(s->slip_rate_lower);
  free(s->slip_upper);
  free(s->slip_lower);
  memset(s, 0, sizeof *s);
}

rs_status rs_nipc_solution_reserve(rs_nip_solution *s, int M)
{
  if (s->capacity >= M && s->x) return RS_OK;
  rs_nip_solution_free(s);
  s->x = calloc((size_t)M, sizeof(double));
  s->pressure = calloc((size_t)M, sizeof(double));
  s->x_shear = calloc((size_t)M, sizeof(double));
  s->shear_upper = calloc((size_t)M, sizeof(double));
  s->shear_lower = calloc((size_t)M, sizeof(double));
  s->slip_rate_upper = calloc((size_t)M, sizeof(double));
  s->slip_rate_lower = calloc((size_t)M, sizeof(double));
  s->slip_upper = calloc((size_t)M, 1);
  s->slip_lower = calloc((size_t)M, 1);
  if (!s->x || !s->pressure || !s->x_shear || !s->shear_upper || !s->shear_lower ||
      !s->slip_rate_upper || !s->slip_rate_lower || !s->slip_upper || !s->slip_lower) {
    rs_nip_solution_free(s);
    return RS_ERROR(RS_ERR_MEMORY, "nip solution of %d nodes", M);
  }
  s->capacity = M;
  return RS_OK;
}

/* nodal pressure p_j (Pa) from the solution vector (0 at both ends) */
static double pnode(const rs_nip_contact *nc, int j)
{
  const int M = nc->M;
  return (j <= 0 || j >= M - 1) ? 0.0 : nc->z[COL_P(j)];
}

/* The wound-on creep xi_1 = eps1_mean - c11 T0/(2h) of the solved state (assemble()). */
static double xi_upper(const rs_nip_contact *nc, double dx)
{
  const int M = nc->M;
  double P = 0;
  for (int j = 1; j < M - 1; ++j) P += dx * nc->z[COL_P(j)];
  return nc->roll_mean_strain * P - nc->cfg.sheet.c11 / (2 * nc->cfg.sheet.h) * nc->z[3 * M - 1];
}

/* y[e] += c x[e], e < n (restrict: vectorised) */
static void axpy_e(int n, double *restrict y, double c, const double *restrict x)
{
  for (int e = 0; e < n; ++e) y[e] += c * x[e];
}

/* Strains at the upstream nodes x_e of the elements and the slip rates of the solved
 * state (the stick rows of assemble()): pbar_e = (p_e + p_{e+1})/2 is the element mean
 * of the hat pressure, s_k,e = eps_sheet(x_e) - eps_k(x_e) + xi_k. eps_k(x_e) = sum_j
 * pe_k(e - j) p_j + sum_e' qe_k(e - e') q_k,e', summed for all e at once, a column (j,
 * then e') at a time: each eps_k(x_e) adds its terms in the same order as a sum of its
 * own. */
static void evaluate(rs_nip_contact *nc, double a, double Ti, double *srate)
{
  const int M = nc->M, E = M - 1;
  const double dx = 2 * a / (M - 1);
  const rs_sheet *sh = &nc->cfg.sheet;
  const double xi[2] = {xi_upper(nc, dx), nc->z[3 * M - 2]};
  double N = Ti, Qprev = 0;
  for (int e = 0; e < E; ++e) {
    double Q = nc->z[COL_Q(0, e)] + nc->z[COL_Q(1, e)];
    nc->pbar[e] = 0.5 * (pnode(nc, e) + pnode(nc, e + 1));
    nc->eps_sheet[e] = rs_sheet_strain(sh, N + 0.125 * dx * (Q - Qprev), pnode(nc, e));
    N += dx * Q;
    Qprev = Q;
  }
  for (int k = 0; k < 2; ++k) {
    double *eps = nc->eps_body[k];
    for (int e = 0; e < E; ++e) eps[e] = 0;
    for (int j = 1; j < M - 1; ++j) axpy_e(E, eps, nc->z[COL_P(j)], nc->ker[k][KP].pe + (M - 1 - j));
    for (int ee = 0; ee < E; ++ee) axpy_e(E, eps, nc->z[COL_Q(k, ee)], nc->ker[k][KQE].qe + (M - 1 - ee));
    for (int e = 0; e < E; ++e) srate[k * E + e] = nc->eps_sheet[e] - eps[e] + xi[k];
  }
}

/* The lower contact needs one stick element, or xi2 is undetermined (its column empty).
 * A free rider (center winder) slips forward on part of the contact and backward on the
 * rest with one element stuck between, where the slip direction changes: keep that one
 * (the neighbour closer to sticking); without a change of direction keep the element
 * closest to sticking (the iteration then reports that no state fits). */
static void keep_lower_stick(const rs_nip_contact *nc, const double *srate, signed char *next)
{
  const int M = nc->M, E = M - 1;
  for (int e = 0; e < E; ++e)
    if (next[E + e] == 0) return;
  const signed char *cur = nc->state + E;
  const double *s = srate + E;
#define CLOSENESS(e) (cur[e] == 0 ? 0.0 : fabs(s[e]))
  int keep = -1;
  for (int e = 0; e + 1 < E && keep < 0; ++e)
    if (next[E + e] != next[E + e + 1]) keep = CLOSENESS(e) <= CLOSENESS(e + 1) ? e : e + 1;
  if (keep < 0) {
    double best = INFINITY;
    for (int e = 0; e < E; ++e)
      if (CLOSENESS(e) < best) {
        best = CLOSENESS(e);
        keep = e;
      }
  }
#undef CLOSENESS
  next[E + keep] = 0;
}

static int same_state(const signed char *a, const signed char *b, int n)
{
  return memcmp(a, b, (size_t)n) == 0;
}

/* The violations of one pass, the friction test of steps 3, 5 and 7:
 *   stick element with |q| > mu pbar           -> slip, sign of q
 *   slip element whose slip rate opposes q      -> stick
 * next gets the changed states; the worst relative violation and its element are returned
 * in *worst, *iworst, *sworst. Returns the number of changes. */
typedef struct pass_violation {
  double worst;
  int iworst;
  signed char sworst;
} pass_violation;

static int pass_changes(const rs_nip_contact *nc, double a, double Ti, const double *srate_all,
                        signed char *next, pass_violation *pv)
{
  const int M = nc->M, E = M - 1;
  const double mu[2] = {nc->cfg.mu_roll, nc->cfg.mu_drum};
  double pmax = 0, smax = fabs(nc->cfg.sheet.c11 * Ti / (2 * nc->cfg.sheet.h));
  for (int e = 0; e < E; ++e) {
    pmax = fmax(pmax, fabs(nc->pbar[e]));
    smax = fmax(smax, fmax(fabs(nc->eps_sheet[e]), fmax(fabs(nc->eps_body[0][e]), fabs(nc->eps_body[1][e]))));
  }
  const double rtol = 1e-8;
  /* Round-off of the shears: the solves meet 1e-14 of the equilibrated right-hand side,
   * whose shear scale is the larger of pmax and the tension over the contact,
   * (|Ti| + |T0|)/(2a). Under a light load and a web tension the second dominates by
   * orders (tests/hard/test_hard_nip.c, light_load: 1e2-1e4 pmax), and a frictionless
   * drum's one stuck element (it defines xi2; its exact shear is 0) would show
   * |q| ~ 1e-14 (Ti/2a) > rtol 1e-6 pmax, be sent to slip, be kept back by
   * keep_lower_stick, and fail with "the drum contact would slip everywhere".
   * 100 x that round-off is tolerated on top of the friction test. */
  const double qround = 1e-12 * (pmax + (fabs(Ti) + fabs(nc->z[3 * M - 1])) / (2 * a));
  int changes = 0;
  pv->worst = 0;
  pv->iworst = -1;
  pv->sworst = 0;
  for (int k = 0; k < 2; ++k)
    for (int e = 0; e < E; ++e) {
      int idx = k * E + e;
      double q = nc->z[COL_Q(k, e)], lim = mu[k] * nc->pbar[e];
      double v = 0;
      signed char ns = nc->state[idx];
      if (nc->state[idx] == 0) {
        double over = fabs(q) - lim;
        double qscale = mu[k] * pmax + 1e-6 * pmax + 1e-300; /* mu = 0: round-off of q */
        if (over > rtol * qscale + qround) {
          ns = q > 0 ? 1 : -1;
          v = over / qscale;
        }
      } else if (lim > 0) {
        double back = -nc->state[idx] * srate_all[idx];
        if (back > rtol * smax) {
          ns = 0;
          v = back / smax;
        }
      }
      if (ns != nc->state[idx]) {
        next[idx] = ns;
        ++changes;
        if (v > pv->worst) {
          pv->worst = v;
          pv->iworst = idx;
          pv->sworst = ns;
        }
      }
    }
  return changes;
}

/* Steps 2-9 of the seed paper with the normal and tangential problems solved together
 * (the paper alternates them; the coupled solve has the same fixed point and needs no
 * outer loop), from the active set in nc->state. Each pass applies pass_changes() until
 * nothing changes (step 9). Terminates: every visited set is remembered; on a repeat the
 * iteration changes only the worst violation per pass, and a second repeat (or the pass
 * budget) is RS_ERR_SOLVER. On success nc->z and srate hold the state. */
static rs_status iterate(rs_nip_contact *nc, double a, double Ti, int budget, double *srate_all,
                         signed char *next, int *passes)
{
  const int M = nc->M, E = M - 1, S = 2 * E;
  /* the lower contact needs a stick element to define xi2 */
  int nstick_low = 0;
  for (int e = 0; e < E; ++e) nstick_low += nc->state[E + e] == 0;
  if (!nstick_low) nc->state[E + E / 2] = 0;
  int nvis = 0, single = 0, it, changes = 0;
  pass_violation pv = {0, -1, 0};
  rs_status st = RS_OK;
  for (it = 1; it <= budget; ++it) {
    if (rs_cancel_requested()) { /* a pass at 1024 nodes takes a large fraction of a second */
      st = RS_ERROR(RS_ERR_INTERRUPTED, "interrupted in stick/slip pass %d at a = %g m", it, a);
      break;
    }
    rs_nipc_assemble(nc, a, Ti);
    st = rs_nipc_lin_solve(nc, a);
    if (st) {
      rs_error_wrap("stick/slip pass %d at a = %g m", it, a);
      break;
    }
    evaluate(nc, a, Ti, srate_all);
    memcpy(next, nc->state, (size_t)S);
    changes = pass_changes(nc, a, Ti, srate_all, next, &pv);
    if (!changes) break;
    if (single) {
      memcpy(next, nc->state, (size_t)S);
      next[pv.iworst] = pv.sworst;
    }
    int seen = 0;
    for (int v = 0; v < nvis && !seen; ++v) seen = same_state(nc->visited + (size_t)v * S, next, S);
    if (seen) {
      if (single) {
        st = RS_ERROR(RS_ERR_SOLVER, "stick/slip iteration cycles at a = %g m after %d passes, "
                      "also when changing one element at a time (last change: %d elements, "
                      "worst violation %.3g relative)", a, it, changes, pv.worst);
        break;
      }
      single = 1;
      memcpy(next, nc->state, (size_t)S);
      next[pv.iworst] = pv.sworst;
    }
    keep_lower_stick(nc, srate_all, next);
    if (same_state(next, nc->state, S)) {
      st = RS_ERROR(RS_ERR_SOLVER, "no consistent stick/slip state at a = %g m after %d passes: "
                    "the drum contact would slip everywhere (worst violation %.3g relative)",
                    a, it, pv.worst);
      break;
    }
    if (nvis < nc->cfg.max_iterations) memcpy(nc->visited + (size_t)nvis++ * S, nc->state, (size_t)S);
    memcpy(nc->state, next, (size_t)S);
  }
  *passes = it > budget ? budget : it;
  if (!st && it > budget)
    st = RS_ERROR(RS_ERR_SOLVER, "stick/slip iteration did not settle at a = %g m in %d passes "
                  "(last pass changed %d elements, worst violation %.3g relative)",
                  a, budget, changes, pv.worst);
  return st;
}

/* A cold start: the LCP's set is the answer up to round-off (one pass confirms it), where
 * the active-set iteration from full stick takes tens of passes; if Lemke fails, the
 * iteration starts from full stick as in the paper. Returns 1 when the LCP gave the set. */
static int cold_start(rs_nip_contact *nc, double a, double Ti, signed char *lcp, int *pivots)
{
  const int E = nc->M - 1, S = 2 * E;
  int from_lcp = 0;
  if (!rs_nipc_lcp(nc, a, Ti, lcp, pivots)) {
    memcpy(nc->state, lcp, (size_t)S);
    /* a frictionless contact slips everywhere (q = mu pbar = 0 exactly); "stuck" with a
     * zero margin is the same state up to round-off */
    for (int k = 0; k < 2; ++k)
      if (!(k ? nc->cfg.mu_drum : nc->cfg.mu_roll))
        for (int e = 0; e < E; ++e) nc->state[k * E + e] = 1;
    from_lcp = 1;
  } else {
    rs_error_clear();
    memset(nc->state, 0, (size_t)S);
  }
  nc->stats_lcp_pivots += *pivots;
  return from_lcp;
}

/* After the iteration failed from a warm set: the LCP's set, iterated within the passes
 * left. Both failures are reported if this fails too. */
static rs_status retry_from_lcp(rs_nip_contact *nc, double a, double Ti, double *srate_all,
                                signed char *next, signed char *lcp, int *it, int *pivots)
{
  const int S = 2 * (nc->M - 1);
  char first[512];
  snprintf(first, sizeof first, "%s", rs_error_message());
  int it2 = 0;
  rs_status sl = rs_nipc_lcp(nc, a, Ti, lcp, pivots);
  nc->stats_lcp_pivots += *pivots;
  if (!sl) {
    memcpy(nc->state, lcp, (size_t)S);
    sl = iterate(nc, a, Ti, nc->cfg.max_iterations - *it, srate_all, next, &it2);
  }
  if (!sl) {
    rs_error_clear();
    *it += it2;
    return RS_OK;
  }
  char second[512];
  snprintf(second, sizeof second, "%s", rs_error_message());
  return RS_ERROR(RS_ERR_SOLVER, "%s; then from the LCP solution (Lemke, %d pivots): %s", first,
                  *pivots, second);
}

/* The solved state as pressures, shears, slip zones, load and frictional dissipation. */
static rs_status fill_solution(const rs_nip_contact *nc, double a, double Ti,
                               const double *srate_all, rs_nip_solution *out)
{
  const int M = nc->M, E = M - 1;
  const double dx = 2 * a / (M - 1);
  out->M = M;
  out->a = a;
  out->dx = dx;
  out->Ti = Ti;
  out->delta0 = nc->z[3 * M - 4];
  out->eps0 = nc->z[3 * M - 3];
  out->xi1 = xi_upper(nc, dx);
  out->xi2 = nc->z[3 * M - 2];
  out->T0 = nc->z[3 * M - 1];
  double P = 0, diss = 0;
  for (int i = 0; i < M; ++i) {
    out->x[i] = -a + i * dx;
    out->pressure[i] = pnode(nc, i);
    P += out->pressure[i] * dx;
  }
  for (int e = 0; e < E; ++e) {
    out->x_shear[e] = -a + (e + 0.5) * dx;
    out->shear_upper[e] = -nc->z[COL_Q(0, e)];
    out->shear_lower[e] = nc->z[COL_Q(1, e)];
    out->slip_upper[e] = nc->state[e] != 0;
    out->slip_lower[e] = nc->state[E + e] != 0;
    out->slip_rate_upper[e] = nc->state[e] ? srate_all[e] : 0.0;
    out->slip_rate_lower[e] = nc->state[E + e] ? srate_all[E + e] : 0.0;
    diss += dx * (nc->z[COL_Q(0, e)] * out->slip_rate_upper[e] + nc->z[COL_Q(1, e)] * out->slip_rate_lower[e]);
  }
  out->load = P;
  out->dissipation = diss;
  if (!isfinite(P) || !isfinite(out->T0)) return RS_ERROR(RS_ERR_SOLVER, "non-finite nip solution at a = %g m", a);
  return RS_OK;
}

/* The stick/slip state at half-width a: the active-set iteration from the warm set (or,
 * cold, from the LCP's set); if it fails (cycles, or no state with a stuck rider element),
 * the LCP of the friction conditions solved by Lemke's method (contact_lcp.c) gives the
 * set to iterate from again, within the same pass budget (max_iterations). */
rs_status rs_nipc_solve_fixed(rs_nip_contact *nc, double a, double Ti, rs_nip_solution *out)
{
  const int S = 2 * (nc->M - 1);
  rs_status st = rs_nipc_kernels(nc, a);
  if (st) return st;
  st = rs_nipc_solution_reserve(out, nc->M);
  if (st) return st;
  if (!nc->have_warm) memset(nc->state, 0, (size_t)S);
  double *srate_all = malloc((size_t)S * sizeof *srate_all);
  signed char *next = malloc((size_t)S), *lcp = malloc((size_t)S);
  if (!srate_all || !next || !lcp) {
    free(srate_all);
    free(next);
    free(lcp);
    return RS_ERROR(RS_ERR_MEMORY, "nip iteration work space");
  }
  int it = 0, pivots = 0, cold_lcp = 0;
  double cond = 0;
  if (!nc->have_warm) cold_lcp = cold_start(nc, a, Ti, lcp, &pivots);
  st = iterate(nc, a, Ti, nc->cfg.max_iterations, srate_all, next, &it);
  if (st == RS_ERR_SOLVER && it < nc->cfg.max_iterations && !cold_lcp)
    st = retry_from_lcp(nc, a, Ti, srate_all, next, lcp, &it, &pivots);
  if (!st && !nc->defer_cond) {
    st = rs_nipc_lin_cond(nc, a, &cond);
    if (st) rs_error_wrap("converged stick/slip state at a = %g m", a);
  }
  if (!st) {
    out->condition_number = cond;
    out->iterations = it;
    out->lcp_pivots = pivots;
    st = fill_solution(nc, a, Ti, srate_all, out);
  }
  nc->have_warm = !st;
  free(next);
  free(lcp);
  free(srate_all);
  return st;
}
