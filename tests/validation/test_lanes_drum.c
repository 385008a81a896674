/* Lanes on a drum-driven winder (src/reel/lanes.c, lanes_web; docs/lanes.md, "Surface and
 * two-drum winders"): the drum drives the lanes it touches, not a tension controller the
 * mean. Checked against the form's closed solution in the stiff-stack limit (R_i = r_c +
 * k t_i): the web reaches the drum at the strain e_d its upstream tension sets,
 * sum w_i a_i e_d = Tbar W (a_i = E_theta t_i), the largest lane carries exactly its
 * upstream share a_i e_d at every layer, the others a_i (e_d + R_i/R_d - 1) or nothing
 * (slack), and the sum the roll takes up falls below Tbar W as the ridge grows; and
 * uniform lanes on a surface winder are the 1-D roll. */
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

/* small.yaml (200 layers, T = 200 N/m, rigid core) on a surface winder with a friction nip
 * solved at every layer (as the lanes solve it) */
static rs_problem *problem(int n_more, const char **more)
{
  const char *sets[8] = {"nip.model=friction", "nip.load=400", "nip.friction.roll=0.2",
                         "nip.update=every", "nip.update_every=1"};
  for (int i = 0; i < n_more; ++i) sets[5 + i] = more[i];
  rs_problem *pb = load_problem(RS_TESTS_DIR "/cli/scenes/small.yaml", 5 + n_more, sets);
  if (pb) pb->winder.type = RS_WINDER_TYPE_SURFACE;
  return pb;
}

static void drum_drives_largest(void)
{
  const char *more[] = {"material.radial.E_r=1e13"};
  rs_problem *pb = problem(1, more);
  if (!pb) return;
  const double w[] = {0.3, 0.7}, f[] = {1.01, 1.0};
  set_lanes_widths(pb, 2, 1.0, w, f);
  rs_reel_result *res = wind(pb);
  if (res) {
    const rs_lanes_result *lr = res->lanes;
    const double t = pb->material.caliper, E = pb->material.E_theta, Tbar = 200.0;
    const double a[] = {E * f[0] * t, E * f[1] * t};
    const double ed = Tbar / (w[0] * a[0] + w[1] * a[1]); /* W = 1 */
    double worst = 0.0, taken_last = 0.0;
    int slack = 0;
    for (int k = 0; k < lr->n_layers; ++k) {
      const double R0 = pb->core.radius + k * f[0] * t, R1 = pb->core.radius + k * f[1] * t;
      const double T0 = a[0] * ed, T1 = fmax(0.0, a[1] * (ed + (R1 / R0 - 1.0)));
      slack += T1 == 0.0;
      worst = fmax(worst, fabs(lr->web_tension[(size_t)k * 2] - T0) / Tbar);
      worst = fmax(worst, fabs(lr->web_tension[(size_t)k * 2 + 1] - T1) / Tbar);
      taken_last = w[0] * lr->web_tension[(size_t)k * 2] + w[1] * lr->web_tension[(size_t)k * 2 + 1];
    }
    CHECK_LOG("the driven lane's tension a_0 e_d (N/m)", a[0] * ed);
    CHECK_LOG("layers with the thin lane slack", slack);
    CHECK_LOG("max |T_i - closed form| / Tbar", worst);
    CHECK_LOG("sum w T at the last layer (N/m; Tbar W = 200)", taken_last);
    CHECK(slack > 0 && slack < lr->n_layers); /* both regimes */
    /* the residual compression at E_r = 1e13 Pa moves R_i by ~1e-11 m a layer (as in
     * test_lanes.stiff_stack_limit) */
    CHECK_LT(worst, 3e-5);
    CHECK_LT(taken_last, 0.75 * Tbar); /* not held: the slack lane's share is not taken up */
  }
  rs_reel_result_destroy(&res);
  free(pb);
}

static void drum_uniform_equals_1d(void)
{
  rs_problem *pb = problem(0, NULL);
  if (!pb) return;
  rs_reel_result *one = wind(pb);
  const double w[] = {0.25, 0.25, 0.25, 0.25}, f[] = {1.0, 1.0, 1.0, 1.0};
  set_lanes_widths(pb, 4, 1.0, w, f);
  rs_reel_result *lanes = wind(pb);
  if (one && lanes) {
    double worst = 0.0;
    for (int k = 0; k < one->n_layers; ++k)
      for (int i = 0; i < 4; ++i) {
        worst = fmax(worst, fabs(lanes->lanes->sigma_r[(size_t)k * 4 + i] - one->sigma_r[k]) /
                                one->core_pressure);
        worst = fmax(worst, fabs(lanes->lanes->wound_on_tension[(size_t)k * 4 + i] -
                                 one->wound_on_tension[k]) / one->wound_on_tension[k]);
      }
    CHECK_LOG("max relative difference lanes vs 1-D", worst);
    CHECK_LT(worst, 1e-14);
  }
  rs_reel_result_destroy(&one);
  rs_reel_result_destroy(&lanes);
  free(pb);
}

static const check_case cases[] = {{"drum_drives_largest", drum_drives_largest},
                                   {"drum_uniform_equals_1d", drum_uniform_equals_1d}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
