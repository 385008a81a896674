/* rs_scene_load: the loader's steps in order (see scene_internal.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/version.h"
#include "scene/ranges.h"
#include "scene/scene_internal.h"
#include "util/error.h"

/* The resolved scene: a header of comments (what it came from, derived values), then the
 * scene with the material inlined, shorthands expanded, defaults and overrides applied.
 * It loads again as a scene and gives the same run. */
/* s for a comment line: control characters as \xNN, so a newline in a --set value or a
 * file name cannot end the comment and put a line of its own into the resolved scene. */
static const char *one_line(const char *s, char *buf, size_t size)
{
  size_t n = 0;
  for (const unsigned char *p = (const unsigned char *)s; *p && n + 5 < size; ++p) {
    if (*p < 0x20 || *p == 0x7f) n += (size_t)snprintf(buf + n, size - n, "\\x%02x", *p);
    else buf[n++] = (char)*p;
  }
  buf[n] = '\0';
  return buf;
}

static rs_status build_resolved(rs_scene *s, int n_sets, const char *const *sets, const char *body)
{
  char head[8192], num[3][64], safe[2][2048];
  size_t len = 0;
#define ADD(...)                                                                         \
  do {                                                                                   \
    int w_ = snprintf(head + len, sizeof head - len, __VA_ARGS__);                       \
    if (w_ > 0) len = (size_t)w_ < sizeof head - len ? len + (size_t)w_ : sizeof head - 1; \
  } while (0)
  ADD("# reelsim %s resolved scene (material inlined, defaults filled, overrides applied)\n",
      RS_VERSION_STRING);
  ADD("# scene: %s\n# material: %s\n", one_line(s->path, safe[0], sizeof safe[0]),
      one_line(s->material_source, safe[1], sizeof safe[1]));
  for (int i = 0; i < n_sets; ++i) ADD("# --set %s\n", one_line(sets[i], safe[0], sizeof safe[0]));
  rsi_ys_fmt(num[0], sizeof num[0], s->problem.final_radius);
  rsi_ys_fmt(num[1], sizeof num[1], s->problem.material.caliper);
  ADD("# derived: final radius %s m, %d layers of caliper %s m", num[0], s->problem.n_layers, num[1]);
  if (s->web_length > 0.0) {
    rsi_ys_fmt(num[2], sizeof num[2], s->web_length);
    ADD(" (from web length %s m)", num[2]);
  }
  ADD("\n%s", s->units_text);
  if (s->problem.tension.law == RS_RECIPE_HYPERBOLIC) {
    rsi_ys_fmt(num[0], sizeof num[0], s->problem.tension.k);
    rsi_ys_fmt(num[1], sizeof num[1], s->problem.tension.end);
    ADD("# derived: tension taper k = %s, end = %s N/m\n", num[0], num[1]);
  }
#undef ADD
  size_t blen = strlen(body);
  s->resolved_text = malloc(len + blen + 1);
  if (!s->resolved_text) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  memcpy(s->resolved_text, head, len);
  memcpy(s->resolved_text + len, body, blen + 1);
  return RS_OK;
}

/* Bad input is noted and reported with the rest (rsi_ys_errors_end); any other failure stops. */
static rs_status input_ok(rs_status st) { return st == RS_ERR_INPUT ? RS_OK : st; }

/* text == NULL: read the file `path`; otherwise parse text[0..len) and use `path` only as
 * the scene's name (messages, model lookup directory, default title and output file). */
static rs_status scene_load(const char *path, const char *text, size_t len, int n_sets,
                            const char *const *sets, rs_scene **out)
{
  if (!out) return RS_ERROR(RS_ERR_INTERNAL, "rs_scene_load: out is NULL");
  *out = NULL;
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no scene file given");
  if (strlen(path) >= RS_PATH_MAX) return RS_ERROR(RS_ERR_INPUT, "%.64s...: path too long", path);
  if (n_sets > 0 && !sets) return RS_ERROR(RS_ERR_INTERNAL, "rs_scene_load: sets is NULL");
  for (int i = 0; i < n_sets; ++i)
    if (!sets[i]) return RS_ERROR(RS_ERR_INTERNAL, "rs_scene_load: sets[%d] is NULL", i);

  rs_scene *s = calloc(1, sizeof *s);
  if (!s) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  snprintf(s->path, sizeof s->path, "%s", path);

  yn *root = NULL;
  char *body = NULL;
  /* Every error is reported together (rsi_ys_note): every bad --set and every unknown key or
   * value of the wrong type; when there are none, every value out of range (the range
   * checks need a tree of the right types). A syntax error or a missing model stops at once. */
  rsi_ys_errors_begin();
  rs_status st = text ? rsi_yn_parse_text(text, len, s->path, &root) : rsi_yn_parse_file(s->path, &root);
  for (int i = 0; st == RS_OK && i < n_sets; ++i) st = rsi_ys_apply_set(root, sets[i], 0);
  if (st == RS_OK) st = rsi_ys_inline_material(root, s);
  for (int i = 0; st == RS_OK && i < n_sets; ++i) st = input_ok(rsi_ys_note(rsi_ys_apply_set(root, sets[i], 1)));
  if (st == RS_OK) {
    /* a bad --set leaves the tree as it was: the file's own errors are still looked for */
    rs_status norm = rsi_ys_normalize(root);
    /* numbers with units -> the keys' SI numbers (units.c), then the schema's checks */
    if (norm == RS_OK) st = input_ok(rsi_ys_convert_units(root, s));
    if (norm == RS_OK && st == RS_OK) st = input_ok(rsi_ys_typecheck(root, &rsi_ys_scene_schema));
    if (norm != RS_OK) st = input_ok(rsi_ys_note(norm));
    rsi_ys_units_note_errors();
  }
  if (st == RS_OK) st = rsi_ys_errors_end();
  if (st == RS_OK) st = rsi_ys_fill_defaults(root, s->path);
  if (st == RS_OK && (st = input_ok(rsi_ys_resolve(root, s))) == RS_OK) st = rsi_ys_errors_end();
  /* plausibility bounds and slip warnings (bounds.c), on values the resolution accepted */
  if (st == RS_OK && (st = input_ok(rsi_ys_check_ranges(root, s))) == RS_OK) st = rsi_ys_errors_end();
  if (st == RS_OK) st = rsi_yn_emit(root, &body);
  if (st == RS_OK) st = build_resolved(s, n_sets, sets, body);

  free(body);
  rsi_yn_free(root);
  if (st != RS_OK) {
    rs_scene_destroy(&s);
    return st;
  }
  *out = s;
  return RS_OK;
}

rs_status rs_scene_load(const char *path, int n_sets, const char *const *sets, rs_scene **out)
{
  return scene_load(path, NULL, 0, n_sets, sets, out);
}

rs_status rs_scene_load_text(const char *name, const char *text, size_t len, int n_sets,
                             const char *const *sets, rs_scene **out)
{
  if (!text && len > 0) return RS_ERROR(RS_ERR_INTERNAL, "rs_scene_load_text: text is NULL");
  return scene_load(name, text ? text : "", len, n_sets, sets, out);
}

void rs_scene_destroy(rs_scene **scene)
{
  if (!scene || !*scene) return;
  free((*scene)->resolved_text);
  free(*scene);
  *scene = NULL;
}
