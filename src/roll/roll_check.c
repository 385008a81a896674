/* The roll engine's invariants, checked (rsi_roll_check_invariants) after every increment
 * in builds with RS_ROLL_CHECKS (CMake REELSIM_ROLL_CHECKS: on in developer and CI builds,
 * off otherwise) and by the tests. Each is stated where its members are declared
 * (roll_internal.h, struct rs_roll); here they are tested in the same words. The O(1)
 * checks run at every call; those that pass over the nodes (O(n)) run when full != 0. */
#include <math.h>

#include "roll/roll_internal.h"

/* !(a <= b), false for NaN against NaN only where the caller means "not a bound" */
#define RS_CHECK(cond, what) \
  do {                       \
    if (!(cond)) return what; \
  } while (0)

/* the counters and indices: O(1) */
static const char *roll_check_indices(const rs_roll *roll)
{
  const int n = roll->n, cap = roll->p.max_layers;
  RS_CHECK(n >= 0 && n <= cap, "0 <= n <= max_layers");
  RS_CHECK(roll->shift == (roll->p.placement == RS_LOAD_BENEATH), "shift is the load placement");
  RS_CHECK(roll->ref_from == -1 && roll->start_C == 0.0,
           "between increments no start is corrected and no reference is being rebased");
  RS_CHECK(roll->start >= 0 && roll->start <= n, "0 <= start <= n");
  RS_CHECK(roll->ref_top >= -1 && roll->ref_top <= n, "-1 <= ref_top <= n");
  RS_CHECK(roll->shape_top >= -1 && roll->shape_top <= cap, "-1 <= shape_top <= max_layers");
  RS_CHECK(roll->prof_top < 0 || (roll->prof_top <= roll->ref_top && isfinite(roll->prof_max)),
           "a profile lies within the reference's nodes and has a finite bound");
  RS_CHECK(roll->prof_next == -1, "between increments no reference's profile waits");
  RS_CHECK(roll->wstep_n >= 0 && roll->wstep_n <= roll->wstep_cap, "wstep_n <= wstep_cap");
  RS_CHECK(roll->lazy_top == 0 || (roll->lazy_top <= roll->lazy_limit && roll->lazy_limit <= n),
           "a lazy zone lies within the nodes that existed when its scale started");
  RS_CHECK(roll->lazy_top > 0 || (roll->lazy_c == 0.0 && roll->lazy_c2 == 0.0),
           "an empty lazy zone has no pending scale");
  RS_CHECK(roll->lazy_top == 0 || (roll->lazy_allowed && roll->lazy_top - 1 <= roll->shape_top),
           "lazy nodes are allowed and covered by the reference's shape");
  RS_CHECK(isfinite(roll->lazy_c) && isfinite(roll->lazy_c2) && isfinite(roll->core_sigma),
           "the lazy scales and the core stress are finite");
  return NULL;
}

/* the arrays over the nodes: O(n) */
static const char *roll_check_arrays(const rs_roll *roll)
{
  const int n = roll->n;
  for (int j = 0; j < n; ++j)
    RS_CHECK(isfinite(roll->sigma_r[j]), "the stored radial stresses are finite");
  for (int j = 1; j < roll->lazy_top; ++j) {
    /* prefix maxima (roll_lazy_freeze): never decreasing up the zone */
    RS_CHECK(!(roll->lazy_a[j] < roll->lazy_a[j - 1]) && !(roll->lazy_b[j] < roll->lazy_b[j - 1]) &&
                 !(roll->scan_L[j] < roll->scan_L[j - 1]),
             "the lazy zone's drift bounds are prefix maxima");
  }
  for (int j = 0; j <= roll->ref_top; ++j)
    RS_CHECK(roll->Er_ref[j] > 0.0, "the reference's moduli are positive");
  /* the shape's bound: |shape_e| (and |shape_h| with Hakiel's placement) <= shape_max */
  const double bound = roll->shape_max * (1.0 + 1e-12);
  for (int j = 0; j <= roll->shape_top && j <= n; ++j) {
    RS_CHECK(roll->shape_e[j] >= 0.0 && roll->shape_e[j] <= bound,
             "0 <= shape_e <= shape_max over the shape's nodes");
    RS_CHECK(roll->shift || fabs(roll->shape_h[j]) <= bound,
             "|shape_h| <= shape_max over the shape's nodes (Hakiel's placement)");
  }
  const double pbound = roll->prof_max * (1.0 + 1e-12);
  for (int j = 0; j <= roll->prof_top; ++j)
    RS_CHECK(fabs(roll->prof_L[j]) <= pbound && isfinite(roll->prof_w[j]),
             "|prof_L| <= prof_max and prof_w finite over the profile's nodes");
  return NULL;
}

/* NULL when the roll's state satisfies its invariants, else the one broken, in words */
const char *rsi_roll_check_invariants(const rs_roll *roll, int full)
{
  const char *why = roll_check_indices(roll);
  if (!why && full) why = roll_check_arrays(roll);
  return why;
}
