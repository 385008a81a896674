/* The deeper lazy level of the roll engine (src/roll/roll_lazy.c, roll_deep in
 * roll_internal.h; docs/roll-model.md, "The deeper lazy level"): on a long roll a reference
 * from a node above the core leaves the nodes far below its node in a level of their own,
 * which carries the shape's rebase factor in its scales. The level forms only on rolls of
 * more than RS_DEEP_MIN_NODES (50,000) nodes; here its least size is lowered to 10 nodes and
 * its span to 0.1 so that an 8000-layer roll of the 6 um PET film of test_roll_profile.
 * film_span (load beneath, the default rtol 1e-3: the reuse held to tol = 2e-5) uses it.
 *   vs_one_level      the two-level engine against the one-level engine (the level never
 *                     formed) and both against reuse: none at rtol 1e-10: levels formed and
 *                     served references; the two engines' core pressure and radial stresses
 *                     agree within 0.05 tol (tol = 2e-5, the reuse's) and the two-level
 *                     engine's errors against the tight run are within 1.2x the one-level
 *                     engine's plus 0.04 tol (test_roll_profile.deep_reference's allowance
 *                     for the rebasing's remainders); every invariant holds after every
 *                     increment, with the checks over the nodes
 *   mis_summed_scale  the same comparison fails when the level's scale has summed 10 % too
 *                     much of the increments since it formed (so the agreement above is
 *                     the level's doing, not a tolerance that cannot fail)
 *   reads_match_full  rs_roll_layer_sigma_r and rs_roll_core_pressure while a level holds
 *                     nodes equal the full profile (rs_roll_sigma_r) bit for bit, and reading
 *                     changes nothing in how the roll winds on
 *   restore_dissolves a roll rewound (rs_roll_restore) while a level holds nodes (the level
 *                     dissolved, the invariants holding after every increment that
 *                     follows) winds on as a one-level twin rewound alike, within 0.05 tol
 *   failure_and_block an increment that overflows (T0 = 1e308 N/m) when a reference from a
 *                     node above the core is due and a level holds nodes, then a lumped
 *                     block of two layers (which dissolves the level): the invariants hold
 *                     after each, and the roll winds on as a one-level twin put through
 *                     the same, within 0.05 tol
 *   renews            (validation) a 25,000-layer roll of the same film, its levels formed
 *                     from 1250 nodes with the shipped span, its references n/1600 increments
 *                     apart as on a long roll: where a reference from the core is due the
 *                     level is renewed instead (at least 20 times), every invariant holds
 *                     (checked every 250 layers and after every renewal), and its errors
 *                     against an rtol 1e-10 run of the one-level engine are within 1.2x the
 *                     one-level engine's at the default tolerance plus 0.04 tol (it fails, by
 *                     28x in the core pressure, when the nodes leaving a renewed level do not
 *                     take its rebase factors, and by 1000x in sigma_r when they do not take
 *                     its scales)
 *   renewed_invariants the same roll alone: at least 20 renewals, the invariants after each
 *                     and every 250 layers, a level holding nodes at the end whose layer
 *                     reads equal the full profile bit for bit (a unit case: valgrind runs
 *                     the renewals' paths)
 *   catches_broken    broken states of the level (a pending scale with no level, a level
 *                     above the lazy zone, a rebase factor that is not positive, a level
 *                     without its depth at forming, a renewal pending between increments,
 *                     bounds that are not prefix maxima) are each reported by the invariant
 *                     check */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "roll/roll_internal.h"
#include "roll_helpers.h"

enum { N = 8000 };
static const double T0 = 100.0, TOL = 2e-5;

/* the 6 um PET film of test_roll_profile.film_span, `layers` long, the reuse held to rtol /
 * 50, whose levels form from min_nodes (INT_MAX: the one-level engine) with the shipped span */
static rs_roll *film_long(int min_nodes, rs_reuse reuse, double rtol, int layers)
{
  const double t = (0.68 - 0.0762) / 100633;
  rs_roll_params p = hakiel_params(0.0762, t, 4.5e9, 1e6, 60.0, 2e-6, 1e10, layers);
  p.rtol = rtol;
  p.reuse = reuse;
  p.placement = RS_LOAD_BENEATH;
  rs_roll *roll = NULL;
  CHECK(rs_roll_create(&p, &roll) == RS_OK);
  if (roll) roll->deep.min_nodes = min_nodes;
  return roll;
}

/* the 8000-layer roll of that film, its levels' span 0.1 (on a short roll the references
 * start low) */
static rs_roll *newsprint(int min_nodes, rs_reuse reuse, double rtol)
{
  rs_roll *roll = film_long(min_nodes, reuse, rtol, N);
  if (roll) roll->deep.span = 0.1;
  return roll;
}

/* winds to n layers, checking the invariants after each increment when checked != 0;
 * *held the most nodes a level held, *c_formed the level's scale when the last one formed */
static int wind_to(rs_roll *roll, int n, int checked, int *held, double *c_formed)
{
  long formed = roll->deep.formed;
  int bad = 0;
  while (roll->n < n) {
    if (rs_roll_add_layers(roll, 1, &T0) != RS_OK) return 0;
    if (held && roll->deep.top > *held) *held = roll->deep.top;
    if (c_formed && roll->deep.formed != formed) *c_formed = roll->deep.c;
    formed = roll->deep.formed;
    const char *why = checked ? rsi_roll_check_invariants(roll, 1) : NULL;
    if (why && !bad++) fprintf(stderr, "layer %d: %s\n", roll->n, why);
  }
  CHECK(bad == 0);
  return bad == 0;
}

/* winds to n layers with the invariants over the nodes checked every 250 layers and after
 * every increment that renewed a level (*held as wind_to's) */
static int wind_checked(rs_roll *roll, int n, int *held)
{
  long renewals = roll->ref.renewals;
  int bad = 0;
  while (roll->n < n) {
    if (rs_roll_add_layers(roll, 1, &T0) != RS_OK) return 0;
    if (roll->deep.top > *held) *held = roll->deep.top;
    const int full = roll->n % 250 == 0 || roll->ref.renewals != renewals;
    renewals = roll->ref.renewals;
    const char *why = full ? rsi_roll_check_invariants(roll, 1) : NULL;
    if (why && !bad++) fprintf(stderr, "layer %d: %s\n", roll->n, why);
  }
  CHECK(bad == 0);
  return bad == 0;
}

/* the largest difference of the radial stresses (in units of T0/s a layer: summed over
 * ~100 increments, as test_roll_lazy) and of the core pressure (relative) */
static void differences(rs_roll *a, rs_roll *b, double *core, double *sr)
{
  const double pa = rs_roll_core_pressure(a), pb = rs_roll_core_pressure(b);
  *core = fabs(pa - pb) / pb;
  const double *sa = rs_roll_sigma_r(a), *sb = rs_roll_sigma_r(b);
  *sr = 0.0;
  for (int j = 0; j < a->n; ++j)
    *sr = fmax(*sr, fabs(sa[j] - sb[j]) / (100.0 * T0 / rs_roll_layer_radius(a, j)));
}

static void vs_one_level(void)
{
  const double rtol = TOL / RS_ACCURACY_PER_RTOL;
  rs_roll *two = newsprint(10, RS_REUSE_ON, rtol), *one = newsprint(INT_MAX, RS_REUSE_ON, rtol);
  rs_roll *ref = newsprint(INT_MAX, RS_REUSE_OFF, 1e-10);
  int held = 0;
  if (two && one && ref && wind_to(two, N, 1, &held, NULL) && wind_to(one, N, 1, NULL, NULL) &&
      wind_to(ref, N, 0, NULL, NULL)) {
    double dc, dr, ec2, er2, ec1, er1;
    differences(two, one, &dc, &dr);
    differences(two, ref, &ec2, &er2);
    differences(one, ref, &ec1, &er1);
    printf("  levels formed %ld (most nodes held %d), deep references %ld / %ld, renewals %ld, "
           "from the core %ld / %ld\n", two->deep.formed, held, two->ref.deep_references,
           one->ref.deep_references, two->ref.renewals, two->stats.full_integrations,
           one->stats.full_integrations);
    printf("  two-level vs one-level: core %.3e sigma_r %.3e (tol %.0e)\n", dc, dr, TOL);
    printf("  vs rtol 1e-10: two-level core %.3e sigma_r %.3e, one-level core %.3e sigma_r "
           "%.3e\n", ec2, er2, ec1, er1);
    CHECK(one->deep.formed == 0);
    CHECK(two->deep.formed >= 5 && held >= 100);
    CHECK_LT(dc, 0.05 * TOL);
    CHECK_LT(dr, 0.05 * TOL);
    CHECK_LT(ec2, 1.2 * ec1 + 0.04 * TOL);
    CHECK_LT(er2, 1.2 * er1 + 0.04 * TOL);
  }
  rs_roll_destroy(&two);
  rs_roll_destroy(&one);
  rs_roll_destroy(&ref);
}

static void mis_summed_scale(void)
{
  const double rtol = TOL / RS_ACCURACY_PER_RTOL;
  rs_roll *two = newsprint(10, RS_REUSE_ON, rtol), *one = newsprint(INT_MAX, RS_REUSE_ON, rtol);
  double c_formed = 0.0;
  if (!two || !one) goto out;
  /* wind until a level holds nodes and has taken some increments */
  int n = 0;
  while (n < N - 1 && !(two->deep.top > 100 && two->ref.age > 20)) {
    if (!wind_to(two, ++n, 0, NULL, &c_formed)) goto out;
  }
  CHECK(two->deep.top > 100);
  if (!(two->deep.top > 100) || !wind_to(one, n, 0, NULL, NULL)) goto out;
  double dc, dr;
  differences(two, one, &dc, &dr);
  printf("  at %d layers, a level of %d nodes: core %.3e sigma_r %.3e\n", n, two->deep.top, dc,
         dr);
  CHECK_LT(dc, 0.05 * TOL);
  CHECK_LT(dr, 0.05 * TOL);
  two->deep.c += 0.1 * (two->deep.c - c_formed); /* 10 % more of what it summed */
  differences(two, one, &dc, &dr);
  printf("  the level's scale 10 %% mis-summed: core %.3e sigma_r %.3e\n", dc, dr);
  CHECK(dc > 0.05 * TOL || dr > 0.05 * TOL);
out:
  rs_roll_destroy(&two);
  rs_roll_destroy(&one);
}

static void reads_match_full(void)
{
  const double rtol = TOL / RS_ACCURACY_PER_RTOL;
  rs_roll *a = newsprint(10, RS_REUSE_ON, rtol), *b = newsprint(10, RS_REUSE_ON, rtol);
  static double lazy[N];
  int seen = 0;
  if (!a || !b) goto out;
  for (int n = 100; n <= N; n += 100) {
    if (!wind_to(a, n, 0, NULL, NULL) || !wind_to(b, n, 0, NULL, NULL)) goto out;
    seen += a->deep.top > 0;
    const double core = rs_roll_core_pressure(a);
    for (int j = 0; j < n; ++j) lazy[j] = rs_roll_layer_sigma_r(a, j);
    const double *full = rs_roll_sigma_r(a); /* a read every 100 layers, b never */
    CHECK(memcmp(lazy, full, (size_t)n * sizeof(double)) == 0);
    CHECK(core == rs_roll_core_pressure(a));
  }
  printf("  a level held nodes at %d of the 80 reads\n", seen);
  CHECK(seen >= 3);
  CHECK(memcmp(rs_roll_sigma_r(a), rs_roll_sigma_r(b), N * sizeof(double)) == 0);
out:
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

static void restore_dissolves(void)
{
  const double rtol = TOL / RS_ACCURACY_PER_RTOL;
  rs_roll *a = newsprint(10, RS_REUSE_ON, rtol), *b = newsprint(INT_MAX, RS_REUSE_ON, rtol);
  rs_roll_state *st = NULL;
  CHECK(rs_roll_state_create(&st) == RS_OK);
  if (!a || !b || !st) goto out;
  int n = 0;
  while (n < N - 200 && !(a->deep.top > 100)) {
    if (!wind_to(a, ++n, 0, NULL, NULL)) goto out;
  }
  CHECK(a->deep.top > 100);
  /* both rewound from n + 50 layers to n */
  if (!wind_to(b, n, 0, NULL, NULL)) goto out;
  for (int i = 0; i < 2; ++i) {
    rs_roll *r = i ? b : a;
    CHECK(rs_roll_save(r, st) == RS_OK);
    if (!wind_to(r, n + 50, 0, NULL, NULL)) goto out;
    CHECK(rs_roll_restore(r, st) == RS_OK);
  }
  const char *wa = rsi_roll_check_invariants(a, 1), *wb = rsi_roll_check_invariants(b, 1);
  printf("  after the restore: %s; the one-level twin: %s\n", wa ? wa : "ok", wb ? wb : "ok");
  CHECK(a->deep.top == 0);
  if (!wind_to(a, N, 1, NULL, NULL) || !wind_to(b, N, 0, NULL, NULL)) goto out;
  double dc, dr;
  differences(a, b, &dc, &dr);
  printf("  restored at %d layers, wound on to %d: core %.3e sigma_r %.3e\n", n, N, dc, dr);
  CHECK_LT(dc, 0.05 * TOL);
  CHECK_LT(dr, 0.05 * TOL);
out:
  rs_roll_state_destroy(&st);
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

/* the same steps on both rolls: an overflowing increment (T0 = 1e308 N/m, which fails),
 * 50 layers, a lumped block of two, 50 layers */
static int fail_then_block(rs_roll *r)
{
  const double huge = 1e308, T2[2] = {T0, T0};
  CHECK(rs_roll_add_layers(r, 1, &huge) == RS_ERR_SOLVER);
  const char *why = rsi_roll_check_invariants(r, 1);
  if (why) fprintf(stderr, "  after the failed increment: %s\n", why);
  CHECK(why == NULL);
  if (!wind_to(r, r->n + 50, 1, NULL, NULL)) return 0;
  CHECK(rs_roll_add_layers(r, 2, T2) == RS_OK);
  CHECK(r->deep.top == 0); /* a lumped block dissolves a level */
  return wind_to(r, r->n + 50, 1, NULL, NULL);
}

static void failure_and_block(void)
{
  const double rtol = TOL / RS_ACCURACY_PER_RTOL;
  rs_roll *a = newsprint(10, RS_REUSE_ON, rtol), *b = newsprint(INT_MAX, RS_REUSE_ON, rtol);
  if (!a || !b) goto out;
  int n = 0; /* a level holds nodes and a reference from a node above the core is due */
  while (n < N - 200 && !(a->deep.top > 100 && a->ref.age >= 32 && a->ref.deep < a->ref.deep_max))
    if (!wind_to(a, ++n, 0, NULL, NULL)) goto out;
  CHECK(a->deep.top > 100);
  printf("  at %d layers, a level of %d nodes, a reference due\n", n, a->deep.top);
  if (!wind_to(b, n, 0, NULL, NULL) || !fail_then_block(a) || !fail_then_block(b)) goto out;
  double dc, dr;
  differences(a, b, &dc, &dr);
  printf("  failed, wound on, a block of two, wound on: core %.3e sigma_r %.3e\n", dc, dr);
  CHECK_LT(dc, 0.05 * TOL);
  CHECK_LT(dr, 0.05 * TOL);
out:
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

static void catches_broken(void)
{
  const double rtol = TOL / RS_ACCURACY_PER_RTOL;
  rs_roll *a = newsprint(10, RS_REUSE_ON, rtol);
  if (!a) return;
  int n = 0;
  while (n < N - 1 && !(a->deep.top > 100 && a->lazy.top > a->deep.top + 10))
    if (!wind_to(a, ++n, 0, NULL, NULL)) break;
  CHECK(a->deep.top > 100 && rsi_roll_check_invariants(a, 1) == NULL);
  if (!(a->deep.top > 100)) goto out;
  roll_deep *d = &a->deep;
  const roll_deep keep = *d;
  const double b5 = a->lazy.b[5];
  const char *why;
  d->top = 0;
  why = rsi_roll_check_invariants(a, 1);
  printf("  a scale with no level: %s\n", why ? why : "(none)");
  CHECK(why != NULL);
  *d = keep;
  d->top = a->lazy.top + 1;
  why = rsi_roll_check_invariants(a, 1);
  printf("  a level above the lazy zone: %s\n", why ? why : "(none)");
  CHECK(why != NULL);
  *d = keep;
  d->A = 0.0;
  why = rsi_roll_check_invariants(a, 1);
  printf("  A = 0: %s\n", why ? why : "(none)");
  CHECK(why && strstr(why, "rebase factor A positive"));
  *d = keep;
  d->depth0 = 0;
  why = rsi_roll_check_invariants(a, 1);
  printf("  a level without its depth at forming: %s\n", why ? why : "(none)");
  CHECK(why && strstr(why, "depth at forming"));
  *d = keep;
  a->ref.renew = 1;
  why = rsi_roll_check_invariants(a, 1);
  printf("  a renewal pending between increments: %s\n", why ? why : "(none)");
  CHECK(why && strstr(why, "no reference is being rebased"));
  a->ref.renew = 0;
  a->lazy.b[5] = a->lazy.b[d->top - 1] + 1.0;
  why = rsi_roll_check_invariants(a, 1);
  printf("  bounds not prefix maxima: %s\n", why ? why : "(none)");
  CHECK(why && strstr(why, "deeper level's drift bounds"));
  a->lazy.b[5] = b5;
  CHECK(rsi_roll_check_invariants(a, 1) == NULL);
out:
  rs_roll_destroy(&a);
}

/* renewed levels: a 25,000-layer roll whose levels form from 1250 nodes (the shipped span),
 * with references n/1600 increments apart as on a long roll, against the one-level engine
 * and a tight run */
static void renews(void)
{
  enum { NL = 25000 };
  const double rtol = TOL / RS_ACCURACY_PER_RTOL;
  rs_roll *two = film_long(NL / 20, RS_REUSE_ON, rtol, NL);
  rs_roll *one = film_long(INT_MAX, RS_REUSE_ON, rtol, NL);
  rs_roll *ref = film_long(INT_MAX, RS_REUSE_ON, 1e-10, NL);
  int held = 0;
  if (two && one && ref && wind_checked(two, NL, &held) && wind_to(one, NL, 0, NULL, NULL) &&
      wind_to(ref, NL, 0, NULL, NULL)) {
    double ec2, er2, ec1, er1;
    differences(two, ref, &ec2, &er2);
    differences(one, ref, &ec1, &er1);
    printf("  levels formed %ld (most nodes held %d), renewed %ld times; references from the "
           "core %ld (the one-level engine %ld)\n", two->deep.formed, held, two->ref.renewals,
           two->stats.full_integrations, one->stats.full_integrations);
    printf("  vs rtol 1e-10: two-level core %.3e sigma_r %.3e, one-level core %.3e sigma_r "
           "%.3e\n", ec2, er2, ec1, er1);
    CHECK(two->ref.renewals >= 20);
    CHECK_LT(ec2, 1.2 * ec1 + 0.04 * TOL);
    CHECK_LT(er2, 1.2 * er1 + 0.04 * TOL);
  }
  rs_roll_destroy(&two);
  rs_roll_destroy(&one);
  rs_roll_destroy(&ref);
}

/* the renewals' state: the 25,000-layer roll of renews alone, its invariants checked every
 * 250 layers and after every renewal, and its layer reads the full profile bit for bit */
static void renewed_invariants(void)
{
  enum { NL = 25000 };
  static double lazy[NL];
  rs_roll *two = film_long(NL / 20, RS_REUSE_ON, TOL / RS_ACCURACY_PER_RTOL, NL);
  int held = 0;
  if (two && wind_checked(two, NL, &held)) {
    printf("  renewed %ld times, %ld levels formed, a level of %d nodes at the end\n",
           two->ref.renewals, two->deep.formed, two->deep.top);
    CHECK(two->ref.renewals >= 20);
    CHECK(two->deep.top > 0);
    for (int j = 0; j < NL; ++j) lazy[j] = rs_roll_layer_sigma_r(two, j);
    CHECK(memcmp(lazy, rs_roll_sigma_r(two), NL * sizeof(double)) == 0);
  }
  rs_roll_destroy(&two);
}

static const check_case cases[] = {{"renewed_invariants", renewed_invariants},{"renews", renews},{"vs_one_level", vs_one_level},
                                   {"mis_summed_scale", mis_summed_scale},
                                   {"reads_match_full", reads_match_full},
                                   {"restore_dissolves", restore_dissolves},
                                   {"failure_and_block", failure_and_block},
                                   {"catches_broken", catches_broken}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
