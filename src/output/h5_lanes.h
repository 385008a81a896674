/* The /lanes group of a reelsim file (internal to the output module; docs/output.md,
 * docs/lanes.md). */
#ifndef RS_OUTPUT_H5_LANES_H
#define RS_OUTPUT_H5_LANES_H

#include <hdf5.h>

#include "reelsim/reel.h"
#include "reelsim/status.h"

/* Each lane's record (res->lanes); writes nothing for a run without lanes. */
rs_status rs_h5_write_lanes(hid_t loc, const rs_reel_result *res);

#endif
