/* The roll engine's invariants (src/roll/roll_check.c, stated in roll_internal.h).
 *   holds_while_winding  after every increment of a 800-layer newsprint roll (the reuse,
 *                        the lazy zone and the drift profile in use), of one with Hakiel's
 *                        placement and of one wound four layers a step, every invariant
 *                        holds, with the checks over the nodes; the rolls did use the lazy
 *                        zone and the profile, so those checks looked at something
 *   catches_broken       each of a set of broken states (a pending lazy scale with no lazy
 *                        node, drift bounds that are not prefix maxima, a profile beyond
 *                        its bound, a shape beyond its bound, a reference above the roll)
 *                        is reported, by name; the state restored, none is
 *   holds_after_restore  a roll rewound to a saved state (rs_roll_restore, what the reel's
 *                        adaptive nip policy does) satisfies every invariant at once, and
 *                        winds on to the stresses of a roll never rewound, within the
 *                        reuse's tolerance (1e-5 here) */
#include <math.h>
#include <string.h>

#include "check.h"
#include "roll/roll_internal.h"
#include "roll_helpers.h"

enum { N = 800 };

static rs_roll *newsprint(rs_load_placement placement)
{
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, N);
  p.rtol = 1e-5 / RS_ACCURACY_PER_RTOL; /* the reuse held to 1e-5: long lazy zones */
  p.placement = placement;
  rs_roll *roll = NULL;
  CHECK(rs_roll_create(&p, &roll) == RS_OK);
  return roll;
}

/* winds the roll to N layers m at a time, checking the invariants after each increment;
 * *lazy and *prof: the largest lazy zone and profile seen */
static void wind_checked(rs_roll *roll, int m, int *lazy, int *prof)
{
  const double T[4] = {682.5, 682.5, 682.5, 682.5};
  int bad = 0;
  *lazy = *prof = 0;
  while (rs_roll_layers(roll) + m <= N) {
    if (rs_roll_add_layers(roll, m, T) != RS_OK) break;
    const char *why = rsi_roll_check_invariants(roll, 1);
    if (why && !bad++) fprintf(stderr, "layer %d: %s\n", rs_roll_layers(roll), why);
    *lazy = roll->lazy.top > *lazy ? roll->lazy.top : *lazy;
    *prof = roll->prof.top > *prof ? roll->prof.top : *prof;
  }
  CHECK(rs_roll_layers(roll) > N - m);
  CHECK(bad == 0);
}

static void holds_while_winding(void)
{
  int lazy, prof;
  rs_roll *roll = newsprint(RS_LOAD_BENEATH);
  if (!roll) return;
  wind_checked(roll, 1, &lazy, &prof);
  printf("load beneath: largest lazy zone %d nodes, profile %d nodes\n", lazy, prof);
  CHECK(lazy > N / 4 && prof > N / 4);
  rs_roll_destroy(&roll);
  roll = newsprint(RS_LOAD_HAKIEL);
  if (!roll) return;
  wind_checked(roll, 1, &lazy, &prof);
  printf("Hakiel: largest lazy zone %d nodes\n", lazy);
  CHECK(lazy > N / 8);
  rs_roll_destroy(&roll);
  roll = newsprint(RS_LOAD_BENEATH);
  if (!roll) return;
  wind_checked(roll, 4, &lazy, &prof);
  rs_roll_destroy(&roll);
}

/* the check reports a broken state, naming what broke (a word of it in `word`) */
static void expect_broken(rs_roll *roll, const char *word)
{
  const char *why = rsi_roll_check_invariants(roll, 1);
  printf("%s: %s\n", word, why ? why : "(not reported)");
  CHECK(why != NULL && strstr(why, word) != NULL);
}

static void catches_broken(void)
{
  rs_roll *roll = newsprint(RS_LOAD_BENEATH);
  if (!roll) return;
  const double T = 682.5;
  for (int k = 0; k < N - 50; ++k) CHECK(rs_roll_add_layers(roll, 1, &T) == RS_OK);
  CHECK(rsi_roll_check_invariants(roll, 1) == NULL);
  CHECK(roll->lazy.top > 10 && roll->prof.top > 10);
  if (!(roll->lazy.top > 10 && roll->prof.top > 10)) goto done;
  const int F = roll->lazy.top, P = roll->prof.top;
  const double a = roll->lazy.a[5], pL = roll->prof.L[P / 2], e = roll->ref.shape_e[3];
  roll->lazy.a[5] = roll->lazy.a[F - 1] + 1.0;
  expect_broken(roll, "prefix maxima");
  roll->lazy.a[5] = a;
  roll->prof.L[P / 2] = 2.0 * roll->prof.max + 1.0;
  expect_broken(roll, "prof.max");
  roll->prof.L[P / 2] = pL;
  roll->ref.shape_e[3] = 2.0 * roll->ref.shape_max;
  expect_broken(roll, "shape_max");
  roll->ref.shape_e[3] = e;
  roll->lazy.top = 0;
  expect_broken(roll, "pending scale");
  roll->lazy.top = F;
  roll->ref.top = roll->n + 1;
  expect_broken(roll, "ref.top");
  roll->ref.top = roll->n - roll->shift;
  roll->ode.lg2_range_max = -1; /* the ODE workspace's */
  expect_broken(roll, "lg2_range_max");
  roll->ode.lg2_range_max = RS_LG2_RANGE_MAX;
  CHECK(rsi_roll_check_invariants(roll, 1) == NULL);
  /* and the roll winds on as before */
  CHECK(rs_roll_add_layers(roll, 1, &T) == RS_OK);
  CHECK(rsi_roll_check_invariants(roll, 1) == NULL);
done:
  rs_roll_destroy(&roll);
}

static void holds_after_restore(void)
{
  rs_roll *roll = newsprint(RS_LOAD_BENEATH), *plain = newsprint(RS_LOAD_BENEATH);
  rs_roll_state *saved = NULL;
  CHECK(rs_roll_state_create(&saved) == RS_OK);
  if (!roll || !plain || !saved) goto done;
  const double T = 682.5;
  for (int k = 0; k < N / 2; ++k) CHECK(rs_roll_add_layers(roll, 1, &T) == RS_OK);
  CHECK(rs_roll_save(roll, saved) == RS_OK);
  for (int k = 0; k < N / 4; ++k) CHECK(rs_roll_add_layers(roll, 1, &T) == RS_OK);
  CHECK(roll->ref.top > N / 2); /* the reference reaches above the state to restore */
  CHECK(rs_roll_restore(roll, saved) == RS_OK);
  const char *why = rsi_roll_check_invariants(roll, 1);
  printf("restored to %d layers: %s\n", rs_roll_layers(roll), why ? why : "every invariant holds");
  CHECK(why == NULL);
  for (int k = N / 2; k < N; ++k) CHECK(rs_roll_add_layers(roll, 1, &T) == RS_OK);
  for (int k = 0; k < N; ++k) CHECK(rs_roll_add_layers(plain, 1, &T) == RS_OK);
  CHECK(rsi_roll_check_invariants(roll, 1) == NULL);
  const double *a = rs_roll_sigma_r(roll), *b = rs_roll_sigma_r(plain);
  double d = 0.0;
  for (int j = 0; j < N; ++j) d = fmax(d, fabs(a[j] - b[j]));
  CHECK_LOG("max |sigma_r - never rewound| / core pressure", d / rs_roll_core_pressure(plain));
  CHECK_LT(d / rs_roll_core_pressure(plain), 1e-5); /* p.rtol x RS_ACCURACY_PER_RTOL */
done:
  rs_roll_state_destroy(&saved);
  rs_roll_destroy(&roll);
  rs_roll_destroy(&plain);
}

static const check_case cases[] = {
    {"holds_while_winding", holds_while_winding},
    {"catches_broken", catches_broken},
    {"holds_after_restore", holds_after_restore},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
