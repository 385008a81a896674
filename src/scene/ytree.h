/* A small YAML node tree that remembers where every value came from.
 *
 * The loader parses with libyaml into this tree (yparse.c) and every later step works on
 * it: it keeps the file and line of every key, the --set override that replaced a value,
 * and a display path ("winding.tension.end", "radial.points[3]"), so every check can say
 * where the offending value was written. */
#ifndef RS_SCENE_YTREE_H
#define RS_SCENE_YTREE_H

#include <stddef.h>

#include "reelsim/status.h"

typedef enum yn_kind { YN_SCALAR, YN_MAP, YN_SEQ } yn_kind;

typedef struct yn yn;
struct yn {
  yn_kind kind;
  char *text;        /* scalar text ("" for an empty value) */
  int quoted;        /* the scalar was quoted in its file: a string, never a number */
  const char *file;  /* file the value was written in (not owned); NULL if none */
  int line;          /* 1-based line of its key (map values) or of the item (sequences) */
  char *origin;      /* "--set key=value" when an override wrote it, "default" when the
                        loader filled it in; NULL for values read from a file */
  char *path;        /* display path within its own file ("core.radius") */
  int n, cap;        /* children */
  char **keys;       /* map keys (NULL for sequences) */
  yn **kids;
};

/* Limits on what one file may hold (docs/scenes.md, "Limits"), each refused while the
 * file is read with RS_ERR_INPUT naming the limit: nesting levels below the top-level
 * mapping, keys in one mapping (looked up by a linear search), values (scalars, lists
 * and mappings, alias copies included), values copied from anchors by aliases, and bytes. */
enum {
  YN_MAX_DEPTH = 64,
  YN_MAX_KEYS = 256,
  YN_MAX_VALUES = 20000,
  YN_MAX_ALIAS_VALUES = 10000,
  YN_MAX_BYTES = 1 << 20
};

/* Parses a YAML file into a tree (yparse.c). `file` must outlive the tree (the nodes
 * point at it). Syntax errors, duplicate keys and the limits above: RS_ERR_INPUT
 * "file:line: ...". A missing file: RS_ERR_INPUT "file: cannot open (reason)". */
rs_status rsi_yn_parse_file(const char *file, yn **out);

/* Same for text in memory (`file` names it in messages). */
rs_status rsi_yn_parse_text(const char *text, size_t len, const char *file, yn **out);

void rsi_yn_free(yn *node);

yn *rsi_yn_new_scalar(const char *text, const char *file, int line, const char *path);
yn *rsi_yn_new_map(const char *file, int line, const char *path);
yn *rsi_yn_new_seq(const char *file, int line, const char *path);
/* Appends to a sequence (frees child on failure). */
rs_status rsi_yn_seq_push(yn *seq, yn *child);

/* Map access. rsi_yn_map_get returns NULL when the key is absent (or node is not a map). */
yn *rsi_yn_map_get(const yn *map, const char *key);
int rsi_yn_map_index(const yn *map, const char *key);
/* Adds key -> child at the end, or replaces the existing value (freeing it). */
rs_status rsi_yn_map_put(yn *map, const char *key, yn *child);
/* Removes key (freeing its value); no-op when absent. */
void rsi_yn_map_remove(yn *map, const char *key);

enum { YN_SEG_MAX = 128 };

/* Splits a key path "a.b[2].c" into its segments "a", "b", "2", "c"; returns how many,
 * or -1 when the path is malformed or has more than `max`. */
int rsi_yn_path_split(const char *path, char seg[][YN_SEG_MAX], int max);
/* 1 and *i when a segment is a list index ("2"). */
int rsi_yn_seg_index(const char *seg, long *i);

/* Looks up a dotted path below `root`: "core.radius", "radial.points[2][0]",
 * "table.1.0" (a number on a sequence is an index). NULL when absent. */
yn *rsi_yn_get(const yn *root, const char *path);

/* Deep copy (the copy points at the same file names). */
yn *rsi_yn_copy(const yn *node);

/* Sets node->origin (copied) on the node and every node below it. */
rs_status rsi_yn_set_origin(yn *node, const char *origin);

/* Re-bases display paths: node->path = prefix (+ "." key / "[i]" below). */
rs_status rsi_yn_set_paths(yn *node, const char *prefix);

/* "file:line" or the override that wrote the value, for error messages. */
void rsi_yn_where(const yn *node, char *buf, size_t size);

/* Emits the tree as block-style YAML (malloc'd, NUL-terminated). */
rs_status rsi_yn_emit(const yn *root, char **text);

/* 1 for an empty value (`key:` with nothing after it, `~`, `null`). */
int rsi_yn_is_empty(const yn *node);

/* Records an input error located at `node`:
 *   "file:line: path: message"   or   "--set k=v: message" for overrides.
 * Returns RS_ERR_INPUT. */
rs_status rsi_yn_error(const yn *node, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The same for a key of `map` that is absent: located at the map, path "map.key". */
rs_status rsi_yn_error_key(const yn *map, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
