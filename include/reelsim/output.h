/* HDF5 output of a wound reel (serial HDF5 1.10). See docs/output.md for the layout. */
#ifndef REELSIM_OUTPUT_H
#define REELSIM_OUTPUT_H

#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Writes the result to `path`: first to a temporary name beside it, renamed onto
 * `path` only when complete, so a failed run never leaves a file that looks whole. */
rs_status rs_output_write(const char *path, const rs_scene *scene, const rs_reel_result *res);

#ifdef __cplusplus
}
#endif
#endif
