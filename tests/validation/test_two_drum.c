/* The two-drum winder and the nip list (docs/nip.md, "Two-drum winders"), checked by hand:
 *  - statics: equal drums N = (W' + Q) / (2 cos theta), sin theta = (c/2)/(R + R_d); unequal
 *    drums against Lami's theorem (a route independent of the code's force balance);
 *  - a wound roll: every nip solve's T0 = Ti + mu (N_front + N_rear + Q), the loads from the
 *    hand statics at the solve's radius and the roll's weight rho g pi (R^2 - r_c^2);
 *  - the saturation: T0 = Ti + sum min(mu N_k, S), capped near the core and not at the end;
 *  - a list of one nip winds bit for bit as the same nip written as a mapping (friction
 *    and contact models);
 *  - the scene's refusals, each naming its key. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/winder.h"
#include "reelsim/defects.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

static const double pi = 3.14159265358979323846;

#define MATERIAL                                                                           \
  "material: {caliper: 70.0e-6, E_theta: 3.5e9, G_rtheta: 50.0e6, density: 640,%s radial: " \
  "{law: pfeiffer, K1: 5.0e3, K2: 60}}\n"                                                   \
  "core: {radius: 0.0762, stiffness: 1.0e9}\n"                                              \
  "winding: {final_radius: 0.12, tension: 350}\n"

static const char *two_drum_nips =
    "winder: {type: two_drum, drum_distance: 1.05, drum_radius: 0.5}\n"
    "nip:\n"
    "  - {position: rear, model: friction, friction: {roll: 0.19}, update: every}\n"
    "  - {position: front, model: friction, friction: {roll: 0.19}}\n"
    "  - {position: rider, model: friction, load: {law: linear, start: 1500, end: 300},\n"
    "     friction: {roll: 0.19}}\n";

static rs_scene *load(const char *extra_material, const char *nips, int n_sets, const char **sets)
{
  char text[4096];
  snprintf(text, sizeof text, MATERIAL "%s", extra_material, nips);
  rs_scene *s = NULL;
  rs_status st = rs_scene_load_text("two-drum.yaml", text, strlen(text), n_sets, sets, &s);
  if (st != RS_OK) printf("  load: %s\n", rs_error_message());
  return s;
}

static rs_reel_result *wind(const rs_scene *s)
{
  rs_reel_result *res = NULL;
  if (!s) return NULL;
  rs_status st = rs_scene_wind(s, NULL, &res);
  if (st != RS_OK) printf("  wind: %s\n", rs_error_message());
  CHECK(st == RS_OK);
  return res;
}

/* equal drums of radius Rd, centres c apart: each carries V / (2 cos theta) */
static double hand_drum_load(double R, double Rd, double c, double V)
{
  const double s = (c / 2.0) / (R + Rd);
  return V / (2.0 * sqrt(1.0 - s * s));
}

static void statics_by_hand(void)
{
  double Nf, Nr, ang;
  /* equal drums: the formula */
  const double R = 0.4, Rd = 0.5, c = 1.05, V = 5000.0;
  CHECK(rs_winder_drum_loads(R, Rd, Rd, c, V, &Nf, &Nr, &ang) == RS_OK);
  CHECK_CLOSE(Nf, hand_drum_load(R, Rd, c, V), 1e-14);
  CHECK_CLOSE(Nr, Nf, 1e-14);
  CHECK_CLOSE(ang, asin(0.525 / 0.9) * 180.0 / pi, 1e-13);
  CHECK_LOG("N per drum, R 0.4 m, V 5000 N/m", Nf);
  /* unequal drums against Lami's theorem: with the normals at alpha_f, alpha_r above the
   * horizontal (law of cosines in the triangle of the three centres),
   * N_f = V cos(alpha_r) / sin(alpha_f + alpha_r), N_r = V cos(alpha_f) / sin(...) */
  const double Rf = 0.3, Rr = 0.6, cc = 1.0, Lf = R + Rf, Lr = R + Rr;
  const double af = acos((Lf * Lf + cc * cc - Lr * Lr) / (2.0 * Lf * cc));
  const double ar = acos((Lr * Lr + cc * cc - Lf * Lf) / (2.0 * Lr * cc));
  CHECK(rs_winder_drum_loads(R, Rf, Rr, cc, V, &Nf, &Nr, NULL) == RS_OK);
  CHECK_CLOSE(Nf, V * cos(ar) / sin(af + ar), 1e-13);
  CHECK_CLOSE(Nr, V * cos(af) / sin(af + ar), 1e-13);
  CHECK_LOG("N front, unequal drums", Nf);
  CHECK_LOG("N rear, unequal drums", Nr);
  /* the roll's weight per width */
  CHECK_CLOSE(rs_winder_roll_weight(640.0, 0.5, 0.0762), 640.0 * 9.80665 * pi * (0.25 - 0.0762 * 0.0762),
              1e-15);
  /* a roll that falls between the drums, and one whose centre lies beyond a drum's */
  CHECK(rs_winder_drum_loads(0.01, 0.5, 0.5, 1.05, V, &Nf, &Nr, NULL) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "falls between") != NULL);
  CHECK(rs_winder_drum_loads(0.05, 0.05, 2.0, 2.0, V, &Nf, &Nr, NULL) == RS_ERR_INPUT);
}

/* Every solve of the wound roll against the hand statics; cap 0: none. Returns the solves
 * whose drum (n_cap[0]) or rider (n_cap[1]) NIT was capped. */
static void check_run(double cap, int n_cap[2])
{
  char extra[64] = "";
  if (cap > 0.0) snprintf(extra, sizeof extra, " nit_saturation: %g,", cap);
  rs_scene *s = load(extra, two_drum_nips, 0, NULL);
  CHECK(s != NULL);
  rs_reel_result *res = wind(s);
  n_cap[0] = n_cap[1] = 0;
  if (res) {
    const double rc = 0.0762, r1 = 0.12, mu = 0.19;
    double worst = 0.0, worst_load = 0.0;
    CHECK(res->n_nip == res->n_layers); /* update: every */
    for (int k = 0; k < res->n_nip; ++k) {
      const double R = res->nip_radius[k];
      const double Q = 1500.0 + (300.0 - 1500.0) * (R - rc) / (r1 - rc);
      const double W = 640.0 * 9.80665 * pi * (R * R - rc * rc);
      const double N = hand_drum_load(R, 0.5, 1.05, W + Q);
      double nd = mu * N, nq = mu * Q;
      if (cap > 0.0 && nd > cap) nd = cap, n_cap[0]++;
      if (cap > 0.0 && nq > cap) nq = cap, n_cap[1]++;
      const double T0 = res->nip_Ti[k] + 2.0 * nd + nq;
      worst = fmax(worst, fabs(res->nip_T0[k] - T0) / T0);
      worst_load = fmax(worst_load, fabs(res->nip_solve_load[k] - (2.0 * N + Q)) / (2.0 * N + Q));
    }
    CHECK_LOG("solves", res->n_nip);
    CHECK_LOG("T0 at the core", res->nip_T0[0]);
    CHECK_LOG("T0 at the end", res->nip_T0[res->n_nip - 1]);
    CHECK_LOG("max rel T0 error against the hand statics", worst);
    CHECK_LOG("max rel total load error", worst_load);
    CHECK_LT(worst, 1e-13);
    CHECK_LT(worst_load, 1e-13);
    /* the layers got the solves' T0 (update every layer) */
    for (int j = 0; j < res->n_layers; ++j) CHECK(res->wound_on_tension[j] == res->nip_T0[j]);
  }
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&s);
}

static void weight_shared(void)
{
  int n_cap[2];
  check_run(0.0, n_cap);
}

static void saturation_caps(void)
{
  int n_cap[2];
  check_run(200.0, n_cap); /* mu N of a drum 346 -> 84 N/m, of the rider 285 -> 57 N/m */
  CHECK_LOG("solves with the drums capped", n_cap[0]);
  CHECK_LOG("solves with the rider capped", n_cap[1]);
  CHECK(n_cap[0] > 0 && n_cap[1] > 0); /* the cap binds near the core ... */
  CHECK(n_cap[0] < 626 && n_cap[1] < 626); /* ... and not at the end */
}

/* The same nip as a mapping and as a list of one: the same bits. */
static void same_bits(const char *nip_fields)
{
  char map[1024], list[1024];
  snprintf(map, sizeof map, "nip: {%s}\n", nip_fields);
  snprintf(list, sizeof list, "nip:\n  - {%s}\n", nip_fields);
  rs_scene *a = load("", map, 0, NULL), *b = load("", list, 0, NULL);
  rs_reel_result *ra = wind(a), *rb = wind(b);
  CHECK(ra && rb);
  if (ra && rb) {
    const int n = ra->n_layers;
    CHECK(rb->n_layers == n);
    CHECK(ra->n_nip == rb->n_nip && ra->n_nip > 0);
    const size_t sz = (size_t)n * sizeof(double);
    CHECK(memcmp(ra->wound_on_tension, rb->wound_on_tension, sz) == 0);
    CHECK(memcmp(ra->nip_load, rb->nip_load, sz) == 0);
    CHECK(memcmp(ra->sigma_r, rb->sigma_r, sz) == 0);
    CHECK(memcmp(ra->sigma_theta, rb->sigma_theta, sz) == 0);
    CHECK_LOG("layers", n);
    CHECK_LOG("nip solves", ra->n_nip);
    CHECK_LOG("T0 of the last layer", ra->wound_on_tension[n - 1]);
  }
  rs_reel_result_destroy(&ra);
  rs_reel_result_destroy(&rb);
  rs_scene_destroy(&a);
  rs_scene_destroy(&b);
}

static void one_nip_list_bit_for_bit(void)
{
  same_bits("model: friction, load: {law: linear, start: 1750, end: 500}, friction: {roll: 0.19}");
  same_bits("model: contact, load: 1750, friction: {roll: 0.19, drum: 0.35}, nodes: 24, "
            "drum: {radius: 0.3, core_radius: 0.25, E: 2.0e11, nu: 0.3}");
}

static void refused(const char *extra, const char *nips, int n_sets, const char **sets,
                    const char *needle)
{
  char text[4096];
  snprintf(text, sizeof text, MATERIAL "%s", extra, nips);
  rs_scene *s = NULL;
  rs_status st = rs_scene_load_text("two-drum.yaml", text, strlen(text), n_sets, sets, &s);
  printf("  %s\n", st == RS_OK ? "(loaded)" : rs_error_message());
  CHECK(st == RS_ERR_INPUT);
  if (st != RS_OK) CHECK(strstr(rs_error_message(), needle) != NULL);
  rs_scene_destroy(&s);
}

static void scene_checks(void)
{
  /* a two-drum winder needs the list */
  refused("", "winder: two_drum\nnip: {model: friction, load: 100, friction: {roll: 0.2}}\n", 0,
          NULL, "winder: a two-drum winder needs nip: as a list");
  /* the roll's weight needs the density */
  const char *no_density[] = {"material.density=null"};
  refused("", two_drum_nips, 1, no_density, "material.density: required by winder two_drum");
  /* drums too far apart for the core: 2 r_c + 2 R_d = 1.1524 m < 1.2 m */
  const char *far[] = {"winder.drum_distance=1.2"};
  refused("", two_drum_nips, 1, far, "winder.drum_distance=1.2: winder: a roll of radius 0.0762 m falls between");
  /* a drum's load comes from the statics */
  const char *drum_load[] = {"nip[0].load=500"};
  refused("", two_drum_nips, 1, drum_load, "nip[0].load=500: a drum of a two-drum winder carries");
  /* front and rear belong to a two-drum winder */
  const char *center[] = {"winder.type=center", "winder.drum_distance=null", "winder.drum_radius=null"};
  refused("", two_drum_nips, 3, center, "nip[0].position: front and rear drums belong");
  /* one front drum only */
  const char *two_rears[] = {"nip[1].position=rear"};
  refused("", two_drum_nips, 1, two_rears, "nip[1].position=rear: a two-drum winder has one rear drum");
  /* an entry's own checks name the entry */
  const char *bad_mu[] = {"nip[2].friction.roll=-1"};
  refused("", two_drum_nips, 1, bad_mu, "nip[2].friction.roll=-1: must be >= 0");
  /* --set reaches into the list */
  const char *set[] = {"nip[2].load.end=400"};
  rs_scene *s = load("", two_drum_nips, 1, set);
  CHECK(s != NULL);
  if (s) {
    const rs_problem *p = rs_scene_problem(s);
    CHECK(p->winder.n_nips == 3);
    CHECK(p->winder.nips[2].load.end == 400.0);
    CHECK(p->winder.position[0] == RS_NIP_AT_REAR && p->winder.position[2] == RS_NIP_AT_RIDER);
    CHECK(rs_defect_core_share(p) == 0.0); /* the drums drive the surface */
  }
  rs_scene_destroy(&s);
}

static const check_case cases[] = {
    {"statics_by_hand", statics_by_hand},
    {"weight_shared", weight_shared},
    {"saturation_caps", saturation_caps},
    {"one_nip_list_bit_for_bit", one_nip_list_bit_for_bit},
    {"scene_checks", scene_checks},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
