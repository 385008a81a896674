/* Shorthands rewritten into the one form the schema knows:
 *   tension: 350                 -> tension: {law: constant, value: 350}
 *   tension: {table: [...]}      -> tension: {law: table, table: [...]}
 *   centrifugal: true / false    -> centrifugal: {} / no key (air likewise)
 *   winder: two_drum             -> winder: {type: two_drum}
 * (the same for nip.load, each list entry's load, and winding.speed). The new nodes keep the line and origin of what the user
 * wrote, so `tension: abc` is still reported as winding.tension at its line. */
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"

static yn *scalar_like(const yn *like, const char *text, const char *path)
{
  yn *n = yn_new_scalar(text, like->file, like->line, path);
  if (n && like->origin && yn_set_origin(n, like->origin) != RS_OK) {
    yn_free(n);
    return NULL;
  }
  return n;
}

static rs_status normalize_recipe(yn *root, const char *parent_path, const char *key)
{
  char path[256];
  yn *parent = yn_get(root, parent_path);
  int i = yn_map_index(parent, key);
  if (i < 0) return RS_OK;
  yn *node = parent->kids[i];
  snprintf(path, sizeof path, "%s.%s.law", parent_path, key);
  if (yn_is_empty(node))
    return yn_error(node, "missing value (a number in N/m, or a recipe such as "
                          "{law: linear, start: 350, end: 280})");
  if (node->kind == YN_SCALAR) {
    yn *map = yn_new_map(node->file, node->line, node->path);
    yn *law = scalar_like(node, "constant", path);
    if (!map || !law) {
      yn_free(map);
      yn_free(law);
      return RS_ERROR(RS_ERR_MEMORY, "out of memory");
    }
    if (node->origin && yn_set_origin(map, node->origin) != RS_OK) {
      yn_free(map);
      yn_free(law);
      return RS_ERROR(RS_ERR_MEMORY, "out of memory");
    }
    rs_status st = yn_map_put(map, "law", law);
    if (st != RS_OK) {
      yn_free(map);
      return st;
    }
    /* move the scalar itself under `value`: it keeps its path, line and origin */
    parent->kids[i] = map;
    st = yn_map_put(map, "value", node);
    return st;
  }
  if (node->kind == YN_MAP && !yn_map_get(node, "law") &&
      (yn_map_get(node, "table") || yn_map_get(node, "points"))) {
    yn *law = scalar_like(node, "table", path);
    if (!law) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
    rs_status st = yn_map_put(node, "law", law);
    if (st != RS_OK) return st;
    /* law first, as people write it */
    for (int j = node->n - 1; j > 0; --j) {
      char *k = node->keys[j];
      yn *v = node->kids[j];
      node->keys[j] = node->keys[j - 1];
      node->kids[j] = node->kids[j - 1];
      node->keys[j - 1] = k;
      node->kids[j - 1] = v;
    }
    return RS_OK;
  }
  return RS_OK;
}

/* centrifugal: true -> centrifugal: {}; centrifugal: false -> no key (off) */
static rs_status normalize_switch(yn *root, const char *key)
{
  int i = yn_map_index(root, key);
  if (i < 0 || root->kids[i]->kind != YN_SCALAR) return RS_OK;
  yn *node = root->kids[i];
  if (strcmp(node->text, "false") == 0) {
    yn_map_remove(root, key);
    return RS_OK;
  }
  if (strcmp(node->text, "true") != 0)
    return yn_error(node, "must be {} or true (on) or false (off) (got '%s')", node->text);
  yn *map = yn_new_map(node->file, node->line, node->path);
  if (!map || (node->origin && yn_set_origin(map, node->origin) != RS_OK)) {
    yn_free(map);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  root->kids[i] = map;
  yn_free(node);
  return RS_OK;
}

/* winder: two_drum -> winder: {type: two_drum} */
static rs_status normalize_winder(yn *root)
{
  int i = yn_map_index(root, "winder");
  if (i < 0 || root->kids[i]->kind != YN_SCALAR || yn_is_empty(root->kids[i])) return RS_OK;
  yn *node = root->kids[i];
  yn *map = yn_new_map(node->file, node->line, node->path);
  if (!map || (node->origin && yn_set_origin(map, node->origin) != RS_OK)) {
    yn_free(map);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  root->kids[i] = map;
  /* the scalar itself goes under `type`: it keeps its path, line and origin, so errors
   * about it name what the user wrote */
  return yn_map_put(map, "type", node);
}

rs_status ys_normalize(yn *root)
{
  rs_status st = RS_OK;
  if (yn_get(root, "winding") && yn_get(root, "winding")->kind == YN_MAP)
    st = normalize_recipe(root, "winding", "tension");
  if (st == RS_OK && yn_get(root, "winding") && yn_get(root, "winding")->kind == YN_MAP)
    st = normalize_recipe(root, "winding", "speed");
  if (st == RS_OK && yn_get(root, "nip") && yn_get(root, "nip")->kind == YN_MAP)
    st = normalize_recipe(root, "nip", "load");
  for (int i = 0; st == RS_OK && yn_get(root, "nip") && yn_get(root, "nip")->kind == YN_SEQ &&
                  i < yn_get(root, "nip")->n; ++i) {
    char entry[32];
    snprintf(entry, sizeof entry, "nip[%d]", i);
    if (yn_get(root, entry)->kind == YN_MAP) st = normalize_recipe(root, entry, "load");
  }
  if (st == RS_OK && root && root->kind == YN_MAP) st = normalize_winder(root);
  if (st == RS_OK && root && root->kind == YN_MAP) st = normalize_switch(root, "centrifugal");
  if (st == RS_OK && root && root->kind == YN_MAP) st = normalize_switch(root, "air");
  return st;
}
