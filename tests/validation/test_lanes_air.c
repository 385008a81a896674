/* Lanes with entrained air (src/reel/lanes.c, effect_air.c's rs_reel_air_ends; docs/lanes.md):
 * each lane carries its films; the sheet ends where the first lane reaches the roll's size,
 * every lane with the same layers:
 *  - uniform lanes with air are the 1-D roll with air (its layers, stresses, films);
 *  - a thick band: the sheet ends before the scene's count, no lane beyond the roll's size,
 *    the band (the highest) within a layer of it. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lanes_helpers.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reel/result_internal.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

/* small.yaml (linear stack, 200 layers to 70 mm) at 8 m/s with air films, no nip */
static rs_problem *problem(void)
{
  const char *sets[] = {"winding.speed=8", "air=true", "air.roughness=1e-6"};
  return load_problem(RS_TESTS_DIR "/cli/scenes/small.yaml", 3, sets);
}

static void uniform_air_equals_1d(void)
{
  rs_problem *pb = problem();
  if (!pb) return;
  rs_reel_result *one = wind(pb);
  set_lanes(pb, 4, 1.0, NULL);
  rs_reel_result *lanes = wind(pb);
  if (one && lanes) {
    const int n = one->n_layers;
    double worst = 0.0;
    CHECK_LOG("layers, 1-D with air", n);
    CHECK_LOG("layers, 4 uniform lanes with air", lanes->n_layers);
    CHECK(n < pb->n_layers && lanes->n_layers == n && lanes->lanes->n_layers == n);
    for (int k = 0; k < n && lanes->n_layers == n; ++k) {
      for (int i = 0; i < 4; ++i)
        worst = fmax(worst, fabs(lanes->lanes->sigma_r[(size_t)k * 4 + i] - one->sigma_r[k]) /
                                one->core_pressure);
      worst = fmax(worst, fabs(lanes->air_film[k] - one->air_film[k]) / one->air_film[k]);
      worst = fmax(worst, fabs(lanes->radius[k] - one->radius[k]) / one->radius[k]);
    }
    CHECK_LOG("max relative difference lanes vs 1-D", worst);
    CHECK_LT(worst, 1e-12);
  }
  rs_reel_result_destroy(&one);
  rs_reel_result_destroy(&lanes);
  free(pb);
}

static void band_ends_together(void)
{
  rs_problem *pb = problem();
  if (!pb) return;
  set_band(pb);
  rs_reel_result *res = wind(pb);
  if (res) {
    const rs_lanes_result *lr = res->lanes;
    const double t = pb->material.caliper;
    double Rmax = 0.0;
    for (int i = 0; i < 5; ++i) Rmax = fmax(Rmax, lr->outer_radius[i]);
    CHECK_LOG("layers wound (scene's count 200)", lr->n_layers);
    CHECK_LOG("the band's final outer radius (m)", lr->outer_radius[2]);
    CHECK_LOG("a plain lane's (m)", lr->outer_radius[0]);
    CHECK(lr->n_layers == res->n_layers && lr->n_layers < pb->n_layers);
    CHECK(Rmax == lr->outer_radius[2]);
    /* the films as the final pressures compress them: the band within a layer and a film
     * of the roll's size, not beyond it */
    CHECK(Rmax <= pb->final_radius + 0.5 * t && Rmax > pb->final_radius - 2.0 * t);
  }
  rs_reel_result_destroy(&res);
  free(pb);
}

static const check_case cases[] = {{"uniform_air_equals_1d", uniform_air_equals_1d},
                                   {"band_ends_together", band_ends_together}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
