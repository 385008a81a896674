/* The /nip group of a reelsim file (internal to the output module; docs/output.md). */
#ifndef RS_OUTPUT_H5_NIP_H
#define RS_OUTPUT_H5_NIP_H

#include <hdf5.h>

#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"

/* The nip record of a run with a nip (where the nip was solved, what it found) and the
 * full contact distributions kept at output.nip_profiles_at. Writes nothing without one. */
rs_status rs_h5_write_nip(hid_t loc, const rs_scene *scene, const rs_reel_result *res);

#endif
