/* The reel winds an rs_problem, plain data: a loaded scene winds exactly as its problem
 * does through rs_reel_wind, and a copy of the problem taken before the scene is destroyed
 * winds the same reel bit for bit (nothing in it points back into the scene). And the
 * scene's accessors give what the file says. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

static int same_doubles(const double *a, const double *b, int n)
{
  return n == 0 || memcmp(a, b, (size_t)n * sizeof *a) == 0;
}

/* Every stored figure of two results bitwise alike (the stress history too). */
static int same_result(const rs_reel_result *a, const rs_reel_result *b)
{
  const int n = a->n_layers;
  if (n != b->n_layers || memcmp(&a->core_pressure, &b->core_pressure, sizeof a->core_pressure))
    return 0;
  if (!same_doubles(a->radius, b->radius, n) || !same_doubles(a->sigma_r, b->sigma_r, n) ||
      !same_doubles(a->sigma_theta, b->sigma_theta, n) ||
      !same_doubles(a->wound_on_tension, b->wound_on_tension, n) ||
      !same_doubles(a->nip_load, b->nip_load, n))
    return 0;
  if (a->n_stages != b->n_stages || a->n_nip != b->n_nip) return 0;
  return same_doubles(a->stage_sigma_r, b->stage_sigma_r, a->n_stages * n) &&
         same_doubles(a->nip_T0, b->nip_T0, a->n_nip);
}

/* Winds `path` three ways: rs_scene_wind, rs_reel_wind(rs_scene_problem), and
 * rs_reel_wind of a copy of the problem after the scene is gone. */
static void three_ways(const char *path, int n_sets, const char **sets, int has_history,
                       int has_nip)
{
  rs_scene *sc = NULL;
  CHECK(rs_scene_load(path, n_sets, sets, &sc) == RS_OK);
  if (!sc) return;
  const rs_problem *pb = rs_scene_problem(sc);
  CHECK(pb != NULL && pb->n_layers > 0);
  rs_reel_result *by_scene = NULL, *by_problem = NULL, *by_copy = NULL;
  CHECK(rs_scene_wind(sc, NULL, &by_scene) == RS_OK);
  CHECK(rs_reel_wind(pb, NULL, &by_problem) == RS_OK);
  rs_problem copy = *pb;
  rs_scene_destroy(&sc);
  CHECK(rs_reel_wind(&copy, NULL, &by_copy) == RS_OK);
  CHECK(by_scene && by_problem && by_copy);
  if (by_scene && by_problem && by_copy) {
    CHECK(by_scene->n_layers == copy.n_layers);
    CHECK((by_scene->n_stages > 0) == has_history); /* the record and nip went through */
    CHECK((by_scene->n_nip > 0) == has_nip);
    CHECK(same_result(by_scene, by_problem));
    CHECK(same_result(by_scene, by_copy));
  }
  rs_reel_result_destroy(&by_scene);
  rs_reel_result_destroy(&by_problem);
  rs_reel_result_destroy(&by_copy);
}

/* 200 layers, linear law, rigid core, with a stress history (problem.record). */
static void plain_reel(void)
{
  const char *sets[] = {"output.history_every=50"};
  three_ways(RS_TESTS_DIR "/cli/scenes/small.yaml", 1, sets, 1, 0);
}

/* A friction nip with a table load recipe (problem.nip), adaptive nip updates. */
static void friction_nip(void)
{
  const char *sets[] = {"winding.final_radius=0.09"};
  three_ways(RS_TESTS_DIR "/validation/scenes/nip-friction-kinks.yaml", 1, sets, 0, 1);
}

/* What the scene says of itself, through the accessors the CLI uses. */
static void scene_accessors(void)
{
  const char *path = RS_TESTS_DIR "/cli/scenes/small.yaml";
  rs_scene *sc = NULL;
  CHECK(rs_scene_load(path, 0, NULL, &sc) == RS_OK);
  if (!sc) return;
  CHECK(strcmp(rs_scene_path(sc), path) == 0);
  CHECK(strcmp(rs_scene_title(sc), "small test reel") == 0);
  CHECK(strcmp(rs_scene_output_file(sc), "small.h5") == 0);
  CHECK(strstr(rs_scene_resolved_text(sc), "small test reel") != NULL);
  char name[8];
  rs_scene_name(sc, name, sizeof name);
  CHECK(strcmp(name, "small") == 0);
  rs_scene_name(sc, name, 4); /* truncated to fit */
  CHECK(strcmp(name, "sma") == 0);
  rs_scene_destroy(&sc);
  CHECK(sc == NULL);
  rs_scene_name(NULL, name, sizeof name);
  CHECK(strcmp(name, "") == 0);
  CHECK(strcmp(rs_scene_title(NULL), "") == 0 && strcmp(rs_scene_path(NULL), "") == 0);
}

/* No scene: no problem, and winding nothing is an error with no result. */
static void no_scene(void)
{
  CHECK(rs_scene_problem(NULL) == NULL);
  rs_reel_result *res = (rs_reel_result *)&res; /* not NULL: must be cleared */
  CHECK(rs_scene_wind(NULL, NULL, &res) == RS_ERR_INTERNAL);
  CHECK(res == NULL);
  rs_error_clear();
}

static const check_case cases[] = {
    {"plain_reel", plain_reel},
    {"friction_nip", friction_nip},
    {"scene_accessors", scene_accessors},
    {"no_scene", no_scene},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
