/* The layout of a reelsim file, shared by the single-run writer (h5_write.c) and the
 * comparison writer (h5_compare.c); internal to the output module. docs/output.md. */
#ifndef RS_OUTPUT_H5_LAYOUT_H
#define RS_OUTPUT_H5_LAYOUT_H

#include <hdf5.h>

#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"
#include "reelsim/storage.h"

/* Root attributes every reelsim file has: program, version, created. */
rs_status rs_h5_write_file_attributes(hid_t file);

/* One run into the group `loc` (the root of a run file, /runs/<name> of a comparison):
 * its attributes (title, scene_file, scene, layers, ..., wall_seconds) and the groups
 * layers/ and final/ (and whatever a run gains later) under it. */
rs_status rs_h5_write_run(hid_t loc, const rs_scene *scene, const rs_reel_result *res);
/* The same with the defect report already assessed (NULL: assessed here). */
rs_status rs_h5_write_run_assessed(hid_t loc, const rs_scene *scene, const rs_reel_result *res,
                                   const rs_defect_report *defects);

/* RS_ERR_INTERNAL when a result lacks an array it claims to have. */
rs_status rs_h5_check_result(const rs_reel_result *res);
/* /storage (docs/output.md, "Storage") under loc: the stages of a storage result. */
rs_status rs_h5_write_storage(hid_t loc, const rs_storage_result *sr);
/* RS_ERR_INTERNAL when a storage result does not fit the reel it stored (NULL fits). */
rs_status rs_h5_check_storage(const rs_storage_result *sr, const rs_reel_result *res);

/* Fills an in-memory file (after the file attributes) with what ctx describes. */
typedef rs_status (*rs_h5_build_fn)(hid_t file, const void *ctx);

/* Checks the target, builds the file in memory with `build`, then stages it onto `path`
 * (temporary + rename, util/atomic_file.h): whole or absent, an older file untouched on failure. */
rs_status rs_h5_write_staged(const char *path, rs_h5_build_fn build, const void *ctx);

#endif
