/* A scene: everything one simulated reel needs, resolved and checked.
 *
 * Loaded from YAML (libyaml) by rs_scene_load; see docs/scenes.md for every key.
 * The scene is the file's view of a reel: the rs_problem it resolves to (what the reel
 * winds, rs_scene_problem) plus what belongs to the file (path, title, where the material
 * came from, the output file, the resolved text). */
#ifndef REELSIM_SCENE_H
#define REELSIM_SCENE_H

#include <stddef.h>
#include <stdio.h>

#include "reelsim/problem.h"
#include "reelsim/reel.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

enum { RS_PATH_MAX = 4096 };

/* Opaque: read through the functions below (the struct: src/scene/scene_type.h). */
typedef struct rs_scene rs_scene;

/* Loads and checks a scene. `sets` are "key.path=value" overrides applied to scalars
 * before checking (the CLI's --set). Errors: RS_ERR_INPUT with "FILE:LINE: key.path: why".
 * The caller owns *out (rs_scene_destroy). */
rs_status rs_scene_load(const char *path, int n_sets, const char *const *sets, rs_scene **out);
/* The same for a scene held in memory: text[0..len) (need not be NUL-terminated) is the
 * file's content and `name` stands for its path (messages, the directory models are
 * looked up in, the default title and output file name). */
rs_status rs_scene_load_text(const char *name, const char *text, size_t len, int n_sets,
                             const char *const *sets, rs_scene **out);
void rs_scene_destroy(rs_scene **scene);

/* What the scene winds: its physics and numerics (owned by the scene). */
const rs_problem *rs_scene_problem(const rs_scene *scene);
/* Winds a loaded scene: rs_reel_wind of rs_scene_problem(scene). */
rs_status rs_scene_wind(const rs_scene *scene, const rs_reel_options *opts,
                        rs_reel_result **out);
/* What the scene says of itself: the file as given, its title, the HDF5 output file ("" =
 * none), the resolved scene as YAML (every key with its value, defaults filled in). Owned
 * by the scene. */
const char *rs_scene_path(const rs_scene *scene);
const char *rs_scene_title(const rs_scene *scene);
const char *rs_scene_output_file(const rs_scene *scene);
const char *rs_scene_resolved_text(const rs_scene *scene);
/* The scene file's name without its directory and last extension, into buf[size],
 * truncated to fit ("cases/newsprint-rider.yaml" -> "newsprint-rider"): what names the
 * scene's outputs. "" for no scene. */
void rs_scene_name(const rs_scene *scene, char *buf, size_t size);

/* Writes the human-readable list of active effects, one per line
 * ("  - core: elastic (E_c = 1e9 Pa), radius 76.2 mm", "  - nip: none (T0 = web tension)"). */
void rs_scene_print_effects(const rs_scene *scene, FILE *out);

/* Slip warnings: values the scene's checks accepted but that lie outside the range plants
 * use for their key, each with the unit slip that would explain it ("cases/x.yaml:7:
 * winding.speed 600 m/s: did you mean 600 m/min? (plants use 0 to 50 m/s)"; the ranges:
 * docs/scenes.md). How many (0 for NULL), and the i-th (0-based; "" out of range). Owned by
 * the scene. */
int rs_scene_warning_count(const rs_scene *scene);
const char *rs_scene_warning(const rs_scene *scene, int i);

RS_END_DECLS
#endif
