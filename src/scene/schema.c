/* The schema of scene and model files (see schema.h and docs/scenes.md). */
#include "scene/schema.h"

#include <stdio.h>
#include <string.h>

#include "reelsim/material.h"
#include "reelsim/problem.h"
#include "reelsim/recipe.h"
#include "reelsim/scene.h"

static const ys_value v_float = {.type = YS_FLOAT};
static const ys_value v_int = {.type = YS_INT};
static const ys_value v_long = {.type = YS_LONG};
static const ys_value v_pair = {.type = YS_LIST, .entry = &v_float, .min = 2, .max = 2, .exact = 1};
static const ys_value v_table = {.type = YS_LIST, .entry = &v_pair, .min = 1, .max = RS_TABLE_MAX};

#define STRING(lo, hi) {.type = YS_STRING, .min = (lo), .max = (hi)}
#define ENUM(list) {.type = YS_ENUM, .names = (list)}
#define MAP(list) {.type = YS_MAP, .fields = (list)}
#define REQ(k, v) {.key = (k), .required = 1, .value = (v)}
#define OPT(k, v) {.key = (k), .value = (v)}
/* optional, with a default (when the sibling `w` is / is not `is`) */
#define DEF(k, v, d) {.key = (k), .value = (v), .def = (d)}
#define DEF_WHEN(k, v, d, w, is) {.key = (k), .value = (v), .def = (d), .when = (w), .when_is = (is)}
#define END {.key = NULL}

/* ---- recipes: tension and nip load ------------------------------------------------ */
static const ys_name recipe_laws[] = {
    {"constant", RS_RECIPE_CONSTANT}, {"linear", RS_RECIPE_LINEAR},
    {"hyperbolic", RS_RECIPE_HYPERBOLIC}, {"torque", RS_RECIPE_TORQUE},
    {"table", RS_RECIPE_TABLE}, {NULL, 0}};
static const ys_value v_recipe_law = ENUM(recipe_laws);

static const ys_field recipe_fields[] = {
    REQ("law", &v_recipe_law), OPT("value", &v_float), OPT("start", &v_float),
    OPT("end", &v_float),      OPT("k", &v_float),     OPT("table", &v_table),
    OPT("points", &v_table),   END};
static const ys_value v_recipe = MAP(recipe_fields);

/* ---- material ----------------------------------------------------------------------- */
static const ys_name radial_laws[] = {{"linear", RS_RADIAL_LINEAR},
                                      {"pfeiffer", RS_RADIAL_PFEIFFER},
                                      {"hakiel", RS_RADIAL_HAKIEL},
                                      {"table", RS_RADIAL_TABLE},
                                      {NULL, 0}};
static const ys_value v_radial_law = ENUM(radial_laws);
static const ys_value v_coefs = {.type = YS_LIST, .entry = &v_float, .min = 1,
                                 .max = RS_HAKIEL_MAX_COEF};

static const ys_field radial_fields[] = {
    REQ("law", &v_radial_law), OPT("E_r", &v_float), OPT("K1", &v_float),
    OPT("K2", &v_float),       OPT("C", &v_coefs),   OPT("points", &v_table),
    END};
static const ys_value v_radial = MAP(radial_fields);

static const ys_value v_name = STRING(0, RS_NAME_MAX - 1);
static const ys_value v_source = STRING(0, RS_PATH_MAX - 1);
static const ys_value v_notes = STRING(0, 1u << 20);

/* After the winder (docs/storage.md): free strains and the Prony series of relaxation */
static const ys_field thermal_fields[] = {REQ("alpha_r", &v_float), REQ("alpha_theta", &v_float),
                                          END};
static const ys_value v_thermal = MAP(thermal_fields);
static const ys_field hygroscopic_fields[] = {REQ("beta_r", &v_float),
                                              REQ("beta_theta", &v_float), END};
static const ys_value v_hygroscopic = MAP(hygroscopic_fields);
static const ys_value v_prony = {.type = YS_LIST, .entry = &v_float, .min = 1,
                                 .max = RS_PRONY_MAX};
static const ys_field viscoelastic_fields[] = {
    REQ("tau", &v_prony), REQ("E_theta", &v_prony), REQ("radial", &v_prony), END};
static const ys_value v_viscoelastic = MAP(viscoelastic_fields);

static const ys_field material_fields[] = {
    DEF("name", &v_name, "inline"),
    OPT("source", &v_source),
    OPT("notes", &v_notes),
    REQ("caliper", &v_float),
    REQ("E_theta", &v_float),
    DEF("nu_rtheta", &v_float, "0"),
    OPT("G_rtheta", &v_float),
    OPT("density", &v_float),
    OPT("pressure_limit", &v_float),
    OPT("friction_layer", &v_float),
    OPT("E_z", &v_float),
    OPT("E_cd", &v_float),
    OPT("nu_md_cd", &v_float),
    REQ("radial", &v_radial),
    OPT("thermal", &v_thermal),
    OPT("hygroscopic", &v_hygroscopic),
    OPT("viscoelastic", &v_viscoelastic),
    OPT("model", &v_name), /* a shipped model these keys change (models.c); gone once inlined */
    OPT("roughness", &v_float),
    OPT("hoop_strength", &v_float),
    OPT("nit_saturation", &v_float),
    END};
static const ys_value v_material = MAP(material_fields);

/* ---- core and winding --------------------------------------------------------------- */
static const ys_field core_fields[] = {
    OPT("radius", &v_float),  OPT("stiffness", &v_float), OPT("bore", &v_float),
    OPT("modulus", &v_float), OPT("poisson", &v_float),   OPT("rating", &v_float),
    OPT("alpha", &v_float),   OPT("beta", &v_float),
    OPT("diameter", &v_float), OPT("inner_diameter", &v_float), OPT("wall", &v_float),
    OPT("friction", &v_float), END}; /* new keys go last: messages list the keys in order */
static const ys_value v_core = MAP(core_fields);

static const ys_field winding_fields[] = {
    OPT("final_radius", &v_float), OPT("web_length", &v_float), REQ("tension", &v_recipe),
    OPT("accel_torque", &v_float), DEF("temperature", &v_float, "23"),
    DEF("humidity", &v_float, "50"), OPT("final_diameter", &v_float), OPT("speed", &v_recipe),
    OPT("acceleration", &v_float), END};
static const ys_value v_winding = MAP(winding_fields);

/* ---- storage after the winder (docs/storage.md) ----------------------------------------- */
static const ys_field stage_fields[] = {REQ("hours", &v_float), OPT("temperature", &v_float),
                                        OPT("humidity", &v_float), END};
static const ys_value v_stage = MAP(stage_fields);
static const ys_value v_storage = {.type = YS_LIST, .entry = &v_stage, .min = 1,
                                   .max = RS_STORAGE_MAX_STAGES};

/* ---- nip ------------------------------------------------------------------------------ */
static const ys_name nip_models[] = {
    {"none", RS_NIP_NONE}, {"friction", RS_NIP_FRICTION}, {"contact", RS_NIP_CONTACT}, {NULL, 0}};
static const ys_value v_nip_model = ENUM(nip_models);
static const ys_name winders[] = {{"center", RS_WINDER_CENTER},
                                  {"surface", RS_WINDER_SURFACE},
                                  {"center-surface", RS_WINDER_CENTER_SURFACE},
                                  {NULL, 0}};
static const ys_value v_winder = ENUM(winders);
static const ys_name nip_updates[] = {
    {"adaptive", RS_NIP_UPDATE_ADAPTIVE}, {"every", RS_NIP_UPDATE_EVERY}, {NULL, 0}};
static const ys_value v_nip_update = ENUM(nip_updates);

/* a nip's place on a two-drum winder (docs/nip.md, "Two-drum winders") */
static const ys_name nip_positions[] = {{"front", RS_NIP_AT_FRONT},
                                        {"rear", RS_NIP_AT_REAR},
                                        {"rider", RS_NIP_AT_RIDER},
                                        {NULL, 0}};
static const ys_value v_nip_position = ENUM(nip_positions);

static const ys_field friction_fields[] = {OPT("roll", &v_float), OPT("drum", &v_float), END};
static const ys_value v_friction = MAP(friction_fields);

static const ys_field drum_fields[] = {
    REQ("radius", &v_float),  REQ("core_radius", &v_float), OPT("E", &v_float),
    OPT("nu", &v_float),      OPT("E_r", &v_float),         OPT("E_theta", &v_float),
    OPT("nu_rtheta", &v_float), OPT("G_rtheta", &v_float),  END};
static const ys_value v_drum = MAP(drum_fields);

/* The nip's defaults apply to a nip that is there (model other than none), each update
 * policy's only to its own knob. T0_rtol 1e-4, not 1e-3: on a reel whose T0 changes
 * (cases/newsprint-surface-taper.yaml) the policy's error dominated the defaults' and 1e-4
 * cut it 7x for 3% more time; where T0 does not change it costs nothing (docs/accuracy.md). */
static const ys_field nip_fields[] = {
    REQ("model", &v_nip_model),
    OPT("load", &v_recipe),
    OPT("friction", &v_friction),
    DEF_WHEN("winder", &v_winder, "center", "model", "!none"),
    DEF_WHEN("torque_share", &v_float, "0.5", "winder", "center-surface"),
    OPT("drum", &v_drum),
    DEF_WHEN("nodes", &v_int, "96", "model", "!none"),
    DEF_WHEN("terms", &v_int, "0", "model", "!none"),
    DEF_WHEN("update", &v_nip_update, "adaptive", "model", "!none"),
    DEF_WHEN("update_every", &v_int, "1", "update", "every"),
    DEF_WHEN("T0_rtol", &v_float, "1e-4", "update", "adaptive"),
    OPT("position", &v_nip_position),
    END};
/* `nip:` is one nip (a mapping) or several (a list of the same mappings) */
static const ys_value v_nip_entry = MAP(nip_fields);
static const ys_value v_nip_list = {.type = YS_LIST, .entry = &v_nip_entry, .min = 1,
                                    .max = RS_MAX_NIPS};
static const ys_value v_nip = {.type = YS_MAP, .fields = nip_fields, .list_form = &v_nip_list};

/* the winder that carries the roll (`winder: two_drum` is {type: two_drum}) */
static const ys_name winder_types[] = {{"center", RS_WINDER_TYPE_CENTER},
                                       {"surface", RS_WINDER_TYPE_SURFACE},
                                       {"two_drum", RS_WINDER_TYPE_TWO_DRUM},
                                       {NULL, 0}};
static const ys_value v_winder_type = ENUM(winder_types);
static const ys_field winder_block_fields[] = {REQ("type", &v_winder_type),
                                               OPT("drum_distance", &v_float),
                                               OPT("drum_radius", &v_float), END};
static const ys_value v_winder_block = MAP(winder_block_fields);

/* ---- numerics and output ------------------------------------------------------------- */
static const ys_name reuses[] = {{"deep", RS_REUSE_ON}, {"none", RS_REUSE_OFF},
                                 {"first-order", RS_REUSE_FIRST_ORDER}, {NULL, 0}};
static const ys_value v_reuse = ENUM(reuses);
static const ys_name placements[] = {
    {"beneath", RS_LOAD_BENEATH}, {"hakiel", RS_LOAD_HAKIEL}, {NULL, 0}};
static const ys_value v_placement = ENUM(placements);
static const ys_name corrections[] = {
    {"on", RS_CORRECTION_ON}, {"off", RS_CORRECTION_OFF}, {NULL, 0}};
static const ys_value v_correction = ENUM(corrections);

static const ys_field numerics_fields[] = {
    DEF("layers_per_step", &v_int, "1"),
    DEF("rtol", &v_float, "1e-3"), /* docs/accuracy.md: corrected, the stresses within ~4e-5 */
    DEF("atol", &v_float, "0"),
    DEF("max_steps", &v_long, "0"),
    DEF("reuse", &v_reuse, "deep"),
    DEF("load_placement", &v_placement, "beneath"),
    DEF("error_correction", &v_correction, "on"),
    END};
static const ys_value v_numerics = MAP(numerics_fields);

static const ys_value v_file = STRING(1, RS_PATH_MAX - 1);
static const ys_value v_profiles = {.type = YS_LIST, .entry = &v_float, .min = 0,
                                    .max = RS_MAX_PROFILES};
static const ys_field output_fields[] = {
    {.key = "file", .value = &v_file, .derived = YS_FROM_STEM_H5},
    DEF("history_every", &v_int, "0"),
    OPT("nip_profiles_at", &v_profiles),
    END};
static const ys_value v_output = MAP(output_fields);

/* ---- winding at speed (docs/roll-model.md, "Centrifugal load") ------------------------ */
static const ys_field centrifugal_fields[] = {END};
static const ys_value v_centrifugal = MAP(centrifugal_fields);
/* entrained air (docs/roll-model.md, "Entrained air"): air at 20 C, the sea-level atmosphere */
static const ys_field air_fields[] = {
    DEF("viscosity", &v_float, "1.8e-5"), OPT("roughness", &v_float),
    DEF("cutoff", &v_float, "3"),         DEF("pressure", &v_float, "101325"),
    OPT("nip_radius", &v_float),          DEF("moving_surfaces", &v_int, "2"), END};
static const ys_value v_air = MAP(air_fields);

/* ---- lanes across the width (docs/lanes.md) ------------------------------------------ *
 * lists up to 4096 long: more than RS_LANES_MAX lanes is the resolution's error, at its key */
static const ys_name lane_nips[] = {
    {"uniform", RS_LANES_NIP_UNIFORM}, {"roller", RS_LANES_NIP_ROLLER}, {NULL, 0}};
static const ys_value v_lane_nip = ENUM(lane_nips);
static const ys_value v_lane_list = {.type = YS_LIST, .entry = &v_float, .min = 1, .max = 4096};
static const ys_value v_lane_profile = {.type = YS_LIST, .entry = &v_pair, .min = 1,
                                        .max = RS_TABLE_MAX};
static const ys_field lanes_fields[] = {
    OPT("width", &v_float),           OPT("count", &v_int),
    OPT("edges", &v_lane_list),       OPT("caliper", &v_lane_list),
    OPT("caliper_profile", &v_lane_profile), OPT("tension_profile", &v_lane_profile),
    DEF("nip", &v_lane_nip, "uniform"), END};
static const ys_value v_lanes = MAP(lanes_fields);

/* ---- the scene ------------------------------------------------------------------------ */
static const ys_value v_title = STRING(0, 511);
static const ys_field scene_fields[] = {
    {.key = "title", .value = &v_title, .derived = YS_FROM_STEM},
    REQ("material", &v_material),
    REQ("core", &v_core),
    REQ("winding", &v_winding),
    OPT("nip", &v_nip),
    OPT("storage", &v_storage),
    OPT("centrifugal", &v_centrifugal),
    OPT("air", &v_air),
    OPT("lanes", &v_lanes),
    DEF("numerics", &v_numerics, "{}"),
    DEF("output", &v_output, "{}"),
    OPT("winder", &v_winder_block),
    END};
const ys_value rsi_ys_scene_schema = MAP(scene_fields);

int rsi_ys_is_shorthand(const char *p)
{
  long k;
  char seg[4][YN_SEG_MAX];
  /* a list entry's load: nip[1].load */
  if (rsi_yn_path_split(p, seg, 4) == 3 && strcmp(seg[0], "nip") == 0 && rsi_yn_seg_index(seg[1], &k) &&
      strcmp(seg[2], "load") == 0)
    return 1;
  return strcmp(p, "material") == 0 || strcmp(p, "winding.tension") == 0 ||
         strcmp(p, "winding.speed") == 0 ||
         strcmp(p, "nip.load") == 0 || strcmp(p, "winder") == 0;
}

const ys_value *rsi_ys_schema_form(const ys_value *s, const yn *node)
{
  return s && s->list_form && node && node->kind == YN_SEQ ? s->list_form : s;
}

const ys_value *rsi_ys_schema_at(const char *path)
{
  char seg[32][YN_SEG_MAX];
  int n = rsi_yn_path_split(path, seg, 32);
  const ys_value *s = n < 0 ? NULL : &rsi_ys_scene_schema;
  for (int i = 0; s && i < n; ++i) {
    long k;
    if (s->list_form && rsi_yn_seg_index(seg[i], &k)) s = s->list_form; /* "nip[1]" */
    if (s->type == YS_LIST) {
      s = rsi_yn_seg_index(seg[i], &k) ? s->entry : NULL;
      continue;
    }
    if (s->type != YS_MAP) return NULL;
    const ys_field *f = s->fields;
    while (f->key && strcmp(f->key, seg[i]) != 0) ++f;
    s = f->key ? f->value : NULL;
  }
  return s;
}

void rsi_ys_schema_keys(const ys_value *mapping, char *buf, size_t size)
{
  size_t len = 0;
  buf[0] = '\0';
  if (mapping->type != YS_MAP) {
    snprintf(buf, size, "(none)");
    return;
  }
  for (const ys_field *f = mapping->fields; f->key; ++f) {
    int n = snprintf(buf + len, size - len, "%s%s", len ? ", " : "", f->key);
    if (n < 0 || (size_t)n >= size - len) break;
    len += (size_t)n;
  }
}
