/* Accuracy on a very soft web and in creep stages (docs/accuracy.md, "A very soft web";
 * docs/storage.md): the errors fall as rtol tightens.
 *   soft_web_rtol   Pfeiffer K1 = 50 Pa, K2 = 20 (E_r = 1 kPa at P = 0, g ~ 1900 at the
 *                   surface), 1500 N/m, 400 layers on a rigid core, the default reuse and
 *                   error correction at rtol 1e-2 .. 1e-6 against every increment from the
 *                   core at rtol 1e-10: core pressure, sigma_r and sigma_theta (incl. the
 *                   innermost layer's) fall monotonically; once the step whose defect crossed
 *                   100 tolerances at rtol 1e-4 lost its correction and the hoop error grew
 *                   25x from rtol 3e-4 to 1e-4
 *   creep_stages    cases/newsprint-storage-creep.yaml at the default rtol 1e-3 against
 *                   rtol 1e-8: every stage's core pressure within 2.5 rtol/50 (was 1.2e-4) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "roll_helpers.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/storage.h"
#include "storage/storage_result.h"

enum { N_SOFT = 400 };
static const double T_SOFT = 1500.0, T_CAL = 70e-6;

static rs_roll *soft(double rtol, rs_reuse reuse)
{
  rs_roll_params p = pfeiffer_params(0.0762, T_CAL, 3.5e9, 50.0, 20.0, INFINITY, N_SOFT);
  p.rtol = rtol;
  p.atol = 0.0; /* rtol */
  p.reuse = reuse;
  return wind(&p, N_SOFT, 1, T_SOFT);
}

static void soft_web_rtol(void)
{
  rs_roll *ref = soft(1e-10, RS_REUSE_OFF);
  CHECK(ref != NULL);
  if (!ref) return;
  const double *hr = rs_roll_sigma_theta(ref), *sr = rs_roll_sigma_r(ref), cp = rs_roll_core_pressure(ref);
  const double unit = T_SOFT / T_CAL, rt[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  double last[4] = {INFINITY, INFINITY, INFINITY, INFINITY};
  for (int i = 0; i < 5; ++i) {
    rs_roll *r = soft(rt[i], RS_REUSE_ON);
    CHECK(r != NULL);
    if (!r) break;
    const double *h = rs_roll_sigma_theta(r), *s = rs_roll_sigma_r(r);
    double e[4] = {fabs(rs_roll_core_pressure(r) / cp - 1.0), 0.0, 0.0, fabs(h[0] - hr[0]) / unit};
    for (int j = 0; j < N_SOFT; ++j) {
      e[1] = fmax(e[1], fabs(s[j] - sr[j]) / cp);
      e[2] = fmax(e[2], fabs(h[j] - hr[j]) / unit);
    }
    printf("  rtol %g: core %.3e  sigma_r %.3e  sigma_theta %.3e  innermost sigma_theta %.3e\n",
           rt[i], e[0], e[1], e[2], e[3]);
    for (int q = 0; q < 3; ++q) CHECK_LT(e[q], last[q]); /* falls with every decade */
    CHECK_LT(e[3], 1e-5 > 3.0 * last[3] ? 1e-5 : 3.0 * last[3]); /* tiny: at most noise */
    CHECK_LT(e[2], 1.0 * rt[i]); /* the hoop error within rtol of T0/t */
    for (int q = 0; q < 4; ++q) last[q] = e[q];
    rs_roll_destroy(&r);
  }
  rs_roll_destroy(&ref);
}

/* the creep case's storage stages at numerics.rtol = rtol */
static rs_storage_result *creep_run(const char *rtol)
{
  char set[64];
  snprintf(set, sizeof set, "numerics.rtol=%s", rtol);
  const char *sets[] = {set};
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL;
  rs_storage_result *sr = NULL;
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-storage-creep.yaml", 1, sets, &sc) == RS_OK);
  if (sc && rs_scene_wind(sc, NULL, &res) == RS_OK)
    CHECK(rs_storage_run(rs_scene_problem(sc), res, &sr) == RS_OK);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
  return sr;
}

static void creep_stages(void)
{
  rs_storage_result *a = creep_run("1e-3"), *b = creep_run("1e-8");
  CHECK(a && b);
  if (a && b) {
    CHECK(a->n_stages == b->n_stages && a->n_stages > 1);
    double worst = 0.0;
    for (int s = 0; s < a->n_stages && s < b->n_stages; ++s)
      worst = fmax(worst, fabs(a->core_pressure[s] / b->core_pressure[s] - 1.0));
    CHECK_LOG("worst stage core pressure, rtol 1e-3 against 1e-8", worst);
    CHECK_LT(worst, 2.5 * RS_ACCURACY_PER_RTOL * 1e-3);
  }
  rs_storage_result_destroy(&a);
  rs_storage_result_destroy(&b);
}

static const check_case cases[] = {{"soft_web_rtol", soft_web_rtol}, {"creep_stages", creep_stages}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
