/* The scene schema: every key of a scene and model file, its type, whether it is required,
 * its default, and what is nested below it. This one table drives the positioned checks on
 * the YAML tree (typecheck.c), the defaults written into it (defaults.c), the creation of
 * keys by --set (overrides.c) and the typed reads the resolution makes (read.c).
 * docs/scenes.md documents every key listed here. */
#ifndef RS_SCENE_SCHEMA_H
#define RS_SCENE_SCHEMA_H

#include <stddef.h>

#include "scene/ytree.h"

typedef enum ys_type {
  YS_FLOAT,  /* a finite number */
  YS_INT,    /* a whole number that fits an int */
  YS_LONG,   /* a whole number that fits a long long */
  YS_ENUM,   /* one of `names` */
  YS_STRING, /* min..max bytes */
  YS_MAP,    /* the keys `fields` */
  YS_LIST    /* min..max entries, each an `entry` (min == max && exact: exactly that many) */
} ys_type;

typedef struct ys_name {
  const char *name;
  int value; /* the rs_ enum value it stands for */
} ys_name;

typedef struct ys_field ys_field;

typedef struct ys_value {
  ys_type type;
  const ys_field *fields; /* YS_MAP: ends with a field whose key is NULL */
  const struct ys_value *entry; /* YS_LIST */
  unsigned min, max;      /* YS_LIST: entries; YS_STRING: bytes */
  int exact;              /* YS_LIST: exactly min entries ("a pair") */
  const ys_name *names;   /* YS_ENUM: ends with a NULL name */
  /* YS_MAP: the value may instead be written as this list (`nip:` as a list of nips); the
   * checks, defaults and paths ("nip[1].load") follow the form the file uses */
  const struct ys_value *list_form;
} ys_value;

/* A default that depends on the scene rather than on the schema: the file's stem. */
typedef enum ys_derived { YS_PLAIN, YS_FROM_STEM, YS_FROM_STEM_H5 } ys_derived;

struct ys_field {
  const char *key;
  int required;
  const ys_value *value;
  /* Default, written into the tree when the key is absent (origin "default") and, for a
   * mapping, an empty one to fill: the text, or "{}" for a mapping. */
  const char *def;
  ys_derived derived;
  /* The default applies only when the sibling key `when` has (or with a leading '!',
   * has not) the text `when_is`; NULL: always. */
  const char *when, *when_is;
};

/* The top-level mapping of a scene file. */
extern const ys_value ys_scene_schema;

/* Keys whose value may also be written as a plain number (a constant recipe) or a name
 * (a model file): the loader rewrites them into mappings before the checks apply. */
int ys_is_shorthand(const char *scene_path);

/* The schema of the value at a dotted path from the top level ("nip.load.table[2]");
 * NULL if the schema has no such key. */
const ys_value *ys_schema_at(const char *scene_path);

/* The schema a node is checked against: s, or s->list_form when the node is a list. */
const ys_value *ys_schema_form(const ys_value *s, const yn *node);

/* The keys of a mapping, ", "-separated, for messages. */
void ys_schema_keys(const ys_value *mapping, char *buf, size_t size);

#endif
