/* One integration of (w, ln y) across the roll with CVODE, one step at a time, the layer
 * nodes inside each step filled by quintic Hermite interpolation, and the reuse of the deep
 * solution of an earlier integration from the core (docs/roll-model.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "roll/roll_internal.h"
#include "util/vector_clones.h"
#include "util/error.h"

/* The state (w, L) at x with its first two x-derivatives, from the equations:
 *   w' = g^2 - 1 - 2w - w^2,   w'' = (g^2)' - 2 (1 + w) w',   L' = w,   L'' = w'. */
typedef struct roll_jet {
  double x, w, dw, d2w, L;
} roll_jet;

static roll_jet roll_jet_at(rs_roll *roll, double x, double w, double L)
{
  double dg2 = 0.0, g2 = rsi_roll_g2_at(roll, x, &dg2);
  double dw = g2 - 1.0 - 2.0 * w - w * w;
  return (roll_jet){x, w, dw, dg2 - 2.0 * (1.0 + w) * dw, L};
}

/* (w, L) inside the step [a, b] by the quintic Hermite interpolant of the values and first
 * two derivatives at its ends (error h^6 y^(6) / 46080 at most: far below the step's own
 * local error, of order h^6 y^(6) / 6 for BDF5), instead of asking CVODE for its
 * interpolant node by node (CVodeGetDky would cost a tenth of the engine's time). The quintic is
 * kept as its monomial coefficients in s = (x - a)/h, so a node costs two Horner sums. */
typedef struct roll_quintic {
  double a, inv_h, cw[6], cL[6];
} roll_quintic;

/* coefficients of p(s) from p, h p', h^2 p'' at s = 0 (p0, d0, c0) and s = 1 (p1, d1, c1) */
static void roll_quintic_coef(double p0, double d0, double c0, double p1, double d1, double c1,
                              double c[6])
{
  c[0] = p0;
  c[1] = d0;
  c[2] = 0.5 * c0;
  c[3] = 10.0 * (p1 - p0) - 6.0 * d0 - 4.0 * d1 - 1.5 * c0 + 0.5 * c1;
  c[4] = 15.0 * (p0 - p1) + 8.0 * d0 + 7.0 * d1 + 1.5 * c0 - c1;
  c[5] = 6.0 * (p1 - p0) - 3.0 * (d0 + d1) - 0.5 * (c0 - c1);
}

static void roll_quintic_make(const roll_jet *a, const roll_jet *b, roll_quintic *q)
{
  const double h = b->x - a->x, hh = h * h;
  q->a = a->x;
  q->inv_h = 1.0 / h;
  roll_quintic_coef(a->w, h * a->dw, hh * a->d2w, b->w, h * b->dw, hh * b->d2w, q->cw);
  roll_quintic_coef(a->L, h * a->w, hh * a->dw, b->L, h * b->w, hh * b->dw, q->cL);
}

/* w at the n nodes x[0..n) inside the step of quintic c (a plain loop: it vectorises) */
static void roll_quintic_fill_w(double a, double inv_h, const double c[6], const double *restrict x,
                                double *restrict w, int n)
{
  const double w0 = c[0], w1 = c[1], w2 = c[2], w3 = c[3], w4 = c[4], w5 = c[5];
  for (int i = 0; i < n; ++i) {
    const double s = (x[i] - a) * inv_h;
    w[i] = ((((w5 * s + w4) * s + w3) * s + w2) * s + w1) * s + w0;
  }
}

/* (w, L) at the n nodes x[0..n) inside the step (plain loops over arrays: they vectorise).
 * With w NULL, L alone (w kept as the step's quintic: roll_wstep_keep). */
RS_VECTOR_CLONES static void roll_quintic_fill(const roll_quintic *q, const double *restrict x,
                                               double *restrict w, double *restrict L, int n)
{
  if (w) roll_quintic_fill_w(q->a, q->inv_h, q->cw, x, w, n);
  const double a = q->a, inv_h = q->inv_h;
  const double l0 = q->cL[0], l1 = q->cL[1], l2 = q->cL[2], l3 = q->cL[3], l4 = q->cL[4],
               l5 = q->cL[5];
  for (int i = 0; i < n; ++i) {
    const double s = (x[i] - a) * inv_h;
    L[i] = ((((l5 * s + l4) * s + l3) * s + l2) * s + l1) * s + l0;
  }
}

/* Keeps the step's quintic of w for its nodes [lo, hi] (roll->wstep); 0 when it cannot
 * (out of memory: then the caller stores w node by node) */
static int roll_wstep_keep(rs_roll *roll, const roll_quintic *q, int lo, int hi)
{
  if (roll->wstep_n == roll->wstep_cap) {
    const int cap = 2 * roll->wstep_cap + 64;
    roll_wstep *s = realloc(roll->wstep, (size_t)cap * sizeof *s);
    if (!s) return 0;
    roll->wstep = s;
    roll->wstep_cap = cap;
  }
  roll_wstep *s = &roll->wstep[roll->wstep_n++];
  s->a = q->a;
  s->inv_h = q->inv_h;
  memcpy(s->c, q->cw, sizeof s->c);
  s->lo = lo;
  s->hi = hi;
  return 1;
}

/* w stored at the kept steps' nodes up to node hi (those above are about to be overwritten),
 * by the same operations as the fill: the steps are then dropped */
void rsi_roll_wstep_store(rs_roll *roll, int hi)
{
  for (int i = 0; i < roll->wstep_n && roll->wstep[i].lo <= hi; ++i) {
    const roll_wstep *s = &roll->wstep[i];
    const int b = s->hi < hi ? s->hi : hi;
    roll_quintic_fill_w(s->a, s->inv_h, s->c, roll->xnode + s->lo, roll->w + s->lo, b - s->lo + 1);
  }
  roll->wstep_n = 0;
}

/* The first step: BDF starts at order 1 (backward Euler), local error h^2 |w''| / 2, so
 * h0 = sqrt(2 (rtol |w0| + atol) / |w''(x0)|) passes the first error test instead of
 * failing it and shrinking; capped by the relaxation scales (w relaxes from w0 (kc at the
 * core) towards g - 1 over dx ~ 1/(2g), and from a large kc (a core much softer than the
 * web) like 1/(x - x_c + 1/kc): start inside the shorter one, or the first Newton
 * iterations diverge). g2 is g^2 at x0. */
static double roll_first_step(const rs_roll *roll, const roll_jet *j0, double g2)
{
  const double cap = 0.05 / fmax(sqrt(g2 + 1.0), fabs(j0->w) + 1.0);
  const double tol = roll->p.rtol * fabs(j0->w) + roll->p.atol, d2 = fabs(j0->d2w);
  if (!(d2 > 0.0)) return cap;
  const double h = 0.5 * sqrt(2.0 * tol / d2); /* half: a margin for the error estimate */
  return h < cap ? h : cap;
}

/* Correcting the integration's global error (docs/roll-model.md, "Correcting the
 * integration's error"). The step's quintic q (the Hermite of its end values and first two
 * derivatives) satisfies the equations up to its defect d = q' - f(x, q), which vanishes with
 * its slope at both ends (the ends' derivatives are the equations'), so in s = (x - a)/h it
 * is s^2 (1 - s)^2 times a smooth factor: its integral over the step is (8/15) h d(1/2),
 * exact for a factor linear in s, from one evaluation of g^2. The error e = q - y of the
 * computed solution against the exact one through the same start obeys, to first order,
 *     e_w' = -a e_w + d_w,   e_L' = e_w + d_L,   a = 2 (1 + w),
 * so across a step, with A = int a dx = 2 (h + L_b - L_a) (L' = w: exact) and the step's
 * defect taken as concentrated at its middle, m = (8/15) h d_w(1/2):
 *     e_w(b) = e_w(a) e^-A + m e^-A/2,
 *     e_L(b) = e_L(a) + e_w(a) h (1 - e^-A)/A + (8/15) h d_L(1/2) + m h (1 - e^-A/2)/A.
 * Measured against integrations at rtol 1e-11 (a standalone CVODE run and the reels of
 * docs/roll-model.md), this estimate is the global error of L to 0.02 - 0.3 %, for BDF and
 * Adams alike: CVODE's own local error estimates account
 * for a third to two thirds of it (steps of a fifth of the depth put the higher terms of the
 * local error at the order of the leading one they estimate). Inside the step the
 * estimate is the quintic Hermite of (e_L, e_w) with their own first two derivatives at the
 * ends (e_L' = e_w, e_L'' = -a e_w, e_w' = -a e_w, e_w'' = (a^2 - 2 w') e_w: the defect and its
 * slope vanish there), which carries the middle's error into the step in the shape the
 * interpolant itself does; subtracted from the step's quintics, the nodes are corrected at
 * no cost a node. */
typedef struct roll_correction {
  double L, w; /* the estimated error of (L, w) at the end of the last step */
} roll_correction;

static void roll_correction_step(rs_roll *roll, roll_correction *c, const roll_jet *ja,
                                 const roll_jet *jb, roll_quintic *q)
{
  const double h = jb->x - ja->x;
  const double *cw = q->cw, *cL = q->cL;
  /* the quintics and their s-derivatives at s = 1/2 */
  const double qw =
      cw[0] + 0.5 * (cw[1] + 0.5 * (cw[2] + 0.5 * (cw[3] + 0.5 * (cw[4] + 0.5 * cw[5]))));
  const double dqw =
      cw[1] + 0.5 * (2.0 * cw[2] + 0.5 * (3.0 * cw[3] + 0.5 * (4.0 * cw[4] + 0.5 * 5.0 * cw[5])));
  const double dqL =
      cL[1] + 0.5 * (2.0 * cL[2] + 0.5 * (3.0 * cL[3] + 0.5 * (4.0 * cL[4] + 0.5 * 5.0 * cL[5])));
  const double g2 = rsi_roll_g2_probe(roll, ja->x + 0.5 * h);
  const double dw = dqw / h - (g2 - 1.0 - 2.0 * qw - qw * qw), dL = dqL / h - qw;
  const double A = 2.0 * (h + jb->L - ja->L), eh = exp(-0.5 * A), D = eh * eh;
  /* h (1 - e^-A)/A and h (1 - e^-A/2)/A from the one exp(), by their Taylor sums where A
   * is small (a rigid core's w ~ -1), where 1 - e^-A would cancel */
  double T, Th;
  if (fabs(A) < 0.02) {
    const double b = 0.5 * A;
    T = h * (1.0 - A * (0.5 - A * (1.0 / 6.0 - A * (1.0 / 24.0 - A / 120.0))));
    Th = 0.5 * h * (1.0 - b * (0.5 - b * (1.0 / 6.0 - b * (1.0 / 24.0 - b / 120.0))));
  } else {
    T = h * (1.0 - D) / A;
    Th = h * (1.0 - eh) / A;
  }
  /* A step CVODE accepted leaves an error of the order of its tolerance (measured: 1.5 - 4x
   * its own estimate). A defect that says a hundred times more is no measure of an error
   * but of a quintic that does not follow the solution inside the step: a stiff transient
   * (w relaxing within the step, as from a rigid core onto a very soft web, g ~ 700), whose
   * end values the method damps to the right ones. Such a step carries what came before
   * and adds nothing (on newsprint-rider no step is near the bound, on the soft web of
   * test_roll_lazy.very_soft_web ~1 % are beyond it, and counted they wreck its roll).
   * Such a step is a transient: w relaxes several times over within it (A > 4), or the
   * defect's w part exceeds the step's own change of w (measured on that web: A >= 11 and
   * |m| >= 5 |dw| in every such step). A large defect in a step that is neither is an
   * error (a step CVODE accepted past its tolerance, where the modulus' curvature changes
   * inside it): corrected, whatever rtol is; dropping those too would make the error of a
   * very soft web (Pfeiffer K1 = 50 Pa) grow as rtol tightens, the step's defect crossing
   * 100 tolerances at rtol 1e-4 (docs/roll-model.md, "A very soft web"). */
  double m = 8.0 / 15.0 * h * dw, dLs = 8.0 / 15.0 * h * dL;
  const double tw = roll->p.rtol * fabs(jb->w) + roll->p.atol;
  const double tL = roll->p.rtol * fabs(jb->L) + roll->p.atol;
  if (!(fabs(m) <= 100.0 * tw && fabs(dLs + m * Th) <= 100.0 * tL) &&
      (fabs(A) > 4.0 || !(fabs(m) <= fabs(jb->w - ja->w))))
    m = dLs = 0.0;
  double eL = c->L + c->w * T + dLs + m * Th, ew = c->w * D + m * eh;
  if (!isfinite(eL) || !isfinite(ew)) { /* an estimate not a number: carry the last one */
    eL = c->L;
    ew = c->w;
  }
  double k[6];
  /* the error's own jets; where w relaxes several times over within the step their
   * curvature (A e_w h) outgrows the error they describe: the end values only. (The defect
   * taken at the middle makes e_w(b) low as A grows, 7 % at A = 2, 32 % at 4; e_L's term
   * stays within 5 %: only the stored w, which Hakiel's placement's hoop stress reads,
   * sees it) */
  if (fabs(A) <= 4.0) {
    const double aa = 2.0 * (1.0 + ja->w), ab = 2.0 * (1.0 + jb->w), hh = h * h;
    roll_quintic_coef(c->L, h * c->w, -hh * aa * c->w, eL, h * ew, -hh * ab * ew, k);
    for (int i = 0; i < 6; ++i) q->cL[i] -= k[i];
    roll_quintic_coef(c->w, -h * aa * c->w, hh * (aa * aa - 2.0 * ja->dw) * c->w, ew,
                      -h * ab * ew, hh * (ab * ab - 2.0 * jb->dw) * ew, k);
    for (int i = 0; i < 6; ++i) q->cw[i] -= k[i];
  } else { /* ends only */
    roll_quintic_coef(c->L, 0.0, 0.0, eL, 0.0, 0.0, k);
    for (int i = 0; i < 6; ++i) q->cL[i] -= k[i];
    roll_quintic_coef(c->w, 0.0, 0.0, ew, 0.0, 0.0, k);
    for (int i = 0; i < 6; ++i) q->cw[i] -= k[i];
  }
  c->L = eL;
  c->w = ew;
}

/* The integration's start at node `first` (0: the core): the nodes it looks at (from
 * first - 1: the Hermite slopes) leave the lazy zone, w at and below it is stored from
 * the last integration's steps, a rebased reference's nodes below it are rebased, and the
 * start's (w, L) corrected by start_C x the profile (rsi_roll_start_set; the node holds
 * them while the increment is built, the reference's again after: rsi_roll_start_release).
 * A reference needs every node, and one from a node above the core (ref.from) has every
 * node leave the lazy zone too, to freeze again below its start with the lazy scale from
 * 0: only nodes that existed when that scale started can join the zone; on a long roll
 * except those of the deeper level (roll_deep), which it keeps or forms. */
static rs_status roll_integration_start(rs_roll *roll, int first, int from_core, double start_C)
{
  int need = from_core ? 0 : first - 1;
  if (!from_core && roll->ref.from > 0 && !roll->ref.renew)
    need = rsi_roll_deep_keep(roll, first); /* or 0 */
  const int F = roll->lazy.top;
  if (need < F) {
    if (roll->ref.renew) /* the level renewed: its top nodes leave it (roll_reference_renew, roll_reference.c) */
      rsi_roll_deep_lower(roll, need);
    else if (!from_core)
      rsi_roll_lazy_flush(roll, need); /* below the deeper level: the level too (roll_deep) */
    else if (rsi_roll_lazy_flush_core(roll))
      rsi_roll_shape_cut(roll, -1); /* the level's nodes' shape stale: none until it is made */
    rs_status st = rsi_roll_prepare_nodes(roll, roll->lazy.top, F);
    if (st) return st;
  }
  if (from_core) {
    roll->w[0] = roll->kc;
    roll->L[0] = 0.0;
  }
  rsi_roll_wstep_store(roll, first); /* w at and below the start, from the last integration */
  if (roll->ref.from > 0) { /* the deeper level carries the factor the others take */
    rsi_roll_deep_rebased(roll, roll->prof.c, roll->prof.L[first]);
    rsi_roll_reference_rebase(roll, first);
  }
  rsi_roll_start_set(roll, first, start_C);
  return RS_OK;
}

/* CVODE restarted at x0 = ln r_first towards xs = ln r_k from the start's (w, L) (from the
 * core (kc, 0); else the reference's values, whose L carries the reference's origin: every
 * L difference the increment is built from stays consistent), r = e^x anchored afresh at
 * the start (its radii do not depend on where the last integration ended), ln g^2 formed
 * in one pass when the nodes are few; *j0 the jet at the start */
static rs_status roll_cvode_restart(rs_roll *roll, int first, int k, roll_jet *j0)
{
  const double x0 = roll->xnode[first], xs = roll->xnode[k];
  const int reinit = rsi_roll_ode_restart(roll, x0, roll->w[first], roll->L[first]);
  if (k - first <= roll->ode.lg2_range_max) rsi_roll_lg2_range(roll, first > 0 ? first - 1 : 0, k);
  *j0 = roll_jet_at(roll, x0, roll->w[first], roll->L[first]);
  const double g2_start = rsi_roll_g2_at(roll, x0, NULL);
  if (reinit != 0 || CVodeSetStopTime(roll->ode.cvode, xs) != CV_SUCCESS ||
      CVodeSetInitStep(roll->ode.cvode, roll_first_step(roll, j0, g2_start)) != CV_SUCCESS)
    return RS_ERROR(RS_ERR_SOLVER, "CVODE re-initialisation failed: %s", roll->ode.cvode_msg);
  return RS_OK;
}

/* The nodes next..last inside the step that ended at tret = cur->x, from its quintic q:
 * r_j = r_c + j t, so the last node inside is j = (e^x - r_c)/t up to rounding, settled
 * against the stored ln r_j (the jet at tret has just formed (e^x - r_c)/t). w is kept as
 * the step's quintic where only a start node will read it (rsi_roll_wstep_store); node k,
 * the step's end, takes its end values, exact. Returns the next node to fill. */
static int roll_step_nodes(rs_roll *roll, const roll_quintic *q, const roll_jet *cur,
                           const roll_correction *corr, int next, int k)
{
  const double *xn = roll->xnode, tret = cur->x;
  int last = (int)rsi_roll_layer_coord_at(roll, tret);
  if (last < next) last = next;
  if (last > k) last = k;
  while (last > next && xn[last] > tret) --last;
  while (last < k && xn[last + 1] <= tret) ++last;
  const int keep = roll->w_lazy && roll_wstep_keep(roll, q, next, last < k ? last : k - 1);
  roll_quintic_fill(q, xn + next, keep ? NULL : roll->w + next, roll->L + next, last - next + 1);
  if (last == k) {
    roll->w[k] = cur->w - corr->w;
    roll->L[k] = cur->L - corr->L;
  }
  return last + 1;
}

/* CVODE's steps from node first to node k, one at a time, each step's nodes filled from its
 * quintic, corrected for the integration's error (roll_correction_step) when asked: every
 * step, since the error it leaves reaches the nodes above it. *steps counts them. */
static rs_status roll_cvode_steps(rs_roll *roll, int first, int k, roll_jet prev, long *steps)
{
  const double xs = roll->xnode[k];
  const sunrealtype *y = N_VGetArrayPointer(roll->ode.y);
  const int correct = roll->p.correction == RS_CORRECTION_ON;
  roll_correction corr = {0.0, 0.0};
  sunrealtype tret = prev.x;
  for (int next = first + 1; next <= k;) {
    if (++*steps > roll->p.max_steps)
      return RS_ERROR(RS_ERR_SOLVER,
                      "CVODE needed more than %ld steps to cross the roll (reached r = %.6g m of "
                      "%.6g m); raise numerics.max_steps or loosen numerics.rtol",
                      roll->p.max_steps, exp(tret), exp(xs));
    int flag = CVode(roll->ode.cvode, xs, roll->ode.y, &tret, CV_ONE_STEP);
    if (flag < 0)
      return RS_ERROR(RS_ERR_SOLVER, "CVODE failed at r = %.9g m (roll outer radius %.9g m): %s",
                      exp(tret), exp(xs),
                      roll->ode.cvode_msg[0] ? roll->ode.cvode_msg : CVodeGetReturnFlagName(flag));
    const roll_jet cur = roll_jet_at(roll, tret, y[0], y[1]);
    roll_quintic q;
    if (correct) {
      roll_quintic_make(&prev, &cur, &q);
      roll_correction_step(roll, &corr, &prev, &cur, &q);
    }
    if (roll->xnode[next] <= tret) {
      if (!correct) roll_quintic_make(&prev, &cur, &q);
      next = roll_step_nodes(roll, &q, &cur, &corr, next, k);
    }
    prev = cur;
  }
  return RS_OK;
}

/* the solver's counters after an integration of `steps` steps (CVODE's restart at every
 * CVodeReInit; the exact corrector forms no Jacobian, the fallback counts its own:
 * roll_corrector.c) */
static void roll_count(rs_roll *roll, long steps)
{
  long nfe = 0;
  CVodeGetNumRhsEvals(roll->ode.cvode, &nfe);
  roll->stats.cvode_steps += steps;
  roll->stats.rhs_evals += nfe;
}

/* The start node's (w, L) back to the reference's once the increment corrected there is
 * built and committed (st RS_OK) or has failed (rsi_roll_start_restore). A reference from a
 * node above the core (rsi_roll_reuse_start) that was committed becomes the reference: its
 * profile continued from that node (rsi_roll_reference_extend), which reads w at every
 * node. */
void rsi_roll_start_release(rs_roll *roll, rs_status st)
{
  if (roll->ref.from > 0 && st == RS_OK) {
    rsi_roll_wstep_store(roll, roll->ref.top);
    rsi_roll_reference_extend(roll);
  }
  rsi_roll_start_restore(roll);
}

/* Integrates (w, L) from r_c to s = r_{k}, storing them at every node 0..k, or, when
 * rsi_roll_reuse_start finds a start node j0, from r_{j0} with the reference's (w, L) there,
 * keeping the reference's values below it (roll_reference.c keeps the reference's books).
 * One CVODE step at a time; the nodes inside each step are interpolated between its ends
 * (roll_quintic_fill), so the cost per node is a short polynomial, not a CVODE call. */
rs_status rsi_roll_integrate(rs_roll *roll, int k)
{
  if (k == 0) { /* the first layer's load on the core: nothing to integrate */
    roll->wstep_n = 0;
    roll->w[0] = roll->kc;
    roll->L[0] = 0.0;
    rsi_roll_reference_core(roll);
    return RS_OK;
  }
  double start_C; /* applied once nothing can fail before it */
  const int j0 = rsi_roll_reuse_start(roll, &start_C), from_core = j0 < 0;
  const int first = from_core ? 0 : j0;
  rs_status st = roll_integration_start(roll, first, from_core, start_C);
  roll_jet j_start;
  if (st == RS_OK) st = roll_cvode_restart(roll, first, k, &j_start);
  if (st) return st;
  rsi_roll_reference_begin(roll, k, j0);
  /* below the start the increment is c x the reference's shape (rsi_roll_block_increment):
   * those nodes can wait (roll_lazy.c) */
  if (!from_core && roll->lazy.ok && j0 <= roll->ref.shape_top && roll->ref.shape_e[j0] > 1e-280)
    rsi_roll_lazy_freeze(roll, j0 - 1);
  long steps = 0;
  st = roll_cvode_steps(roll, first, k, j_start, &steps);
  if (st) return st;
  rsi_roll_reference_end(roll, k, first);
  roll_count(roll, steps);
  return RS_OK;
}
