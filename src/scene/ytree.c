/* The positioned YAML tree (see ytree.h): build, look up, edit, emit (yparse.c reads it). */
#include "scene/ytree.h"
#include "util/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

static char *dup_str(const char *s)
{
  size_t n = strlen(s) + 1;
  char *d = malloc(n);
  if (d) memcpy(d, s, n);
  return d;
}

static yn *yn_alloc(yn_kind kind, const char *file, int line, const char *path)
{
  yn *n = calloc(1, sizeof *n);
  if (!n) return NULL;
  n->kind = kind;
  n->file = file;
  n->line = line;
  n->path = dup_str(path ? path : "");
  if (!n->path) {
    free(n);
    return NULL;
  }
  return n;
}

yn *rsi_yn_new_scalar(const char *text, const char *file, int line, const char *path)
{
  yn *n = yn_alloc(YN_SCALAR, file, line, path);
  if (!n) return NULL;
  n->text = dup_str(text);
  if (!n->text) {
    rsi_yn_free(n);
    return NULL;
  }
  return n;
}

yn *rsi_yn_new_map(const char *file, int line, const char *path)
{
  return yn_alloc(YN_MAP, file, line, path);
}

yn *rsi_yn_new_seq(const char *file, int line, const char *path)
{
  return yn_alloc(YN_SEQ, file, line, path);
}

void rsi_yn_free(yn *node)
{
  if (!node) return;
  for (int i = 0; i < node->n; ++i) {
    if (node->keys) free(node->keys[i]);
    rsi_yn_free(node->kids[i]);
  }
  free(node->keys);
  free(node->kids);
  free(node->text);
  free(node->origin);
  free(node->path);
  free(node);
}

static int grow(yn *node)
{
  if (node->n < node->cap) return 1;
  int cap = node->cap ? 2 * node->cap : 4;
  yn **kids = realloc(node->kids, (size_t)cap * sizeof *kids);
  if (!kids) return 0;
  node->kids = kids;
  if (node->kind == YN_MAP) {
    char **keys = realloc(node->keys, (size_t)cap * sizeof *keys);
    if (!keys) return 0;
    node->keys = keys;
  }
  node->cap = cap;
  return 1;
}

int rsi_yn_map_index(const yn *map, const char *key)
{
  if (!map || map->kind != YN_MAP) return -1;
  for (int i = 0; i < map->n; ++i)
    if (strcmp(map->keys[i], key) == 0) return i;
  return -1;
}

yn *rsi_yn_map_get(const yn *map, const char *key)
{
  int i = rsi_yn_map_index(map, key);
  return i < 0 ? NULL : map->kids[i];
}

rs_status rsi_yn_map_put(yn *map, const char *key, yn *child)
{
  int i = rsi_yn_map_index(map, key);
  if (i >= 0) {
    rsi_yn_free(map->kids[i]);
    map->kids[i] = child;
    return RS_OK;
  }
  char *k = dup_str(key);
  if (!k || !grow(map)) {
    free(k);
    rsi_yn_free(child);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory building the scene tree");
  }
  map->keys[map->n] = k;
  map->kids[map->n++] = child;
  return RS_OK;
}

void rsi_yn_map_remove(yn *map, const char *key)
{
  int i = rsi_yn_map_index(map, key);
  if (i < 0) return;
  free(map->keys[i]);
  rsi_yn_free(map->kids[i]);
  for (int j = i + 1; j < map->n; ++j) {
    map->keys[j - 1] = map->keys[j];
    map->kids[j - 1] = map->kids[j];
  }
  --map->n;
}

rs_status rsi_yn_seq_push(yn *seq, yn *child)
{
  if (!grow(seq)) {
    rsi_yn_free(child);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory building the scene tree");
  }
  seq->kids[seq->n++] = child;
  return RS_OK;
}

static void child_path(char *buf, size_t size, const char *parent, const char *key, int index)
{
  if (key)
    snprintf(buf, size, "%s%s%s", parent, parent[0] ? "." : "", key);
  else
    snprintf(buf, size, "%s[%d]", parent, index);
}

/* ---- lookup and edits ------------------------------------------------------------ */

/* Splits "a.b[2].c" into segments "a", "b", "2", "c". */
int rsi_yn_path_split(const char *path, char seg[][YN_SEG_MAX], int max)
{
  int n = 0;
  const char *p = path;
  while (*p) {
    size_t len;
    if (*p == '.') {
      if (p == path || p[1] == '\0' || p[1] == '.') return -1;
      ++p;
      continue;
    }
    if (*p == '[') {
      len = strcspn(p + 1, "]");
      if (p[1 + len] != ']' || len == 0) return -1;
      if (n == max || len >= YN_SEG_MAX) return -1;
      memcpy(seg[n], p + 1, len);
      seg[n++][len] = '\0';
      p += len + 2;
      continue;
    }
    len = strcspn(p, ".[");
    if (n == max || len >= YN_SEG_MAX) return -1;
    memcpy(seg[n], p, len);
    seg[n++][len] = '\0';
    p += len;
  }
  return n;
}

int rsi_yn_seg_index(const char *seg, long *i)
{
  char *end;
  if (!seg[0]) return 0;
  *i = strtol(seg, &end, 10);
  return *end == '\0' && *i >= 0;
}

yn *rsi_yn_get(const yn *root, const char *path)
{
  char seg[32][YN_SEG_MAX];
  int n = rsi_yn_path_split(path, seg, 32);
  const yn *cur = root;
  for (int i = 0; cur && i < n; ++i) {
    long k;
    if (cur->kind == YN_SEQ)
      cur = rsi_yn_seg_index(seg[i], &k) && k < cur->n ? cur->kids[k] : NULL;
    else
      cur = rsi_yn_map_get(cur, seg[i]);
  }
  return n < 0 ? NULL : (yn *)cur;
}

yn *rsi_yn_copy(const yn *node)
{
  yn *c = yn_alloc(node->kind, node->file, node->line, node->path);
  if (!c) return NULL;
  c->quoted = node->quoted;
  if ((node->text && !(c->text = dup_str(node->text))) ||
      (node->origin && !(c->origin = dup_str(node->origin)))) {
    rsi_yn_free(c);
    return NULL;
  }
  for (int i = 0; i < node->n; ++i) {
    yn *kid = rsi_yn_copy(node->kids[i]);
    if (!kid) {
      rsi_yn_free(c);
      return NULL;
    }
    if ((node->kind == YN_MAP ? rsi_yn_map_put(c, node->keys[i], kid) : rsi_yn_seq_push(c, kid)) != RS_OK) {
      rsi_yn_free(c);
      return NULL;
    }
  }
  return c;
}

rs_status rsi_yn_set_origin(yn *node, const char *origin)
{
  free(node->origin);
  node->origin = dup_str(origin);
  if (!node->origin) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  for (int i = 0; i < node->n; ++i) {
    rs_status st = rsi_yn_set_origin(node->kids[i], origin);
    if (st != RS_OK) return st;
  }
  return RS_OK;
}

rs_status rsi_yn_set_paths(yn *node, const char *prefix)
{
  char *p = dup_str(prefix);
  if (!p) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  free(node->path);
  node->path = p;
  char sub[512];
  for (int i = 0; i < node->n; ++i) {
    child_path(sub, sizeof sub, prefix, node->kind == YN_MAP ? node->keys[i] : NULL, i);
    rs_status st = rsi_yn_set_paths(node->kids[i], sub);
    if (st != RS_OK) return st;
  }
  return RS_OK;
}

int rsi_yn_is_empty(const yn *node)
{
  return node->kind == YN_SCALAR && !node->quoted &&
         (node->text[0] == '\0' || strcmp(node->text, "~") == 0 || strcmp(node->text, "null") == 0);
}

void rsi_yn_where(const yn *node, char *buf, size_t size)
{
  if (node->origin && strcmp(node->origin, "default") != 0)
    snprintf(buf, size, "%s", node->origin);
  else if (node->file && node->line > 0)
    snprintf(buf, size, "%s:%d", node->file, node->line);
  else
    snprintf(buf, size, "%s", node->file ? node->file : "(scene)");
}

static rs_status verror(const yn *node, const char *path, const char *fmt, va_list ap)
{
  char where[1024], msg[1536];
  vsnprintf(msg, sizeof msg, fmt, ap);
  rsi_yn_where(node, where, sizeof where);
  if (node->origin && strcmp(node->origin, "default") != 0)
    return RS_ERROR(RS_ERR_INPUT, "%s: %s", where, msg);
  return RS_ERROR(RS_ERR_INPUT, "%s: %s: %s", where, path[0] ? path : "(top level)", msg);
}

rs_status rsi_yn_error(const yn *node, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  rs_status st = verror(node, node->path, fmt, ap);
  va_end(ap);
  return st;
}

rs_status rsi_yn_error_key(const yn *map, const char *key, const char *fmt, ...)
{
  char path[600];
  va_list ap;
  snprintf(path, sizeof path, "%s%s%s", map->path, map->path[0] ? "." : "", key);
  va_start(ap, fmt);
  rs_status st = verror(map, path, fmt, ap);
  va_end(ap);
  return st;
}

/* ---- emission --------------------------------------------------------------------- */

typedef struct buf {
  char *data;
  size_t len, cap;
} buf;

static int buf_write(void *ctx, unsigned char *data, size_t size)
{
  buf *b = ctx;
  if (b->len + size + 1 > b->cap) {
    size_t cap = b->cap ? b->cap : 1024;
    while (cap < b->len + size + 1) cap *= 2;
    char *d = realloc(b->data, cap);
    if (!d) return 0;
    b->data = d;
    b->cap = cap;
  }
  memcpy(b->data + b->len, data, size);
  b->len += size;
  b->data[b->len] = '\0';
  return 1;
}

static int all_scalars(const yn *node)
{
  for (int i = 0; i < node->n; ++i)
    if (node->kids[i]->kind != YN_SCALAR) return 0;
  return 1;
}

static int emit_scalar(yaml_emitter_t *em, const char *text, int quoted)
{
  yaml_event_t ev;
  yaml_scalar_event_initialize(&ev, NULL, NULL, (yaml_char_t *)text, (int)strlen(text), !quoted, 1,
                               quoted ? YAML_DOUBLE_QUOTED_SCALAR_STYLE : YAML_ANY_SCALAR_STYLE);
  return yaml_emitter_emit(em, &ev);
}

/* Sequences of numbers (table rows, coefficient lists) read best in flow style. */
static int emit_node(yaml_emitter_t *em, const yn *node, int in_flow)
{
  yaml_event_t ev;
  switch (node->kind) {
  case YN_SCALAR: return emit_scalar(em, node->text, node->quoted);
  case YN_SEQ: {
    int flow = in_flow || all_scalars(node) ||
               (node->n > 0 && node->kids[0]->kind == YN_SEQ && all_scalars(node->kids[0]));
    yaml_sequence_start_event_initialize(&ev, NULL, NULL, 1,
                                         flow ? YAML_FLOW_SEQUENCE_STYLE : YAML_BLOCK_SEQUENCE_STYLE);
    if (!yaml_emitter_emit(em, &ev)) return 0;
    for (int i = 0; i < node->n; ++i)
      if (!emit_node(em, node->kids[i], flow)) return 0;
    yaml_sequence_end_event_initialize(&ev);
    return yaml_emitter_emit(em, &ev);
  }
  case YN_MAP: {
    yaml_mapping_start_event_initialize(&ev, NULL, NULL, 1,
                                        in_flow ? YAML_FLOW_MAPPING_STYLE : YAML_BLOCK_MAPPING_STYLE);
    if (!yaml_emitter_emit(em, &ev)) return 0;
    for (int i = 0; i < node->n; ++i)
      if (!emit_scalar(em, node->keys[i], 0) || !emit_node(em, node->kids[i], in_flow)) return 0;
    yaml_mapping_end_event_initialize(&ev);
    return yaml_emitter_emit(em, &ev);
  }
  }
  return 0;
}

rs_status rsi_yn_emit(const yn *root, char **text)
{
  yaml_emitter_t em;
  yaml_event_t ev;
  buf b = {0};
  *text = NULL;
  if (!yaml_emitter_initialize(&em)) return RS_ERROR(RS_ERR_MEMORY, "cannot initialise libyaml");
  yaml_emitter_set_output(&em, buf_write, &b);
  yaml_emitter_set_unicode(&em, 1);
  yaml_emitter_set_width(&em, 96);
  yaml_emitter_set_indent(&em, 2);
  int ok = yaml_stream_start_event_initialize(&ev, YAML_UTF8_ENCODING) &&
           yaml_emitter_emit(&em, &ev) &&
           yaml_document_start_event_initialize(&ev, NULL, NULL, NULL, 1) &&
           yaml_emitter_emit(&em, &ev) && emit_node(&em, root, 0) &&
           yaml_document_end_event_initialize(&ev, 1) && yaml_emitter_emit(&em, &ev) &&
           yaml_stream_end_event_initialize(&ev) && yaml_emitter_emit(&em, &ev) &&
           yaml_emitter_flush(&em);
  const char *problem = em.problem ? em.problem : "out of memory";
  yaml_emitter_delete(&em);
  if (!ok) {
    free(b.data);
    return RS_ERROR(RS_ERR_INTERNAL, "cannot write the scene as YAML: %s", problem);
  }
  *text = b.data;
  return RS_OK;
}
