/* YAML text -> the positioned tree (ytree.h), event by event from libyaml's parser.
 *
 * The tree is built here rather than by libyaml's document loader so that hostile input
 * is refused while it is read, before it costs anything: the loader would first build
 * the whole document (10^5 nesting levels take libyaml 15 s) and aliases would then be
 * expanded into the tree (the "billion laughs": 8 levels of 9 aliases are 4.3e7 values).
 * The limits (docs/scenes.md, "Limits") are far beyond any real scene: one with all three
 * tables at their 256 rows has about 2,400 values, 5 levels and 20 kB. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "scene/ytree.h"
#include "util/error.h"

typedef struct anchor {
  char *name;
  const yn *node; /* owned by the tree being built */
  long size;      /* values in it */
  int height;     /* levels below it */
} anchor;

typedef struct builder {
  yaml_parser_t parser;
  const char *file;
  const char *text; /* the input, for the line of a reader error */
  size_t len;
  anchor *anchors;
  int n_anchors, cap_anchors;
  long values; /* values in the tree, alias copies included */
  long copied; /* values copied from anchors */
} builder;

/* libyaml's reader (bytes -> characters) gives no mark, only the byte offset of the bad
 * byte: its line is 1 + the newlines before it, its column 1 + the characters (UTF-8 lead
 * bytes; the text before it decoded) since the last one. */
static rs_status reader_error(const builder *b)
{
  const yaml_parser_t *p = &b->parser;
  size_t off = p->problem_offset < b->len ? p->problem_offset : b->len;
  int line = 1, column = 1;
  for (size_t i = 0; i < off; ++i) {
    unsigned char c = (unsigned char)b->text[i];
    if (c == '\n') {
      ++line;
      column = 1;
    } else if ((c & 0xC0) != 0x80) {
      ++column;
    }
  }
  char what[32] = "";
  if (p->problem_value >= 0 && p->problem_value <= 0xFF)
    snprintf(what, sizeof what, " (byte 0x%02X)", (unsigned)p->problem_value);
  else if (p->problem_value > 0xFF)
    snprintf(what, sizeof what, " (U+%04X)", (unsigned)p->problem_value);
  return RS_ERROR(RS_ERR_INPUT,
                  "%s:%d: column %d: %s%s: a scene must be UTF-8 text without control characters",
                  b->file, line, column, p->problem ? p->problem : "unreadable text", what);
}

static rs_status syntax_error(builder *b)
{
  const yaml_parser_t *p = &b->parser;
  if (p->error == YAML_MEMORY_ERROR) return RS_ERROR(RS_ERR_MEMORY, "out of memory reading %s", b->file);
  if (p->error == YAML_READER_ERROR) return reader_error(b);
  const char *ctx = p->context ? p->context : "";
  return RS_ERROR(RS_ERR_INPUT, "%s:%d: YAML syntax error: %s%s%s", b->file,
                  (int)p->problem_mark.line + 1, p->problem ? p->problem : "?", ctx[0] ? " " : "",
                  ctx);
}

static rs_status next_event(builder *b, yaml_event_t *ev)
{
  if (!yaml_parser_parse(&b->parser, ev)) return syntax_error(b);
  return RS_OK;
}

static int line_of(const yaml_event_t *ev) { return (int)ev->start_mark.line + 1; }

static void measure(const yn *node, long *size, int *height)
{
  long s = 1;
  int h = 0;
  for (int i = 0; i < node->n; ++i) {
    long ks;
    int kh;
    measure(node->kids[i], &ks, &kh);
    s += ks;
    if (kh + 1 > h) h = kh + 1;
  }
  *size = s;
  *height = h;
}

/* Remembers `node` under the anchor `name` (NULL: none). A later anchor of the same name
 * hides an earlier one, as in YAML. */
static rs_status add_anchor(builder *b, const yaml_char_t *name, const yn *node)
{
  if (!name) return RS_OK;
  if (b->n_anchors == b->cap_anchors) {
    int cap = b->cap_anchors ? 2 * b->cap_anchors : 8;
    anchor *a = realloc(b->anchors, (size_t)cap * sizeof *a);
    if (!a) return RS_ERROR(RS_ERR_MEMORY, "out of memory reading %s", b->file);
    b->anchors = a;
    b->cap_anchors = cap;
  }
  anchor *a = &b->anchors[b->n_anchors];
  size_t len = strlen((const char *)name) + 1;
  if (!(a->name = malloc(len))) return RS_ERROR(RS_ERR_MEMORY, "out of memory reading %s", b->file);
  memcpy(a->name, name, len);
  a->node = node;
  measure(node, &a->size, &a->height);
  ++b->n_anchors;
  return RS_OK;
}

static const anchor *find_anchor(const builder *b, const yaml_char_t *name)
{
  for (int i = b->n_anchors - 1; i >= 0; --i)
    if (strcmp(b->anchors[i].name, (const char *)name) == 0) return &b->anchors[i];
  return NULL;
}

static rs_status count_value(builder *b, int line, long n)
{
  b->values += n;
  if (b->values > YN_MAX_VALUES)
    return RS_ERROR(RS_ERR_INPUT, "%s:%d: more than %d values in one file (the limit for scene files)",
                    b->file, line, YN_MAX_VALUES);
  return RS_OK;
}

static rs_status too_deep(const builder *b, int line)
{
  return RS_ERROR(RS_ERR_INPUT, "%s:%d: nesting deeper than %d levels (the limit for scene files)",
                  b->file, line, YN_MAX_DEPTH);
}

static void child_path(char *buf, size_t size, const char *parent, const char *key, int index)
{
  if (key)
    snprintf(buf, size, "%s%s%s", parent, parent[0] ? "." : "", key);
  else
    snprintf(buf, size, "%s[%d]", parent, index);
}

/* *alias -> a copy of the anchored value, within the copy and depth budgets */
static rs_status expand_alias(builder *b, const yaml_event_t *ev, int line, const char *path,
                              int depth, yn **out)
{
  const anchor *a = find_anchor(b, ev->data.alias.anchor);
  if (!a)
    return RS_ERROR(RS_ERR_INPUT, "%s:%d: %s: alias *%s names no complete anchor before it",
                    b->file, line_of(ev), path[0] ? path : "(top level)",
                    (const char *)ev->data.alias.anchor);
  if (b->copied + a->size > YN_MAX_ALIAS_VALUES)
    return RS_ERROR(RS_ERR_INPUT,
                    "%s:%d: too many alias expansions (limit %d values copied from anchors)",
                    b->file, line_of(ev), YN_MAX_ALIAS_VALUES);
  if (depth + a->height > YN_MAX_DEPTH) return too_deep(b, line_of(ev));
  rs_status st = count_value(b, line_of(ev), a->size);
  if (st != RS_OK) return st;
  b->copied += a->size;
  yn *c = rsi_yn_copy(a->node);
  if (!c || rsi_yn_set_paths(c, path) != RS_OK) {
    rsi_yn_free(c);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory reading %s", b->file);
  }
  c->line = line;
  *out = c;
  return RS_OK;
}

static rs_status build(builder *b, yaml_event_t *ev, int line, const char *path, int depth,
                       yn **out);

static rs_status build_seq(builder *b, yn *n, const char *path, int depth)
{
  char sub[512];
  for (int i = 0;; ++i) {
    yaml_event_t ev;
    rs_status st = next_event(b, &ev);
    if (st != RS_OK) return st;
    if (ev.type == YAML_SEQUENCE_END_EVENT) {
      yaml_event_delete(&ev);
      return RS_OK;
    }
    yn *kid = NULL;
    child_path(sub, sizeof sub, path, NULL, i);
    st = build(b, &ev, line_of(&ev), sub, depth + 1, &kid);
    if (st == RS_OK) st = rsi_yn_seq_push(n, kid);
    if (st != RS_OK) return st;
  }
}

static rs_status build_map(builder *b, yn *n, const char *path, int depth)
{
  char sub[512];
  for (;;) {
    yaml_event_t ev;
    rs_status st = next_event(b, &ev);
    if (st != RS_OK) return st;
    if (ev.type == YAML_MAPPING_END_EVENT) {
      yaml_event_delete(&ev);
      return RS_OK;
    }
    int kline = line_of(&ev);
    const char *key = NULL;
    size_t klen = 0;
    if (ev.type == YAML_SCALAR_EVENT) {
      key = (const char *)ev.data.scalar.value;
      klen = ev.data.scalar.length;
    } else if (ev.type == YAML_ALIAS_EVENT) {
      const anchor *a = find_anchor(b, ev.data.alias.anchor);
      if (a && a->node->kind == YN_SCALAR) key = a->node->text, klen = strlen(key);
    }
    if (!key) {
      yaml_event_delete(&ev);
      return RS_ERROR(RS_ERR_INPUT, "%s:%d: %s: keys must be plain names", b->file, kline,
                      path[0] ? path : "(top level)");
    }
    child_path(sub, sizeof sub, path, key, 0);
    if (strlen(key) != klen)
      st = RS_ERROR(RS_ERR_INPUT, "%s:%d: %s: key contains a NUL character", b->file, kline, path);
    else if (n->n == YN_MAX_KEYS)
      st = RS_ERROR(RS_ERR_INPUT, "%s:%d: %s: more than %d keys in one mapping (the limit for "
                    "scene files)", b->file, kline, path[0] ? path : "(top level)", YN_MAX_KEYS);
    else if (rsi_yn_map_index(n, key) >= 0)
      st = RS_ERROR(RS_ERR_INPUT, "%s:%d: %s: duplicate key '%s'", b->file, kline, sub, key);
    /* the value comes next; the key stays in `ev` until it is stored */
    yaml_event_t val;
    if (st == RS_OK) st = next_event(b, &val);
    yn *kid = NULL;
    if (st == RS_OK) st = build(b, &val, kline, sub, depth + 1, &kid);
    if (st == RS_OK) st = rsi_yn_map_put(n, key, kid);
    yaml_event_delete(&ev);
    if (st != RS_OK) return st;
  }
}

/* Builds the value that starts with *ev (consumed) at `line`, `depth` levels down. */
static rs_status build(builder *b, yaml_event_t *ev, int line, const char *path, int depth,
                       yn **out)
{
  rs_status st = RS_OK;
  yn *n = NULL;
  *out = NULL;
  if (depth > YN_MAX_DEPTH) st = too_deep(b, line_of(ev));
  else if (ev->type == YAML_ALIAS_EVENT) st = expand_alias(b, ev, line, path, depth, &n);
  else st = count_value(b, line_of(ev), 1);
  if (st != RS_OK || ev->type == YAML_ALIAS_EVENT) {
    yaml_event_delete(ev);
    *out = n;
    return st;
  }

  const yaml_char_t *anchor_name = NULL;
  switch (ev->type) {
  case YAML_SCALAR_EVENT:
    n = rsi_yn_new_scalar("", b->file, line, path);
    if (n) {
      free(n->text);
      n->text = malloc(ev->data.scalar.length + 1);
    }
    if (!n || !n->text) {
      st = RS_ERROR(RS_ERR_MEMORY, "out of memory reading %s", b->file);
      break;
    }
    memcpy(n->text, ev->data.scalar.value, ev->data.scalar.length);
    n->text[ev->data.scalar.length] = '\0';
    if (strlen(n->text) != ev->data.scalar.length)
      st = RS_ERROR(RS_ERR_INPUT, "%s:%d: %s: value contains a NUL character", b->file, line, path);
    n->quoted = ev->data.scalar.style != YAML_PLAIN_SCALAR_STYLE;
    anchor_name = ev->data.scalar.anchor;
    break;
  case YAML_SEQUENCE_START_EVENT:
  case YAML_MAPPING_START_EVENT: {
    int seq = ev->type == YAML_SEQUENCE_START_EVENT;
    n = seq ? rsi_yn_new_seq(b->file, line, path) : rsi_yn_new_map(b->file, line, path);
    if (!n) {
      st = RS_ERROR(RS_ERR_MEMORY, "out of memory reading %s", b->file);
      break;
    }
    st = seq ? build_seq(b, n, path, depth) : build_map(b, n, path, depth);
    anchor_name = seq ? ev->data.sequence_start.anchor : ev->data.mapping_start.anchor;
    break;
  }
  default:
    st = RS_ERROR(RS_ERR_INTERNAL, "%s:%d: unexpected YAML event %d", b->file, line, (int)ev->type);
    break;
  }
  /* registered only once complete: an alias inside its own anchor is refused */
  if (st == RS_OK) st = add_anchor(b, anchor_name, n);
  yaml_event_delete(ev);
  if (st != RS_OK) {
    rsi_yn_free(n);
    return st;
  }
  *out = n;
  return RS_OK;
}

/* Expects an event of `type` next. */
static rs_status expect(builder *b, yaml_event_type_t type, yaml_event_t *ev)
{
  rs_status st = next_event(b, ev);
  if (st == RS_OK && ev->type != type) {
    yaml_event_delete(ev);
    return RS_ERROR(RS_ERR_INTERNAL, "%s: unexpected YAML event %d (wanted %d)", b->file,
                    (int)ev->type, (int)type);
  }
  return st;
}

static rs_status parse_stream(builder *b, yn **out)
{
  yaml_event_t ev;
  rs_status st = expect(b, YAML_STREAM_START_EVENT, &ev);
  if (st != RS_OK) return st;
  yaml_event_delete(&ev);
  if ((st = next_event(b, &ev)) != RS_OK) return st;
  if (ev.type == YAML_STREAM_END_EVENT) {
    yaml_event_delete(&ev);
    return RS_ERROR(RS_ERR_INPUT, "%s: the file is empty", b->file);
  }
  yaml_event_delete(&ev); /* document start */
  yn *root = NULL;
  if ((st = next_event(b, &ev)) != RS_OK) return st;
  if ((st = build(b, &ev, 1, "", 0, &root)) != RS_OK) return st;
  if (root->kind != YN_MAP) {
    rsi_yn_free(root);
    return RS_ERROR(RS_ERR_INPUT, "%s:1: the file must be a mapping of keys to values", b->file);
  }
  st = expect(b, YAML_DOCUMENT_END_EVENT, &ev);
  if (st == RS_OK) {
    yaml_event_delete(&ev);
    st = next_event(b, &ev);
  }
  if (st == RS_OK && ev.type != YAML_STREAM_END_EVENT) {
    /* a second document would be silently ignored: refuse it instead */
    yaml_event_delete(&ev);
    st = next_event(b, &ev);
    if (st == RS_OK)
      st = RS_ERROR(RS_ERR_INPUT, "%s:%d: only one YAML document per file", b->file, line_of(&ev));
  }
  yaml_event_delete(&ev); /* zeroed by libyaml when it was not filled or deleted */
  if (st != RS_OK) {
    rsi_yn_free(root);
    return st;
  }
  *out = root;
  return RS_OK;
}

rs_status rsi_yn_parse_text(const char *text, size_t len, const char *file, yn **out)
{
  builder b = {.file = file, .text = text, .len = len};
  *out = NULL;
  if (len > YN_MAX_BYTES)
    return RS_ERROR(RS_ERR_INPUT, "%s: larger than %d bytes (the limit for scene files)", file,
                    YN_MAX_BYTES);
  if (!yaml_parser_initialize(&b.parser))
    return RS_ERROR(RS_ERR_MEMORY, "cannot initialise the YAML parser");
  yaml_parser_set_input_string(&b.parser, (const unsigned char *)text, len);
  rs_status st = parse_stream(&b, out);
  yaml_parser_delete(&b.parser);
  for (int i = 0; i < b.n_anchors; ++i) free(b.anchors[i].name);
  free(b.anchors);
  return st;
}

rs_status rsi_yn_parse_file(const char *file, yn **out)
{
  *out = NULL;
  FILE *f = fopen(file, "rb");
  if (!f) return RS_ERROR(RS_ERR_INPUT, "%s: cannot open (%s)", file, strerror(errno));
  /* one byte more than the limit tells a file at the limit from one beyond it */
  char *text = malloc((size_t)YN_MAX_BYTES + 1);
  if (!text) {
    fclose(f);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory reading %s", file);
  }
  size_t len = fread(text, 1, (size_t)YN_MAX_BYTES + 1, f);
  int bad = ferror(f);
  fclose(f);
  rs_status st = bad ? RS_ERROR(RS_ERR_INPUT, "%s: read error", file)
                     : rsi_yn_parse_text(text, len, file, out);
  free(text);
  return st;
}
