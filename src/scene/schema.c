/* libcyaml schema of scene and model files (see schema.h and docs/scenes.md). */
#include "scene/schema.h"

#include <stdlib.h>
#include <string.h>

#include "reelsim/recipe.h"
#include "scene/ytree.h"

#define OPT CYAML_FLAG_OPTIONAL
#define REQ CYAML_FLAG_DEFAULT

static const cyaml_schema_value_t float_entry = {CYAML_VALUE_FLOAT(CYAML_FLAG_DEFAULT, double)};
static const cyaml_schema_value_t pair_entry = {
    CYAML_VALUE_SEQUENCE_FIXED(CYAML_FLAG_DEFAULT, double, &float_entry, 2)};

/* ---- recipes: tension and nip load ------------------------------------------------ */
static const cyaml_strval_t recipe_laws[] = {
    {"constant", RS_RECIPE_CONSTANT},     {"linear", RS_RECIPE_LINEAR},
    {"hyperbolic", RS_RECIPE_HYPERBOLIC}, {"torque", RS_RECIPE_TORQUE},
    {"table", RS_RECIPE_TABLE},
};

static const cyaml_schema_field_t recipe_fields[] = {
    CYAML_FIELD_ENUM("law", REQ | CYAML_FLAG_STRICT, ys_recipe, law, recipe_laws,
                     CYAML_ARRAY_LEN(recipe_laws)),
    CYAML_FIELD_FLOAT("value", OPT, ys_recipe, value),
    CYAML_FIELD_FLOAT("start", OPT, ys_recipe, start),
    CYAML_FIELD_FLOAT("end", OPT, ys_recipe, end),
    CYAML_FIELD_FLOAT("k", OPT, ys_recipe, k),
    CYAML_FIELD_SEQUENCE("table", CYAML_FLAG_POINTER | OPT, ys_recipe, table, &pair_entry, 1,
                         RS_TABLE_MAX),
    CYAML_FIELD_SEQUENCE("points", CYAML_FLAG_POINTER | OPT, ys_recipe, points, &pair_entry, 1,
                         RS_TABLE_MAX),
    CYAML_FIELD_END};

/* ---- material ----------------------------------------------------------------------- */
static const cyaml_strval_t radial_laws[] = {
    {"linear", RS_RADIAL_LINEAR},
    {"pfeiffer", RS_RADIAL_PFEIFFER},
    {"hakiel", RS_RADIAL_HAKIEL},
    {"table", RS_RADIAL_TABLE},
};

static const cyaml_schema_field_t radial_fields[] = {
    CYAML_FIELD_ENUM("law", REQ | CYAML_FLAG_STRICT, ys_radial, law, radial_laws,
                     CYAML_ARRAY_LEN(radial_laws)),
    CYAML_FIELD_FLOAT("E_r", OPT, ys_radial, E_r),
    CYAML_FIELD_FLOAT("K1", OPT, ys_radial, K1),
    CYAML_FIELD_FLOAT("K2", OPT, ys_radial, K2),
    CYAML_FIELD_SEQUENCE("C", OPT, ys_radial, C, &float_entry, 1, RS_HAKIEL_MAX_COEF),
    CYAML_FIELD_SEQUENCE("points", CYAML_FLAG_POINTER | OPT, ys_radial, points, &pair_entry, 1,
                         RS_TABLE_MAX),
    CYAML_FIELD_END};

static const cyaml_schema_field_t material_fields[] = {
    CYAML_FIELD_STRING_PTR("name", CYAML_FLAG_POINTER | OPT, ys_material, name, 0,
                           RS_NAME_MAX - 1),
    CYAML_FIELD_STRING_PTR("source", CYAML_FLAG_POINTER | OPT, ys_material, source, 0,
                           RS_PATH_MAX - 1),
    CYAML_FIELD_STRING_PTR("notes", CYAML_FLAG_POINTER | OPT, ys_material, notes, 0,
                           CYAML_UNLIMITED),
    CYAML_FIELD_FLOAT("caliper", REQ, ys_material, caliper),
    CYAML_FIELD_FLOAT("E_theta", REQ, ys_material, E_theta),
    CYAML_FIELD_FLOAT("nu_rtheta", OPT, ys_material, nu_rtheta),
    CYAML_FIELD_FLOAT("G_rtheta", OPT, ys_material, G_rtheta),
    CYAML_FIELD_FLOAT("density", OPT, ys_material, density),
    CYAML_FIELD_FLOAT("pressure_limit", OPT, ys_material, pressure_limit),
    CYAML_FIELD_FLOAT("friction_layer", OPT, ys_material, friction_layer),
    CYAML_FIELD_FLOAT("E_z", OPT, ys_material, E_z),
    CYAML_FIELD_FLOAT("E_cd", OPT, ys_material, E_cd),
    CYAML_FIELD_FLOAT("nu_md_cd", OPT, ys_material, nu_md_cd),
    CYAML_FIELD_MAPPING("radial", REQ, ys_material, radial, radial_fields),
    CYAML_FIELD_END};

const cyaml_schema_value_t ys_material_value = {
    CYAML_VALUE_MAPPING(CYAML_FLAG_DEFAULT, ys_material, material_fields)};

/* ---- core and winding --------------------------------------------------------------- */
static const cyaml_schema_field_t core_fields[] = {
    CYAML_FIELD_FLOAT("radius", REQ, ys_core, radius),
    CYAML_FIELD_FLOAT("stiffness", OPT, ys_core, stiffness),
    CYAML_FIELD_FLOAT("bore", OPT, ys_core, bore),
    CYAML_FIELD_FLOAT("modulus", OPT, ys_core, modulus),
    CYAML_FIELD_FLOAT("poisson", OPT, ys_core, poisson),
    CYAML_FIELD_FLOAT("rating", OPT, ys_core, rating),
    CYAML_FIELD_END};

static const cyaml_schema_field_t winding_fields[] = {
    CYAML_FIELD_FLOAT("final_radius", OPT, ys_winding, final_radius),
    CYAML_FIELD_FLOAT("web_length", OPT, ys_winding, web_length),
    CYAML_FIELD_MAPPING("tension", REQ, ys_winding, tension, recipe_fields),
    CYAML_FIELD_FLOAT("accel_torque", OPT, ys_winding, accel_torque),
    CYAML_FIELD_END};

/* ---- nip ------------------------------------------------------------------------------ */
static const cyaml_strval_t nip_models[] = {
    {"none", RS_NIP_NONE},
    {"friction", RS_NIP_FRICTION},
    {"contact", RS_NIP_CONTACT},
};

static const cyaml_strval_t winders[] = {
    {"center", RS_WINDER_CENTER},
    {"surface", RS_WINDER_SURFACE},
    {"center-surface", RS_WINDER_CENTER_SURFACE},
};

static const cyaml_strval_t nip_updates[] = {
    {"adaptive", RS_NIP_UPDATE_ADAPTIVE},
    {"every", RS_NIP_UPDATE_EVERY},
};

static const cyaml_schema_field_t friction_fields[] = {
    CYAML_FIELD_FLOAT("roll", OPT, ys_friction, roll),
    CYAML_FIELD_FLOAT("drum", OPT, ys_friction, drum),
    CYAML_FIELD_END};

static const cyaml_schema_field_t drum_fields[] = {
    CYAML_FIELD_FLOAT("radius", REQ, ys_drum, radius),
    CYAML_FIELD_FLOAT("core_radius", REQ, ys_drum, core_radius),
    CYAML_FIELD_FLOAT("E", OPT, ys_drum, E),
    CYAML_FIELD_FLOAT("nu", OPT, ys_drum, nu),
    CYAML_FIELD_FLOAT("E_r", OPT, ys_drum, E_r),
    CYAML_FIELD_FLOAT("E_theta", OPT, ys_drum, E_theta),
    CYAML_FIELD_FLOAT("nu_rtheta", OPT, ys_drum, nu_rtheta),
    CYAML_FIELD_FLOAT("G_rtheta", OPT, ys_drum, G_rtheta),
    CYAML_FIELD_END};

static const cyaml_schema_field_t nip_fields[] = {
    CYAML_FIELD_ENUM("model", REQ | CYAML_FLAG_STRICT, ys_nip, model, nip_models,
                     CYAML_ARRAY_LEN(nip_models)),
    CYAML_FIELD_MAPPING("load", OPT, ys_nip, load, recipe_fields),
    CYAML_FIELD_MAPPING("friction", OPT, ys_nip, friction, friction_fields),
    CYAML_FIELD_ENUM("winder", OPT | CYAML_FLAG_STRICT, ys_nip, winder, winders,
                     CYAML_ARRAY_LEN(winders)),
    CYAML_FIELD_FLOAT("torque_share", OPT, ys_nip, torque_share),
    CYAML_FIELD_MAPPING("drum", OPT, ys_nip, drum, drum_fields),
    CYAML_FIELD_INT("nodes", OPT, ys_nip, nodes),
    CYAML_FIELD_INT("terms", OPT, ys_nip, terms),
    CYAML_FIELD_ENUM("update", OPT | CYAML_FLAG_STRICT, ys_nip, update, nip_updates,
                     CYAML_ARRAY_LEN(nip_updates)),
    CYAML_FIELD_INT("update_every", OPT, ys_nip, update_every),
    CYAML_FIELD_FLOAT("T0_rtol", OPT, ys_nip, T0_rtol),
    CYAML_FIELD_END};

/* ---- numerics and output ------------------------------------------------------------- */
static const cyaml_strval_t numerics_reuses[] = {
    {"deep", RS_REUSE_ON},
    {"none", RS_REUSE_OFF},
};

static const cyaml_strval_t numerics_placements[] = {
    {"beneath", RS_LOAD_BENEATH},
    {"hakiel", RS_LOAD_HAKIEL},
};

static const cyaml_schema_field_t numerics_fields[] = {
    CYAML_FIELD_INT("layers_per_step", OPT, ys_numerics, layers_per_step),
    CYAML_FIELD_FLOAT("rtol", OPT, ys_numerics, rtol),
    CYAML_FIELD_FLOAT("atol", OPT, ys_numerics, atol),
    CYAML_FIELD_INT("max_steps", OPT, ys_numerics, max_steps),
    CYAML_FIELD_ENUM("reuse", OPT | CYAML_FLAG_STRICT, ys_numerics, reuse, numerics_reuses,
                     CYAML_ARRAY_LEN(numerics_reuses)),
    CYAML_FIELD_ENUM("load_placement", OPT | CYAML_FLAG_STRICT, ys_numerics, load_placement,
                     numerics_placements, CYAML_ARRAY_LEN(numerics_placements)),
    CYAML_FIELD_END};

static const cyaml_schema_field_t output_fields[] = {
    CYAML_FIELD_STRING_PTR("file", CYAML_FLAG_POINTER | OPT, ys_output, file, 1,
                           RS_PATH_MAX - 1),
    CYAML_FIELD_INT("history_every", OPT, ys_output, history_every),
    CYAML_FIELD_SEQUENCE("nip_profiles_at", CYAML_FLAG_POINTER | OPT, ys_output, nip_profiles_at,
                         &float_entry, 0, RS_MAX_PROFILES),
    CYAML_FIELD_END};

/* ---- the scene ------------------------------------------------------------------------ */
static const cyaml_schema_field_t scene_fields[] = {
    CYAML_FIELD_STRING_PTR("title", CYAML_FLAG_POINTER | OPT, ys_scene, title, 0, 511),
    CYAML_FIELD_MAPPING("material", REQ, ys_scene, material, material_fields),
    CYAML_FIELD_MAPPING("core", REQ, ys_scene, core, core_fields),
    CYAML_FIELD_MAPPING("winding", REQ, ys_scene, winding, winding_fields),
    CYAML_FIELD_MAPPING("nip", OPT, ys_scene, nip, nip_fields),
    CYAML_FIELD_MAPPING("numerics", OPT, ys_scene, numerics, numerics_fields),
    CYAML_FIELD_MAPPING("output", OPT, ys_scene, output, output_fields),
    CYAML_FIELD_END};

const cyaml_schema_value_t ys_scene_schema = {
    CYAML_VALUE_MAPPING(CYAML_FLAG_POINTER, ys_scene, scene_fields)};

int ys_is_shorthand(const char *p)
{
  return strcmp(p, "material") == 0 || strcmp(p, "winding.tension") == 0 ||
         strcmp(p, "nip.load") == 0;
}

const cyaml_schema_value_t *ys_schema_at(const char *path)
{
  char seg[32][YN_SEG_MAX];
  int n = yn_path_split(path, seg, 32);
  const cyaml_schema_value_t *s = n < 0 ? NULL : &ys_scene_schema;
  for (int i = 0; s && i < n; ++i) {
    if (s->type == CYAML_SEQUENCE || s->type == CYAML_SEQUENCE_FIXED) {
      long k;
      s = yn_seg_index(seg[i], &k) ? s->sequence.entry : NULL;
      continue;
    }
    if (s->type != CYAML_MAPPING) return NULL;
    const cyaml_schema_field_t *f = s->mapping.fields;
    while (f->key && strcmp(f->key, seg[i]) != 0) ++f;
    s = f->key ? &f->value : NULL;
  }
  return s;
}
