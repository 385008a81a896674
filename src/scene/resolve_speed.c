/* Winding at speed (docs/roll-model.md, "Centrifugal load"): winding.speed and the
 * `centrifugal` switch, from the checked tree into the problem. A speed without an effect
 * that uses it winds exactly as at rest. */
#include <math.h>
#include <string.h>

#include "reelsim/recipe.h"
#include "scene/scene_internal.h"

rs_status ys_resolve_speed(const yn *root, rs_scene *s)
{
  rs_problem *p = &s->problem;
  memset(&p->speed, 0, sizeof p->speed);
  p->centrifugal = 0;
  if (ys_has(root, "winding.speed")) {
    rs_status st = ys_resolve_recipe(root, "winding.speed", "speed", p->core.radius,
                                     p->final_radius, &p->speed);
    if (st) return st;
  }
  if (!ys_has(root, "centrifugal")) return RS_OK;
  if (!ys_has(root, "winding.speed"))
    return ys_fail(root, "winding.speed", "required by centrifugal: the web speed in m/s");
  if (!ys_has(root, "material.density"))
    return ys_fail(root, "material.density",
                   "required by centrifugal: the web density in kg/m^3");
  p->centrifugal = 1;
  /* Without a nip T0 is the web tension, known now: a layer whose T0 <= rho t V^2 would not
   * stay on the spinning roll (with a nip the reel checks T0 as it finds it). */
  if (p->nip.model != RS_NIP_NONE) return RS_OK;
  const double t = p->material.caliper;
  for (int j = 0; j < p->n_layers; ++j) {
    const double r = p->core.radius + (j + 1) * t, T0 = rs_recipe_eval(&p->tension, r);
    const double V = rs_recipe_eval(&p->speed, r), spin = p->material.density * t * V * V;
    if (!(T0 > spin))
      return ys_fail(root, "winding.speed",
                     "centrifugal load: at r = %.6g m (layer %d of %d) the web tension %g N/m "
                     "is not above rho t V^2 = %g N/m (%g m/s): the web cannot stay on the "
                     "spinning roll",
                     r, j + 1, p->n_layers, T0, spin, V);
  }
  return RS_OK;
}
