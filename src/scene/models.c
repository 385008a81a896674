/* Material models by name: `material: newsprint` is looked up
 *   1. <scene dir>/newsprint.yaml
 *   2. <scene dir>/models/newsprint.yaml
 *   3. <scene dir>/../models/newsprint.yaml
 *   4. $REELSIM_MODELS/newsprint.yaml when that is set
 *   5. the shipped models: the source tree's models/ for a program run from the build
 *      tree, else the installed <datadir>/reelsim/models (model_dirs.c)
 * A name ending in .yaml/.yml or holding a '/' is a path (relative to the scene's
 * directory). The model file's lines stay attached to its values, so an error in it
 * names the model file, not the scene.
 * `material: {model: NAME, caliper: ...}` loads the model the same way and then replaces
 * the keys given beside `model`. */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "scene/model_dirs.h"
#include "scene/scene_internal.h"
#include "util/error.h"

static int ends_with(const char *s, const char *suffix)
{
  size_t n = strlen(s), m = strlen(suffix);
  return n >= m && strcmp(s + n - m, suffix) == 0;
}

/* Lexical clean-up for display: "cases/../models/x.yaml" -> "models/x.yaml". */
static void clean_path(const char *in, char *out, size_t size)
{
  char tmp[RS_PATH_MAX];
  const char *parts[256];
  int n = 0, abs = in[0] == '/';
  snprintf(tmp, sizeof tmp, "%s", in);
  for (char *save = NULL, *p = strtok_r(tmp, "/", &save); p; p = strtok_r(NULL, "/", &save)) {
    if (strcmp(p, ".") == 0) continue;
    if (strcmp(p, "..") == 0 && n > 0 && strcmp(parts[n - 1], "..") != 0) {
      --n;
      continue;
    }
    if (strcmp(p, "..") == 0 && abs) continue;
    if (n < 256) parts[n++] = p;
  }
  size_t len = 0;
  out[0] = '\0';
  if (abs && size > 1) out[len++] = '/', out[len] = '\0';
  for (int i = 0; i < n; ++i) {
    int w = snprintf(out + len, size - len, "%s%s", i ? "/" : "", parts[i]);
    if (w < 0 || (size_t)w >= size - len) break;
    len += (size_t)w;
  }
  if (len == 0) snprintf(out, size, ".");
}

static void scene_dir(const char *scene_path, char *dir, size_t size)
{
  const char *slash = strrchr(scene_path, '/');
  if (!slash) {
    snprintf(dir, size, ".");
  } else if (slash == scene_path) {
    snprintf(dir, size, "/");
  } else {
    snprintf(dir, size, "%.*s", (int)(slash - scene_path), scene_path);
  }
}

static void join(char *out, size_t size, const char *dir, const char *rest)
{
  char raw[RS_PATH_MAX];
  if (rest[0] == '/' || strcmp(dir, ".") == 0)
    snprintf(raw, sizeof raw, "%s", rest);
  else
    snprintf(raw, sizeof raw, "%s/%s", dir, rest);
  clean_path(raw, out, size);
}

int rsi_ys_model_candidates(const char *scene_path, const char *name, char cand[][RS_PATH_MAX],
                        int max)
{
  char dir[RS_PATH_MAX], file[RS_PATH_MAX];
  int n = 0;
  scene_dir(scene_path, dir, sizeof dir);
  if (strchr(name, '/') || ends_with(name, ".yaml") || ends_with(name, ".yml")) {
    if (max > 0) join(cand[n++], RS_PATH_MAX, dir, name);
    return n;
  }
  snprintf(file, sizeof file, "%s.yaml", name);
  const char *sub[3] = {"", "models/", "../models/"};
  for (int i = 0; i < 3 && n < max; ++i) {
    char rel[RS_PATH_MAX];
    snprintf(rel, sizeof rel, "%s%s", sub[i], file);
    join(cand[n++], RS_PATH_MAX, dir, rel);
  }
  char lib[YS_MODEL_DIRS_MAX][RS_PATH_MAX];
  int n_lib = rsi_ys_model_dirs(lib, YS_MODEL_DIRS_MAX);
  for (int i = 0; i < n_lib && n < max; ++i) join(cand[n++], RS_PATH_MAX, lib[i], file);
  return n;
}

static int same_file(const struct stat *a, const struct stat *b)
{
  return a->st_dev == b->st_dev && a->st_ino == b->st_ino;
}

/* `material: {model: NAME, key: value, ...}`: the model's keys, each key given beside
 * `model` replacing the model's (a whole mapping such as `radial` is replaced, not merged:
 * a law's keys belong together). The given values keep the scene's lines. */
static rs_status override_model(yn *model, yn *given)
{
  for (int i = 0; i < given->n; ++i) {
    if (strcmp(given->keys[i], "model") == 0) continue;
    yn *v = rsi_yn_copy(given->kids[i]);
    if (!v) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
    rs_status st = rsi_yn_map_put(model, given->keys[i], v);
    if (st != RS_OK) return st;
  }
  return RS_OK;
}

rs_status rsi_ys_inline_material(yn *root, rs_scene *scene)
{
  yn *mat = rsi_yn_map_get(root, "material");
  if (!mat) return rsi_yn_error_key(root, "material", "required key is missing");
  yn *given = NULL; /* the mapping holding `model`, whose other keys override the model's */
  if (mat->kind == YN_MAP) {
    yn *name = rsi_yn_map_get(mat, "model");
    if (!name) {
      snprintf(scene->material_source, sizeof scene->material_source, "inline");
      return RS_OK;
    }
    if (name->kind != YN_SCALAR || rsi_yn_is_empty(name))
      return rsi_yn_error(name, "expected a model name (e.g. pet-film)");
    given = mat;
    mat = name;
  }
  if (mat->kind != YN_SCALAR || rsi_yn_is_empty(mat))
    return rsi_yn_error(mat, "expected a model name (e.g. newsprint) or a mapping of material keys");

  char cand[3 + YS_MODEL_DIRS_MAX][RS_PATH_MAX];
  int n = rsi_ys_model_candidates(scene->path, mat->text, cand, 3 + YS_MODEL_DIRS_MAX);
  struct stat self, st;
  int have_self = stat(scene->path, &self) == 0;
  const char *found = NULL;
  for (int i = 0; i < n && !found; ++i)
    if (stat(cand[i], &st) == 0 && S_ISREG(st.st_mode) && !(have_self && same_file(&st, &self)))
      found = cand[i];
  if (!found) {
    char tried[(3 + YS_MODEL_DIRS_MAX) * (RS_PATH_MAX + 2)];
    size_t len = 0;
    tried[0] = '\0';
    for (int i = 0; i < n; ++i) {
      int w = snprintf(tried + len, sizeof tried - len, "%s%s", i ? ", " : "", cand[i]);
      if (w > 0 && (size_t)w < sizeof tried - len) len += (size_t)w;
    }
    return rsi_yn_error(mat, "no material model '%s' (looked for: %s)", mat->text, tried);
  }
  memcpy(scene->material_source, found, strlen(found) + 1); /* both RS_PATH_MAX */

  yn *model;
  rs_status s = rsi_yn_parse_file(scene->material_source, &model);
  if (s != RS_OK) return s;
  yn *nested = rsi_yn_map_get(model, "model");
  if (nested) {
    s = rsi_yn_error(nested, "a model file cannot name another model");
    rsi_yn_free(model);
    return s;
  }
  /* the model's values keep their own file and lines; a --set on the name stays visible */
  if (!rsi_yn_map_get(model, "name")) {
    yn *name = rsi_yn_new_scalar(mat->text, mat->file, mat->line, "material");
    if (!name) {
      rsi_yn_free(model);
      return RS_ERROR(RS_ERR_MEMORY, "out of memory");
    }
    if (mat->origin) rsi_yn_set_origin(name, mat->origin);
    if ((s = rsi_yn_map_put(model, "name", name)) != RS_OK) {
      rsi_yn_free(model);
      return s;
    }
  }
  yn *source = rsi_yn_new_scalar(scene->material_source, root->file, 0, "material.source");
  if (!source || rsi_yn_set_origin(source, "default") != RS_OK ||
      (s = rsi_yn_map_put(model, "source", source)) != RS_OK) {
    rsi_yn_free(model);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  if (given && (s = override_model(model, given)) != RS_OK) {
    rsi_yn_free(model);
    return s;
  }
  return rsi_yn_map_put(root, "material", model);
}
