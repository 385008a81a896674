/* The reel loop's effects (src/reel/effect.h):
 *  - the list holds exactly the effects the problem has (a problem without one runs none of
 *    its code), in the loop's order;
 *  - the phases stepped by hand (create, step, finish) give rs_reel_wind's result bit for
 *    bit, with every effect on;
 *  - a driver's own effect sets the web tension (the route of a lanes driver): twice the
 *    recipe's tension equals, bit for bit, the problem with twice the tension;
 *  - a driver's tension phase (web_tension, nip_load) is what the loop and the nip read:
 *    twice the recipes' tension and load equal, bit for bit, a problem with both doubled;
 *  - the ops are called as effect.h says: begin, tension, wound and after_increment once
 *    per increment or layer, collect and finish once, in the list's order. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/effect.h"
#include "reelsim/scene.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

static const char *small = RS_TESTS_DIR "/cli/scenes/small.yaml"; /* 200 layers, T = 200 N/m */

/* every effect on: history, air, a friction nip, the centrifugal load */
static const char *all_on[] = {"output.history_every=30", "winding.speed=8", "air=true",
                               "air.roughness=1e-6",      "air.nip_radius=0.1",
                               "nip.model=friction",      "nip.load=400",
                               "nip.friction.roll=0.2",   "material.density=900",
                               "centrifugal=true",        "numerics.layers_per_step=3"};
#define N_ALL_ON ((int)(sizeof all_on / sizeof all_on[0]))

static rs_scene *load(int n_sets, const char **sets)
{
  rs_scene *sc = NULL;
  if (rs_scene_load(small, n_sets, sets, &sc) != RS_OK) printf("  error: %s\n", rs_error_message());
  CHECK(sc != NULL);
  return sc;
}

static int same_array(const double *a, const double *b, int n)
{
  return (!a && !b) || (a && b && memcmp(a, b, (size_t)n * sizeof(double)) == 0);
}

/* Bit for bit: the per-layer arrays, the core pressure, the history and the nip record. */
static void check_same(const rs_reel_result *a, const rs_reel_result *b)
{
  const int n = a->n_layers;
  CHECK(n == b->n_layers && n > 0);
  CHECK(same_array(a->radius, b->radius, n) && same_array(a->sigma_r, b->sigma_r, n));
  CHECK(same_array(a->sigma_theta, b->sigma_theta, n));
  CHECK(same_array(a->wound_on_tension, b->wound_on_tension, n));
  CHECK(same_array(a->web_tension, b->web_tension, n));
  CHECK(same_array(a->air_film, b->air_film, n) && same_array(a->at_speed_sigma_r, b->at_speed_sigma_r, n));
  CHECK(same_array(a->wound_radius, b->wound_radius, n));
  CHECK(memcmp(&a->core_pressure, &b->core_pressure, sizeof(double)) == 0);
  CHECK(a->n_stages == b->n_stages && a->n_nip == b->n_nip && a->nip_solves == b->nip_solves);
  CHECK(same_array(a->stage_sigma_r, b->stage_sigma_r, a->n_stages * n));
  CHECK(same_array(a->nip_T0, b->nip_T0, a->n_nip));
}

/* The names of a state's effects, joined by spaces. */
static void effect_names(const rs_problem *pb, char *out, size_t size)
{
  rs_reel_state *s = NULL;
  CHECK(rs_reel_state_create(pb, NULL, 0, &s) == RS_OK);
  out[0] = '\0';
  for (int k = 0; s && k < s->n_effects; ++k) {
    if (k) strncat(out, " ", size - strlen(out) - 1);
    strncat(out, s->effects[k].ops->name, size - strlen(out) - 1);
  }
  rs_reel_state_destroy(&s);
}

static void list_holds_what_the_problem_has(void)
{
  char names[256];
  rs_scene *plain = load(0, NULL), *all = load(N_ALL_ON, all_on);
  const char *nip_only[] = {"nip.model=friction", "nip.load=400", "nip.friction.roll=0.2"};
  rs_scene *nip = load(3, nip_only);
  if (!plain || !all || !nip) goto out;
  effect_names(rs_scene_problem(plain), names, sizeof names);
  printf("  no effect:   %s\n", names);
  CHECK(strcmp(names, "gauge") == 0);
  effect_names(rs_scene_problem(nip), names, sizeof names);
  printf("  a nip:       %s\n", names);
  CHECK(strcmp(names, "nip gauge") == 0);
  effect_names(rs_scene_problem(all), names, sizeof names);
  printf("  all:         %s\n", names);
  CHECK(strcmp(names, "history air nip centrifugal gauge") == 0);
out:
  rs_scene_destroy(&plain);
  rs_scene_destroy(&all);
  rs_scene_destroy(&nip);
}

/* Winds pb through the phases by hand, with `extra` driver effects first. */
static rs_status wind_stepped(const rs_problem *pb, const rs_reel_effect *extra, int n_extra,
                              rs_reel_result **res)
{
  rs_reel_state *s = NULL;
  rs_status st = rs_reel_state_create(pb, extra, n_extra, &s);
  *res = NULL;
  if (!s) return st;
  while (st == RS_OK && !s->done) st = rs_reel_state_step(s);
  st = rs_reel_state_finish(s, st, res);
  rs_reel_state_destroy(&s);
  return st;
}

static void stepped_equals_wind(void)
{
  rs_scene *sc = load(N_ALL_ON, all_on);
  rs_reel_result *a = NULL, *b = NULL;
  if (!sc) return;
  CHECK(rs_reel_wind(rs_scene_problem(sc), NULL, &a) == RS_OK);
  CHECK(wind_stepped(rs_scene_problem(sc), NULL, 0, &b) == RS_OK);
  if (a && b) {
    CHECK_LOG("layers", a->n_layers);
    CHECK_LOG("history stages", a->n_stages);
    CHECK_LOG("nip solves", a->nip_solves);
    CHECK(a->air_film && a->at_speed_sigma_r && a->n_stages > 1 && a->nip_solves > 0);
    check_same(a, b);
  }
  rs_reel_result_destroy(&a);
  rs_reel_result_destroy(&b);
  rs_scene_destroy(&sc);
}

/* a driver's tension: k times the recipe's */
static rs_status scaled_tension(rs_reel_effect *e, const rs_reel_state *s, rs_reel_step *step,
                                rs_reel_layer *L)
{
  (void)s;
  (void)step;
  L->Ti = L->T0 = *(const double *)e->content * L->Ti;
  return RS_OK;
}

/* The scene (n_sets overrides) wound stepped with a driver's effect equals, bit for bit, the
 * scene with n_ref overrides wound by rs_reel_wind; its first layer's T0 is T0 */
static void driver_equals_recipe(int n_sets, const char **sets, int n_ref, const char **ref_sets,
                                 const rs_reel_effect *driver, double T0)
{
  rs_scene *sc = load(n_sets, sets), *ref = load(n_ref, ref_sets);
  rs_reel_result *a = NULL, *b = NULL;
  if (!sc || !ref) goto out;
  CHECK(wind_stepped(rs_scene_problem(sc), driver, 1, &a) == RS_OK);
  CHECK(rs_reel_wind(rs_scene_problem(ref), NULL, &b) == RS_OK);
  if (a && b) {
    CHECK_LOG("core pressure, by the driver", a->core_pressure);
    CHECK_LOG("core pressure, by the recipes", b->core_pressure);
    CHECK_LOG("T0 of the first layer, by the driver", a->wound_on_tension[0]);
    CHECK(a->wound_on_tension[0] == T0 && a->nip_load[0] == b->nip_load[0]);
    check_same(a, b);
  }
out:
  rs_reel_result_destroy(&a);
  rs_reel_result_destroy(&b);
  rs_scene_destroy(&sc);
  rs_scene_destroy(&ref);
}

static void driver_sets_tension(void)
{
  const char *twice[] = {"winding.tension=400"};
  static const rs_reel_effect_ops ops = {.name = "scaled", .tension = scaled_tension};
  double k = 2.0;
  rs_reel_effect scaled = {&ops, &k};
  driver_equals_recipe(0, NULL, 1, twice, &scaled, 400.0);
}

/* a driver's tension phase (effect.h: web_tension, nip_load): k times the recipes' */
static double phase_tension(const rs_reel_effect *e, const rs_reel_state *s, double r)
{
  return *(const double *)e->content * rs_recipe_eval(&s->pb->tension, r);
}

static double phase_load(const rs_reel_effect *e, const rs_reel_state *s, double r)
{
  return *(const double *)e->content * rs_recipe_eval(&s->pb->nip.load, r);
}

/* the tension phase (the lanes' route): the loop's Ti and w and the nip's solve all read it;
 * twice the recipes' tension and load equal, bit for bit, a problem with both doubled (a
 * friction nip solved at every layer: T0 = Ti + mu w = 400 + 0.2 x 800) */
static void phase_sets_tension_and_load(void)
{
  const char *nip[] = {"nip.model=friction", "nip.load=400", "nip.friction.roll=0.2",
                       "nip.update=every", "nip.update_every=1", "winding.tension=400",
                       "nip.load=800"};
  static const rs_reel_effect_ops ops = {
      .name = "phase", .web_tension = phase_tension, .nip_load = phase_load};
  double k = 2.0;
  rs_reel_effect phase = {&ops, &k};
  driver_equals_recipe(5, nip, 7, nip, &phase, 400.0 + 0.2 * 800.0);
}

/* a spy effect: counts its calls, and sees the history's last stage already closed */
typedef struct spy {
  int begin, tension, wound, after, collect, finish, setup;
  int stages_at_collect;
} spy;

static rs_status spy_setup(rs_reel_effect *e, rs_reel_state *s, rs_roll_params *p)
{
  (void)s, (void)p;
  ((spy *)e->content)->setup++;
  return RS_OK;
}
static rs_status spy_begin(rs_reel_effect *e, rs_reel_state *s, rs_reel_step *step)
{
  (void)s, (void)step;
  ((spy *)e->content)->begin++;
  return RS_OK;
}
static rs_status spy_tension(rs_reel_effect *e, const rs_reel_state *s, rs_reel_step *step,
                             rs_reel_layer *L)
{
  (void)s, (void)step, (void)L;
  ((spy *)e->content)->tension++;
  return RS_OK;
}
static rs_status spy_wound(rs_reel_effect *e, const rs_reel_state *s, rs_reel_layer *L)
{
  (void)s, (void)L;
  ((spy *)e->content)->wound++;
  return RS_OK;
}
static rs_status spy_after(rs_reel_effect *e, const rs_reel_state *s)
{
  (void)s;
  ((spy *)e->content)->after++;
  return RS_OK;
}
static rs_status spy_collect(rs_reel_effect *e, const rs_reel_state *s, rs_status st)
{
  (void)st;
  ((spy *)e->content)->collect++;
  ((spy *)e->content)->stages_at_collect = s->res->n_stages;
  return RS_OK;
}
static rs_status spy_finish(rs_reel_effect *e, const rs_reel_state *s, rs_status st)
{
  (void)s, (void)st;
  ((spy *)e->content)->finish++;
  return RS_OK;
}

static void ops_called_as_stated(void)
{
  const char *sets[] = {"numerics.layers_per_step=7", "output.history_every=60"};
  rs_scene *sc = load(2, sets);
  static const rs_reel_effect_ops ops = {.name = "spy", .setup = spy_setup, .begin = spy_begin,
                                         .tension = spy_tension, .wound = spy_wound,
                                         .after_increment = spy_after, .collect = spy_collect,
                                         .finish = spy_finish};
  spy c = {0};
  rs_reel_effect e = {&ops, &c};
  rs_reel_result *res = NULL;
  if (!sc) return;
  CHECK(wind_stepped(rs_scene_problem(sc), &e, 1, &res) == RS_OK);
  if (res) {
    const int n = res->n_layers, incs = (n + 6) / 7;
    CHECK_LOG("layers", n);
    CHECK_LOG("increments", res->increments);
    CHECK(n == 200 && res->increments == incs);
    CHECK(c.setup == 1 && c.collect == 1 && c.finish == 1);
    CHECK(c.begin == incs && c.after == incs);
    CHECK(c.tension == n && c.wound == n);
    /* the spy is first in the list: the history's collect (its last stage) comes after */
    CHECK(c.stages_at_collect == res->n_stages - 1);
  }
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

static const check_case cases[] = {
    {"list_holds_what_the_problem_has", list_holds_what_the_problem_has},
    {"stepped_equals_wind", stepped_equals_wind},
    {"driver_sets_tension", driver_sets_tension},
    {"ops_called_as_stated", ops_called_as_stated},
    {"phase_sets_tension_and_load", phase_sets_tension_and_load},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
