/* reelsim: the whole public API in one include.
 *
 *   #include <reelsim/reelsim.h>
 *
 * Link with reelsim::reelsim (CMake: find_package(reelsim CONFIG)) or
 * `pkg-config --cflags --libs reelsim`. Every function returns an rs_status and records
 * what went wrong (reelsim/status.h). Every public header is listed here (a test checks
 * it); a new one goes in its layer's place. */
#ifndef REELSIM_REELSIM_H
#define REELSIM_REELSIM_H

/* base: status and the error record, the version, clocks */
#include "reelsim/status.h"
#include "reelsim/version.h"
#include "reelsim/clock.h"

/* materials, recipes, the numerical choices */
#include "reelsim/core.h"
#include "reelsim/material.h"
#include "reelsim/recipe.h"
#include "reelsim/numerics.h"

/* the nip */
#include "reelsim/nip.h"

/* the reel: winds a problem */
#include "reelsim/problem.h"
#include "reelsim/reel.h"
#include "reelsim/defects.h"
#include "reelsim/storage.h"

/* scenes (YAML -> problem), files */
#include "reelsim/scene.h"
#include "reelsim/output.h"
#include "reelsim/reader.h"

/* applications' libraries: accuracy study, plots */
#include "reelsim/study.h"
#include "reelsim/fit.h"
#include "reelsim/plot.h"

#endif
