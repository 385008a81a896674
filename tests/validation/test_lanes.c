/* Lanes across the width (src/reel/lanes.c, docs/lanes.md), against what holds
 * independently of the driver:
 *  - uniform lanes are the 1-D roll (to round-off), whatever the threads;
 *  - the lanes' tensions add up to the winder's: sum w_i T_i = Tbar W at every layer, Tbar
 *    the recipe at the lanes' mean radius;
 *  - the stiff-stack limit (E_r 1e13 Pa on a rigid core): R_i = r_c + k t_i and T_i from the
 *    coupling's formula in closed form (two lanes, both taut);
 *  - convergence in the lane count for a smooth caliper bump (the ridge height, second order);
 *  - the trends the literature reports: a thick band runs hard (its core pressure and web
 *    tension up), a thin lane goes slack, a rigid roller carries its load on the high lanes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "lanes_helpers.h"
#include "reelsim/recipe.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reel/result_internal.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

/* 200 layers of a linear-law web (t = 100 um, E_theta 4 GPa, E_r 20 MPa), T = 200 N/m */
static const char *small = RS_TESTS_DIR "/cli/scenes/small.yaml";

/* a linear taper 250 -> 150 N/m over the roll */
static void taper(rs_problem *pb)
{
  pb->tension.law = RS_RECIPE_LINEAR;
  pb->tension.start = 250.0;
  pb->tension.end = 150.0;
}

static rs_problem *problem(int n_sets, const char **sets) { return load_problem(small, n_sets, sets); }

static void uniform_equals_1d(void)
{
  rs_problem *pb = problem(0, NULL);
  if (!pb) return;
  taper(pb);
  rs_reel_result *one = wind(pb);
  set_lanes(pb, 4, 1.0, NULL);
  setenv("REELSIM_LANES_THREADS", "1", 1);
  rs_reel_result *l1 = wind(pb);
  setenv("REELSIM_LANES_THREADS", "3", 1);
  rs_reel_result *l3 = wind(pb);
  unsetenv("REELSIM_LANES_THREADS");
  if (one && l1 && l3) {
    const int n = one->n_layers, m = 4;
    double worst = 0.0, scale = one->core_pressure;
    CHECK(l1->n_layers == n && l1->lanes && l1->lanes->n_layers == n);
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < m; ++i) {
        worst = fmax(worst, fabs(l1->lanes->sigma_r[(size_t)k * m + i] - one->sigma_r[k]) / scale);
        worst = fmax(worst, fabs(l1->lanes->wound_on_tension[(size_t)k * m + i] -
                                 one->wound_on_tension[k]) / one->wound_on_tension[k]);
      }
    for (int i = 0; i < m; ++i)
      worst = fmax(worst, fabs(l1->lanes->core_pressure[i] - one->core_pressure) / scale);
    CHECK_LOG("max relative difference lanes vs 1-D", worst);
    CHECK_LT(worst, 1e-10);
    CHECK(!memcmp(l1->lanes->sigma_r, l3->lanes->sigma_r, (size_t)n * m * sizeof(double)));
    CHECK(l3->lanes->threads == 3 && l1->lanes->threads == 1);
  }
  rs_reel_result_destroy(&one);
  rs_reel_result_destroy(&l1);
  rs_reel_result_destroy(&l3);
  free(pb);
}

static void tension_sum_every_layer(void)
{
  rs_problem *pb = problem(0, NULL);
  if (!pb) return;
  taper(pb);
  const double f[] = {1.0, 1.01, 0.995, 1.0, 1.02};
  set_lanes(pb, 5, 1.5, f);
  pb->lanes.width[0] = 0.1, pb->lanes.width[4] = 0.5; /* unequal widths */
  rs_reel_result *res = wind(pb);
  if (res) {
    const rs_lanes_result *lr = res->lanes;
    double worst = 0.0, W = 0.0;
    for (int i = 0; i < 5; ++i) W += pb->lanes.width[i];
    for (int k = 0; k < lr->n_layers; ++k) {
      double sum = 0.0, r = 0.0;
      for (int i = 0; i < 5; ++i) {
        sum += pb->lanes.width[i] * lr->web_tension[(size_t)k * 5 + i];
        r += pb->lanes.width[i] * (pb->core.radius + (k + 1) * lr->caliper[i]);
      }
      const double Tbar = rs_recipe_eval(&pb->tension, r / W);
      worst = fmax(worst, fabs(sum - Tbar * W) / (Tbar * W));
    }
    CHECK_LOG("max |sum w T - Tbar W| / Tbar W", worst);
    CHECK_LT(worst, 1e-12);
  }
  rs_reel_result_destroy(&res);
  free(pb);
}

/* two lanes, t1 = 1.01 t, widths 0.3 and 0.7: with R_i = r_c + k t_i and both taut,
 * e = (Tbar W - sum w_i a_i (R_i/Rbar - 1)) / sum w_i a_i, T_i = a_i (e + R_i/Rbar - 1);
 * where that makes the thin lane's negative it is slack (0) and the thick one carries
 * Tbar W / w_1. E_r 1e13 Pa on the rigid core of small.yaml. */
static void stiff_stack_limit(void)
{
  const char *sets[] = {"material.radial.E_r=1e13"};
  rs_problem *pb = problem((int)(sizeof sets / sizeof sets[0]), sets);
  if (!pb) return;
  const double f[] = {1.01, 1.0};
  set_lanes(pb, 2, 1.0, f);
  pb->lanes.width[0] = 0.3, pb->lanes.width[1] = 0.7;
  rs_reel_result *res = wind(pb);
  if (res) {
    const rs_lanes_result *lr = res->lanes;
    const double w[] = {0.3, 0.7}, t = pb->material.caliper, E = pb->material.E_theta;
    double worst = 0.0;
    int slack = 0;
    for (int k = 0; k < lr->n_layers; ++k) {
      double R[2], a[2], Rbar = 0.0, num = 200.0, den = 0.0;
      for (int i = 0; i < 2; ++i) {
        R[i] = pb->core.radius + k * f[i] * t;
        a[i] = E * f[i] * t;
        Rbar += w[i] * R[i];
      }
      for (int i = 0; i < 2; ++i) num -= w[i] * a[i] * (R[i] / Rbar - 1.0), den += w[i] * a[i];
      const double e = num / den;
      double T[2];
      for (int i = 0; i < 2; ++i) T[i] = a[i] * (e + R[i] / Rbar - 1.0);
      if (T[1] < 0.0) T[1] = 0.0, T[0] = 200.0 / w[0], ++slack;
      for (int i = 0; i < 2; ++i)
        worst = fmax(worst, fabs(lr->web_tension[(size_t)k * 2 + i] - T[i]) / 200.0);
    }
    CHECK_LOG("layers with the thin lane slack", slack);
    CHECK(slack > 0 && slack < lr->n_layers); /* both regimes are checked */
    CHECK_LOG("max |T_i - closed form| / Tbar", worst);
    /* T_i - Tbar ~ a_i (R_i - Rbar) / Rbar grows to ~10^3 N/m here; what is left of the
     * stack's compression at E_r = 1e13 Pa (~1e-11 m per layer) moves T_i by a_i/Rbar times
     * it, ~2e-3 N/m (2e-11 m of R_i, ~1e-5 of Tbar) */
    CHECK_LT(worst, 3e-5);
    CHECK_ABS(lr->outer_radius[0], pb->core.radius + lr->n_layers * 1.01 * t, 1e-8);
  }
  rs_reel_result_destroy(&res);
  free(pb);
}

/* the width-mean core pressure (sum w_i P_i / W, an integral over the width) with a
 * Gaussian caliper bump of 0.5 % at x = 0.3 m (0.15 m wide) on 0.9 m, n equal lanes */
static double bump_core_pressure(rs_problem *pb, int n)
{
  double f[RS_LANES_MAX];
  for (int i = 0; i < n; ++i) {
    const double u = (0.9 * (i + 0.5) / n - 0.3) / 0.15;
    f[i] = 1.0 + 0.005 * exp(-u * u);
  }
  set_lanes(pb, n, 0.9, f);
  rs_reel_result *res = wind(pb);
  double P = NAN;
  if (res) P = res->core_pressure;
  rs_reel_result_destroy(&res);
  return P;
}

static void lane_count_convergence(void)
{
  rs_problem *pb = problem(0, NULL);
  if (!pb) return;
  const double p1 = bump_core_pressure(pb, 10), p2 = bump_core_pressure(pb, 20),
               p3 = bump_core_pressure(pb, 40);
  CHECK_LOG("mean core pressure, 10 lanes (Pa)", p1);
  CHECK_LOG("mean core pressure, 20 lanes (Pa)", p2);
  CHECK_LOG("mean core pressure, 40 lanes (Pa)", p3);
  const double ratio = fabs(p2 - p1) / fabs(p3 - p2);
  CHECK_LOG("error ratio per halving", ratio);
  CHECK_LT(fabs(p3 - p2), fabs(p2 - p1));
  CHECK_LT(3.0, ratio);
  free(pb);
}

static void thick_band_runs_hard(void)
{
  rs_problem *pb = problem(0, NULL);
  if (!pb) return;
  set_band(pb);
  rs_reel_result *res = wind(pb);
  if (res) {
    const rs_lanes_result *lr = res->lanes;
    const int n = lr->n_layers;
    CHECK_LOG("band core pressure (Pa)", lr->core_pressure[2]);
    CHECK_LOG("other lanes' core pressure (Pa)", lr->core_pressure[0]);
    CHECK_LT(1.5 * lr->core_pressure[0], lr->core_pressure[2]);
    CHECK_LT(200.0, lr->web_tension[(size_t)(n - 1) * 5 + 2]);
    CHECK_LT(lr->web_tension[(size_t)(n - 1) * 5 + 0], 200.0);
    rs_lanes_summary s;
    CHECK(rs_lanes_summarize(res, 0.0, &s) && s.hardest == 2 && s.ridge_x == lr->x[2]);
  }
  rs_reel_result_destroy(&res);
  free(pb);
}

static void thin_lane_goes_slack(void)
{
  rs_problem *pb = problem(0, NULL);
  if (!pb) return;
  const double f[] = {1.0, 1.0, 0.97, 1.0, 1.0};
  set_lanes(pb, 5, 1.0, f);
  rs_reel_result *res = wind(pb);
  if (res) {
    const rs_lanes_result *lr = res->lanes;
    rs_lanes_summary s;
    CHECK(rs_lanes_summarize(res, 0.0, &s) && s.slack_lanes == 1 && isfinite(s.slack_from[2]));
    CHECK_LOG("the thin lane slack from r (m)", s.slack_from[2]);
    const int n = lr->n_layers;
    CHECK(lr->slack[(size_t)(n - 1) * 5 + 2] == 1 && lr->web_tension[(size_t)(n - 1) * 5 + 2] == 0.0);
  }
  rs_reel_result_destroy(&res);
  free(pb);
}

static void roller_on_high_lanes(void)
{
  const char *sets[] = {"nip.model=friction", "nip.load=2000", "nip.friction.roll=0.2"};
  rs_problem *pb = problem(3, sets);
  if (!pb) return;
  set_band(pb);
  pb->lanes.nip = RS_LANES_NIP_ROLLER;
  rs_reel_result *res = wind(pb);
  if (res) {
    const rs_lanes_result *lr = res->lanes;
    const int k = lr->n_layers - 1;
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) sum += 0.2 * lr->nip_load[(size_t)k * 5 + i];
    CHECK_LOG("the band's load (N/m)", lr->nip_load[(size_t)k * 5 + 2]);
    CHECK_LOG("a flat lane's load (N/m)", lr->nip_load[(size_t)k * 5 + 0]);
    CHECK_CLOSE(sum, 2000.0, 1e-12);
    CHECK_LT(2000.0, lr->nip_load[(size_t)k * 5 + 2]);
    CHECK_LT(lr->nip_load[(size_t)k * 5 + 0], 2000.0);
    /* the nip-induced part follows the load: T0 - T = mu N on the friction center winder */
    CHECK_CLOSE(lr->wound_on_tension[(size_t)k * 5 + 2] - lr->web_tension[(size_t)k * 5 + 2],
                0.2 * lr->nip_load[(size_t)k * 5 + 2], 1e-9);
  }
  rs_reel_result_destroy(&res);
  free(pb);
}

static const check_case cases[] = {
    {"uniform_equals_1d", uniform_equals_1d},
    {"tension_sum_every_layer", tension_sum_every_layer},
    {"stiff_stack_limit", stiff_stack_limit},
    {"lane_count_convergence", lane_count_convergence},
    {"thick_band_runs_hard", thick_band_runs_hard},
    {"thin_lane_goes_slack", thin_lane_goes_slack},
    {"roller_on_high_lanes", roller_on_high_lanes},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
