/* Walks the schema (schema.c) over the positioned YAML tree: unknown keys, missing
 * required keys, scalar types, enum values and list lengths, each reported at the line
 * the user wrote it (or the --set that wrote it). After this the typed reads (read.c)
 * cannot fail. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene_internal.h"

static const char *kind_name(const yn *node)
{
  switch (node->kind) {
  case YN_MAP: return "a mapping";
  case YN_SEQ: return "a list";
  case YN_SCALAR: break;
  }
  return "a single value";
}

int ys_parse_double(const char *text, double *out)
{
  char *end;
  if (!text[0]) return 0;
  errno = 0;
  double v = strtod(text, &end);
  if (*end || end == text) return 0;
  *out = v;
  return 1;
}

static rs_status check_float(const yn *node)
{
  double v;
  if (yn_is_empty(node)) return yn_error(node, "missing value (expected a number)");
  if (node->quoted) return yn_error(node, "expected a number, got the string \"%s\"", node->text);
  if (!ys_parse_double(node->text, &v)) return yn_error(node, "not a number (got '%s')", node->text);
  if (!isfinite(v)) return yn_error(node, "must be a finite number (got '%s')", node->text);
  return RS_OK;
}

static rs_status check_int(const yn *node, int is_long)
{
  char *end;
  if (yn_is_empty(node)) return yn_error(node, "missing value (expected a whole number)");
  if (node->quoted)
    return yn_error(node, "expected a whole number, got the string \"%s\"", node->text);
  errno = 0;
  long long v = strtoll(node->text, &end, 10);
  if (*end || end == node->text) return yn_error(node, "not a whole number (got '%s')", node->text);
  long long lo = is_long ? LLONG_MIN : INT_MIN, hi = is_long ? LLONG_MAX : INT_MAX;
  if (errno == ERANGE || v < lo || v > hi)
    return yn_error(node, "number out of range (got '%s')", node->text);
  return RS_OK;
}

static rs_status check_enum(const yn *node, const ys_value *s)
{
  char list[512];
  size_t len = 0;
  list[0] = '\0';
  for (const ys_name *e = s->names; e->name; ++e) {
    if (strcmp(node->text, e->name) == 0) return RS_OK;
    int n = snprintf(list + len, sizeof list - len, "%s%s", e != s->names ? ", " : "", e->name);
    if (n > 0 && (size_t)n < sizeof list - len) len += (size_t)n;
  }
  if (yn_is_empty(node)) return yn_error(node, "missing value (one of: %s)", list);
  return yn_error(node, "unknown value '%s' (expected one of: %s)", node->text, list);
}

/* 1 when s is well-formed UTF-8 (no overlong forms, surrogates or code points beyond
 * U+10FFFF): a file's YAML is, but a --set value is whatever bytes the shell passed, and
 * the resolved scene (YAML) and the summaries (JSON) must hold it. */
static int is_utf8(const unsigned char *s)
{
  while (*s) {
    int n;
    unsigned lo = 0x80, hi = 0xBF;
    if (s[0] < 0x80) n = 1;
    else if (s[0] >= 0xC2 && s[0] <= 0xDF) n = 2;
    else if (s[0] >= 0xE0 && s[0] <= 0xEF) n = 3;
    else if (s[0] >= 0xF0 && s[0] <= 0xF4) n = 4;
    else return 0;
    if (s[0] == 0xE0) lo = 0xA0;
    if (s[0] == 0xED) hi = 0x9F;
    if (s[0] == 0xF0) lo = 0x90;
    if (s[0] == 0xF4) hi = 0x8F;
    if (n > 1 && (s[1] < lo || s[1] > hi)) return 0;
    for (int i = 2; i < n; ++i)
      if (s[i] < 0x80 || s[i] > 0xBF) return 0;
    s += n;
  }
  return 1;
}

static rs_status check_value(const yn *node, const ys_value *s);

/* Mappings and lists go on after a bad entry, so that one load reports every error
 * (ys_note); each error is noted where it is found. */
static rs_status check_mapping(const yn *node, const ys_value *s)
{
  char keys[512];
  rs_status bad = RS_OK;
  if (node->kind != YN_MAP) {
    if (yn_is_empty(node))
      return ys_note(yn_error(node, "missing value (expected a mapping of keys)"));
    if (node->kind == YN_SCALAR)
      return ys_note(yn_error(node, "expected a mapping of keys, got '%s'", node->text));
    return ys_note(yn_error(node, "expected a mapping of keys, got %s", kind_name(node)));
  }
  for (int i = 0; i < node->n; ++i) {
    const ys_field *f = s->fields;
    while (f->key && strcmp(f->key, node->keys[i]) != 0) ++f;
    if (!f->key) {
      ys_schema_keys(s, keys, sizeof keys);
      bad = ys_note(yn_error(node->kids[i], "unknown key '%s' (expected one of: %s)",
                             node->keys[i], keys));
      continue;
    }
    rs_status st = check_value(node->kids[i], f->value);
    if (st != RS_OK && st != RS_ERR_INPUT) return st;
    if (st != RS_OK) bad = st;
  }
  for (const ys_field *f = s->fields; f->key; ++f)
    if (f->required && yn_map_index(node, f->key) < 0)
      bad = ys_note(yn_error_key(node, f->key, "required key is missing"));
  return bad;
}

static rs_status check_sequence(const yn *node, const ys_value *s)
{
  if (node->kind != YN_SEQ) {
    if (yn_is_empty(node)) return ys_note(yn_error(node, "missing value (expected a list)"));
    if (node->kind == YN_SCALAR)
      return ys_note(yn_error(node, "expected a list, got '%s'", node->text));
    return ys_note(yn_error(node, "expected a list, got %s", kind_name(node)));
  }
  unsigned n = (unsigned)node->n;
  if (s->exact && n != s->min)
    return ys_note(yn_error(node, "must have exactly %u values (got %u)", s->min, n));
  if (n < s->min)
    return ys_note(yn_error(node, "needs at least %u entr%s (got %u)", s->min,
                            s->min == 1 ? "y" : "ies", n));
  if (n > s->max) return ys_note(yn_error(node, "takes at most %u entries (got %u)", s->max, n));
  rs_status bad = RS_OK;
  for (int i = 0; i < node->n; ++i) {
    rs_status st = check_value(node->kids[i], s->entry);
    if (st != RS_OK && st != RS_ERR_INPUT) return st;
    if (st != RS_OK) bad = st;
  }
  return bad;
}

static rs_status check_scalar(const yn *node, const ys_value *s);

static rs_status check_value(const yn *node, const ys_value *s)
{
  s = ys_schema_form(s, node);
  if (s->type == YS_MAP) return check_mapping(node, s);
  if (s->type == YS_LIST) return check_sequence(node, s);
  return ys_note(check_scalar(node, s));
}

static rs_status check_scalar(const yn *node, const ys_value *s)
{
  if (node->kind != YN_SCALAR)
    return yn_error(node, "expected a single value, got %s", kind_name(node));
  switch (s->type) {
  case YS_FLOAT: return check_float(node);
  case YS_INT: return check_int(node, 0);
  case YS_LONG: return check_int(node, 1);
  case YS_ENUM: return check_enum(node, s);
  case YS_STRING: {
    size_t len = strlen(node->text);
    if (node->text[0] == '\0' && s->min > 0) return yn_error(node, "must not be empty");
    if (yn_is_empty(node) && s->min > 0) return yn_error(node, "missing value");
    if (len > s->max) return yn_error(node, "too long (at most %u characters)", s->max);
    if (!is_utf8((const unsigned char *)node->text)) return yn_error(node, "not UTF-8 text");
    return RS_OK;
  }
  case YS_MAP:
  case YS_LIST: break;
  }
  return RS_ERROR(RS_ERR_INTERNAL, "schema type %d not handled by the scene checks", (int)s->type);
}

rs_status ys_typecheck(const yn *node, const ys_value *schema)
{
  return check_value(node, schema);
}

