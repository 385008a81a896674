/* Tension tapers and hoop stress: the ordering winding practice relies on. With the same
 * reel and the same mean tension, inner layers end up most compressed in the hoop
 * direction under a rising taper, less under constant tension, least under a falling
 * taper (tapers exist to relieve the inner wraps: Roisum 1994; Hakiel 1987 shows the
 * mechanism: outer wraps add pressure, inner wraps lose tension). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "reelsim/reel.h"

static double min_hoop(rs_recipe_kind law, double start, double end)
{
  rs_scene sc;
  memset(&sc, 0, sizeof sc);
  sc.problem.material.caliper = 70e-6;
  sc.problem.material.E_theta = 3.5e9;
  sc.problem.material.radial.law = RS_RADIAL_PFEIFFER;
  sc.problem.material.radial.K1 = 5e3;
  sc.problem.material.radial.K2 = 60;
  sc.problem.core.kind = RS_CORE_RIGID;
  sc.problem.core.radius = 0.0762;
  sc.problem.final_radius = 0.16;
  sc.problem.n_layers = (int)lround((sc.problem.final_radius - sc.problem.core.radius) / sc.problem.material.caliper);
  sc.problem.tension.law = law;
  sc.problem.tension.start = start;
  sc.problem.tension.end = end;
  sc.problem.tension.k = NAN;
  CHECK(rs_radial_law_prepare(&sc.problem.material.radial) == RS_OK);
  CHECK(rs_recipe_prepare(&sc.problem.tension, sc.problem.core.radius, sc.problem.final_radius) == RS_OK);
  sc.problem.numerics.layers_per_step = 1;
  sc.problem.numerics.rtol = 1e-6;
  rs_reel_result *res = NULL;
  CHECK(rs_reel_wind(&sc, NULL, &res) == RS_OK);
  rs_reel_summary sum;
  rs_reel_summarize(res, &sum);
  rs_reel_result_destroy(&res);
  return sum.min_hoop;
}

static void hoop_compression_ordering(void)
{
  double rising = min_hoop(RS_RECIPE_LINEAR, 100, 900);
  double constant = min_hoop(RS_RECIPE_CONSTANT, 500, 500);
  double falling = min_hoop(RS_RECIPE_LINEAR, 900, 100);
  CHECK_LOG("min hoop, rising 100 -> 900 N/m (Pa)", rising);
  CHECK_LOG("min hoop, constant 500 N/m (Pa)", constant);
  CHECK_LOG("min hoop, falling 900 -> 100 N/m (Pa)", falling);
  CHECK_LT(rising, constant);
  CHECK_LT(constant, falling);
  CHECK_LT(rising, 0.0); /* the rising taper starves the inner wraps into compression */
}

static const check_case cases[] = {{"hoop_compression_ordering", hoop_compression_ordering}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
