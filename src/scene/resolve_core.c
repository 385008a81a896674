/* The core's geometry as plants give it: the outside as radius or diameter, the inside as
 * bore (a radius), inner_diameter or wall; or, with no outside given, inner_diameter and
 * wall together (a 3 in core with a 12 mm wall: r = ID/2 + wall). */
#include <stdio.h>

#include "scene/scene_internal.h"

/* radius: the core's outer radius (m); *bore: its inner radius when one of the inside keys
 * is given (*has_bore), with the key it came from in *bore_key. */
rs_status rsi_ys_core_geometry(const yn *root, double *radius, const char **key, double *bore,
                           int *has_bore, const char **bore_key)
{
  int has_r = rsi_ys_has(root, "core.radius"), has_d = rsi_ys_has(root, "core.diameter"),
      has_b = rsi_ys_has(root, "core.bore"), has_id = rsi_ys_has(root, "core.inner_diameter"),
      has_w = rsi_ys_has(root, "core.wall");
  *has_bore = 0;
  *bore = 0.0;
  *bore_key = has_b ? "core.bore" : has_id ? "core.inner_diameter" : "core.wall";
  if (has_r && has_d)
    return rsi_ys_fail(root, "core.diameter", "give either core.radius or core.diameter, not both");
  const double id = rsi_ys_num(root, "core.inner_diameter"), wall = rsi_ys_num(root, "core.wall");
  if (has_id && !(id >= 0.0)) return rsi_ys_fail(root, "core.inner_diameter", "must be >= 0 m (got %g)", id);
  if (has_w && !(wall > 0.0)) return rsi_ys_fail(root, "core.wall", "must be > 0 m (got %g)", wall);
  if (!has_r && !has_d) {
    if (!has_id || !has_w || has_b)
      return rsi_ys_fail(root, "core.radius",
                     "required: the core size as radius (m), diameter (m), or inner_diameter "
                     "and wall (m)");
    *radius = 0.5 * id + wall;
    *bore = 0.5 * id;
    *has_bore = 1;
    *key = "core.inner_diameter";
    return RS_OK;
  }
  *key = has_r ? "core.radius" : "core.diameter";
  double v = rsi_ys_num(root, *key);
  if (!(v > 0.0)) return rsi_ys_fail(root, *key, "must be > 0 m (got %g)", v);
  *radius = has_r ? v : 0.5 * v;
  if (has_b + has_id + has_w > 1)
    return rsi_ys_fail(root, has_w ? "core.wall" : "core.inner_diameter",
                   "give one of core.bore, core.inner_diameter and core.wall (the inside of "
                   "the core), not two");
  if (has_b + has_id + has_w == 0) return RS_OK;
  *has_bore = 1;
  *bore = has_b ? rsi_ys_num(root, "core.bore") : has_id ? 0.5 * id : *radius - wall;
  if (has_id && !(*bore < *radius))
    return rsi_ys_fail(root, "core.inner_diameter", "must be < the core's outer diameter %g m (got %g)",
                   2.0 * *radius, id);
  if (has_w && !(*bore >= 0.0))
    return rsi_ys_fail(root, "core.wall", "must be <= the core's outer radius %g m (got %g)",
                   *radius, wall);
  return RS_OK;
}
