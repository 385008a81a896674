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

static const check_case cases[] = {{"rewind_is_exact", rewind_is_exact}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
