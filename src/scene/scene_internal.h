/* Internal interface between the scene loader's steps:
 *   parse (yparse.c) -> --set material (overrides.c) -> model lookup (models.c)
 *   -> other --set (overrides.c) -> shorthands (normalize.c) -> schema checks on the tree
 *   (typecheck.c) -> defaults (defaults.c) -> typed reads (read.c), range checks and
 *   derived values (resolve_*.c) -> resolved text (load.c, emitted from the tree).
 * The schema (schema.c) is the one description of the keys the steps share. */
#ifndef RS_SCENE_INTERNAL_H
#define RS_SCENE_INTERNAL_H

#include <stddef.h>
#include <stdio.h>

#include "reelsim/scene.h"
#include "scene/scene_type.h"
#include "scene/schema.h"
#include "scene/ytree.h"

/* typecheck.c */
rs_status rsi_ys_typecheck(const yn *node, const ys_value *schema);
int rsi_ys_parse_double(const char *text, double *out);

/* read.c: typed values of the checked tree at a dotted path (see read.c). */
double rsi_ys_num(const yn *root, const char *path);
long long rsi_ys_int(const yn *root, const char *path);
int rsi_ys_enum(const yn *root, const char *path); /* the rs_ enum value of its name */
const char *rsi_ys_str(const yn *root, const char *path);
/* a list of numbers, and a list of pairs [a, b]: how many (at most max) */
int rsi_ys_nums(const yn *root, const char *path, double *out, int max);
int rsi_ys_pairs(const yn *root, const char *path, double *a, double *b, int max);

/* overrides.c: applies one "key.path=value". pass 0 applies only a set of `material`
 * itself (before the model is looked up), pass 1 everything else. */
rs_status rsi_ys_apply_set(yn *root, const char *set, int pass);

/* models.c: replaces a `material: name` by the model file's tree (lines stay those of
 * the model file) and fills scene->material_source. */
rs_status rsi_ys_inline_material(yn *root, rs_scene *scene);
/* The search order for a model name (for messages and tests): up to `max` candidates. */
int rsi_ys_model_candidates(const char *scene_path, const char *name, char cand[][RS_PATH_MAX],
                        int max);

/* normalize.c: `tension: 350` -> {law: constant, value: 350}; a table without `law`. */
rs_status rsi_ys_normalize(yn *root);

/* defaults.c: fills absent optional keys (marked origin "default"); the title and the
 * output file are named after the scene's path. */
rs_status rsi_ys_fill_defaults(yn *root, const char *scene_path);

/* resolve_*.c: the checked tree -> rs_scene, with range checks located through the tree. */
rs_status rsi_ys_resolve_material(const yn *root, rs_material *m);
rs_status rsi_ys_resolve_recipe(const yn *root, const char *path, const char *what, double r0,
                            double r1, rs_recipe *out);
rs_status rsi_ys_resolve(const yn *root, rs_scene *scene);
/* resolve_core.c: the core's outer radius and, when given, its inner radius (bore,
 * inner_diameter or wall), with the keys they came from */
rs_status rsi_ys_core_geometry(const yn *root, double *radius, const char **key, double *bore,
                           int *has_bore, const char **bore_key);
/* resolve_storage.c: winding temperature and humidity, storage stages, the material's
 * thermal, hygroscopic and viscoelastic data, the core's expansion (docs/storage.md). */
rs_status rsi_ys_resolve_storage(const yn *root, rs_scene *scene);
/* resolve_winder.c: `nip` (a mapping or a list) and `winder` into the problem, and the
 * drums' capacity of every nip (docs/nip.md, "Two-drum winders"). resolve.c hands in its
 * steps for one nip (the tree's `nip` mapping into scene->problem.nip; by_winder: its load
 * comes from the winder's statics) and for one drum's friction capacity along the roll;
 * the list applies them to each entry. */
typedef rs_status (*ys_nip_step)(const yn *root, rs_scene *scene, int by_winder);
typedef rs_status (*ys_capacity_step)(const yn *root, const rs_scene *scene);
rs_status rsi_ys_resolve_nips(const yn *root, rs_scene *scene, ys_nip_step one);
rs_status rsi_ys_check_nips_capacity(const yn *root, rs_scene *scene, ys_capacity_step one);
/* effects_winder.c: the lines of `nip:` as a list (1 when it printed them, 0 for one nip)
 * and the nips' saturation, for reelsim check */
int rsi_ys_print_nips(FILE *out, const rs_scene *scene);
void rsi_ys_print_nip_saturation(FILE *out, const rs_scene *scene);
/* resolve_speed.c: winding.speed and the centrifugal load */
rs_status rsi_ys_resolve_speed(const yn *root, rs_scene *scene);
/* resolve_lanes.c: the `lanes` block (docs/lanes.md); count 0 without it */
rs_status rsi_ys_resolve_lanes(const yn *root, rs_scene *scene);

/* Reports an error at a dotted scene path; when the key is absent, at its nearest
 * present parent ("file:line: nip.load: required by ..."). */
rs_status rsi_ys_fail(const yn *root, const char *path, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int rsi_ys_has(const yn *root, const char *path);

/* diag.c: every error of a load, reported together (one line each, the first
 * YS_MAX_ERRORS of them). rsi_ys_note(st) keeps the recorded message when st is RS_ERR_INPUT
 * and returns st; rsi_ys_errors_end() records them all as one message (lines joined by '\n')
 * and returns RS_ERR_INPUT, or RS_OK when there were none. */
enum { YS_MAX_ERRORS = 20 };
void rsi_ys_errors_begin(void);
rs_status rsi_ys_note(rs_status st);
int rsi_ys_errors(void);
rs_status rsi_ys_errors_end(void);

/* effects.c / resolve: numbers for people: 1e9 rather than 1e+09. */
void rsi_ys_fmt(char *buf, size_t size, double v);

#endif
