/* Save and restore: winding from a restored state is bit-for-bit the same as never having
 * left it (the adaptive nip policy relies on this to rewind). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "reelsim/roll.h"

static rs_roll *newsprint(int n)
{
  rs_roll_params p = {0};
  p.core_radius = 0.0762;
  p.caliper = 70e-6;
  p.E_theta = 3.5e9;
  p.core_stiffness = 1e9;
  p.radial.law = RS_RADIAL_PFEIFFER;
  p.radial.K1 = 5e3;
  p.radial.K2 = 60;
  p.max_layers = n;
  p.rtol = 1e-6;
  rs_roll *roll = NULL;
  CHECK(rs_roll_create(&p, &roll) == RS_OK);
  return roll;
}

static void wind(rs_roll *roll, int m, double T)
{
  for (int i = 0; i < m; ++i) CHECK(rs_roll_add_layers(roll, 1, &T) == RS_OK);
}

static void rewind_is_exact(void)
{
  rs_roll *a = newsprint(60), *b = newsprint(60);
  rs_roll_state *st = NULL;
  CHECK(rs_roll_state_create(&st) == RS_OK);
  if (!a || !b || !st) return;
  wind(a, 20, 500);
  wind(b, 20, 500);
  CHECK(rs_roll_save(b, st) == RS_OK);
  wind(b, 15, 900); /* a detour */
  CHECK(rs_roll_restore(b, st) == RS_OK);
  CHECK(rs_roll_layers(b) == 20);
  wind(a, 30, 450);
  wind(b, 30, 450);
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
