/* --set key.path=value: replaces one scalar of the scene before anything is checked.
 *
 * A key the file leaves out but the schema knows (numerics.layers_per_step with no
 * numerics section) is created; a key the schema does not know, a path through a single
 * value, or a path that ends on a whole mapping or list is refused. The value is checked
 * later with everything else, and errors about it name the --set that wrote it.
 * KEY=null (or ~) removes the key instead, so a --set can switch between keys that
 * exclude each other (final_radius / web_length). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene_internal.h"
#include "util/error.h"

/* dst = a + sep + b, cut to size (paths here are bounded by the --set text anyway) */
static void join3(char *dst, size_t size, const char *a, const char *sep, const char *b)
{
  size_t len = 0;
  const char *parts[3] = {a, sep, b};
  for (int i = 0; i < 3; ++i)
    for (const char *p = parts[i]; *p && len + 1 < size; ++p) dst[len++] = *p;
  dst[len] = '\0';
}

static int is_scalar_schema(const ys_value *s) { return s->type != YS_MAP && s->type != YS_LIST; }

/* YAML's null: `--set KEY=null` removes the key */
static int is_null(const char *value) { return strcmp(value, "null") == 0 || strcmp(value, "~") == 0; }

static rs_status set_scalar(yn *node, const char *value, const char *origin)
{
  char *text = malloc(strlen(value) + 1);
  if (!text) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  strcpy(text, value);
  free(node->text);
  node->text = text;
  node->quoted = 0;
  return rsi_yn_set_origin(node, origin);
}

/* --set KEY=null: the key goes, as if the file had never had it (its default, if any,
 * applies). A key the schema does not know is refused like any --set; a key that is not
 * there already is left absent. */
static rs_status remove_key(yn *root, const char *origin, const char *path,
                            char seg[][YN_SEG_MAX], int n)
{
  if (!rsi_ys_schema_at(path)) {
    char keys[512], parent[1024];
    snprintf(parent, sizeof parent, "%s", path);
    char *dot = strrchr(parent, '.');
    if (dot) *dot = '\0';
    const ys_value *ps = dot ? rsi_ys_schema_at(parent) : &rsi_ys_scene_schema;
    rsi_ys_schema_keys(ps ? ps : &rsi_ys_scene_schema, keys, sizeof keys);
    return RS_ERROR(RS_ERR_INPUT, "%s: unknown key '%s'%s%s (expected one of: %s)", origin,
                    seg[n - 1], dot ? " in " : "", dot ? parent : "", keys);
  }
  yn *cur = root;
  for (int i = 0; i < n - 1 && cur; ++i) {
    long idx;
    if (cur->kind == YN_SEQ)
      cur = rsi_yn_seg_index(seg[i], &idx) && idx < cur->n ? cur->kids[idx] : NULL;
    else
      cur = rsi_yn_map_get(cur, seg[i]);
  }
  if (!cur) return RS_OK;
  if (cur->kind != YN_MAP)
    return RS_ERROR(RS_ERR_INPUT, "%s: only a key of a mapping can be removed", origin);
  rsi_yn_map_remove(cur, seg[n - 1]);
  return RS_OK;
}

/* --set centrifugal=true / air=true switches the effect on (an empty mapping: its keys take
 * their defaults, and later --set air.roughness=... fill it; a mapping already there stays
 * as it is), =false switches it off (the key goes). */
static int is_switch(const char *path) { return strcmp(path, "centrifugal") == 0 || strcmp(path, "air") == 0; }

static rs_status set_switch(yn *root, const char *key, const char *value, const char *origin)
{
  if (strcmp(value, "false") == 0) {
    rsi_yn_map_remove(root, key);
    return RS_OK;
  }
  yn *have = rsi_yn_map_get(root, key);
  if (have && have->kind == YN_MAP) return RS_OK;
  yn *map = rsi_yn_new_map(root->file, 0, key);
  if (!map) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rsi_yn_set_origin(map, origin);
  if (st == RS_OK) st = rsi_yn_map_put(root, key, map);
  else rsi_yn_free(map);
  return st;
}

enum { WALKED_MAX = 2400 }; /* the path walked so far, "winding.tension.points[2]" */

/* One step of the walk into the list *cur: its entry seg ("2"); walked gains "[2]". */
static rs_status step_into_list(yn **cur, const char *seg, char *walked, const char *origin)
{
  char next[WALKED_MAX], num[32];
  long idx;
  if (!rsi_yn_seg_index(seg, &idx))
    return RS_ERROR(RS_ERR_INPUT, "%s: %s is a list: expected an entry number, got '%s'",
                    origin, walked, seg);
  if (idx >= (*cur)->n)
    return RS_ERROR(RS_ERR_INPUT, "%s: %s has no entry %ld (it has %d)", origin, walked, idx,
                    (*cur)->n);
  snprintf(num, sizeof num, "[%ld]", idx);
  join3(next, sizeof next, walked, "", num);
  memcpy(walked, next, sizeof next);
  *cur = (*cur)->kids[idx];
  return RS_OK;
}

/* The key seg, absent from the mapping cur at `walked`, created at path `next` when the
 * schema knows it: the scalar `value` when it is the path's last key, else an empty
 * mapping (a list's entries are not created). */
static rs_status create_key(yn *root, yn *cur, const char *seg, const char *walked,
                            const char *next, int last, const char *value, const char *origin,
                            yn **out)
{
  char keys[512];
  const ys_value *s = rsi_ys_schema_at(next);
  if (!s) {
    const ys_value *ps = walked[0] ? rsi_ys_schema_at(walked) : &rsi_ys_scene_schema;
    rsi_ys_schema_keys(ps ? ps : &rsi_ys_scene_schema, keys, sizeof keys);
    return RS_ERROR(RS_ERR_INPUT, "%s: unknown key '%s'%s%s (expected one of: %s)", origin,
                    seg, walked[0] ? " in " : "", walked, keys);
  }
  if (last && !is_scalar_schema(s) && !rsi_ys_is_shorthand(next))
    return RS_ERROR(RS_ERR_INPUT, "%s: %s is a %s, not a single value", origin, next,
                    s->type == YS_MAP ? "mapping" : "list");
  if (!last && s->type != YS_MAP)
    return RS_ERROR(RS_ERR_INPUT, "%s: cannot create entries of the list %s with --set",
                    origin, next);
  yn *kid = last ? rsi_yn_new_scalar(value, root->file, 0, next) : rsi_yn_new_map(root->file, 0, next);
  if (!kid) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = rsi_yn_set_origin(kid, origin);
  if (st == RS_OK) st = rsi_yn_map_put(cur, seg, kid);
  else rsi_yn_free(kid);
  *out = st == RS_OK ? kid : NULL;
  return st;
}

/* The scalar at the path seg[0..n-1] from root, the keys the schema knows created on the
 * way (create_key); *out the node found or made. */
static rs_status walk_to(yn *root, char seg[][YN_SEG_MAX], int n, const char *value,
                         const char *origin, yn **out)
{
  char walked[WALKED_MAX] = "";
  yn *cur = root;
  rs_status st = RS_OK;
  for (int i = 0; i < n && st == RS_OK; ++i) {
    char next[WALKED_MAX];
    if (cur->kind == YN_SEQ) {
      st = step_into_list(&cur, seg[i], walked, origin);
      continue;
    }
    if (cur->kind != YN_MAP)
      return RS_ERROR(RS_ERR_INPUT, "%s: %s is a single value, not a mapping with key '%s'",
                      origin, walked, seg[i]);
    join3(next, sizeof next, walked, walked[0] ? "." : "", seg[i]);
    yn *kid = rsi_yn_map_get(cur, seg[i]);
    if (!kid) st = create_key(root, cur, seg[i], walked, next, i == n - 1, value, origin, &kid);
    memcpy(walked, next, sizeof walked);
    cur = kid;
  }
  *out = cur;
  return st;
}

rs_status rsi_ys_apply_set(yn *root, const char *set, int pass)
{
  char origin[RS_PATH_MAX + 16], path[1024], seg[16][YN_SEG_MAX];
  snprintf(origin, sizeof origin, "--set %s", set);
  const char *eq = strchr(set, '=');
  if (!eq || eq == set)
    return RS_ERROR(RS_ERR_INPUT, "%s: expected key.path=value (e.g. numerics.rtol=1e-8)", origin);
  size_t plen = (size_t)(eq - set);
  if (plen >= sizeof path) return RS_ERROR(RS_ERR_INPUT, "%s: key path too long", origin);
  memcpy(path, set, plen);
  path[plen] = '\0';
  const char *value = eq + 1;

  /* the model is chosen before it is looked up: material and material.model go first */
  int names_model = strcmp(path, "material") == 0 || strcmp(path, "material.model") == 0;
  if ((pass == 0) != names_model) return RS_OK;
  if (strcmp(path, "material.model") == 0 && !is_null(value)) {
    yn *mat = rsi_yn_map_get(root, "material");
    if (mat && mat->kind == YN_SCALAR) return set_scalar(mat, value, origin); /* material: NAME */
  }

  if (is_switch(path) && (strcmp(value, "true") == 0 || strcmp(value, "false") == 0) &&
      root->kind == YN_MAP)
    return set_switch(root, path, value, origin);

  int n = rsi_yn_path_split(path, seg, 16);
  if (n <= 0) return RS_ERROR(RS_ERR_INPUT, "%s: malformed key path '%s'", origin, path);
  if (is_null(value)) return remove_key(root, origin, path, seg, n);

  yn *cur = NULL;
  rs_status st = walk_to(root, seg, n, value, origin, &cur);
  if (st != RS_OK) return st;
  if (cur->kind != YN_SCALAR)
    return RS_ERROR(RS_ERR_INPUT, "%s: %s is a %s, not a single value", origin, path,
                    cur->kind == YN_MAP ? "mapping" : "list");
  return set_scalar(cur, value, origin);
}
