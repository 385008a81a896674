/* Units, plausibility bounds and plant ranges of the scene's numeric keys (docs/scenes.md
 * lists each beside its key).
 *
 * Every number of a scene is stored in the key's scene unit (SI, or hours and degrees
 * Celsius where the schema says so). A value may carry a unit ("20 um", "600 m/min",
 * "2 pli"): units.c converts it with UDUNITS-2 before the schema checks, so the rest of the
 * loader and the physics see plain SI numbers. After the range checks of the resolution,
 * bounds.c holds each value to its hard bounds (exit 2 with the likely unit slip) and notes
 * a slip warning for a value outside the range plants use. */
#ifndef RS_SCENE_RANGES_H
#define RS_SCENE_RANGES_H

#include "reelsim/scene.h"
#include "scene/ytree.h"

typedef struct ys_range {
  const char *path;  /* the key without list indices: "storage.hours", "winding.tension.value" */
  /* the scene unit in UDUNITS syntax ("m", "N/m", "h", "degC"); "" for a plain number
   * that takes no unit; a table of pairs: "m|N/m", one unit per column */
  const char *unit;
  double lo, hi;     /* hard bounds (a pair: on its second column); NaN: none */
  double plo, phi;   /* the range plants use (a pair: second column); NaN: none */
  const char *alt;   /* units a slip is likely in, space-separated ("um mm") */
} ys_range;

/* The entry of a key path (indices dropped); NULL when the key has none. */
const ys_range *rsi_ys_range_of(const char *path);
/* The unit of a key (column < 0) or of one column of its pairs ("m|N/m", column 0 or 1). */
void rsi_ys_column_unit(const char *unit, int column, char *out, size_t size);
/* The table, for the test that every numeric key of the schema has an entry. */
const ys_range *rsi_ys_ranges(int *n);

/* units.c: converts every number written with a unit into the key's scene unit, in place
 * (the text becomes the SI number, %.15g; scene->units_text lists each conversion). Errors
 * (unknown unit, wrong dimension, a unit on a plain-number key), located at the value, are
 * held back (RS_ERR_INPUT if any) and noted (rsi_ys_note) by rsi_ys_units_note_errors() after the
 * schema checks, so that the load's errors stay in the order of the file's keys as before. */
rs_status rsi_ys_convert_units(yn *root, rs_scene *scene);
void rsi_ys_units_note_errors(void);
/* v (in unit `from`) in unit `to`; 0 when either is unknown or they do not convert. */
int rsi_ys_unit_convert(double v, const char *from, const char *to, double *out);
/* A value text "NUMBER UNIT": the number and the unit part (trimmed) in unit[]; 0 when the
 * text does not start with a number or has no unit. */
int rsi_ys_split_quantity(const char *text, double *v, char *unit, size_t size);

/* bounds.c: the hard bounds (errors noted) and slip warnings (kept in the scene) over the
 * resolved tree. */
rs_status rsi_ys_check_ranges(const yn *root, rs_scene *scene);

/* Calls fn on every number of the tree the schema calls a number (lists of numbers and the
 * columns of tables of pairs included), with its key path without indices and, for a
 * column of a pair, the column (0, 1; -1 otherwise). Stops at the first status not RS_OK
 * other than RS_ERR_INPUT (which fn notes itself, if it wants) and goes on after that. */
typedef rs_status (*ys_number_fn)(yn *node, const char *path, int column, void *ctx);
rs_status rsi_ys_each_number(yn *root, ys_number_fn fn, void *ctx);

#endif
