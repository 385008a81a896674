/* The numerical choices a problem makes for its roll (rs_numerics, reelsim/problem.h):
 * where a new layer's load goes, whether the deep solution is reused, whether each
 * integration is corrected for its error. The engine that reads them is private
 * (src/roll/roll.h); docs/roll-model.md explains each. */
#ifndef REELSIM_NUMERICS_H
#define REELSIM_NUMERICS_H

#include "reelsim/export.h"
RS_BEGIN_DECLS

/* Where a new layer's wound-on load goes (docs/roll-model.md, "Where a new layer's load
 * goes"). Both meet as the caliper goes to zero; they differ at first order in t. */
typedef enum rs_load_placement {
  RS_LOAD_BENEATH = 0,   /* the default: the layer joins at hoop stress T0/t and, as a thin
                            ring, presses on the roll beneath it: the increment lives on
                            [r_c, s_{k-1}] with ds(s_{k-1}) = -T0/s_{k-1}, the new layer's
                            outer face is traction free (the exact statics of real layers) */
  RS_LOAD_HAKIEL = 1     /* Hakiel (1987): ds(s_k) = -T0/s_k at the new layer's outer radius,
                            the new layer part of the loaded body */
} rs_load_placement;

/* Whether an increment may keep the deep part of an earlier integration from the core
 * where the modulus has barely changed since, and integrate only from there up (the error
 * this adds to an increment is held to a share of rtol, RS_ACCURACY_PER_RTOL in the engine,
 * times T0/s). docs/roll-model.md,
 * "Reusing the deep solution" and "The deep part corrected for the drift" (the default, with
 * one layer per increment and its load beneath it; otherwise the first-order reuse). */
typedef enum rs_reuse {
  RS_REUSE_ON = 0,       /* the default: the deep part reused, corrected to first order
                            for the modulus drift since it was integrated */
  RS_REUSE_OFF = 1,      /* every increment integrated from the core */
  RS_REUSE_FIRST_ORDER = 2 /* the deep part reused as it was integrated, its drift held to
                            the tolerance at first order (the start sinks as it drifts) */
} rs_reuse;

/* Whether the (w, ln y) each integration stores is corrected for its error
 * (docs/roll-model.md, "Correcting the integration's error"): each step's quintic
 * interpolant misses the equations by a defect measured at its middle, and the errors
 * this leaves are carried up the roll by the equations' linearisation; subtracted, the
 * stresses come out 80x or more closer to a tight reference at equal cost. */
typedef enum rs_correction {
  RS_CORRECTION_ON = 0,  /* the default */
  RS_CORRECTION_OFF = 1  /* the stored ln y as CVODE integrates it */
} rs_correction;

RS_END_DECLS
#endif
