/* Defaults for optional keys, from the schema (schema.c), written into the tree so that
 * the resolved scene (stored with every result) shows every value the run used.
 * docs/scenes.md lists them. */
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"
#include "util/path_stem.h"

typedef struct stems {
  char title[512];               /* the scene file's stem, cut to a title's 511 bytes */
  char file[RS_PATH_MAX + 8];    /* stem.h5 */
  const char *scene_path;
} stems;

static rs_status put(yn *map, const char *key, yn *node)
{
  rs_status st = yn_set_origin(node, "default");
  if (st != RS_OK) {
    yn_free(node);
    return st;
  }
  return yn_map_put(map, key, node);
}

/* `when` holds for this mapping: the sibling key has (or, "!x", has not) the text */
static int applies(const yn *map, const ys_field *f)
{
  if (!f->when) return 1;
  const yn *sib = yn_map_get(map, f->when);
  if (!sib || sib->kind != YN_SCALAR) return 0;
  if (f->when_is[0] == '!') return strcmp(sib->text, f->when_is + 1) != 0;
  return strcmp(sib->text, f->when_is) == 0;
}

static rs_status fill(yn *map, const ys_value *schema, const stems *st)
{
  char path[600];
  for (const ys_field *f = schema->fields; f->key; ++f) {
    yn *kid = yn_map_get(map, f->key);
    if (!kid && (f->def || f->derived != YS_PLAIN) && applies(map, f)) {
      const char *text = f->def;
      if (f->derived == YS_FROM_STEM) text = st->title;
      if (f->derived == YS_FROM_STEM_H5) {
        if (strlen(st->file) >= RS_PATH_MAX)
          return RS_ERROR(RS_ERR_INPUT, "%.64s...: the scene name is too long to name the "
                          "output file after it; give output.file", st->scene_path);
        text = st->file;
      }
      snprintf(path, sizeof path, "%s%s%s", map->path, map->path[0] ? "." : "", f->key);
      int is_map = f->value->type == YS_MAP;
      kid = is_map ? yn_new_map(map->file, 0, path) : yn_new_scalar(text, map->file, 0, path);
      if (!kid) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
      rs_status s = put(map, f->key, kid);
      if (s != RS_OK) return s;
    }
    if (kid && kid->kind == YN_MAP && f->value->type == YS_MAP) {
      rs_status s = fill(kid, f->value, st);
      if (s != RS_OK) return s;
    }
    /* a mapping written as a list of them (nip:): each entry's defaults */
    for (int i = 0; kid && kid->kind == YN_SEQ && f->value->list_form && i < kid->n; ++i) {
      if (kid->kids[i]->kind != YN_MAP) continue;
      rs_status s = fill(kid->kids[i], f->value->list_form->entry, st);
      if (s != RS_OK) return s;
    }
  }
  return RS_OK;
}

rs_status ys_fill_defaults(yn *root, const char *scene_path)
{
  stems st = {.scene_path = scene_path};
  char name[RS_PATH_MAX];
  rs_path_stem(scene_path, name, sizeof name);
  snprintf(st.file, sizeof st.file, "%s.h5", name);

  /* The defaults must pass the checks the user's values pass: a title is at most 511
   * bytes (cut at a UTF-8 character boundary), the output name at most RS_PATH_MAX - 1.
   * Only a scene name given through rs_scene_load_text can be that long. */
  size_t cut = strlen(name);
  if (cut >= sizeof st.title) {
    cut = sizeof st.title - 1; /* back off while the first byte left out continues a character */
    while (cut > 0 && ((unsigned char)name[cut] & 0xC0) == 0x80) --cut;
  }
  memcpy(st.title, name, cut);
  st.title[cut] = '\0';
  return fill(root, &ys_scene_schema, &st);
}
