/* Helpers of the lanes' tests (tests/validation/test_lanes*.c): a scene's problem, lanes set
 * on it, a reel wound with its failure printed. */
#ifndef RS_TESTS_LANES_HELPERS_H
#define RS_TESTS_LANES_HELPERS_H

#include <stdio.h>
#include <string.h>

#include <stdlib.h>

#include "check.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

/* the problem of a scene with n_sets overrides (malloc'd; NULL, with the error printed and a
 * failed check, when the scene does not load) */
static inline rs_problem *load_problem(const char *scene, int n_sets, const char **sets)
{
  rs_scene *sc = NULL;
  if (rs_scene_load(scene, n_sets, sets, &sc) != RS_OK) printf("  error: %s\n", rs_error_message());
  CHECK(sc != NULL);
  if (!sc) return NULL;
  rs_problem *pb = malloc(sizeof *pb);
  *pb = *rs_scene_problem(sc);
  rs_scene_destroy(&sc);
  return pb;
}

/* n lanes of widths w (NULL: W / n each, W the width) side by side from x = 0, with the
 * caliper factors f (NULL: 1) and a uniform entry tension */
static inline void set_lanes_widths(rs_problem *pb, int n, double W, const double *w,
                                    const double *f)
{
  memset(&pb->lanes, 0, sizeof pb->lanes);
  pb->lanes.count = n;
  double x = 0.0;
  for (int i = 0; i < n; ++i) {
    pb->lanes.width[i] = w ? w[i] : W / n;
    pb->lanes.x[i] = w ? x + 0.5 * w[i] : W * (i + 0.5) / n;
    x += pb->lanes.width[i];
    pb->lanes.caliper[i] = f ? f[i] : 1.0;
    pb->lanes.tension[i] = 1.0;
  }
}

/* n equal lanes over width W with the caliper factors f (NULL: 1) */
static inline void set_lanes(rs_problem *pb, int n, double W, const double *f)
{
  set_lanes_widths(pb, n, W, NULL, f);
}

/* the reel wound (NULL, with the error printed and a failed check, when it fails) */
static inline rs_reel_result *wind(const rs_problem *pb)
{
  rs_reel_result *res = NULL;
  rs_status st = rs_reel_wind(pb, NULL, &res);
  if (st) printf("  error: %s\n", rs_error_message());
  CHECK(st == RS_OK && res);
  return st ? (rs_reel_result_destroy(&res), NULL) : res;
}

/* a 2 % thick band in the middle of 5 equal lanes over 1 m */
static inline void set_band(rs_problem *pb)
{
  const double f[] = {1.0, 1.0, 1.02, 1.0, 1.0};
  set_lanes(pb, 5, 1.0, f);
}

#endif
