/* Defect-risk rules (docs/defects.md) on hand-made profiles whose answers are known:
 * where sigma_theta < 0 (information), the critical stress of one layer on the stack's
 * elastic foundation (its closed form, two routes), the slip capacity mu P 2 pi r^2,
 * ratios against the limits, and "not assessed" when a limit is absent. The starring and
 * cinching verdicts themselves: tests/unit/test_verdicts.c. */

#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/defects.h"
#include "reelsim/scene.h"

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

static const double pi = 3.14159265358979323846;

/* n layers of caliper 1 mm on a 0.1 m core, sigma_r = -1e5 Pa, sigma_theta = +1e6 Pa. */
static rs_reel_result *profile(int n)
{
  rs_reel_result *r = calloc(1, sizeof *r);
  r->n_layers = n;
  r->core_radius = 0.1;
  r->core_pressure = 2.0e5;
  size_t sz = (size_t)(n > 0 ? n : 1) * sizeof(double);
  r->radius = malloc(sz);
  r->sigma_r = malloc(sz);
  r->sigma_theta = malloc(sz);
  r->wound_on_tension = malloc(sz);
  r->web_tension = malloc(sz);
  r->nip_load = malloc(sz);
  for (int j = 0; j < n; ++j) {
    r->radius[j] = 0.1 + (j + 1) * 1.0e-3;
    r->sigma_r[j] = -1.0e5;
    r->sigma_theta[j] = 1.0e6;
    r->wound_on_tension[j] = r->web_tension[j] = 300.0;
    r->nip_load[j] = 0.0;
  }
  return r;
}

static void profile_free(rs_reel_result *r) { rs_reel_result_destroy(&r); }

static rs_defect_report *assess(const rs_reel_result *r, const rs_defect_limits *lim)
{
  rs_defect_report *rep = NULL;
  rs_defect_limits none = {0};
  CHECK(rs_defects_assess(r, lim ? lim : &none, &rep) == RS_OK);
  return rep;
}

static void hoop_no_compression(void)
{
  rs_reel_result *r = profile(50);
  r->sigma_theta[20] = 1.0;  /* least, but still tension */
  r->sigma_theta[21] = -0.0; /* a negative zero is no compression */
  rs_defect_report *rep = assess(r, NULL);
  CHECK(rep->hoop.verdict == RS_DEFECT_OK);
  CHECK(rep->hoop.layers == 0 && rep->hoop.n_ranges == 0 && rep->hoop.ranges == NULL);
  CHECK(rep->hoop.min == 0.0 && rep->hoop.min_radius == r->radius[21]);
  rs_defect_report_destroy(&rep);
  CHECK(rep == NULL);
  profile_free(r);
}

static void hoop_one_layer(void)
{
  rs_reel_result *r = profile(50);
  r->sigma_theta[17] = -3.0e4;
  rs_defect_report *rep = assess(r, NULL);
  CHECK(rep->hoop.verdict == RS_DEFECT_PRESENT);
  CHECK(rep->hoop.layers == 1 && rep->hoop.n_ranges == 1);
  CHECK(rep->hoop.ranges[0].first == 17 && rep->hoop.ranges[0].last == 17);
  CHECK(rep->hoop.ranges[0].r_first == r->radius[17] &&
        rep->hoop.ranges[0].r_last == r->radius[17]);
  CHECK(rep->hoop.min == -3.0e4 && rep->hoop.min_radius == r->radius[17]);
  rs_defect_report_destroy(&rep);
  profile_free(r);
}

/* Ranges touching both ends of the roll, and one in the middle. */
static void hoop_ranges(void)
{
  rs_reel_result *r = profile(40);
  for (int j = 0; j < 5; ++j)
    r->sigma_theta[j] = -1.0e3 * (j + 1);
  for (int j = 12; j <= 14; ++j)
    r->sigma_theta[j] = -2.0e5;
  r->sigma_theta[13] = -2.5e5;
  for (int j = 38; j < 40; ++j)
    r->sigma_theta[j] = -1.0;
  rs_defect_report *rep = assess(r, NULL);
  CHECK(rep->hoop.verdict == RS_DEFECT_PRESENT);
  CHECK(rep->hoop.layers == 10 && rep->hoop.n_ranges == 3);
  if (rep->hoop.n_ranges == 3) {
    CHECK(rep->hoop.ranges[0].first == 0 && rep->hoop.ranges[0].last == 4);
    CHECK(rep->hoop.ranges[1].first == 12 && rep->hoop.ranges[1].last == 14);
    CHECK(rep->hoop.ranges[2].first == 38 && rep->hoop.ranges[2].last == 39);
    CHECK(rep->hoop.ranges[2].r_last == r->radius[39]);
  }
  CHECK(rep->hoop.min == -2.5e5 && rep->hoop.min_radius == r->radius[13]);
  rs_defect_report_destroy(&rep);
  profile_free(r);
}

static void limits_absent(void)
{
  rs_reel_result *r = profile(30);
  rs_defect_report *rep = assess(r, NULL);
  CHECK(rep->pressure.verdict == RS_DEFECT_NOT_ASSESSED);
  CHECK(rep->slip.verdict == RS_DEFECT_NOT_ASSESSED);
  CHECK(rep->core.verdict == RS_DEFECT_NOT_ASSESSED);
  CHECK(strcmp(rs_defect_verdict_name(rep->slip.verdict), "not assessed") == 0);
  /* the figures are still reported */
  CHECK(rep->pressure.max == 2.0e5 && rep->pressure.max_radius == 0.1);
  CHECK(rep->core.pressure == 2.0e5);
  rs_defect_report_destroy(&rep);
  /* a torque without friction (or the reverse) cannot be assessed either */
  rs_defect_limits half = {.accel_torque = 10.0};
  rep = assess(r, &half);
  CHECK(rep->slip.verdict == RS_DEFECT_NOT_ASSESSED);
  rs_defect_report_destroy(&rep);
  profile_free(r);
}

static void zero_layers(void)
{
  rs_reel_result *r = profile(0);
  rs_radial_law law = {.law = RS_RADIAL_LINEAR, .E_r = 1e6};
  rs_defect_limits lim = {.pressure_limit = 1e6, .core_rating = 1e6, .accel_torque = 10.0,
                          .friction_layer = 0.3, .E_theta = 3e9, .radial = &law};
  rs_defect_report *rep = assess(r, &lim);
  CHECK(rep->hoop.verdict == RS_DEFECT_NOT_ASSESSED);
  CHECK(rep->starring.verdict == RS_DEFECT_NOT_ASSESSED);
  CHECK(rep->pressure.verdict == RS_DEFECT_NOT_ASSESSED);
  CHECK(rep->slip.verdict == RS_DEFECT_NOT_ASSESSED);
  CHECK(rep->core.verdict == RS_DEFECT_NOT_ASSESSED);
  rs_defect_report_destroy(&rep);
  profile_free(r);
}

/* Peak over the layers and the core contact; at the limit is not over it. */
static void pressure_limit(void)
{
  rs_reel_result *r = profile(30);
  r->sigma_r[7] = -4.0e5;
  rs_defect_limits lim = {.pressure_limit = 4.0e5};
  rs_defect_report *rep = assess(r, &lim);
  CHECK(rep->pressure.max == 4.0e5 && rep->pressure.max_radius == r->radius[7]);
  CHECK(rep->pressure.verdict == RS_DEFECT_OK);
  CHECK(rep->pressure.ratio == 1.0);
  rs_defect_report_destroy(&rep);
  lim.pressure_limit = 3.2e5;
  rep = assess(r, &lim);
  CHECK(rep->pressure.verdict == RS_DEFECT_RISK);
  CHECK_CLOSE(rep->pressure.ratio, 1.25, 1e-15);
  rs_defect_report_destroy(&rep);
  /* the core contact carries the most */
  r->core_pressure = 5.0e5;
  rep = assess(r, &lim);
  CHECK(rep->pressure.max == 5.0e5 && rep->pressure.max_radius == r->core_radius);
  rs_defect_report_destroy(&rep);
  profile_free(r);
}

static void core_rating(void)
{
  rs_reel_result *r = profile(10);
  rs_defect_limits lim = {.core_rating = 4.0e5};
  rs_defect_report *rep = assess(r, &lim);
  CHECK(rep->core.verdict == RS_DEFECT_OK);
  CHECK_CLOSE(rep->core.ratio, 0.5, 1e-15);
  rs_defect_report_destroy(&rep);
  lim.core_rating = 1.0e5;
  rep = assess(r, &lim);
  CHECK(rep->core.verdict == RS_DEFECT_RISK);
  CHECK_CLOSE(rep->core.ratio, 2.0, 1e-15);
  rs_defect_report_destroy(&rep);
  profile_free(r);
}

/* M_f = mu P 2 pi r^2: 0.3 * 1e5 Pa * 2 pi * (0.1 m)^2 = 600 pi N m/m. */
static void slip_capacity_formula(void)
{
  CHECK_CLOSE(rs_defect_slip_capacity(0.3, 1.0e5, 0.1), 600.0 * pi, 1e-15);
  CHECK(rs_defect_slip_capacity(0.3, 0.0, 0.1) == 0.0);
  CHECK(rs_defect_slip_capacity(0.3, -5.0, 0.1) == 0.0); /* a gap transmits nothing */
}

static void slip_one_layer(void)
{
  rs_reel_result *r = profile(1);
  rs_defect_limits lim = {.accel_torque = 1.0, .friction_layer = 0.3};
  rs_defect_report *rep = assess(r, &lim);
  CHECK(rep->slip.verdict == RS_DEFECT_NOT_ASSESSED); /* no interface between layers */
  rs_defect_report_destroy(&rep);
  profile_free(r);
}

/* sigma_cr = sqrt(E_theta E_r / 3) is Hetenyi's N_cr = 2 sqrt(k D) of a strip of unit
 * width (D = E_theta t^3 / 12) on a Winkler foundation k = E_r / t, divided by t: checked
 * against that formula evaluated directly at several calipers (the caliper cancels). */
static void buckling_critical_formula(void)
{
  const double E[][2] = {{3.5e9, 3.0e5}, {3.5e9, 6.0e7}, {4.5e9, 1.0e6}, {1.0e8, 2.0e4}};
  const double t[] = {23e-6, 70e-6, 1e-3};
  for (size_t i = 0; i < sizeof E / sizeof E[0]; ++i) {
    double sc = rs_defect_critical_hoop_stress(E[i][0], E[i][1]);
    for (size_t m = 0; m < sizeof t / sizeof t[0]; ++m) {
      double D = E[i][0] * t[m] * t[m] * t[m] / 12.0, k = E[i][1] / t[m];
      CHECK_CLOSE(sc, 2.0 * sqrt(k * D) / t[m], 1e-14);
    }
  }
  /* newsprint at zero pressure, E_r = K1 K2 = 3e5 Pa: sqrt(3.5e14) Pa */
  CHECK_CLOSE(rs_defect_critical_hoop_stress(3.5e9, 3.0e5), 18708286.933869706, 1e-15);
  CHECK(rs_defect_critical_hoop_stress(0.0, 1e6) == 0.0);
  CHECK(rs_defect_critical_hoop_stress(3e9, -1.0) == 0.0);
}

/* An independent route to the same value: a layer inside the roll, between two unloaded
 * half-stacks of identical layers joined by interface springs k = E_r / t. A mode
 * w_n = w0 alpha^|n| cos(q x) decays into each half-stack with alpha + 1/alpha =
 * 2 + D q^4 / k, so the buckling layer needs N(q) = D q^2 + 2 k (1 - alpha) / q^2. Its
 * infimum over wavelengths (q -> 0) is 2 sqrt(k D): the one-sided Winkler value. */
static void buckling_layered_stack_limit(void)
{
  const double E_theta = 3.5e9, E_r = 6.0e7, t = 70e-6;
  double D = E_theta * t * t * t / 12.0, k = E_r / t;
  double q0 = pow(k / D, 0.25); /* the Winkler half-wavenumber scale */
  double want = rs_defect_critical_hoop_stress(E_theta, E_r) * t, prev = INFINITY;
  for (double f = 1.0; f > 1e-3; f *= 0.5) {
    double q = f * q0, s = D * pow(q, 4) / k;
    double one_minus_alpha = sqrt(s + 0.25 * s * s) - 0.5 * s; /* the root alpha < 1 */
    double N = D * q * q + 2.0 * k * one_minus_alpha / (q * q);
    CHECK(N > want * (1.0 - 1e-12)); /* never below the Winkler value */
    CHECK(N <= prev);                /* falling towards it as the wave lengthens */
    prev = N;
  }
  CHECK_LOG("N(q -> 0) (N/m)", prev);
  CHECK_LOG("2 sqrt(k D) (N/m)", want);
  CHECK_CLOSE(prev, want, 1e-9);
}

static void limits_from_scene(void)
{
  const char *sets[] = {"material.pressure_limit=2.5e6", "material.friction_layer=0.35",
                        "winding.accel_torque=40", "core.rating=3e6"};
  rs_scene *sc = NULL;
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 4, sets, &sc) == RS_OK);
  if (!sc) return;
  rs_defect_limits lim;
  rs_defect_limits_from_problem(rs_scene_problem(sc), &lim);
  CHECK(lim.pressure_limit == 2.5e6 && lim.friction_layer == 0.35);
  CHECK(lim.accel_torque == 40.0 && lim.core_rating == 3e6);
  /* the starring rule's web: newsprint's E_theta and Pfeiffer law (models/newsprint.yaml) */
  CHECK(lim.E_theta == 3.5e9 && lim.radial == &rs_scene_problem(sc)->material.radial);
  CHECK(lim.radial->law == RS_RADIAL_PFEIFFER && lim.radial->K1 == 5.0e3 && lim.radial->K2 == 60);
  rs_scene_destroy(&sc);
  /* absent keys: 0, "not given" */
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 0, NULL, &sc) == RS_OK);
  if (!sc) return;
  rs_defect_limits_from_problem(rs_scene_problem(sc), &lim);
  CHECK(lim.pressure_limit == 0.0 && lim.friction_layer == 0.0);
  CHECK(lim.accel_torque == 0.0 && lim.core_rating == 0.0);
  rs_scene_destroy(&sc);
  /* refused values */
  const char *bad[][1] = {{"material.pressure_limit=0"},
                          {"core.rating=-1"},
                          {"material.friction_layer=0"},
                          {"winding.accel_torque=5"}};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 1, bad[i], &sc) == RS_ERR_INPUT);
    printf("  %s -> %s\n", bad[i][0], rs_error_message());
    rs_scene_destroy(&sc);
  }
}

static const check_case cases[] = {
    {"hoop_no_compression", hoop_no_compression},
    {"hoop_one_layer", hoop_one_layer},
    {"hoop_ranges", hoop_ranges},
    {"limits_absent", limits_absent},
    {"zero_layers", zero_layers},
    {"pressure_limit", pressure_limit},
    {"core_rating", core_rating},
    {"slip_capacity_formula", slip_capacity_formula},
    {"slip_one_layer", slip_one_layer},
    {"buckling_critical_formula", buckling_critical_formula},
    {"buckling_layered_stack_limit", buckling_layered_stack_limit},
    {"limits_from_scene", limits_from_scene},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
