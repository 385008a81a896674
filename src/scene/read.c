/* Typed reads from the checked tree: the values the resolution (resolve*.c) turns into an
 * rs_scene. The checks (typecheck.c) have held every value to its schema type and the
 * defaults (defaults.c) are in place, so a read cannot fail; a key the file leaves out
 * (and that has no default) reads as 0, "" or an empty list. A read whose type is not the
 * schema's is the loader's own fault and aborts in a debug build. */
#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene_internal.h"

/* the scalar at path, checked against the schema type the caller expects */
static const yn *scalar(const yn *root, const char *path, ys_type type)
{
  const ys_value *s = rsi_ys_schema_at(path);
  (void)s, (void)type; /* checked only in a debug build */
  assert(s && (s->type == type || (type == YS_INT && s->type == YS_LONG)));
  const yn *n = rsi_yn_get(root, path);
  return n && n->kind == YN_SCALAR ? n : NULL;
}

double rsi_ys_num(const yn *root, const char *path)
{
  const yn *n = scalar(root, path, YS_FLOAT);
  double v = 0.0;
  if (n && !rsi_ys_parse_double(n->text, &v)) v = 0.0;
  return v;
}

long long rsi_ys_int(const yn *root, const char *path)
{
  const yn *n = scalar(root, path, YS_INT);
  return n ? strtoll(n->text, NULL, 10) : 0;
}

int rsi_ys_enum(const yn *root, const char *path)
{
  const yn *n = scalar(root, path, YS_ENUM);
  if (!n) return 0;
  for (const ys_name *e = rsi_ys_schema_at(path)->names; e->name; ++e)
    if (strcmp(e->name, n->text) == 0) return e->value;
  return 0;
}

const char *rsi_ys_str(const yn *root, const char *path)
{
  const yn *n = scalar(root, path, YS_STRING);
  return n ? n->text : "";
}

int rsi_ys_nums(const yn *root, const char *path, double *out, int max)
{
  const yn *n = rsi_yn_get(root, path);
  int count = 0;
  assert(rsi_ys_schema_at(path) && rsi_ys_schema_at(path)->type == YS_LIST);
  for (int i = 0; n && n->kind == YN_SEQ && i < n->n && count < max; ++i)
    if (rsi_ys_parse_double(n->kids[i]->text ? n->kids[i]->text : "", &out[count])) ++count;
  return count;
}

int rsi_ys_pairs(const yn *root, const char *path, double *a, double *b, int max)
{
  const yn *n = rsi_yn_get(root, path);
  int count = 0;
  assert(rsi_ys_schema_at(path) && rsi_ys_schema_at(path)->type == YS_LIST);
  for (int i = 0; n && n->kind == YN_SEQ && i < n->n && count < max; ++i) {
    const yn *p = n->kids[i];
    if (p->kind != YN_SEQ || p->n != 2 || !p->kids[0]->text || !p->kids[1]->text) continue;
    if (rsi_ys_parse_double(p->kids[0]->text, &a[count]) && rsi_ys_parse_double(p->kids[1]->text, &b[count]))
      ++count;
  }
  return count;
}
