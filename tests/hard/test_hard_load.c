/* Hard cases for the roll build-up engine, tensions, laws and failures: scenes at the edges
 * of its physics and numerics, each with a stated expectation that does not come from the
 * engine itself (docs/robustness.md has the table with the measured values; stiffness and
 * size at their extremes: test_hard.c).
 *
 *   tension_scaling_linear     T from 1e-9 to 1e6 N/m: sigma/T the same (linear law)
 *   tension_limits_pfeiffer    T -> 0: the linear law of modulus K1 K2; T huge: bounds
 *   taper_through_zero         the loader refuses T < 0; a taper ending at exactly 0 runs
 *   hakiel_vs_table            a strongly varying Hakiel law = its dense table
 *   table_steep                E_r over 5 decades in a table: bounds, rtol convergence
 *   equilibrium_increment      sigma_theta = d(r sigma_r)/dr, one increment, 4th-order FD
 *   failure_keeps_finished     a failing run keeps the finished layers, bit for bit
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "roll/roll.h"
#include "reelsim/scene.h"
#include "roll_helpers.h"
#include "hard/hard_roll.h"


/* ---- tension: near zero, very high ----------------------------------------------------------- */

/* A linear law is linear in T: sigma(T)/T is the same for every T (the engine's Riccati
 * solution does not see T at all). Identity checked to 1e-12 from 1e-9 to 1e6 N/m. */
static void tension_scaling_linear(void)
{
  const double Ts[] = {1e-9, 1e-3, 1.0, 1e3, 1e6};
  const int n = 400;
  rs_roll_params p = linear_params(0.0762, 70e-6, 3.5e9, 20e6, 1e9, n);
  p.rtol = 1e-6;
  p.atol = 0;
  rs_roll *ref = wind(&p, n, 1, 1.0);
  if (!ref) return;
  for (size_t i = 0; i < sizeof Ts / sizeof Ts[0]; ++i) {
    rs_roll *roll = wind(&p, n, 1, Ts[i]);
    if (!roll) return;
    double worst = 0.0;
    for (int j = 0; j < n; ++j) {
      worst = fmax(worst, fabs(rs_roll_sigma_r(roll)[j] / Ts[i] - rs_roll_sigma_r(ref)[j]) /
                              fabs(rs_roll_sigma_r(ref)[j]));
      worst = fmax(worst, fabs(rs_roll_sigma_theta(roll)[j] / Ts[i] -
                               rs_roll_sigma_theta(ref)[j]) / (1.0 / 70e-6));
    }
    printf("  T %-8g core pressure / T %.17g   max |sigma/T - ref| %.3g\n", Ts[i],
           rs_roll_core_pressure(roll) / Ts[i], worst);
    CHECK_CLOSE(rs_roll_core_pressure(roll) / Ts[i], rs_roll_core_pressure(ref), 1e-12);
    CHECK_LT(worst, 1e-12);
    rs_roll_destroy(&roll);
  }
  rs_roll_destroy(&ref);
}

/* Pfeiffer: as T -> 0 every pressure is << K1, so E_r -> K1 K2 and the roll is the linear
 * one of that modulus (Altmann); the relative difference is O(P_max/K1). At T = 1e-4 N/m
 * it is checked against Altmann to 1e-5. At T = 1e5 N/m the pressures reach hundreds of
 * MPa and E_r exceeds E_theta near the core (g < 1: the increments grow inwards): finite,
 * the bounds that still hold (no upper one), and more pressure than the rest-modulus roll. */
static void tension_limits_pfeiffer(void)
{
  const double rc = 0.0762, t = 70e-6, Et = 3.5e9, K1 = 5e3, K2 = 60.0;
  const int n = 600;
  rs_roll_params p = pfeiffer_params(rc, t, Et, K1, K2, INFINITY, n);
  p.rtol = 1e-10;
  p.atol = 0;
  rs_roll *low = wind(&p, n, 1, 1e-4);
  if (!low) return;
  double *sr = malloc(n * sizeof(double)), *st = malloc(n * sizeof(double)), core;
  altmann_roll(sqrt(Et / (K1 * K2)), -1.0, rc, t, n, 1e-4, sr, st, &core, p.placement);
  double worst = 0.0;
  for (int j = 0; j < n; ++j)
    worst = fmax(worst, fabs(rs_roll_sigma_r(low)[j] - sr[j]) / fabs(sr[j]));
  CHECK_LOG("T = 1e-4: max P / K1", -rs_roll_sigma_r(low)[0] / K1);
  CHECK_LOG("T = 1e-4: max rel diff from linear (K1 K2)", worst);
  CHECK_LT(worst, 1e-5);
  CHECK_CLOSE(rs_roll_core_pressure(low), core, 1e-5);
  rs_roll_destroy(&low);

  p.rtol = 1e-6;
  rs_roll *high = wind(&p, n, 1, 1e5);
  if (!high) return;
  CHECK(all_finite(high));
  CHECK_LOG("T = 1e5: core pressure (Pa)", rs_roll_core_pressure(high));
  CHECK_LOG("T = 1e5: core pressure / sum T/s", check_bounds(high, &p, 1e5, 0));
  double E_core = rs_radial_modulus(&p.radial, rs_roll_core_pressure(high));
  CHECK_LOG("T = 1e5: g at the core", sqrt(Et / E_core));
  /* stiffer under pressure than at rest: more pressure than the rest-modulus roll */
  CHECK_LT(core * 1e9, rs_roll_core_pressure(high));
  free(sr);
  free(st);
  rs_roll_destroy(&high);
}

/* ---- tension tapers through zero (scene level) -------------------------------------------- */

static const char taper_scene[] =
    "material: {caliper: 100.0e-6, E_theta: 4.0e9, radial: {law: linear, E_r: 20.0e6}}\n"
    "core: {radius: 0.05}\n"
    "winding: {final_radius: %s, tension: %s}\n";

static rs_status load_taper(const char *radius, const char *tension, rs_scene **out)
{
  char text[512];
  snprintf(text, sizeof text, taper_scene, radius, tension);
  return rs_scene_load_text("taper.yaml", text, strlen(text), 0, NULL, out);
}

/* The loader refuses a taper that makes T negative anywhere on the roll (exit 2, naming
 * where); one that ends at exactly 0 runs, also when the rounded layer count puts the last
 * layer beyond the final radius (recipes hold their end value there), and the last layer
 * then carries nothing: sigma_r = sigma_theta = 0 exactly. */
static void taper_through_zero(void)
{
  static const char *const refused[] = {"{law: linear, start: 200, end: -50}",
                                        "{law: linear, start: 200, end: -1.0e-9}",
                                        "{law: hyperbolic, start: 200, end: -10}",
                                        "{law: hyperbolic, start: 200, k: 5}",
                                        "{table: [[0.05, 200], [0.06, 0], [0.07, -1]]}"};
  static const char *const zero[] = {"{law: linear, start: 200, end: 0}",
                                     "{law: hyperbolic, start: 200, end: 0}",
                                     "{table: [[0.05, 200], [0.07, 0]]}"};
  static const char *const radii[] = {"0.07", "0.07004", "0.06996"}; /* N t =, <, > r1 - rc */
  rs_scene *sc = NULL;
  for (size_t i = 0; i < sizeof refused / sizeof refused[0]; ++i) {
    rs_status st = load_taper("0.07", refused[i], &sc);
    printf("  %s -> %s: %s\n", refused[i], rs_status_name(st), rs_error_message());
    CHECK(st == RS_ERR_INPUT && sc == NULL);
    CHECK(strstr(rs_error_message(), "winding.tension") != NULL);
    rs_scene_destroy(&sc);
  }
  for (size_t i = 0; i < sizeof zero / sizeof zero[0]; ++i)
    for (size_t k = 0; k < sizeof radii / sizeof radii[0]; ++k) {
      rs_status st = load_taper(radii[k], zero[i], &sc);
      if (st != RS_OK) printf("  %s\n", rs_error_message());
      CHECK(st == RS_OK);
      if (st != RS_OK) continue;
      rs_reel_result *res = NULL;
      st = rs_scene_wind(sc, NULL, &res);
      if (st != RS_OK) printf("  %s\n", rs_error_message());
      CHECK(st == RS_OK);
      int n = res->n_layers;
      printf("  %s, final radius %s: %d layers, last T0 %.17g, core pressure %.17g\n", zero[i],
             radii[k], n, res->wound_on_tension[n - 1], res->core_pressure);
      CHECK(n == rs_scene_problem(sc)->n_layers);
      if (res->radius[n - 1] >= rs_scene_problem(sc)->final_radius) {
        /* at or beyond r1 the taper's end value 0 holds */
        CHECK(res->wound_on_tension[n - 1] == 0.0);
        CHECK(res->sigma_r[n - 1] == 0.0 && res->sigma_theta[n - 1] == 0.0);
      }
      for (int j = 0; j < n; ++j) CHECK(res->wound_on_tension[j] >= 0.0);
      rs_reel_result_destroy(&res);
      rs_scene_destroy(&sc);
    }
}

/* ---- strongly varying laws ------------------------------------------------------------------ */

/* Hakiel E_r = 2e4 + 40 P + 1e-4 P^2 (Pa): 2e4 Pa at rest, ~1e8 Pa at 1 MPa (g^2 from 1.75e5
 * to ~35). The same law as a dense table (256 points, monotone cubic) is another code path
 * for the same function; the rolls agree to the table's interpolation error (< 1e-3). */
static void hakiel_vs_table(void)
{
  const int n = 800;
  rs_roll_params p = hakiel_params(0.0762, 70e-6, 3.5e9, 2e4, 40.0, 1e-4, INFINITY, n);
  p.rtol = 1e-8;
  p.atol = 0;
  rs_roll *hk = wind(&p, n, 1, 400.0);
  if (!hk) return;
  CHECK(all_finite(hk));
  check_bounds(hk, &p, 400.0, 1);
  double Pmax = -rs_roll_sigma_r(hk)[0] * 4.0;
  rs_roll_params q = p;
  q.radial.law = RS_RADIAL_TABLE;
  q.radial.n_points = RS_TABLE_MAX;
  for (int i = 0; i < RS_TABLE_MAX; ++i) {
    /* points dense where E_r changes fastest in relative terms (low P) */
    double P = Pmax * pow((double)i / (RS_TABLE_MAX - 1), 2.0);
    q.radial.P[i] = P;
    q.radial.E[i] = rs_radial_modulus(&p.radial, P);
  }
  CHECK(rs_radial_law_prepare(&q.radial) == RS_OK);
  rs_roll *tb = wind(&q, n, 1, 400.0);
  if (!tb) return;
  double d = profile_diff(tb, hk);
  CHECK_LOG("E_r at rest / at the core pressure",
            rs_radial_modulus(&p.radial, 0) /
                rs_radial_modulus(&p.radial, rs_roll_core_pressure(hk)));
  CHECK_LOG("core pressure, hakiel (Pa)", rs_roll_core_pressure(hk));
  CHECK_LOG("core pressure, table (Pa)", rs_roll_core_pressure(tb));
  CHECK_LOG("max |sigma_r diff| / max|sigma_r|", d);
  CHECK_LT(d, 1e-3);
  CHECK_CLOSE(rs_roll_core_pressure(tb), rs_roll_core_pressure(hk), 1e-3);
  rs_roll_destroy(&tb);
  rs_roll_destroy(&hk);
}

/* A table whose E_r climbs five decades (1e4 -> 1e9 Pa) over 0..2 MPa in 6 points, with
 * a steep step in the middle. Bounds, finite, convergence in rtol (1e-5, 1e-7 vs 1e-10). */
static void table_steep(void)
{
  const int n = 1000;
  const double P[] = {0, 1e3, 1e4, 1.1e4, 1e5, 2e6}, E[] = {1e4, 3e4, 1e6, 1e8, 3e8, 1e9};
  rs_roll_params p = linear_params(0.0762, 70e-6, 3.5e9, 1.0, 2e9, n);
  p.radial.law = RS_RADIAL_TABLE;
  p.radial.n_points = 6;
  memcpy(p.radial.P, P, sizeof P);
  memcpy(p.radial.E, E, sizeof E);
  CHECK(rs_radial_law_prepare(&p.radial) == RS_OK);
  p.rtol = 1e-10;
  p.atol = 0;
  rs_roll *ref = wind(&p, n, 1, 300.0);
  if (!ref) return;
  CHECK(all_finite(ref));
  CHECK_LOG("core pressure (Pa)", rs_roll_core_pressure(ref));
  CHECK_LOG("core pressure / sum T/s", check_bounds(ref, &p, 300.0, 1));
  const double rtols[2] = {1e-5, 1e-7};
  converges_in_rtol(&p, n, 300.0, rtols, ref);
  rs_roll_destroy(&ref);
}

/* ---- equilibrium --------------------------------------------------------------------------- */

/* sigma_theta = d(r sigma_r)/dr holds for each increment exactly (the hoop increment is
 * ds + r ds'). Checked from outside: the change of both profiles when one layer is wound
 * onto a 2000-layer Pfeiffer film roll, d(r dsr)/dr by the 4th-order central difference
 * over the layer nodes (error ~ (g t/r)^4 / 30 < 1e-10 here), at the interior nodes where
 * the frozen E_r is smooth on the stencil (within 1%: not the outermost layers, where the
 * Pfeiffer modulus changes at layer scale and so does ds); tolerance 1e-8 of
 * max |d sigma_theta| (the engine runs at rtol 1e-10). The accumulated
 * profile does not obey it at layer scale: each layer adds its own -T/s and T/t where it
 * is born, a jump the finite difference sees (docs/robustness.md). The point values at the
 * nodes are Hakiel's accounting; with the default placement the engine reports each
 * layer's mean hoop stress, built from this same equilibrium over the turn and checked
 * against the exact turn-by-turn statics (tests/validation/test_ring_statics.c). */
static void equilibrium_increment(void)
{
  const int n = 2000;
  const double t = 12e-6, T = 120.0;
  rs_roll_params p = pfeiffer_params(0.0762, t, 4.5e9, 3e3, 80.0, 3e9, n + 1);
  p.rtol = 1e-10;
  p.atol = 0;
  p.placement = RS_LOAD_HAKIEL;
  rs_roll *roll = wind(&p, n, 1, T);
  if (!roll) return;
  double *sr0 = malloc(n * sizeof(double)), *st0 = malloc(n * sizeof(double));
  memcpy(sr0, rs_roll_sigma_r(roll), n * sizeof(double));
  memcpy(st0, rs_roll_sigma_theta(roll), n * sizeof(double));
  double one = T;
  CHECK(rs_roll_add_layers(roll, 1, &one) == RS_OK);
  const double *sr = rs_roll_sigma_r(roll), *st = rs_roll_sigma_theta(roll);
  double scale = 0.0, worst = 0.0;
  int checked = 0;
  for (int j = 0; j < n; ++j) scale = fmax(scale, fabs(st[j] - st0[j]));
  for (int j = 2; j < n - 2; ++j) {
    /* only where the frozen modulus is smooth on the stencil (E_r within 1%) */
    double lo = INFINITY, hi = 0.0, f[5];
    for (int d = -2; d <= 2; ++d) {
      double E = rs_radial_modulus(&p.radial, -sr0[j + d]);
      lo = fmin(lo, E);
      hi = fmax(hi, E);
      f[d + 2] = rs_roll_layer_radius(roll, j + d) * (sr[j + d] - sr0[j + d]);
    }
    if (hi > 1.01 * lo) continue;
    ++checked;
    double deriv = (-f[4] + 8.0 * f[3] - 8.0 * f[1] + f[0]) / (12.0 * t);
    worst = fmax(worst, fabs(deriv - (st[j] - st0[j])));
  }
  CHECK_LOG("nodes checked (E_r within 1% on the stencil)", checked);
  CHECK_LT(0.8 * n, checked);
  CHECK_LOG("g at the surface", sqrt(4.5e9 / rs_radial_modulus(&p.radial, -sr0[n - 1])));
  CHECK_LOG("max |d sigma_theta| of the increment (Pa)", scale);
  CHECK_LOG("max |FD d(r ds)/dr - d sigma_theta| / max", worst / scale);
  CHECK_LT(worst / scale, 1e-8);
  free(sr0);
  free(st0);
  rs_roll_destroy(&roll);
}

/* ---- failure ------------------------------------------------------------------------------- */

/* A Hakiel law whose E_r = 1e6 - P^2 turns negative above 1 kPa stops the run with
 * RS_ERR_SOLVER naming the radius and the pressure; the result keeps the layers finished,
 * and they are bit for bit those of a roll wound to exactly that many layers. */
static void failure_keeps_finished(void)
{
  static const char scene[] =
      "material:\n"
      "  caliper: 100.0e-6\n"
      "  E_theta: 4.0e9\n"
      "  radial: {law: hakiel, C: [1.0e6, 0, -1.0]}\n"
      "core: {radius: 0.05}\n"
      "winding: {final_radius: %s, tension: 8}\n";
  char text[512];
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL, *again = NULL;
  snprintf(text, sizeof text, scene, "0.07");
  CHECK(rs_scene_load_text("fail.yaml", text, strlen(text), 0, NULL, &sc) == RS_OK);
  if (!sc) return;
  rs_status st = rs_scene_wind(sc, NULL, &res);
  printf("  %s\n  (at %s)\n", rs_error_message(), rs_error_where());
  CHECK(st == RS_ERR_SOLVER);
  CHECK(strstr(rs_error_message(), "is not positive") != NULL);
  CHECK(strstr(rs_error_message(), "pressure") != NULL);
  CHECK(strstr(rs_error_message(), "r = ") != NULL);
  CHECK(res != NULL);
  if (!res) return;
  int k = res->n_layers;
  CHECK_LOG("layers finished", k);
  CHECK(k > 0 && k < rs_scene_problem(sc)->n_layers);
  rs_scene_destroy(&sc);

  char radius[64];
  snprintf(radius, sizeof radius, "%.17g", 0.05 + k * 100.0e-6);
  snprintf(text, sizeof text, scene, radius);
  CHECK(rs_scene_load_text("fail.yaml", text, strlen(text), 0, NULL, &sc) == RS_OK);
  if (!sc) return;
  CHECK(rs_scene_problem(sc)->n_layers == k);
  CHECK(rs_scene_wind(sc, NULL, &again) == RS_OK);
  CHECK(again->n_layers == k);
  CHECK(memcmp(res->sigma_r, again->sigma_r, (size_t)k * sizeof(double)) == 0);
  CHECK(memcmp(res->sigma_theta, again->sigma_theta, (size_t)k * sizeof(double)) == 0);
  CHECK(res->core_pressure == again->core_pressure);
  rs_reel_result_destroy(&again);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

static const check_case cases[] = {
    {"tension_scaling_linear", tension_scaling_linear},
    {"tension_limits_pfeiffer", tension_limits_pfeiffer},
    {"taper_through_zero", taper_through_zero},
    {"hakiel_vs_table", hakiel_vs_table},
    {"table_steep", table_steep},
    {"equilibrium_increment", equilibrium_increment},
    {"failure_keeps_finished", failure_keeps_finished},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
