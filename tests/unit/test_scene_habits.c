/* A new user's scene habits: sizes as diameters, a shipped model with changes, --set
 * KEY=null, every error of a scene at once, and the size figures of the summary (wound
 * length and mass against the closed form of equal-caliper layers). */
#define _XOPEN_SOURCE 700 /* M_PI */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "scene/scene_type.h" /* the fields: these tests look inside */

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

/* a scene named as if it sat in cases/, so `material: NAME` finds the shipped models */
#define NAME RS_ROOT_DIR "/cases/habits.yaml"

static rs_scene *load_text(const char *text, int n, const char *const *sets)
{
  rs_scene *s = NULL;
  rs_status st = rs_scene_load_text(NAME, text, strlen(text), n, sets, &s);
  if (st != RS_OK) fprintf(stderr, "load: %s\n", rs_error_message());
  CHECK(st == RS_OK);
  return s;
}

/* loads, expecting RS_ERR_INPUT with every `want` in the message */
static void refused(const char *text, int n, const char *const *sets, const char *want1,
                    const char *want2)
{
  rs_scene *s = NULL;
  CHECK(rs_scene_load_text(NAME, text, strlen(text), n, sets, &s) == RS_ERR_INPUT);
  CHECK(s == NULL);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), want1) != NULL);
  if (want2) CHECK(strstr(rs_error_message(), want2) != NULL);
}

static const char *radius_scene = "material: newsprint\n"
                                  "core: {radius: 0.0762}\n"
                                  "winding: {final_radius: 0.3, tension: 350}\n";

/* core.diameter and winding.final_diameter are twice the radii; one of each pair. */
static void diameter_keys(void)
{
  rs_scene *a = load_text(radius_scene, 0, NULL);
  rs_scene *b = load_text("material: newsprint\n"
                          "core: {diameter: 0.1524}\n"
                          "winding: {final_diameter: 0.6, tension: 350}\n",
                          0, NULL);
  if (a && b) {
    CHECK(a->problem.core.radius == b->problem.core.radius);
    CHECK(a->problem.final_radius == b->problem.final_radius);
    CHECK(a->problem.n_layers == b->problem.n_layers);
  }
  rs_scene_destroy(&a);
  rs_scene_destroy(&b);
  refused("material: newsprint\ncore: {radius: 0.0762, diameter: 0.1524}\n"
          "winding: {final_radius: 0.3, tension: 350}\n",
          0, NULL, "habits.yaml:2: core.diameter: give either core.radius or core.diameter", NULL);
  refused("material: newsprint\ncore: {diameter: 0.1524}\n"
          "winding: {final_radius: 0.3, final_diameter: 0.6, tension: 350}\n",
          0, NULL, "winding.final_radius", "winding.final_diameter");
  refused("material: newsprint\ncore: {diameter: 0.1524}\n"
          "winding: {final_diameter: 0.1, tension: 350}\n",
          0, NULL, "winding.final_diameter: must be > the core diameter 0.1524 m", NULL);
  refused("material: newsprint\ncore: {stiffness: 1e9}\n"
          "winding: {final_diameter: 0.6, tension: 350}\n",
          0, NULL, "core.radius: required: the core size as radius (m), diameter (m), or inner_diameter and wall (m)", NULL);
}

/* Layers one caliper thick: sum_j pi (r_{j-1} + r_j) = pi (r_N^2 - r_c^2) / t exactly
 * (a telescoping sum), and the mass is rho t L = rho pi (r_N^2 - r_c^2). */
static void sizes_closed_form(void)
{
  enum { N = 1000 };
  double radius[N];
  const double rc = 0.0762, t = 80e-6, rho = 730.0;
  for (int j = 0; j < N; ++j) radius[j] = rc + (j + 1) * t;
  rs_reel_result res = {.n_layers = N, .radius = radius, .core_radius = rc};
  rs_problem p = {.material = {.caliper = t, .density = rho}};
  rs_reel_sizes z;
  rs_reel_sizes_of(&res, &p, &z);
  double rN = radius[N - 1], area = M_PI * (rN * rN - rc * rc);
  CHECK(z.diameter == 2.0 * rN);
  CHECK_CLOSE(z.wound_length, area / t, 1e-12);
  CHECK(z.has_mass == 1);
  CHECK_CLOSE(z.mass, rho * area, 1e-12);
  p.material.density = 0.0;
  rs_reel_sizes_of(&res, &p, &z);
  CHECK(z.has_mass == 0 && z.mass == 0.0);
}

/* material: {model: pet-film, caliper: 50e-6} is pet-film with the caliper changed; the
 * resolved text loads back to the same material. */
static void model_with_changes(void)
{
  rs_scene *plain = load_text("material: pet-film\ncore: {radius: 0.0762}\n"
                              "winding: {final_radius: 0.1, tension: 100}\n",
                              0, NULL);
  rs_scene *s = load_text("material: {model: pet-film, caliper: 50.0e-6, density: 1000}\n"
                          "core: {radius: 0.0762}\n"
                          "winding: {final_radius: 0.1, tension: 100}\n",
                          0, NULL);
  if (plain && s) {
    const rs_material *a = &plain->problem.material, *b = &s->problem.material;
    CHECK(a->caliper == 23e-6 && b->caliper == 50e-6);
    CHECK(b->density == 1000.0);
    CHECK(a->E_theta == b->E_theta && a->nu_rtheta == b->nu_rtheta && a->G_rtheta == b->G_rtheta);
    CHECK(memcmp(&a->radial, &b->radial, sizeof a->radial) == 0);
    CHECK(strcmp(b->name, "pet-film") == 0);
    CHECK(strstr(s->material_source, "models/pet-film.yaml") != NULL);
    rs_scene *again = load_text(s->resolved_text, 0, NULL);
    if (again) {
      CHECK(again->problem.material.caliper == 50e-6);
      CHECK(again->problem.material.E_theta == b->E_theta);
      CHECK(again->problem.n_layers == s->problem.n_layers);
    }
    rs_scene_destroy(&again);
  }
  rs_scene_destroy(&plain);
  rs_scene_destroy(&s);

  /* --set material.model picks another model under the same changes */
  const char *other[] = {"material.model=linerboard"};
  s = load_text("material: {model: pet-film, caliper: 50.0e-6}\ncore: {radius: 0.0762}\n"
                "winding: {final_radius: 0.1, tension: 100}\n",
                1, other);
  if (s) CHECK(strcmp(s->problem.material.name, "linerboard") == 0 && s->problem.material.caliper == 50e-6);
  rs_scene_destroy(&s);

  refused("material: {model: unobtainium, caliper: 50.0e-6}\ncore: {radius: 0.0762}\n"
          "winding: {final_radius: 0.1, tension: 100}\n",
          0, NULL, "habits.yaml:1: material.model: no material model 'unobtainium'", NULL);
  /* a changed key is checked like any other, at the scene's line */
  refused("material:\n  model: pet-film\n  caliper: -1\ncore: {radius: 0.0762}\n"
          "winding: {final_radius: 0.1, tension: 100}\n",
          0, NULL, "habits.yaml:3: material.caliper: must be > 0 m (got -1)", NULL);
}

/* --set KEY=null removes the key: the size switches from final_radius to web_length. */
static void set_null_removes(void)
{
  const char *sets[] = {"winding.final_radius=null", "winding.web_length=5000"};
  rs_scene *s = load_text(radius_scene, 2, sets);
  if (s) {
    double rc = 0.0762, t = s->problem.material.caliper;
    CHECK(s->web_length == 5000.0);
    CHECK_CLOSE(s->problem.final_radius, sqrt(rc * rc + 5000.0 * t / M_PI), 1e-15);
    CHECK(strstr(s->resolved_text, "final_radius:") == NULL);
  }
  rs_scene_destroy(&s);
  /* without the null, both sizes are there and the scene is refused */
  refused(radius_scene, 1, sets + 1, "give either final_radius or web_length", NULL);
  /* a key not in the file: nothing to remove; a key not in the schema: refused */
  const char *absent[] = {"numerics.rtol=null"}, *typo[] = {"winding.final_radius_=null"};
  s = load_text(radius_scene, 1, absent);
  if (s) CHECK(s->problem.numerics.rtol == 1e-3); /* the default */
  rs_scene_destroy(&s);
  refused(radius_scene, 1, typo, "--set winding.final_radius_=null: unknown key 'final_radius_' in winding", NULL);
  /* a required key removed is reported as missing */
  const char *req[] = {"winding.tension=~"};
  refused(radius_scene, 1, req, "winding.tension: required key is missing", NULL);
}

/* the message's lines */
static int count_lines(const char *m)
{
  int n = *m ? 1 : 0;
  for (; *m; ++m) n += *m == '\n';
  return n;
}

/* Every error of a scene in one message, one a line, in the order of the file; range
 * errors of independent parts together; the first 20 and a count of the rest. */
static void every_error_at_once(void)
{
  const char *types = "material:\n  caliper: abc\n  E_theta: 1e9\n  radial: {law: linear, E_r: 1e7}\n"
                      "core: {radius: 0.05, radus: 3}\n"
                      "winding: {final_radius: 0.3, tension: 100}\n"
                      "nip: {model: frictio}\n";
  const char *sets[] = {"numerics.rtoll=1"};
  rs_scene *s = NULL;
  CHECK(rs_scene_load_text(NAME, types, strlen(types), 1, sets, &s) == RS_ERR_INPUT);
  const char *m = rs_error_message();
  printf("%s\n", m);
  CHECK(count_lines(m) == 4);
  const char *want[] = {"--set numerics.rtoll=1: unknown key 'rtoll' in numerics",
                        "habits.yaml:2: material.caliper: not a number (got 'abc')",
                        "habits.yaml:5: core.radus: unknown key 'radus'",
                        "habits.yaml:7: nip.model: unknown value 'frictio'"};
  const char *at = m;
  for (int i = 0; i < 4; ++i) { /* each there, in this order */
    const char *p = strstr(at, want[i]);
    CHECK(p != NULL);
    if (p) at = p;
  }

  /* range errors: material, core and numerics together; the roll size, which needs the
   * core, is not checked (its error would only repeat the core's) */
  const char *ranges = "material: {caliper: -1, E_theta: 1e9, radial: {law: linear, E_r: 1e7}}\n"
                       "core: {radius: -0.05}\n"
                       "winding: {final_radius: 0.01, tension: 100}\n"
                       "numerics: {layers_per_step: 0}\n";
  CHECK(rs_scene_load_text(NAME, ranges, strlen(ranges), 0, NULL, &s) == RS_ERR_INPUT);
  m = rs_error_message();
  printf("%s\n", m);
  CHECK(count_lines(m) == 3);
  CHECK(strstr(m, "habits.yaml:1: material.caliper: must be > 0 m (got -1)\n") == m + strlen(NAME) - strlen("habits.yaml"));
  CHECK(strstr(m, "habits.yaml:2: core.radius: must be > 0 m (got -0.05)") != NULL);
  CHECK(strstr(m, "habits.yaml:4: numerics.layers_per_step: must be >= 1 (got 0)") != NULL);
  CHECK(strstr(m, "final_radius") == NULL);

  /* 25 unknown keys: the first 20 and how many more */
  char many[4096];
  size_t len = (size_t)snprintf(many, sizeof many, "%s", radius_scene);
  len += (size_t)snprintf(many + len, sizeof many - len, "numerics:\n");
  for (int i = 0; i < 25; ++i)
    len += (size_t)snprintf(many + len, sizeof many - len, "  bad%02d: 1\n", i);
  CHECK(rs_scene_load_text(NAME, many, len, 0, NULL, &s) == RS_ERR_INPUT);
  m = rs_error_message();
  CHECK(count_lines(m) == 21);
  CHECK(strstr(m, "bad19") != NULL && strstr(m, "bad20") == NULL);
  CHECK(strstr(m, "\n(5 more errors not shown; 25 in all)") != NULL);
  CHECK(s == NULL);

  /* one error: the message is that error's alone, as before */
  refused("material: newsprint\ncore: {radius: 0.0762}\nwinding: {final_radius: 0.3}\n", 0, NULL,
          "habits.yaml:3: winding.tension: required key is missing", NULL);
  CHECK(count_lines(rs_error_message()) == 1);
}

#define DRUM_SCENE(tension)                                                                   \
  "material: newsprint\n"                                                                  \
  "core: {radius: 0.0762}\n"                                                               \
  "winding: {final_radius: 0.088, tension: " tension "}\n"                                 \
  "nip: {model: contact, winder: surface, load: 1750,\n"                                   \
  "      friction: {roll: 0.19, drum: 0.35},\n"                                            \
  "      drum: {radius: 0.3, core_radius: 0.28, E: 2.1e11, nu: 0.3}}\n"
static const char *drum_scene = DRUM_SCENE("350");

/* A surface winder's drum carries Ti by friction alone: mu_drum P = 0.35 x 1750 = 612.5 N/m
 * must exceed it all along the roll. A tension table rising 350 -> 800 N/m over
 * [0.0762, 0.088] m reaches 612.5 N/m at r* = 0.0762 + 0.0118 x 262.5/450 = 0.08306 m: the
 * layer going on at R = r_c + j t carries Ti(R + t), first too much for j + 1 =
 * ceil((r* - r_c)/t) = ceil(98.33) = 99: layer 99 of 169, at R = r_c + 98 t = 0.08306 m. */
static void drum_capacity_checked(void)
{
  rs_scene *s = load_text(drum_scene, 0, NULL);
  rs_scene_destroy(&s);
  refused(DRUM_SCENE("{table: [[0.0762, 350], [0.088, 800]]}"), 0, NULL,
          "habits.yaml:5: nip.friction.drum: the drum cannot carry the web by friction from "
          "roll radius r = 0.08306 m (layer 99 of 169) on: nip.friction.drum x nip.load = "
          "0.35 x 1750 = 612.5 N/m is not above winding.tension = 614.28 N/m, all of which the "
          "drum carries on a surface winder; raise nip.load or nip.friction.drum, or lower "
          "winding.tension",
          NULL);
  /* a constant tension above the capacity: refused at the first layer */
  const char *high[] = {"winding.tension=700"};
  refused(drum_scene, 1, high, "from roll radius r = 0.0762 m (layer 1 of 169)", "surface winder");
  /* the same reel on a center winder (the drum carries nothing), a center-surface winder
   * whose drum carries half (400 < 612.5 N/m), or with the friction nip: accepted */
  const char *ok[][2] = {{"nip.winder=center", "winding.tension=800"},
                         {"nip.winder=center-surface", "winding.tension=800"},
                         {"nip.model=friction", "winding.tension=800"}};
  for (int i = 0; i < 3; ++i) {
    s = load_text(drum_scene, 2, ok[i]);
    rs_scene_destroy(&s);
  }
  /* center-surface with a share of 0.2 carries 0.8 x 800 = 640 > 612.5: refused */
  const char *share[] = {"nip.winder=center-surface", "nip.torque_share=0.2", "winding.tension=800"};
  refused(drum_scene, 3, share,
          "(layer 1 of 169) on: nip.friction.drum x nip.load = 0.35 x 1750 = 612.5 N/m is not "
          "above (1 - nip.torque_share) x winding.tension = (1 - 0.2) x 800 = 640 N/m, what the "
          "drum carries on a center-surface winder",
          NULL);
}

static const check_case cases[] = {
    {"drum_capacity_checked", drum_capacity_checked},
    {"every_error_at_once", every_error_at_once},
    {"diameter_keys", diameter_keys},
    {"sizes_closed_form", sizes_closed_form},
    {"model_with_changes", model_with_changes},
    {"set_null_removes", set_null_removes},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
