/* Winding at speed (docs/roll-model.md, "Centrifugal load", "Entrained air"):
 * winding.speed, the `centrifugal` switch and the `air` block, from the checked tree into
 * the problem. A speed without an effect that uses it winds exactly as at rest. */
#include <math.h>
#include <string.h>

#include "reelsim/recipe.h"
#include "scene/scene_internal.h"

/* air: the entrained film (docs/roll-model.md, "Entrained air"); needs the speed and a
 * roughness (air.roughness, else material.roughness) */
static rs_status resolve_air(const yn *root, rs_scene *s)
{
  rs_problem *p = &s->problem;
  memset(&p->air, 0, sizeof p->air);
  if (!rsi_ys_has(root, "air")) return RS_OK;
  if (!rsi_ys_has(root, "winding.speed"))
    return rsi_ys_fail(root, "winding.speed", "required by air: the web speed in m/s");
  rs_air_spec *a = &p->air;
  a->viscosity = rsi_ys_num(root, "air.viscosity");
  a->cutoff = rsi_ys_num(root, "air.cutoff");
  a->pressure = rsi_ys_num(root, "air.pressure");
  const long long surfaces = rsi_ys_int(root, "air.moving_surfaces");
  a->moving_surfaces = surfaces == 1 ? 1 : 2;
  if (surfaces != 1 && surfaces != 2)
    return rsi_ys_fail(root, "air.moving_surfaces",
                   "must be 2 (web and roll surface both carry air in: U = 2V) or 1 (U = V) "
                   "(got %lld)", surfaces);
  if (!(a->viscosity > 0.0 && a->viscosity < INFINITY))
    return rsi_ys_fail(root, "air.viscosity", "must be > 0 Pa s (got %g)", a->viscosity);
  if (!(a->cutoff >= 0.0 && a->cutoff < INFINITY))
    return rsi_ys_fail(root, "air.cutoff", "must be >= 0 roughnesses (got %g)", a->cutoff);
  if (!(a->pressure > 0.0 && a->pressure < INFINITY))
    return rsi_ys_fail(root, "air.pressure", "must be > 0 Pa, absolute (got %g)", a->pressure);
  if (rsi_ys_has(root, "air.roughness")) {
    a->roughness = rsi_ys_num(root, "air.roughness");
    if (!(a->roughness >= 0.0 && a->roughness < INFINITY))
      return rsi_ys_fail(root, "air.roughness", "must be >= 0 m (got %g)", a->roughness);
  } else if (rsi_ys_has(root, "material.roughness")) {
    a->roughness = p->material.roughness;
  } else {
    return rsi_ys_fail(root, "air.roughness",
                   "required by air: the combined RMS roughness of the web's faces in m "
                   "(or give material.roughness)");
  }
  if (p->nip.model != RS_NIP_NONE) {
    if (rsi_ys_has(root, "air.nip_radius")) a->nip_radius = rsi_ys_num(root, "air.nip_radius");
    else if (rsi_ys_has(root, "nip.drum.radius")) a->nip_radius = p->nip.drum.radius;
    else
      return rsi_ys_fail(root, "air.nip_radius",
                     "required by air with a nip: the nip roller's radius in m (or give "
                     "nip.drum.radius)");
    if (!(a->nip_radius > 0.0 && a->nip_radius < INFINITY))
      return rsi_ys_fail(root, "air.nip_radius", "must be > 0 m (got %g)", a->nip_radius);
  }
  a->on = 1;
  return RS_OK;
}

rs_status rsi_ys_resolve_speed(const yn *root, rs_scene *s)
{
  rs_problem *p = &s->problem;
  memset(&p->speed, 0, sizeof p->speed);
  p->centrifugal = 0;
  rs_status st = RS_OK;
  if (rsi_ys_has(root, "winding.speed")) {
    st = rsi_ys_resolve_recipe(root, "winding.speed", "speed", p->core.radius,
                                     p->final_radius, &p->speed);
    if (st) return st;
  }
  if ((st = resolve_air(root, s))) return st;
  if (!rsi_ys_has(root, "centrifugal")) return RS_OK;
  if (!rsi_ys_has(root, "winding.speed"))
    return rsi_ys_fail(root, "winding.speed", "required by centrifugal: the web speed in m/s");
  if (!rsi_ys_has(root, "material.density"))
    return rsi_ys_fail(root, "material.density",
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
      return rsi_ys_fail(root, "winding.speed",
                     "centrifugal load: at r = %.6g m (layer %d of %d) the web tension %g N/m "
                     "is not above rho t V^2 = %g N/m (%g m/s): the web cannot stay on the "
                     "spinning roll",
                     r, j + 1, p->n_layers, T0, spin, V);
  }
  return RS_OK;
}
