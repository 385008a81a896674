/* The roll engine's invariants, checked (rsi_roll_check_invariants) after every increment
 * in builds with RS_ROLL_CHECKS (CMake REELSIM_ROLL_CHECKS: on in developer and CI builds,
 * off otherwise) and by the tests. Each component's is stated where it is declared
 * (roll_internal.h) and tested here in the same words, one function per component. The
 * O(1) checks run at every call; those that pass over the nodes (O(n)) when full != 0. */
#include <math.h>

#include "roll/roll_internal.h"

#define RS_CHECK(cond, what)  \
  do {                        \
    if (!(cond)) return what; \
  } while (0)

/* the roll's own: its counters and stored stresses */
static const char *roll_check_roll(const rs_roll *roll, int full)
{
  const int n = roll->n, cap = roll->p.max_layers;
  RS_CHECK(n >= 0 && n <= cap, "0 <= n <= max_layers");
  RS_CHECK(roll->shift == (roll->p.placement == RS_LOAD_BENEATH), "shift is the load placement");
  RS_CHECK(isfinite(roll->core_sigma), "the core stress is finite");
  RS_CHECK(roll->wstep_n >= 0 && roll->wstep_n <= roll->wstep_cap, "wstep_n <= wstep_cap");
  for (int j = 0; full && j < n; ++j)
    RS_CHECK(isfinite(roll->sigma_r[j]), "the stored radial stresses are finite");
  return NULL;
}

/* the ODE workspace (roll_ode) */
static const char *roll_check_ode(const rs_roll *roll)
{
  const roll_ode *o = &roll->ode;
  RS_CHECK(o->cvode && o->y && o->sunctx, "the ODE workspace has its CVODE");
  RS_CHECK(!o->NLS != !(o->fallback_LS && o->fallback_A),
           "exactly one corrector: the exact one or CVODE's Newton iteration");
  RS_CHECK(o->nodes_in_use >= 0 && o->nodes_in_use <= roll->p.max_layers + 1,
           "the nodes in use exist");
  RS_CHECK(o->lg2_range_max >= 0, "lg2_range_max >= 0");
  RS_CHECK(o->g2c.epoch <= o->epoch && o->gepoch <= o->epoch && o->lg2_range_epoch <= o->epoch,
           "no cache is ahead of the moduli's epoch");
  return NULL;
}

/* the reference solution (roll_reference) */
static const char *roll_check_reference(const rs_roll *roll, int full)
{
  const roll_reference *r = &roll->ref;
  const int n = roll->n;
  RS_CHECK(r->from == -1 && r->renew == 0 && r->start_C == 0.0,
           "between increments no start is corrected and no reference is being rebased");
  RS_CHECK(r->start >= 0 && r->start <= n, "0 <= start <= n");
  RS_CHECK(r->top >= -1 && r->top <= n, "-1 <= ref.top <= n");
  RS_CHECK(r->shape_top >= -1 && r->shape_top <= roll->p.max_layers,
           "-1 <= shape_top <= max_layers");
  if (!full) return NULL;
  for (int j = 0; j <= r->top; ++j) RS_CHECK(r->Er[j] > 0.0, "the reference's moduli are positive");
  const double bound = r->shape_max * (1.0 + 1e-12);
  for (int j = 0; j <= r->shape_top && j <= n; ++j) {
    RS_CHECK(r->shape_e[j] >= 0.0 && r->shape_e[j] <= bound,
             "0 <= shape_e <= shape_max over the shape's nodes");
    RS_CHECK(roll->shift || fabs(r->shape_h[j]) <= bound,
             "|shape_h| <= shape_max over the shape's nodes (Hakiel's placement)");
  }
  return NULL;
}

/* the drift profile (roll_profile) */
static const char *roll_check_profile(const rs_roll *roll, int full)
{
  const roll_profile *p = &roll->prof;
  RS_CHECK(p->top < 0 || (p->top <= roll->ref.top && isfinite(p->max)),
           "a profile lies within the reference's nodes and has a finite bound");
  RS_CHECK(p->next == -1, "between increments no reference's profile waits");
  RS_CHECK(isfinite(p->c), "the profile's drift scale is finite");
  const double bound = p->max * (1.0 + 1e-12);
  for (int j = 0; full && j <= p->top; ++j)
    RS_CHECK(fabs(p->L[j]) <= bound && isfinite(p->w[j]),
             "|prof.L| <= prof.max and prof.w finite over the profile's nodes");
  return NULL;
}

/* the lazy drift bounds a, b and Lmax never fall over the nodes [lo, hi) (prefix maxima
 * starting at lo: the deeper level's from 0, the lazy zone's from the level's top) */
static int lazy_maxima_rise(const roll_lazy *z, int lo, int hi)
{
  for (int j = lo + 1; j < hi; ++j)
    if (z->a[j] < z->a[j - 1] || z->b[j] < z->b[j - 1] || z->Lmax[j] < z->Lmax[j - 1]) return 0;
  return 1;
}

/* the lazy deep part (roll_lazy) */
static const char *roll_check_lazy(const rs_roll *roll, int full)
{
  const roll_lazy *z = &roll->lazy;
  RS_CHECK(z->top == 0 || (z->top <= z->limit && z->limit <= roll->n),
           "a lazy zone lies within the nodes that existed when its scale started");
  RS_CHECK(z->top > roll->deep.top || (z->c == 0.0 && z->c2 == 0.0),
           "an empty lazy zone has no pending scale");
  RS_CHECK(z->top == 0 || (z->allowed && z->top - 1 <= roll->ref.shape_top),
           "lazy nodes are allowed and covered by the reference's shape");
  RS_CHECK(isfinite(z->c) && isfinite(z->c2), "the lazy scales are finite");
  RS_CHECK(!full || lazy_maxima_rise(z, roll->deep.top, z->top),
           "the lazy zone's drift bounds are prefix maxima");
  return NULL;
}

/* the deeper lazy level (roll_deep) */
static const char *roll_check_deep(const rs_roll *roll, int full)
{
  const roll_deep *d = &roll->deep;
  RS_CHECK(d->min_nodes >= 1 && d->span > 0.0,
           "the deeper level's least size is at least a node, its span positive");
  RS_CHECK(d->top > 0 || (d->c == 0.0 && d->c2 == 0.0 && d->B == 0.0 && d->A == 1.0 &&
                          d->depth0 == 0),
           "an empty deeper level has no pending scale nor rebase factor");
  RS_CHECK(d->top == 0 || (d->depth0 > 0 && d->depth0 <= roll->n),
           "a deeper level has its depth at forming, 0 < depth0 <= n");
  RS_CHECK(isfinite(d->c) && isfinite(d->c2) && isfinite(d->B) && d->A > 0.0 && d->A < INFINITY,
           "the deeper level's scales are finite and its rebase factor A positive");
  if (d->top == 0) return NULL;
  RS_CHECK(d->top <= roll->lazy.top && roll->lazy.top <= roll->lazy.limit,
           "the deeper level lies within the lazy zone's nodes");
  RS_CHECK(roll->shift && d->top - 1 <= roll->ref.shape_top,
           "the deeper level has the load beneath and the reference's shape covers it");
  RS_CHECK(!full || lazy_maxima_rise(&roll->lazy, 0, d->top),
           "the deeper level's drift bounds are prefix maxima");
  return NULL;
}

/* entrained air at its radius (roll_air) */
static const char *roll_check_air(const rs_roll *roll, int full)
{
  const roll_air *a = &roll->air;
  RS_CHECK(a->node_r || !a->geom, "nodes at their real radii have their arrays");
  if (!a->node_r || !full) return NULL;
  for (int j = 0; j <= roll->n; ++j) {
    RS_CHECK(j == 0 || a->node_r[j] > a->node_r[j - 1], "the nodes' radii rise");
    RS_CHECK(a->inv_pitch[j] > 0.0 && a->pitch_sq[j] > 0.0, "every pitch is positive");
  }
  return NULL;
}

/* NULL when the roll's state satisfies its invariants, else the one broken, in words */
const char *rsi_roll_check_invariants(const rs_roll *roll, int full)
{
  const char *why = roll_check_roll(roll, full);
  if (!why) why = roll_check_ode(roll);
  if (!why) why = roll_check_reference(roll, full);
  if (!why) why = roll_check_profile(roll, full);
  if (!why) why = roll_check_lazy(roll, full);
  if (!why) why = roll_check_deep(roll, full);
  if (!why) why = roll_check_air(roll, full);
  return why;
}
