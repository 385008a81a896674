/* The lanes' accessors (reel.h): one per array of the lanes' record, named after it, as the
 * result's own (result_access.c). The record is private (reel/result_internal.h), so fields
 * can be added without breaking a program or the Python package, which calls these by
 * name. */
#include <stddef.h>

#include "reel/result_internal.h"

/* the lanes' array `field`, `r` rows of `c` columns (c 0: a vector of r), or NULL and 0, 0
 * when the result has no lanes or no such array (nip_load without a nip) */
#define RS_LANES_ARRAY(type, name, field, r, c)                                          \
  const type *rs_lanes_result_##name(const rs_reel_result *res, int *rows, int *cols)   \
  {                                                                                      \
    const rs_lanes_result *lr = res ? res->lanes : NULL;                                 \
    const int has = lr && lr->count > 0 && lr->field;                                    \
    if (rows) *rows = has ? (r) : 0;                                                     \
    if (cols) *cols = has ? (c) : 0;                                                     \
    return has ? lr->field : NULL;                                                       \
  }

int rs_lanes_result_count(const rs_reel_result *res)
{
  return res && res->lanes ? res->lanes->count : 0;
}

RS_LANES_ARRAY(double, x, x, lr->count, 0)
RS_LANES_ARRAY(double, width, width, lr->count, 0)
RS_LANES_ARRAY(double, caliper, caliper, lr->count, 0)
RS_LANES_ARRAY(double, core_pressure, core_pressure, lr->count, 0)
RS_LANES_ARRAY(double, outer_radius, outer_radius, lr->count, 0)
RS_LANES_ARRAY(double, strain, strain, lr->n_layers, 0)
RS_LANES_ARRAY(double, wound_on_tension, wound_on_tension, lr->n_layers, lr->count)
RS_LANES_ARRAY(double, web_tension, web_tension, lr->n_layers, lr->count)
RS_LANES_ARRAY(unsigned char, slack, slack, lr->n_layers, lr->count)
RS_LANES_ARRAY(double, nip_load, nip_load, lr->n_layers, lr->count)
RS_LANES_ARRAY(double, final_sigma_r, sigma_r, lr->n_layers, lr->count)
RS_LANES_ARRAY(double, final_sigma_theta, sigma_theta, lr->n_layers, lr->count)
RS_LANES_ARRAY(double, final_radius, radius, lr->n_layers, lr->count)
