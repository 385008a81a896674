/* HDF5 output of a wound reel (serial HDF5 1.10). See docs/output.md for the layout. */
#ifndef REELSIM_OUTPUT_H
#define REELSIM_OUTPUT_H

#include <stddef.h>

#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Writes the result to `path`: first to a temporary name beside it, renamed onto
 * `path` only when complete, so a failed run never leaves a file that looks whole. */
rs_status rs_output_write(const char *path, const rs_scene *scene, const rs_reel_result *res);

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

#ifdef __cplusplus
}
#endif
#endif
