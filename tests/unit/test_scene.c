/* Scene loader: every case loads, overrides apply, derived values follow their
 * formulas, defaults are filled, model files are found in the documented order, and the
 * resolved text loads back to the same scene. */
#define _XOPEN_SOURCE 700 /* setenv, mkdtemp, M_PI */

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "reelsim/scene.h"
#include "scene/scene_type.h" /* the fields: these tests look inside */

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

static char tmpdir[256];

static void make_tmpdir(void)
{
  snprintf(tmpdir, sizeof tmpdir, "/tmp/rs_scene_XXXXXX");
  CHECK(mkdtemp(tmpdir) != NULL);
}

static void write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "w");
  CHECK(f != NULL);
  if (!f) return;
  fputs(text, f);
  fclose(f);
}

static void rm_rf(const char *dir)
{
  char cmd[512];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  CHECK(system(cmd) == 0);
}

static rs_scene *load(const char *path, int n, const char *const *sets)
{
  rs_scene *s = NULL;
  rs_status st = rs_scene_load(path, n, sets, &s);
  if (st != RS_OK) fprintf(stderr, "load %s: %s\n", path, rs_error_message());
  CHECK(st == RS_OK);
  return s;
}

static void same_scene(const rs_scene *a, const rs_scene *b)
{
  CHECK(strcmp(a->title, b->title) == 0);
  CHECK(strcmp(a->problem.material.name, b->problem.material.name) == 0);
  CHECK(a->problem.material.caliper == b->problem.material.caliper);
  CHECK(a->problem.material.E_theta == b->problem.material.E_theta);
  CHECK(a->problem.material.nu_rtheta == b->problem.material.nu_rtheta);
  CHECK(memcmp(&a->problem.material.radial, &b->problem.material.radial, sizeof a->problem.material.radial) == 0);
  CHECK(memcmp(&a->problem.core, &b->problem.core, sizeof a->problem.core) == 0);
  CHECK(a->problem.final_radius == b->problem.final_radius);
  CHECK(a->problem.n_layers == b->problem.n_layers);
  CHECK(a->problem.tension.law == b->problem.tension.law);
  CHECK(a->problem.tension.start == b->problem.tension.start);
  CHECK(a->problem.tension.n_points == b->problem.tension.n_points);
  if (a->problem.tension.law == RS_RECIPE_HYPERBOLIC) CHECK_CLOSE(b->problem.tension.k, a->problem.tension.k, 1e-12);
  if (a->problem.tension.law == RS_RECIPE_LINEAR) CHECK(a->problem.tension.end == b->problem.tension.end);
  CHECK(a->problem.nip.model == b->problem.nip.model);
  CHECK(a->problem.nip.mu_roll == b->problem.nip.mu_roll);
  CHECK(memcmp(&a->problem.numerics, &b->problem.numerics, sizeof a->problem.numerics) == 0);
  CHECK(strcmp(a->output.file, b->output.file) == 0);
}

/* Every shipped case loads; its resolved text loads back to the same scene. */
static void load_all_cases(void)
{
  const char *dir = RS_ROOT_DIR "/cases";
  DIR *d = opendir(dir);
  CHECK(d != NULL);
  if (!d) return;
  int n = 0;
  make_tmpdir();
  for (struct dirent *e; (e = readdir(d));) {
    size_t len = strlen(e->d_name);
    if (len < 6 || strcmp(e->d_name + len - 5, ".yaml") != 0) continue;
    char path[512], again[512];
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    rs_scene *s = load(path, 0, NULL);
    if (!s) continue;
    ++n;
    printf("  %-28s %6d layers, material from %s\n", e->d_name, s->problem.n_layers, s->material_source);
    CHECK(s->resolved_text && strstr(s->resolved_text, "title:"));
    /* round trip: the resolved text is itself a scene, beside which no model is needed */
    snprintf(again, sizeof again, "%s/%s", tmpdir, e->d_name);
    write_file(again, s->resolved_text);
    rs_scene *t = load(again, 0, NULL);
    if (t) {
      same_scene(s, t);
      CHECK(strcmp(t->material_source, "inline") == 0);
    }
    rs_scene_destroy(&t);
    rs_scene_destroy(&s);
  }
  closedir(d);
  rm_rf(tmpdir);
  CHECK_LOG("cases loaded", n);
  CHECK(n >= 4);
}

/* The contract scene reads as documented. */
static void contract_scene(void)
{
  rs_scene *s = load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 0, NULL);
  if (!s) return;
  CHECK(strcmp(s->title, "Newsprint, center winding with a rider roll") == 0);
  CHECK(strcmp(s->problem.material.name, "newsprint") == 0);
  CHECK(strstr(s->material_source, "models/newsprint.yaml") != NULL);
  CHECK(s->problem.material.caliper == 70.0e-6);
  CHECK(s->problem.material.E_theta == 3.5e9);
  CHECK(s->problem.material.radial.law == RS_RADIAL_PFEIFFER);
  CHECK(s->problem.material.radial.K1 == 5.0e3 && s->problem.material.radial.K2 == 60);
  CHECK(s->problem.core.kind == RS_CORE_ELASTIC && s->problem.core.radius == 0.0762 && s->problem.core.stiffness == 1e9);
  CHECK(s->problem.final_radius == 0.5 && s->web_length == 0.0);
  CHECK(s->problem.n_layers == 6054); /* (0.5 - 0.0762) / 70e-6 = 6054.3 */
  CHECK(s->problem.tension.law == RS_RECIPE_CONSTANT && s->problem.tension.start == 350);
  CHECK(s->problem.nip.model == RS_NIP_FRICTION && s->problem.nip.mu_roll == 0.19);
  CHECK(s->problem.nip.load.law == RS_RECIPE_CONSTANT && s->problem.nip.load.start == 1750);
  CHECK(s->problem.nip.nodes == 96 && s->problem.nip.winder == RS_WINDER_CENTER);
  CHECK(s->problem.numerics.layers_per_step == 1 && s->problem.numerics.rtol == 1e-6);
  CHECK(strcmp(s->output.file, "newsprint-rider.h5") == 0);
  rs_scene_destroy(&s);
}

static void set_override(void)
{
  const char *sets[] = {"winding.tension=300", "material.caliper=80e-6", "nip.friction.roll=0.25",
                        "output.file=x.h5"};
  rs_scene *s = load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 4, sets);
  if (!s) return;
  CHECK(s->problem.tension.law == RS_RECIPE_CONSTANT && s->problem.tension.start == 300);
  CHECK(s->problem.material.caliper == 80e-6);
  CHECK(s->problem.n_layers == (int)lround((0.5 - 0.0762) / 80e-6));
  CHECK(s->problem.nip.mu_roll == 0.25);
  CHECK(strcmp(s->output.file, "x.h5") == 0);
  CHECK(strstr(s->resolved_text, "# --set winding.tension=300") != NULL);
  rs_scene_destroy(&s);

  /* a key absent from the file but known to the schema is created */
  const char *more[] = {"numerics.layers_per_step=10", "material=pet-film",
                        "winding.tension.k=0.5"};
  s = load(RS_ROOT_DIR "/cases/newsprint-taper.yaml", 1, more);
  if (s) CHECK(s->problem.numerics.layers_per_step == 10);
  rs_scene_destroy(&s);
  s = load(RS_ROOT_DIR "/cases/newsprint-taper.yaml", 2, more);
  if (s) CHECK(strcmp(s->problem.material.name, "pet-film") == 0 && s->problem.material.caliper == 23e-6);
  rs_scene_destroy(&s);

  /* both end and k on a hyperbolic taper: refused, naming k */
  rs_scene *bad = NULL;
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-taper.yaml", 3, more, &bad) == RS_ERR_INPUT);
  CHECK(bad == NULL);
  CHECK(strstr(rs_error_message(), "--set winding.tension.k=0.5") != NULL);
  printf("  %s\n", rs_error_message());

  /* a path the schema does not know, and a value that is not a number */
  const char *wrong[] = {"core.radus=1"}, *nan_[] = {"numerics.rtol=abc"};
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 1, wrong, &bad) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "--set core.radus=1: unknown key 'radus'") != NULL);
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 1, nan_, &bad) == RS_ERR_INPUT);
  CHECK(strcmp(rs_error_message(), "--set numerics.rtol=abc: not a number (got 'abc')") == 0);
}

/* Web length L on a core r_c with caliper t: pi (r1^2 - r_c^2) = L t. */
static void web_length_formula(void)
{
  rs_scene *s = load(RS_ROOT_DIR "/cases/linerboard-table.yaml", 0, NULL);
  if (!s) return;
  double rc = s->problem.core.radius, t = s->problem.material.caliper, L = s->web_length;
  CHECK(L == 3000.0);
  double r1 = s->problem.final_radius;
  CHECK_LOG("final radius from 3000 m of 250 um board", r1);
  CHECK_CLOSE(M_PI * (r1 * r1 - rc * rc), L * t, 1e-14);
  CHECK_CLOSE(r1, sqrt(0.0762 * 0.0762 + 3000.0 * 250e-6 / M_PI), 1e-15);
  CHECK(s->problem.n_layers == (int)lround((r1 - rc) / t));
  rs_scene_destroy(&s);
}

static void defaults_filled(void)
{
  char path[512];
  make_tmpdir();
  snprintf(path, sizeof path, "%s/plain-roll.yaml", tmpdir);
  write_file(path, "material: {caliper: 1e-4, E_theta: 4e9, radial: {law: linear, E_r: 2e7}}\n"
                   "core: {radius: 0.05}\n"
                   "winding: {final_radius: 0.06, tension: 100}\n");
  rs_scene *s = load(path, 0, NULL);
  if (s) {
    CHECK(strcmp(s->title, "plain-roll") == 0);
    CHECK(strcmp(s->material_source, "inline") == 0);
    CHECK(strcmp(s->problem.material.name, "inline") == 0);
    CHECK(s->problem.material.nu_rtheta == 0.0 && s->problem.material.G_rtheta == 0.0);
    CHECK(s->problem.core.kind == RS_CORE_RIGID);
    CHECK(s->problem.n_layers == 100);
    CHECK(s->problem.nip.model == RS_NIP_NONE);
    CHECK(s->problem.numerics.layers_per_step == 1 && s->problem.numerics.rtol == 1e-3);
    CHECK(s->problem.numerics.atol == 0.0 && s->problem.numerics.max_steps == 0);
    CHECK(strcmp(s->output.file, "plain-roll.h5") == 0 && s->problem.record.history_every == 0);
    CHECK(strstr(s->resolved_text, "layers_per_step: 1") != NULL);
  }
  rs_scene_destroy(&s);

  /* a nip fills its own defaults: winder center, 96 nodes */
  const char *nip[] = {"nip.model=friction", "nip.load=1000", "nip.friction.roll=0.2"};
  s = load(path, 3, nip);
  if (s) {
    CHECK(s->problem.nip.model == RS_NIP_FRICTION && s->problem.nip.nodes == 96);
    CHECK(s->problem.nip.winder == RS_WINDER_CENTER && s->problem.nip.mu_roll == 0.2);
  }
  rs_scene_destroy(&s);
  rm_rf(tmpdir);
}

static void put_model(const char *dir, const char *caliper)
{
  char path[1024], text[256];
  snprintf(path, sizeof path, "%s/m.yaml", dir);
  snprintf(text, sizeof text,
           "caliper: %s\nE_theta: 4e9\nradial: {law: linear, E_r: 2e7}\n", caliper);
  write_file(path, text);
}

static double lookup_caliper(const char *scene, char *source, size_t size)
{
  rs_scene *s = NULL;
  double c = NAN;
  if (rs_scene_load(scene, 0, NULL, &s) == RS_OK) {
    c = s->problem.material.caliper;
    snprintf(source, size, "%s", s->material_source);
  } else {
    snprintf(source, size, "%s", rs_error_message());
  }
  rs_scene_destroy(&s);
  return c;
}

/* beside the scene, then <dir>/models, then <dir>/../models, then $REELSIM_MODELS */
static void material_lookup_order(void)
{
  char scene[512], sub[512], lib[512], path[512], src[4096];
  make_tmpdir();
  snprintf(scene, sizeof scene, "%s/scenes/s.yaml", tmpdir);
  snprintf(sub, sizeof sub, "%s/scenes", tmpdir);
  snprintf(lib, sizeof lib, "%s/lib", tmpdir);
  char cmd[1024];
  snprintf(cmd, sizeof cmd, "mkdir -p '%s/scenes/models' '%s/models' '%s/lib'", tmpdir, tmpdir,
           tmpdir);
  CHECK(system(cmd) == 0);
  write_file(scene, "material: m\ncore: {radius: 0.05}\nwinding: {final_radius: 0.06, tension: 1}\n");
  put_model(sub, "1e-4");
  snprintf(path, sizeof path, "%s/scenes/models", tmpdir);
  put_model(path, "2e-4");
  snprintf(path, sizeof path, "%s/models", tmpdir);
  put_model(path, "3e-4");
  put_model(lib, "4e-4");
  setenv("REELSIM_MODELS", lib, 1);

  CHECK(lookup_caliper(scene, src, sizeof src) == 1e-4);
  CHECK(strstr(src, "/scenes/m.yaml") != NULL);
  snprintf(path, sizeof path, "%s/scenes/m.yaml", tmpdir);
  unlink(path);
  CHECK(lookup_caliper(scene, src, sizeof src) == 2e-4);
  CHECK(strstr(src, "/scenes/models/m.yaml") != NULL);
  snprintf(path, sizeof path, "%s/scenes/models/m.yaml", tmpdir);
  unlink(path);
  CHECK(lookup_caliper(scene, src, sizeof src) == 3e-4);
  /* shown without the "..": <tmp>/models/m.yaml */
  snprintf(path, sizeof path, "%s/models/m.yaml", tmpdir);
  CHECK(strcmp(src, path) == 0);
  unlink(path);
  CHECK(lookup_caliper(scene, src, sizeof src) == 4e-4);
  CHECK(strstr(src, "/lib/m.yaml") != NULL);
  snprintf(path, sizeof path, "%s/lib/m.yaml", tmpdir);
  unlink(path);
  CHECK(isnan(lookup_caliper(scene, src, sizeof src)));
  CHECK(strstr(src, "no material model 'm'") != NULL);
  printf("  %s\n", src);

  /* without REELSIM_MODELS the project's models/ is the last place */
  unsetenv("REELSIM_MODELS");
  write_file(scene, "material: newsprint\ncore: {radius: 0.05}\n"
                    "winding: {final_radius: 0.06, tension: 1}\n");
  CHECK(lookup_caliper(scene, src, sizeof src) == 70e-6);
  CHECK(strcmp(src, RS_ROOT_DIR "/models/newsprint.yaml") == 0);

  /* a scene named like its material does not find itself */
  snprintf(path, sizeof path, "%s/scenes/newsprint.yaml", tmpdir);
  rename(scene, path);
  CHECK(lookup_caliper(path, src, sizeof src) == 70e-6);
  rm_rf(tmpdir);
}

/* Errors carry file, line and key path; an error in a model names the model file. */
static void error_locations(void)
{
  char scene[512], model[512];
  rs_scene *s = NULL;
  make_tmpdir();
  snprintf(scene, sizeof scene, "%s/e.yaml", tmpdir);
  snprintf(model, sizeof model, "%s/foo.yaml", tmpdir);
  write_file(model, "# foo\nname: foo\nE_theta: 3.5e9\ncaliper: -7e-05\n"
                    "radial: {law: linear, E_r: 5e7}\n");
  write_file(scene, "title: t\nmaterial: foo\ncore: {radius: 0.0762}\n"
                    "winding:\n  final_radius: 0.5\n  tension: {law: linear, start: 350, end: -12.3}\n");
  char want[1024];
  CHECK(rs_scene_load(scene, 0, NULL, &s) == RS_ERR_INPUT);
  snprintf(want, sizeof want, "%s:4: caliper: must be > 0 m (got -7e-05)", model);
  CHECK(strcmp(rs_error_message(), want) == 0);
  printf("  %s\n", rs_error_message());

  write_file(model, "caliper: 7e-05\nE_theta: 3.5e9\nradial: {law: linear, E_r: 5e7}\n");
  CHECK(rs_scene_load(scene, 0, NULL, &s) == RS_ERR_INPUT);
  snprintf(want, sizeof want,
           "%s:6: winding.tension.end: taper makes the tension negative at r = 0.5 m (-12.3 N/m)",
           scene);
  CHECK(strcmp(rs_error_message(), want) == 0);
  printf("  %s\n", rs_error_message());
  CHECK(s == NULL);
  rm_rf(tmpdir);
}

/* Titles and file names with YAML's special characters survive the resolved text. */
static void resolved_quoting(void)
{
  char path[512], again[512];
  make_tmpdir();
  snprintf(path, sizeof path, "%s/q.yaml", tmpdir);
  snprintf(again, sizeof again, "%s/again.yaml", tmpdir);
  write_file(path, "title: 'a: b # c, [d] {e} \"f\" yes'\n"
                   "material: {caliper: 1e-4, E_theta: 4e9, radial: {law: linear, E_r: 2e7}}\n"
                   "core: {radius: 0.05}\n"
                   "winding: {final_radius: 0.06, tension: '{table: [[0.05, 100], [0.06, 90]]}'}\n");
  rs_scene *s = NULL;
  /* a quoted string where a recipe belongs is refused, not parsed */
  CHECK(rs_scene_load(path, 0, NULL, &s) == RS_ERR_INPUT);
  printf("  %s\n", rs_error_message());
  write_file(path, "title: 'a: b # c, [d] {e} \"f\" yes'\n"
                   "material: {caliper: 1e-4, E_theta: 4e9, radial: {law: linear, E_r: 2e7}}\n"
                   "core: {radius: 0.05}\n"
                   "winding: {final_radius: 0.06, tension: {table: [[0.05, 100], [0.06, 90]]}}\n"
                   "output: {file: 'out dir/x: y.h5'}\n");
  s = load(path, 0, NULL);
  if (s) {
    CHECK(strcmp(s->title, "a: b # c, [d] {e} \"f\" yes") == 0);
    write_file(again, s->resolved_text);
    rs_scene *t = load(again, 0, NULL);
    if (t) {
      same_scene(s, t);
      CHECK(strcmp(t->output.file, "out dir/x: y.h5") == 0);
      CHECK(t->problem.tension.n_points == 2 && t->problem.tension.value[1] == 90);
    }
    rs_scene_destroy(&t);
  }
  rs_scene_destroy(&s);
  rm_rf(tmpdir);
}

static const check_case cases[] = {
    {"resolved_quoting", resolved_quoting},
    {"load_all_cases", load_all_cases},
    {"contract_scene", contract_scene},
    {"set_override", set_override},
    {"web_length_formula", web_length_formula},
    {"defaults_filled", defaults_filled},
    {"material_lookup_order", material_lookup_order},
    {"error_locations", error_locations},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
