/* Save and restore: winding from a restored state is bit-for-bit the same as never having
 * left it (the adaptive nip policy relies on this to rewind). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "roll_helpers.h"

static rs_roll *newsprint(int n)
{
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, n);
  p.rtol = 1e-6;
  p.atol = 0.0; /* = rtol */
  rs_roll *roll = NULL;
  CHECK(rs_roll_create(&p, &roll) == RS_OK);
  return roll;
}

static void wind_more(rs_roll *roll, int m, double T)
{
  for (int i = 0; i < m; ++i) CHECK(rs_roll_add_layers(roll, 1, &T) == RS_OK);
}

static void rewind_is_exact(void)
{
  rs_roll *a = newsprint(60), *b = newsprint(60);
  rs_roll_state *st = NULL;
  CHECK(rs_roll_state_create(&st) == RS_OK);
  if (!a || !b || !st) return;
  wind_more(a, 20, 500);
  wind_more(b, 20, 500);
  CHECK(rs_roll_save(b, st) == RS_OK);
  wind_more(b, 15, 900); /* a detour */
  CHECK(rs_roll_restore(b, st) == RS_OK);
  CHECK(rs_roll_layers(b) == 20);
  wind_more(a, 30, 450);
  wind_more(b, 30, 450);
  CHECK(rs_roll_layers(a) == rs_roll_layers(b));
  CHECK(memcmp(rs_roll_sigma_r(a), rs_roll_sigma_r(b), 50 * sizeof(double)) == 0);
  CHECK(memcmp(rs_roll_sigma_theta(a), rs_roll_sigma_theta(b), 50 * sizeof(double)) == 0);
  CHECK(rs_roll_core_pressure(a) == rs_roll_core_pressure(b));
  rs_roll_stats sa, sb;
  rs_roll_get_stats(a, &sa);
  rs_roll_get_stats(b, &sb);
  CHECK(sb.increments == sa.increments + 15); /* the detour's work stays counted */
  rs_roll_state_destroy(&st);
  rs_roll_state_destroy(&st);
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

/* An increment whose stresses are not finite (a wound-on tension of 1e308 N/m: T0/s
 * overflows) fails with RS_ERR_SOLVER saying so and leaves the roll's stresses exactly as
 * they were: the one-layer increment is checked before anything is written
 * (src/roll/roll_layer.c, rsi_roll_commit); then the roll winds on. */
static void nonfinite_keeps_roll(void)
{
  enum { N = 1000 };
  rs_roll *a = newsprint(N + 2);
  if (!a) return;
  wind_more(a, N, 500);
  static double sr[N], sth[N];
  memcpy(sr, rs_roll_sigma_r(a), sizeof sr);
  memcpy(sth, rs_roll_sigma_theta(a), sizeof sth);
  const double core = rs_roll_core_pressure(a);
  double T = 1e308;
  CHECK(rs_roll_add_layers(a, 1, &T) == RS_ERR_SOLVER);
  CHECK(strstr(rs_error_message(), "non-finite stress increment") != NULL);
  CHECK(rs_roll_layers(a) == N);
  CHECK(memcmp(rs_roll_sigma_r(a), sr, sizeof sr) == 0);
  CHECK(memcmp(rs_roll_sigma_theta(a), sth, sizeof sth) == 0);
  CHECK(rs_roll_core_pressure(a) == core);
  wind_more(a, 1, 500);
  CHECK(rs_roll_layers(a) == N + 1);
  CHECK(isfinite(rs_roll_core_pressure(a)) && rs_roll_core_pressure(a) > core);
  rs_roll_destroy(&a);
}

static const check_case cases[] = {{"rewind_is_exact", rewind_is_exact},
                                   {"nonfinite_keeps_roll", nonfinite_keeps_roll}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
