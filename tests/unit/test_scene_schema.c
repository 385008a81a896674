/* The scene schema (src/scene/schema.c), the one table of keys the loader's checks,
 * defaults, --set and typed reads share: every key it lists is documented in
 * docs/scenes.md, every default it gives passes its own key's checks, and every path
 * it resolves leads to the value type the table says. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene/scene_internal.h"

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

static char *docs;

/* `key`, key: (in a YAML example or a flow mapping) or .key` (in a dotted path) */
static int documented(const char *key)
{
  char pat[3][160];
  snprintf(pat[0], sizeof pat[0], "`%s`", key);
  snprintf(pat[1], sizeof pat[1], "%s:", key);
  snprintf(pat[2], sizeof pat[2], ".%s`", key);
  for (int i = 0; i < 3; ++i)
    if (strstr(docs, pat[i])) return 1;
  return 0;
}

static int walk_docs(const ys_value *v, const char *path)
{
  int n = 0;
  if (v->type == YS_LIST) { /* a list's entries are reached by index: storage[0].hours */
    char sub[256];
    snprintf(sub, sizeof sub, "%s[0]", path);
    return walk_docs(v->entry, sub);
  }
  if (v->type != YS_MAP) return 0;
  for (const ys_field *f = v->fields; f->key; ++f) {
    char sub[256];
    snprintf(sub, sizeof sub, "%s%s%s", path, path[0] ? "." : "", f->key);
    if (!documented(f->key)) printf("  not in docs/scenes.md: %s\n", sub);
    CHECK(documented(f->key));
    CHECK(rsi_ys_schema_at(sub) == f->value);
    n += 1 + walk_docs(f->value, sub);
  }
  return n;
}

static void schema_documented(void)
{
  FILE *f = fopen(RS_ROOT_DIR "/docs/scenes.md", "rb");
  CHECK(f != NULL);
  if (!f) return;
  docs = calloc(1, 1 << 20);
  CHECK(docs != NULL);
  if (docs) {
    size_t len = fread(docs, 1, (1 << 20) - 1, f);
    docs[len] = '\0';
    int keys = walk_docs(&rsi_ys_scene_schema, "");
    printf("  %d keys\n", keys);
    CHECK(keys > 60);
  }
  fclose(f);
  free(docs);
  docs = NULL;
}

static int walk_defaults(const ys_value *v)
{
  int n = 0;
  if (v->type == YS_LIST) return walk_defaults(v->entry);
  if (v->type != YS_MAP) return 0;
  for (const ys_field *f = v->fields; f->key; ++f) {
    if (f->def && f->value->type != YS_MAP) {
      yn *node = rsi_yn_new_scalar(f->def, "schema", 1, f->key);
      CHECK(node != NULL);
      rs_status st = node ? rsi_ys_typecheck(node, f->value) : RS_ERR_MEMORY;
      if (st != RS_OK) printf("  default of %s: %s\n", f->key, rs_error_message());
      CHECK(st == RS_OK);
      rsi_yn_free(node);
      ++n;
    }
    CHECK(!f->required || !f->def); /* a required key never needs its default */
    if (f->when) {
      /* the key a default depends on is a sibling enum */
      const ys_field *s = v->fields;
      while (s->key && strcmp(s->key, f->when) != 0) ++s;
      CHECK(s->key != NULL);
      if (s->key) CHECK(s->value->type == YS_ENUM && s < f); /* filled before it */
    }
    n += walk_defaults(f->value);
  }
  return n;
}

static void defaults_pass_checks(void)
{
  int n = walk_defaults(&rsi_ys_scene_schema);
  printf("  %d defaults\n", n);
  CHECK(n >= 14);
}

static const check_case cases[] = {
    {"schema_documented", schema_documented},
    {"defaults_pass_checks", defaults_pass_checks},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
