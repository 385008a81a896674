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
  rs_problem pb;
  memset(&pb, 0, sizeof pb);
  pb.material.caliper = 70e-6;
  pb.material.E_theta = 3.5e9;
  pb.material.radial.law = RS_RADIAL_PFEIFFER;
  pb.material.radial.K1 = 5e3;
  pb.material.radial.K2 = 60;
  pb.core.kind = RS_CORE_RIGID;
  pb.core.radius = 0.0762;
  pb.final_radius = 0.16;
  pb.n_layers = (int)lround((pb.final_radius - pb.core.radius) / pb.material.caliper);
  pb.tension.law = law;
  pb.tension.start = start;
  pb.tension.end = end;
  pb.tension.k = NAN;
  CHECK(rs_radial_law_prepare(&pb.material.radial) == RS_OK);
  CHECK(rs_recipe_prepare(&pb.tension, pb.core.radius, pb.final_radius) == RS_OK);
  pb.numerics.layers_per_step = 1;
  pb.numerics.rtol = 1e-6;
  rs_reel_result *res = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &res) == RS_OK);
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
