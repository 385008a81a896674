/* The scene schema: libcyaml descriptions of every key, and the plain structs libcyaml
 * loads them into. The same schema drives the positioned checks on the YAML tree
 * (typecheck.c), so unknown keys, types and required keys are reported against the
 * line a user wrote, and libcyaml then only does the typed load.
 * docs/scenes.md documents every key listed here. */
#ifndef RS_SCENE_SCHEMA_H
#define RS_SCENE_SCHEMA_H

#include <cyaml/cyaml.h>

#include "reelsim/material.h"
#include "reelsim/scene.h"

typedef struct ys_pair {
  double v[2];
} ys_pair;

typedef struct ys_recipe {
  int law; /* rs_recipe_kind */
  double value, start, end, k;
  ys_pair *table;
  unsigned table_count;
  ys_pair *points; /* alias of table */
  unsigned points_count;
} ys_recipe;

typedef struct ys_radial {
  int law; /* rs_radial_kind */
  double E_r, K1, K2;
  double C[RS_HAKIEL_MAX_COEF];
  unsigned C_count;
  ys_pair *points;
  unsigned points_count;
} ys_radial;

typedef struct ys_material {
  char *name, *source, *notes;
  double caliper, E_theta, nu_rtheta, G_rtheta, density;
  double pressure_limit, friction_layer; /* defect checks */
  double E_z, E_cd, nu_md_cd; /* the sheet in the contact nip (docs/nip.md) */
  ys_radial radial;
} ys_material;

typedef struct ys_core {
  double radius, stiffness, bore, modulus, poisson;
  double rating; /* defect check */
} ys_core;

typedef struct ys_winding {
  double final_radius, web_length;
  ys_recipe tension;
  double accel_torque; /* slip check */
} ys_winding;

typedef struct ys_friction {
  double roll, drum;
} ys_friction;

typedef struct ys_drum {
  double radius, core_radius, E, nu, E_r, E_theta, nu_rtheta, G_rtheta;
} ys_drum;

typedef struct ys_nip {
  int model; /* rs_nip_model_kind */
  ys_recipe load;
  ys_friction friction;
  int winder; /* rs_winder_kind */
  double torque_share;
  ys_drum drum;
  int nodes, terms;
  int update; /* rs_nip_update_kind */
  int update_every;
  double T0_rtol;
} ys_nip;

typedef struct ys_numerics {
  int layers_per_step;
  double rtol, atol;
  long max_steps;
  int reuse;
  int load_placement;
} ys_numerics;

typedef struct ys_output {
  char *file;
  int history_every;
  double *nip_profiles_at;
  unsigned nip_profiles_at_count;
} ys_output;

typedef struct ys_scene {
  char *title;
  ys_material material;
  ys_core core;
  ys_winding winding;
  ys_nip nip;
  ys_numerics numerics;
  ys_output output;
} ys_scene;

/* Top-level schema of a scene file (a pointer to ys_scene). */
extern const cyaml_schema_value_t ys_scene_schema;
/* A material mapping (a model file, or the inline `material:` value). */
extern const cyaml_schema_value_t ys_material_value;

/* Keys whose value may also be written as a plain number (a constant recipe) or a name
 * (a model file): the loader rewrites them into mappings before the schema applies. */
int ys_is_shorthand(const char *scene_path);

/* The schema of a mapping field by dotted path from the top level; NULL if the
 * schema has no such key. *parent_out (optional) receives the enclosing mapping. */
const cyaml_schema_value_t *ys_schema_at(const char *scene_path);

#endif
