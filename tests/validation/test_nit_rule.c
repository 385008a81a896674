/* The nip-induced tension of the shipped newsprint model (models/newsprint.yaml) on a
 * center winder with an undriven rider, against the measured rule
 *   NIT = T0 - Ti ~ mu N   below about 2000 N/m,
 * proportional to the nip load N (N/m) with the interlayer friction coefficient mu as the
 * slope at low load, levelling off (becoming independent of the load) at high load: Good,
 * Wu & Fikes (1994) for newsprint, and the wound-in-tension measurements of Good and
 * co-workers on film and paper summarised by Balaji & Good ("Wound-in-tension in a
 * non-woven web"). Checked (docs/nip.md, "NIT = mu N"; docs/validation.md, "Nip"):
 *  - NIT within 10 % of mu N at six loads up to 1000 N/m, mid-roll and near full roll;
 *  - the slope dNIT/dN within 10 % of mu at the lowest loads, the secant slopes falling
 *    with load, and below mu/2 between 16 and 25 kN/m (levelling off), NIT still rising;
 *  - the contrast the rule decides: with G_rtheta = E_r-level (2 MPa, the contact nip's
 *    former default) the same stack falls below 0.9 mu N at 1000 N/m;
 *  - a material without G_rtheta is refused by the contact nip (exit 2, naming the key).
 * The scene is loaded and the nip solved at a radius as `reelsim nip SCENE --radius R`. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "nip/nip_contact.h"
#include "reelsim/scene.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

#define SCENE RS_TESTS_DIR "/validation/scenes/nit-newsprint-rider.yaml"

/* NIT (N/m) at roll radius R for each load; one handle, solved in load order. Returns
 * the scene's mu_roll, or 0 on failure. */
static double nit_curve(const char *const *sets, int n_sets, double R, const double *loads,
                        int n, double *nit)
{
  rs_scene *sc = NULL;
  rs_nip_contact *nc = NULL;
  double mu = 0;
  rs_status st = rs_scene_load(SCENE, n_sets, sets, &sc);
  if (st == RS_OK) st = rs_nip_contact_create_from_spec(&rs_scene_problem(sc)->nip, &rs_scene_problem(sc)->material, &nc);
  for (int i = 0; st == RS_OK && i < n; ++i) {
    rs_nip_state ns = {R, rs_scene_problem(sc)->core.radius, rs_recipe_eval(&rs_scene_problem(sc)->tension, R), loads[i], 0, 0};
    ns.surface_modulus = rs_radial_modulus(&rs_scene_problem(sc)->material.radial, 0.0);
    rs_nip_solution sol = {0};
    st = rs_nip_contact_solve_state(nc, &ns, &sol);
    if (st == RS_OK) nit[i] = sol.T0 - sol.Ti;
    rs_nip_solution_free(&sol);
  }
  if (st != RS_OK) printf("  error: %s\n", rs_error_message());
  CHECK(st == RS_OK);
  if (st == RS_OK) mu = rs_scene_problem(sc)->nip.mu_roll;
  rs_nip_contact_destroy(&nc);
  rs_scene_destroy(&sc);
  return mu;
}

/* NIT / (mu N) within 10 % of 1 for N up to 1000 N/m, at mid-roll and near full roll. */
static void nit_equals_mu_n(void)
{
  const double loads[] = {100, 200, 400, 600, 800, 1000}, radii[] = {0.15, 0.4};
  for (int k = 0; k < 2; ++k) {
    double nit[6], worst = 0;
    double mu = nit_curve(NULL, 0, radii[k], loads, 6, nit);
    if (!(mu > 0)) return;
    for (int i = 0; i < 6; ++i) {
      double f = nit[i] / (mu * loads[i]);
      printf("  R = %-5g m  N = %-5g N/m  NIT = %-10.5g N/m  mu N = %-8.5g  NIT/(mu N) = %.4f\n",
             radii[k], loads[i], nit[i], mu * loads[i], f);
      worst = fmax(worst, fabs(f - 1));
    }
    CHECK_LOG("worst |NIT/(mu N) - 1|, N <= 1000 N/m", worst);
    CHECK_LT(worst, 0.10);
  }
}

/* Slope ~mu at low load, secant slopes falling, below mu/2 at high load, NIT rising. */
static void levelling_at_high_load(void)
{
  const double loads[] = {100, 200, 1000, 2000, 5000, 10000, 16000, 25000};
  enum { N = 8 };
  double nit[N];
  double mu = nit_curve(NULL, 0, 0.15, loads, N, nit);
  if (!(mu > 0)) return;
  double prev = INFINITY;
  for (int i = 1; i < N; ++i) {
    double slope = (nit[i] - nit[i - 1]) / (loads[i] - loads[i - 1]);
    printf("  N %5g .. %5g N/m: NIT %8.2f .. %8.2f N/m, secant slope / mu = %.4f\n",
           loads[i - 1], loads[i], nit[i - 1], nit[i], slope / mu);
    if (i == 1) {
      CHECK_LOG("low-load slope / mu", slope / mu);
      CHECK_CLOSE(slope, mu, 0.10);
    }
    if (i == N - 1) {
      CHECK_LOG("high-load slope / mu (16 .. 25 kN/m)", slope / mu);
      CHECK_LT(slope, 0.5 * mu);
    }
    CHECK(slope > 0);    /* NIT still rises: it levels off, it does not fall */
    CHECK_LT(slope, prev); /* and rises ever more slowly */
    prev = slope;
  }
}

/* The rule discriminates: a shear-soft stack (G_rtheta ~ E_r under the nip, 2 MPa; the
 * contact nip's default before G_rtheta was required) falls below 0.9 mu N at 1000 N/m. */
static void shear_soft_stack_misses_rule(void)
{
  const char *sets[] = {"material.G_rtheta=2e6"};
  const double load = 1000;
  double nit;
  double mu = nit_curve(sets, 1, 0.15, &load, 1, &nit);
  if (!(mu > 0)) return;
  CHECK_LOG("NIT/(mu N) at 1000 N/m, G_rtheta 2 MPa", nit / (mu * load));
  CHECK_LT(nit / (mu * load), 0.9);
}

/* A material without G_rtheta: the contact nip refuses it, naming the key (exit 2). */
static void refused_without_g_rtheta(void)
{
  static const char text[] =
      "material: {caliper: 70.0e-6, E_theta: 3.5e9, radial: {law: pfeiffer, K1: 5.0e3, K2: 60}}\n"
      "core: {radius: 0.0762}\n"
      "winding: {final_radius: 0.2, tension: 350}\n"
      "nip: {model: contact, load: 1000, winder: center, friction: {roll: 0.19, drum: 0.35},\n"
      "      drum: {radius: 0.3, core_radius: 0.05, E: 2.1e11, nu: 0.3}}\n";
  rs_scene *sc = NULL;
  rs_nip_contact *nc = NULL;
  rs_status st = rs_scene_load_text("no-g.yaml", text, strlen(text), 0, NULL, &sc);
  CHECK(st == RS_OK);
  if (st != RS_OK) return;
  st = rs_nip_contact_create_from_spec(&rs_scene_problem(sc)->nip, &rs_scene_problem(sc)->material, &nc);
  printf("  message: %s\n", rs_error_message());
  CHECK(st == RS_ERR_INPUT);
  CHECK(rs_status_exit_code(st) == 2);
  CHECK(strstr(rs_error_message(), "material.G_rtheta") != NULL);
  CHECK(nc == NULL);
  rs_nip *nip = NULL; /* the reel's seam refuses it alike */
  st = rs_nip_create(&rs_scene_problem(sc)->nip, &rs_scene_problem(sc)->material, &nip);
  CHECK(st == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "material.G_rtheta") != NULL);
  rs_nip_destroy(&nip);
  rs_scene_destroy(&sc);
}

static const check_case cases[] = {
    {"nit_equals_mu_n", nit_equals_mu_n},
    {"levelling_at_high_load", levelling_at_high_load},
    {"shear_soft_stack_misses_rule", shear_soft_stack_misses_rule},
    {"refused_without_g_rtheta", refused_without_g_rtheta},
};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
