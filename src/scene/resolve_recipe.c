/* Recipes (web tension, nip load) from the checked tree, with the checks a user needs:
 * the keys each law takes, a sorted table, and no taper that goes negative on the roll. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/recipe.h"
#include "scene/scene_internal.h"

/* which keys each law takes: value start end k table points */
static const char *law_keys(rs_recipe_kind law)
{
  switch (law) {
  case RS_RECIPE_CONSTANT: return "value";
  case RS_RECIPE_LINEAR: return "start, end";
  case RS_RECIPE_HYPERBOLIC: return "start and one of end, k";
  case RS_RECIPE_TORQUE: return "start";
  case RS_RECIPE_TABLE: return "table (or points)";
  }
  return "";
}

static int law_uses(rs_recipe_kind law, const char *key)
{
  switch (law) {
  case RS_RECIPE_CONSTANT: return strcmp(key, "value") == 0;
  case RS_RECIPE_LINEAR: return strcmp(key, "start") == 0 || strcmp(key, "end") == 0;
  case RS_RECIPE_HYPERBOLIC:
    return strcmp(key, "start") == 0 || strcmp(key, "end") == 0 || strcmp(key, "k") == 0;
  case RS_RECIPE_TORQUE: return strcmp(key, "start") == 0;
  case RS_RECIPE_TABLE: return strcmp(key, "table") == 0 || strcmp(key, "points") == 0;
  }
  return 0;
}

/* the number `key` of the recipe at `path` */
static double num(const yn *root, const char *path, const char *key)
{
  char full[256];
  snprintf(full, sizeof full, "%s.%s", path, key);
  return ys_num(root, full);
}

/* A key the law does not take is an error at that key (a torque recipe's 'end' says why). */
static rs_status unused_keys(const yn *root, const char *path, const char *what,
                             rs_recipe_kind law)
{
  char key[256];
  const yn *node = yn_get(root, path);
  for (int i = 0; i < node->n; ++i) {
    const char *k = node->keys[i];
    if (strcmp(k, "law") == 0 || law_uses(law, k)) continue;
    snprintf(key, sizeof key, "%s.%s", path, k);
    if (law == RS_RECIPE_TORQUE && strcmp(k, "end") == 0)
      return ys_fail(root, key,
                     "a torque recipe is fixed by its start value (%s = start r0 / r); "
                     "remove 'end', or use law: hyperbolic with end (or k)",
                     what);
    return ys_fail(root, key, "not used by law %s (it takes: %s)", rs_recipe_law_name(law),
                   law_keys(law));
  }
  return RS_OK;
}

/* The law's numbers into out (every key it needs present). */
static rs_status read_law(const yn *root, const char *path, rs_recipe_kind law, rs_recipe *out)
{
  char key[256];
  const yn *node = yn_get(root, path);
#define NEED(k)                                                                              \
  do {                                                                                       \
    if (!yn_map_get(node, k))                                                                \
      return ys_fail(root, path, "law %s needs '%s' (it takes: %s)", rs_recipe_law_name(law), \
                     k, law_keys(law));                                                      \
  } while (0)
  switch (law) {
  case RS_RECIPE_CONSTANT:
    NEED("value");
    out->start = out->end = num(root, path, "value");
    break;
  case RS_RECIPE_LINEAR:
    NEED("start");
    NEED("end");
    out->start = num(root, path, "start");
    out->end = num(root, path, "end");
    break;
  case RS_RECIPE_HYPERBOLIC: {
    NEED("start");
    int has_end = yn_map_get(node, "end") != NULL, has_k = yn_map_get(node, "k") != NULL;
    if (has_end == has_k) {
      snprintf(key, sizeof key, "%s.%s", path, has_k ? "k" : "end");
      return ys_fail(root, has_k ? key : path,
                     "law hyperbolic takes either 'end' or 'k', %s",
                     has_k ? "not both" : "and neither is given");
    }
    out->start = num(root, path, "start");
    if (has_end) out->end = num(root, path, "end");
    else out->k = num(root, path, "k");
    break;
  }
  case RS_RECIPE_TORQUE:
    NEED("start");
    out->start = num(root, path, "start");
    break;
  case RS_RECIPE_TABLE: {
    int has_t = yn_map_get(node, "table") != NULL, has_p = yn_map_get(node, "points") != NULL;
    if (has_t && has_p) {
      snprintf(key, sizeof key, "%s.points", path);
      return ys_fail(root, key, "give the table as 'table' or as 'points', not both");
    }
    NEED(has_p ? "points" : "table");
    snprintf(key, sizeof key, "%s.%s", path, has_p ? "points" : "table");
    out->n_points = ys_pairs(root, key, out->r, out->value, RS_TABLE_MAX);
    break;
  }
  }
#undef NEED
  return RS_OK;
}

/* The recipe's own checks (rs_recipe_prepare), reported at the table row they name. */
static rs_status prepare_at_key(const yn *root, const char *path, const char *tkey, double r0,
                                double r1, rs_recipe *out)
{
  if (rs_recipe_prepare(out, r0, r1) == RS_OK) return RS_OK;
  char msg[1024], key[256];
  int idx;
  snprintf(msg, sizeof msg, "%s", rs_error_message());
  const char *at = strstr(msg, "table[");
  if (out->law == RS_RECIPE_TABLE && at && sscanf(at, "table[%d]", &idx) == 1)
    snprintf(key, sizeof key, "%s.%s[%d]", path, tkey, idx);
  else
    snprintf(key, sizeof key, "%s", path);
  return ys_fail(root, key, "%s", msg);
}

/* No negative value on [r0, r1], reported where it is (each law is monotone, a table is
 * piecewise linear: the minimum sits at an end or at a point), and table radii > 0. */
static rs_status check_sign(const yn *root, const char *path, const char *what,
                            const char *tkey, double r0, double r1, const rs_recipe *out)
{
  char key[256];
  const char *unit = strcmp(what, "speed") == 0 ? "m/s" : "N/m";
  double vmin = rs_recipe_min(out);
  if (!(vmin >= 0.0)) {
    double v0 = rs_recipe_eval(out, r0), v1 = rs_recipe_eval(out, r1);
    switch (out->law) {
    case RS_RECIPE_TABLE: {
      int imin = 0;
      for (int i = 1; i < out->n_points; ++i)
        if (out->value[i] < out->value[imin]) imin = i;
      snprintf(key, sizeof key, "%s.%s[%d][1]", path, tkey, imin);
      return ys_fail(root, key, "the %s must not be negative (got %g %s at r = %g m)", what,
                     out->value[imin], unit, out->r[imin]);
    }
    case RS_RECIPE_CONSTANT:
      snprintf(key, sizeof key, "%s.value", path);
      return ys_fail(root, key, "the %s must not be negative (got %g %s)", what, v0, unit);
    default:
      if (!(v0 >= 0.0)) {
        snprintf(key, sizeof key, "%s.start", path);
        return ys_fail(root, key, "the %s must not be negative (got %g %s at the core, r = %g m)",
                       what, v0, unit, r0);
      }
      snprintf(key, sizeof key, "%s.%s", path, yn_map_get(yn_get(root, path), "k") ? "k" : "end");
      return ys_fail(root, key, "taper makes the %s negative at r = %.3g m (%.3g %s)", what, r1,
                     v1, unit);
    }
  }
  for (int i = 0; i < out->n_points; ++i)
    if (out->r[i] <= 0.0) {
      snprintf(key, sizeof key, "%s.%s[%d]", path, tkey, i);
      return ys_fail(root, key, "radius must be > 0 m (got %g)", out->r[i]);
    }
  return RS_OK;
}

rs_status ys_resolve_recipe(const yn *root, const char *path, const char *what, double r0,
                            double r1, rs_recipe *out)
{
  char key[256];
  snprintf(key, sizeof key, "%s.law", path);
  rs_recipe_kind law = (rs_recipe_kind)ys_enum(root, key);
  rs_status st = unused_keys(root, path, what, law);
  if (st) return st;
  memset(out, 0, sizeof *out);
  out->law = law;
  out->end = NAN;
  out->k = NAN;
  st = read_law(root, path, law, out);
  if (st) return st;
  const char *tkey = yn_map_get(yn_get(root, path), "points") ? "points" : "table";
  st = prepare_at_key(root, path, tkey, r0, r1, out);
  if (st) return st;
  return check_sign(root, path, what, tkey, r0, r1, out);
}
