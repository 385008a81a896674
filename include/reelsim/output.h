/* HDF5 output of a wound reel (serial HDF5 1.10). See docs/output.md for the layout. */
#ifndef REELSIM_OUTPUT_H
#define REELSIM_OUTPUT_H

#include <stddef.h>

#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"
#include "reelsim/storage.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

/* Writes the result to `path`: first to a temporary name beside it, renamed onto
 * `path` only when complete, so a failed run never leaves a file that looks whole. */
rs_status rs_output_write(const char *path, const rs_scene *scene, const rs_reel_result *res);
/* The same with the storage stages (rs_storage_run) under /storage (docs/output.md);
 * storage NULL: exactly rs_output_write. */
rs_status rs_output_write_stored(const char *path, const rs_scene *scene,
                                 const rs_reel_result *res, const rs_storage_result *storage);

/* CSV export (docs/output.md): writes DIR/<name>-profile.csv (layer, radius_m, sigma_r_Pa,
 * sigma_theta_Pa, pressure_Pa, wound_on_tension_N_per_m) and DIR/<name>-wot.csv (radius_m,
 * web_tension_N_per_m, nip_load_N_per_m, wound_on_tension_N_per_m): a header line, one row
 * per layer, %.17g. Each file goes to a temporary that is renamed into place only when
 * both are complete. DIR must be an existing, writable directory (RS_ERR_INPUT). */
rs_status rs_output_write_csv(const char *dir, const char *name, const rs_reel_result *res);
/* The check rs_output_write_csv starts with, for callers that want it before winding. */
rs_status rs_output_check_csv_dir(const char *dir);
/* DIR/<name>-<which>.csv into buf (RS_ERR_INPUT when it does not fit). */
rs_status rs_output_csv_path(const char *dir, const char *name, const char *which, char *buf,
                             size_t size);

/* The check every writer starts with, for callers that want it before a long run:
 * RS_ERR_IO naming `path` when its directory is missing, not a directory or not
 * writable, or `path` is a directory or a device. */
rs_status rs_output_check_target(const char *path);

/* One run of a comparison (`reelsim compare`): a scene and what winding it gave. */
typedef struct rs_output_run {
  const rs_scene *scene;
  const rs_reel_result *result;
} rs_output_run;

/* Writes n >= 1 runs to one file, staged like rs_output_write (docs/output.md, "Comparison
 * files"): run i's layout (what rs_output_write puts on the root) under
 * /runs/<rs_output_run_name(i, n)>, and /summary with the key figures of every run, in
 * order. */
rs_status rs_output_write_compare(const char *path, int n, const rs_output_run *runs);

/* The group name of run i (0-based) of n: "<i+1>-<scene file name without directory and
 * extension>", the number zero-padded to the width of n ("01-rider" .. "12-taper") so
 * that the groups sort in run order. */
void rs_output_run_name(int i, int n, const char *scene_path, char *buf, size_t size);

RS_END_DECLS
#endif
