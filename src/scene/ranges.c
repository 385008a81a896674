/* The scene's numeric keys: unit, hard bounds and the range plants use (docs/scenes.md
 * shows each beside its key), and the walk over a tree's numbers; the checks that hold the
 * resolved values to the table are bounds.c, the conversion of units units.c.
 *
 * A value beyond a hard bound cannot be meant (a caliper of 20 mm, a modulus of 1e308 Pa)
 * and is refused (exit 2) with the unit slip that would explain it; a value inside the
 * bounds but outside what plants use (a winding speed of 600 m/s) still runs, with a
 * warning naming the slip. The bounds sit far outside the plant ranges, so that no
 * real roll is refused; the solver's own limits are not what they guard. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/ranges.h"
#include "scene/scene_internal.h"

#define NONE NAN
/* key, unit, hard low, hard high, plant low, plant high, likely slips */
static const ys_range table[] = {
    {"material.caliper", "m", 1e-9, 1e-2, 0.5e-6, 2e-3, "um mm mil"}, /* capacitor films: 0.5 um */
    {"material.E_theta", "Pa", 1, 1e13, 1e7, 5e11, "kPa MPa GPa psi"},
    {"material.nu_rtheta", "", -1, 1, NONE, NONE, ""},
    {"material.G_rtheta", "Pa", 1, 1e13, 1e4, 5e11, "kPa MPa GPa"},
    {"material.density", "kg/m3", 1, 1e5, 100, 1e4, "g/cm3"},
    {"material.pressure_limit", "Pa", 1, 1e12, 1e4, 1e10, "kPa MPa psi"},
    {"material.friction_layer", "", 0, 10, 0.05, 2, ""},
    {"material.hoop_strength", "Pa", 1, 1e12, 1e5, 1e9, "kPa MPa psi"},
    {"material.nit_saturation", "N/m", 1e-3, 1e7, 5, 2e4, "kN/m N/mm pli"},
    {"material.E_z", "Pa", 1, 1e13, 1e4, 5e11, "kPa MPa GPa"},
    {"material.E_cd", "Pa", 1, 1e13, 1e7, 5e11, "kPa MPa GPa"},
    {"material.nu_md_cd", "", -1, 1, NONE, NONE, ""},
    {"material.roughness", "m", 0, 1e-3, 0, 2e-5, "um"},
    {"material.radial.E_r", "Pa", 1, 1e13, 1e3, 5e11, "kPa MPa GPa"},
    {"material.radial.K1", "Pa", 1e-3, 1e12, 1, 1e8, "kPa MPa"},
    {"material.radial.K2", "", 1e-6, 1e6, 0.1, 1e4, ""},
    /* C0, C1 P, C2 P^2, ...: each coefficient its own unit (Pa, 1, 1/Pa, ...) */
    {"material.radial.C", "", -1e300, 1e300, NONE, NONE, ""},
    {"material.radial.points", "Pa|Pa", 1, 1e13, 1e3, 5e11, "kPa MPa GPa"},
    {"material.thermal.alpha_r", "1/K", -1e-2, 1e-2, -1e-3, 1e-3, ""},
    {"material.thermal.alpha_theta", "1/K", -1e-2, 1e-2, -1e-3, 1e-3, ""},
    {"material.hygroscopic.beta_r", "", -0.1, 0.1, -1e-2, 1e-2, ""},
    {"material.hygroscopic.beta_theta", "", -0.1, 0.1, -1e-2, 1e-2, ""},
    {"material.viscoelastic.tau", "h", 1e-9, 1e9, NONE, NONE, ""},
    {"material.viscoelastic.E_theta", "", 0, 1, NONE, NONE, ""},
    {"material.viscoelastic.radial", "", 0, 1, NONE, NONE, ""},
    {"core.radius", "m", 1e-3, 5, 0.01, 0.15, "mm in"},
    {"core.diameter", "m", 2e-3, 10, 0.02, 0.3, "mm in"},
    {"core.inner_diameter", "m", 0, 10, 0.01, 0.3, "mm in"},
    {"core.wall", "m", 1e-5, 5, 1e-3, 0.05, "mm in"},
    {"core.stiffness", "Pa", 1, 1e13, 1e5, 5e11, "kPa MPa GPa psi"},
    {"core.bore", "m", 0, 5, 0, 0.15, "mm in"},
    {"core.modulus", "Pa", 1, 1e13, 1e7, 5e11, "MPa GPa psi"},
    {"core.poisson", "", -1, 0.5, NONE, NONE, ""},
    {"core.rating", "Pa", 1, 1e12, 1e4, 1e10, "kPa MPa psi"},
    {"core.alpha", "1/K", -1e-2, 1e-2, -1e-3, 1e-3, ""},
    {"core.beta", "", -0.1, 0.1, -1e-2, 1e-2, ""},
    {"core.friction", "", 0, 10, 0.05, 2, ""},
    {"winding.final_radius", "m", 1e-3, 20, 0.02, 2, "mm in"},
    {"winding.final_diameter", "m", 2e-3, 40, 0.04, 4, "mm in"},
    {"winding.web_length", "m", 1e-6, 1e9, 1, 2e6, "km ft"},
    {"winding.accel_torque", "N", 0, 1e8, NONE, NONE, ""},
    {"winding.acceleration", "m/s2", 0, 1e4, 0, 10, ""},
    {"winding.temperature", "degC", -200, 500, -30, 100, "degF"},
    {"winding.humidity", "", 0, 100, NONE, NONE, ""},
    {"winding.tension.value", "N/m", 0, 1e7, 5, 1e4, "kN/m N/mm pli"},
    {"winding.tension.start", "N/m", 0, 1e7, 5, 1e4, "kN/m N/mm pli"},
    {"winding.tension.end", "N/m", 0, 1e7, 5, 1e4, "kN/m N/mm pli"},
    {"winding.tension.k", "", -1e6, 1e6, NONE, NONE, ""},
    {"winding.tension.table", "m|N/m", 0, 1e7, 5, 1e4, "kN/m N/mm pli"},
    {"winding.tension.points", "m|N/m", 0, 1e7, 5, 1e4, "kN/m N/mm pli"},
    {"winding.speed.value", "m/s", 0, 1000, 0, 50, "m/min ft/min"},
    {"winding.speed.start", "m/s", 0, 1000, 0, 50, "m/min ft/min"},
    {"winding.speed.end", "m/s", 0, 1000, 0, 50, "m/min ft/min"},
    {"winding.speed.k", "", -1e6, 1e6, NONE, NONE, ""},
    {"winding.speed.table", "m|m/s", 0, 1000, 0, 50, "m/min ft/min"},
    {"winding.speed.points", "m|m/s", 0, 1000, 0, 50, "m/min ft/min"},
    {"nip.load.value", "N/m", 0, 1e8, 10, 2e5, "kN/m N/mm pli"},
    {"nip.load.start", "N/m", 0, 1e8, 10, 2e5, "kN/m N/mm pli"},
    {"nip.load.end", "N/m", 0, 1e8, 10, 2e5, "kN/m N/mm pli"},
    {"nip.load.k", "", -1e6, 1e6, NONE, NONE, ""},
    {"nip.load.table", "m|N/m", 0, 1e8, 10, 2e5, "kN/m N/mm pli"},
    {"nip.load.points", "m|N/m", 0, 1e8, 10, 2e5, "kN/m N/mm pli"},
    {"nip.friction.roll", "", 0, 10, 0.02, 2, ""},
    {"nip.friction.drum", "", 0, 10, 0.02, 2, ""},
    {"nip.torque_share", "", 0, 1, NONE, NONE, ""},
    {"nip.T0_rtol", "", 1e-12, 0.5, NONE, NONE, ""},
    {"nip.drum.radius", "m", 1e-3, 10, 0.01, 1.5, "mm in"},
    {"nip.drum.core_radius", "m", 0, 10, 0, 1.5, "mm in"},
    {"nip.drum.E", "Pa", 1, 1e13, 1e5, 5e11, "MPa GPa psi"},
    {"nip.drum.nu", "", -1, 0.5, NONE, NONE, ""},
    {"nip.drum.E_r", "Pa", 1, 1e13, 1e5, 5e11, "MPa GPa psi"},
    {"nip.drum.E_theta", "Pa", 1, 1e13, 1e5, 5e11, "MPa GPa psi"},
    {"nip.drum.nu_rtheta", "", -1, 1, NONE, NONE, ""},
    {"nip.drum.G_rtheta", "Pa", 1, 1e13, 1e4, 5e11, "MPa GPa psi"},
    {"storage.hours", "h", 0, 1e6, 0, 2e4, "min s"},
    {"storage.temperature", "degC", -200, 500, -40, 100, "degF"},
    {"storage.humidity", "", 0, 100, NONE, NONE, ""},
    {"numerics.rtol", "", 1e-12, 0.1, NONE, NONE, ""},
    {"numerics.atol", "", 0, 1, NONE, NONE, ""},
    {"output.nip_profiles_at", "m", 0, 20, NONE, NONE, "mm in"},
    {"air.viscosity", "Pa.s", 1e-7, 10, 5e-6, 1e-4, "mPa.s"},
    {"air.roughness", "m", 0, 1e-3, 0, 2e-5, "um"},
    {"air.cutoff", "", 0, 1e3, NONE, NONE, ""},
    {"air.pressure", "Pa", 1, 1e9, 3e4, 3e5, "kPa bar psi"},
    {"air.nip_radius", "m", 1e-3, 10, 0.01, 1.5, "mm in"},
    {"winder.drum_distance", "m", 2e-3, 40, 0.1, 4, "mm in"},
    {"winder.drum_radius", "m", 1e-3, 10, 0.05, 1.5, "mm in"},
    {"lanes.width", "m", 1e-4, 100, 0.05, 12, "mm in"},
    {"lanes.edges", "m", -100, 100, -12, 12, "mm in"},
    {"lanes.caliper", "", 0, 100, 0.5, 2, ""},
    {"lanes.caliper_profile", "m|", 0, 100, 0.5, 2, ""},
    {"lanes.tension_profile", "m|", 0, 100, 0.2, 5, ""},
};

const ys_range *rsi_ys_ranges(int *n)
{
  *n = (int)(sizeof table / sizeof table[0]);
  return table;
}

const ys_range *rsi_ys_range_of(const char *path)
{
  char key[256];
  size_t len = 0;
  for (const char *p = path; *p && len + 1 < sizeof key; ++p) { /* drop "[3]" */
    if (*p == '[') {
      while (*p && *p != ']') ++p;
      if (!*p) break;
      continue;
    }
    key[len++] = *p;
  }
  key[len] = '\0';
  for (size_t i = 0; i < sizeof table / sizeof table[0]; ++i)
    if (strcmp(table[i].path, key) == 0) return &table[i];
  return NULL;
}

/* ---- walking the numbers of the tree along the schema --------------------------------- */
static int is_pair_list(const ys_value *s)
{
  return s->type == YS_LIST && s->entry->type == YS_LIST && s->entry->exact &&
         s->entry->entry->type == YS_FLOAT;
}

static rs_status walk(yn *node, const ys_value *s, const char *path, ys_number_fn fn, void *ctx);

static rs_status visit(yn *node, const char *path, int column, ys_number_fn fn, void *ctx)
{
  if (node->kind != YN_SCALAR) return RS_OK;
  return fn(node, path, column, ctx);
}

static rs_status walk(yn *node, const ys_value *s, const char *path, ys_number_fn fn, void *ctx)
{
  rs_status bad = RS_OK, st = RS_OK;
  s = rsi_ys_schema_form(s, node);
  if (s->type == YS_FLOAT) return visit(node, path, -1, fn, ctx);
  if (s->type == YS_LIST && node->kind == YN_SEQ) {
    int pairs = is_pair_list(s);
    for (int i = 0; i < node->n; ++i) {
      yn *kid = node->kids[i];
      if (!pairs) st = walk(kid, s->entry, path, fn, ctx);
      for (int j = 0; pairs && kid->kind == YN_SEQ && j < kid->n && j < 2; ++j) {
        st = visit(kid->kids[j], path, j, fn, ctx);
        if (st != RS_OK) break;
      }
      if (st != RS_OK && st != RS_ERR_INPUT) return st;
      if (st != RS_OK) bad = st;
    }
  }
  if (s->type == YS_MAP && node->kind == YN_MAP) {
    for (int i = 0; i < node->n; ++i) {
      const ys_field *f = s->fields;
      while (f->key && strcmp(f->key, node->keys[i]) != 0) ++f;
      if (!f->key) continue;
      char sub[256];
      snprintf(sub, sizeof sub, "%s%s%s", path, path[0] ? "." : "", f->key);
      st = walk(node->kids[i], f->value, sub, fn, ctx);
      if (st != RS_OK && st != RS_ERR_INPUT) return st;
      if (st != RS_OK) bad = st;
    }
  }
  return bad;
}

rs_status rsi_ys_each_number(yn *root, ys_number_fn fn, void *ctx)
{
  return root ? walk(root, &rsi_ys_scene_schema, "", fn, ctx) : RS_OK;
}

void rsi_ys_column_unit(const char *unit, int column, char *out, size_t size)
{
  const char *bar = strchr(unit, '|');
  if (!bar || column < 0) snprintf(out, size, "%s", unit);
  else if (column == 0) snprintf(out, size, "%.*s", (int)(bar - unit), unit);
  else snprintf(out, size, "%s", bar + 1);
}
