/* Walks the libcyaml schema over the positioned YAML tree: unknown keys, missing
 * required keys, scalar types, enum values and list lengths, each reported at the line
 * the user wrote it. libcyaml would find the same faults, but only in the text the loader
 * hands it (after overrides and shorthands), where its line numbers mean nothing. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene_internal.h"

static void key_list(const cyaml_schema_field_t *f, char *buf, size_t size)
{
  size_t len = 0;
  buf[0] = '\0';
  for (; f->key; ++f) {
    int n = snprintf(buf + len, size - len, "%s%s", len ? ", " : "", f->key);
    if (n < 0 || (size_t)n >= size - len) break;
    len += (size_t)n;
  }
}

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

static rs_status check_int(const yn *node, unsigned size)
{
  char *end;
  if (yn_is_empty(node)) return yn_error(node, "missing value (expected a whole number)");
  if (node->quoted)
    return yn_error(node, "expected a whole number, got the string \"%s\"", node->text);
  errno = 0;
  long long v = strtoll(node->text, &end, 10);
  if (*end || end == node->text) return yn_error(node, "not a whole number (got '%s')", node->text);
  long long lo = size >= 8 ? LLONG_MIN : INT_MIN, hi = size >= 8 ? LLONG_MAX : INT_MAX;
  if (errno == ERANGE || v < lo || v > hi)
    return yn_error(node, "number out of range (got '%s')", node->text);
  return RS_OK;
}

static rs_status check_enum(const yn *node, const cyaml_schema_value_t *s)
{
  char list[512];
  size_t len = 0;
  list[0] = '\0';
  for (uint32_t i = 0; i < s->enumeration.count; ++i) {
    if (strcmp(node->text, s->enumeration.strings[i].str) == 0) return RS_OK;
    int n = snprintf(list + len, sizeof list - len, "%s%s", i ? ", " : "",
                     s->enumeration.strings[i].str);
    if (n > 0 && (size_t)n < sizeof list - len) len += (size_t)n;
  }
  if (yn_is_empty(node)) return yn_error(node, "missing value (one of: %s)", list);
  return yn_error(node, "unknown value '%s' (expected one of: %s)", node->text, list);
}

static rs_status check_value(const yn *node, const cyaml_schema_value_t *s);

static rs_status check_mapping(const yn *node, const cyaml_schema_value_t *s)
{
  char keys[512];
  if (node->kind != YN_MAP) {
    if (yn_is_empty(node)) return yn_error(node, "missing value (expected a mapping of keys)");
    if (node->kind == YN_SCALAR)
      return yn_error(node, "expected a mapping of keys, got '%s'", node->text);
    return yn_error(node, "expected a mapping of keys, got %s", kind_name(node));
  }
  for (int i = 0; i < node->n; ++i) {
    const cyaml_schema_field_t *f = s->mapping.fields;
    while (f->key && strcmp(f->key, node->keys[i]) != 0) ++f;
    if (!f->key) {
      key_list(s->mapping.fields, keys, sizeof keys);
      return yn_error(node->kids[i], "unknown key '%s' (expected one of: %s)", node->keys[i],
                      keys);
    }
    if (f->value.type == CYAML_IGNORE) continue;
    rs_status st = check_value(node->kids[i], &f->value);
    if (st != RS_OK) return st;
  }
  for (const cyaml_schema_field_t *f = s->mapping.fields; f->key; ++f)
    if (!(f->value.flags & CYAML_FLAG_OPTIONAL) && yn_map_index(node, f->key) < 0)
      return yn_error_key(node, f->key, "required key is missing");
  return RS_OK;
}

static rs_status check_sequence(const yn *node, const cyaml_schema_value_t *s)
{
  if (node->kind != YN_SEQ) {
    if (yn_is_empty(node)) return yn_error(node, "missing value (expected a list)");
    if (node->kind == YN_SCALAR) return yn_error(node, "expected a list, got '%s'", node->text);
    return yn_error(node, "expected a list, got %s", kind_name(node));
  }
  unsigned n = (unsigned)node->n;
  if (s->type == CYAML_SEQUENCE_FIXED && n != s->sequence.min)
    return yn_error(node, "must have exactly %u values (got %u)", s->sequence.min, n);
  if (n < s->sequence.min)
    return yn_error(node, "needs at least %u entr%s (got %u)", s->sequence.min,
                    s->sequence.min == 1 ? "y" : "ies", n);
  if (n > s->sequence.max)
    return yn_error(node, "takes at most %u entries (got %u)", s->sequence.max, n);
  for (int i = 0; i < node->n; ++i) {
    rs_status st = check_value(node->kids[i], s->sequence.entry);
    if (st != RS_OK) return st;
  }
  return RS_OK;
}

static rs_status check_value(const yn *node, const cyaml_schema_value_t *s)
{
  switch (s->type) {
  case CYAML_MAPPING: return check_mapping(node, s);
  case CYAML_SEQUENCE:
  case CYAML_SEQUENCE_FIXED: return check_sequence(node, s);
  default: break;
  }
  if (node->kind != YN_SCALAR)
    return yn_error(node, "expected a single value, got %s", kind_name(node));
  switch (s->type) {
  case CYAML_FLOAT: return check_float(node);
  case CYAML_INT: return check_int(node, s->data_size);
  case CYAML_ENUM: return check_enum(node, s);
  case CYAML_STRING: {
    size_t len = strlen(node->text);
    if (node->text[0] == '\0' && s->string.min > 0) return yn_error(node, "must not be empty");
    if (yn_is_empty(node) && s->string.min > 0) return yn_error(node, "missing value");
    if (len > s->string.max)
      return yn_error(node, "too long (at most %u characters)", s->string.max);
    return RS_OK;
  }
  default: break;
  }
  return RS_ERROR(RS_ERR_INTERNAL, "schema type %d not handled by the scene checks", (int)s->type);
}

rs_status ys_typecheck(const yn *node, const cyaml_schema_value_t *schema)
{
  return check_value(node, schema);
}

void ys_schema_keys(const cyaml_schema_value_t *mapping, char *buf, size_t size)
{
  if (mapping->type != CYAML_MAPPING) {
    snprintf(buf, size, "(none)");
    return;
  }
  key_list(mapping->mapping.fields, buf, size);
}
