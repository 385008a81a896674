/* The /defects group of a reelsim file (internal to the output module; docs/output.md). */
#ifndef RS_OUTPUT_H5_DEFECTS_H
#define RS_OUTPUT_H5_DEFECTS_H

#include <hdf5.h>

#include "reelsim/defects.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"

/* Assesses the defect-risk rules (reelsim/defects.h) on the result, unless `given` has
 * the report already, and writes their verdicts, figures and flagged ranges under
 * /defects. */
rs_status rs_h5_write_defects(hid_t file, const rs_scene *scene, const rs_reel_result *res,
                              const rs_defect_report *given);

#endif
