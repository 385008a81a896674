/* Defaults for optional keys, written into the tree so that the resolved scene (stored
 * with every result) shows every value the run used. docs/scenes.md lists them. */
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"
#include "util/path_stem.h"

static rs_status put_default(yn *map, const char *key, const char *text)
{
  char path[512];
  if (yn_map_index(map, key) >= 0) return RS_OK;
  snprintf(path, sizeof path, "%s%s%s", map->path, map->path[0] ? "." : "", key);
  yn *n = yn_new_scalar(text, map->file, 0, path);
  if (!n) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = yn_set_origin(n, "default");
  if (st != RS_OK) {
    yn_free(n);
    return st;
  }
  return yn_map_put(map, key, n);
}

static yn *ensure_map(yn *root, const char *key)
{
  yn *m = yn_map_get(root, key);
  if (m) return m;
  m = yn_new_map(root->file, 0, key);
  if (!m || yn_set_origin(m, "default") != RS_OK || yn_map_put(root, key, m) != RS_OK) return NULL;
  return m;
}

rs_status ys_fill_defaults(yn *root, const rs_scene *scene)
{
  char name[RS_PATH_MAX], file[RS_PATH_MAX + 8];
  rs_status st;
  rs_path_stem(scene->path, name, sizeof name);
  snprintf(file, sizeof file, "%s.h5", name);

  /* The defaults must pass the checks the user's values pass: a title is at most 511
   * bytes (cut at a UTF-8 character boundary), the output name at most RS_PATH_MAX - 1.
   * Only a scene name given through rs_scene_load_text can be that long. */
  char title[512];
  size_t cut = strlen(name);
  if (cut >= sizeof title) {
    cut = sizeof title - 1; /* back off while the first byte left out continues a character */
    while (cut > 0 && ((unsigned char)name[cut] & 0xC0) == 0x80) --cut;
  }
  memcpy(title, name, cut);
  title[cut] = '\0';
  if ((st = put_default(root, "title", title)) != RS_OK) return st;

  yn *mat = yn_map_get(root, "material");
  if ((st = put_default(mat, "name", "inline")) != RS_OK) return st;
  if ((st = put_default(mat, "nu_rtheta", "0")) != RS_OK) return st;

  yn *num = ensure_map(root, "numerics");
  yn *out = num ? ensure_map(root, "output") : NULL;
  if (!out) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if ((st = put_default(num, "layers_per_step", "1")) != RS_OK ||
      (st = put_default(num, "rtol", "1e-5")) != RS_OK || /* docs/accuracy.md: on every story scene's front */
      (st = put_default(num, "atol", "0")) != RS_OK ||
      (st = put_default(num, "max_steps", "0")) != RS_OK ||
      (st = put_default(num, "reuse", "deep")) != RS_OK ||
      (st = put_default(num, "load_placement", "beneath")) != RS_OK)
    return st;
  if (!yn_map_get(out, "file") && strlen(file) >= RS_PATH_MAX)
    return RS_ERROR(RS_ERR_INPUT, "%.64s...: the scene name is too long to name the output "
                    "file after it; give output.file", scene->path);
  if ((st = put_default(out, "file", file)) != RS_OK ||
      (st = put_default(out, "history_every", "0")) != RS_OK)
    return st;

  yn *nip = yn_map_get(root, "nip");
  if (nip && strcmp(yn_map_get(nip, "model")->text, "none") != 0) {
    if ((st = put_default(nip, "winder", "center")) != RS_OK ||
        (st = put_default(nip, "nodes", "64")) != RS_OK ||
        (st = put_default(nip, "terms", "0")) != RS_OK ||
        (st = put_default(nip, "update", "adaptive")) != RS_OK)
      return st;
    /* each update policy gets only its own knob */
    if (strcmp(yn_map_get(nip, "update")->text, "every") == 0)
      st = put_default(nip, "update_every", "1");
    else
      /* 1e-4, not 1e-3: on a reel whose T0 changes (cases/newsprint-surface-taper.yaml) the
       * policy's error dominated the defaults' and 1e-4 cut it 7x for 3% more time; where T0
       * does not change it costs nothing (docs/accuracy.md) */
      st = put_default(nip, "T0_rtol", "1e-4");
    if (st != RS_OK) return st;
    if (strcmp(yn_map_get(nip, "winder")->text, "center-surface") == 0 &&
        (st = put_default(nip, "torque_share", "0.5")) != RS_OK)
      return st;
  }
  return RS_OK;
}
