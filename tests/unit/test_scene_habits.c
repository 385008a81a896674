/* A new user's scene habits: sizes as diameters, a shipped model with changes, --set
 * KEY=null, every error of a scene at once, and the size figures of the summary (wound
 * length and mass against the closed form of equal-caliper layers). */
#define _XOPEN_SOURCE 700 /* M_PI */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
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
          0, NULL, "core.radius: required: the core size as radius (m) or diameter (m)", NULL);
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
  if (s) CHECK(s->problem.numerics.rtol == 1e-5); /* the default */
  rs_scene_destroy(&s);
  refused(radius_scene, 1, typo, "--set winding.final_radius_=null: unknown key 'final_radius_' in winding", NULL);
  /* a required key removed is reported as missing */
  const char *req[] = {"winding.tension=~"};
  refused(radius_scene, 1, req, "winding.tension: required key is missing", NULL);
}

static const check_case cases[] = {
    {"diameter_keys", diameter_keys},
    {"sizes_closed_form", sizes_closed_form},
    {"model_with_changes", model_with_changes},
    {"set_null_removes", set_null_removes},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
