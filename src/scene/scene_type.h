/* The scene's fields (private to the library: applications use the functions of
 * reelsim/scene.h). Filled by the loader (src/scene); read by the scene's accessors and by
 * tests that build scenes by hand. Plain data: the scene owns nothing but `resolved_text`,
 * freed by rs_scene_destroy. */
#ifndef RS_SCENE_TYPE_H
#define RS_SCENE_TYPE_H

#include "reelsim/problem.h"
#include "reelsim/scene.h"

enum { RS_SCENE_MAX_WARNINGS = 16 };

typedef struct rs_output_spec {
  char file[RS_PATH_MAX];  /* HDF5 output; "" = none unless -o */
} rs_output_spec;

struct rs_scene {
  char path[RS_PATH_MAX];           /* the scene file as given */
  char title[512];
  char material_source[RS_PATH_MAX];/* models/ file the material came from, or "inline" */
  rs_problem problem;               /* what the reel winds: physics and numerics */
  double web_length;                /* m (0 when final_radius was given) */
  rs_output_spec output;
  char *resolved_text;              /* the resolved scene as YAML (owned) */
  /* numbers written with a unit and what they became, for the resolved scene's header
   * ("# units: material.caliper: 20 um = 2e-05 m"; units.c) */
  char units_text[2048];
  /* slip warnings: values outside the range plants use (ranges.c) */
  int n_warnings;
  char warnings[RS_SCENE_MAX_WARNINGS][320];
};

#endif
