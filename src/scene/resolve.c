/* Typed scene -> rs_scene: the core, the roll size, recipes, the nip, numerics and
 * output, each range-checked against the line it came from. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"

enum { RS_MAX_LAYERS = 10000000 };
static const double pi = 3.14159265358979323846;

static rs_status resolve_core(const yn *root, const ys_core *y, rs_core *c)
{
  int elastic = ys_has(root, "core.stiffness");
  int tube = ys_has(root, "core.bore") || ys_has(root, "core.modulus") ||
             ys_has(root, "core.poisson");
  memset(c, 0, sizeof *c);
  if (!(y->radius > 0.0)) return ys_fail(root, "core.radius", "must be > 0 m (got %g)", y->radius);
  c->radius = y->radius;
  if (ys_has(root, "core.rating")) {
    if (!(y->rating > 0.0))
      return ys_fail(root, "core.rating", "must be > 0 Pa (got %g; omit the key to skip the check)",
                     y->rating);
    c->rating = y->rating;
  }
  if (elastic && tube)
    return ys_fail(root, "core.stiffness",
                   "give either stiffness (an elastic core) or bore, modulus and poisson "
                   "(a tube), not both");
  if (elastic) {
    if (!(y->stiffness > 0.0))
      return ys_fail(root, "core.stiffness", "must be > 0 Pa (got %g)", y->stiffness);
    c->kind = RS_CORE_ELASTIC;
    c->stiffness = y->stiffness;
    return RS_OK;
  }
  if (!tube) {
    c->kind = RS_CORE_RIGID;
    return RS_OK;
  }
  static const char *const tube_keys[] = {"core.bore", "core.modulus", "core.poisson"};
  for (int i = 0; i < 3; ++i)
    if (!ys_has(root, tube_keys[i]))
      return ys_fail(root, tube_keys[i], "a tube core needs bore, modulus and poisson");
  if (!(y->bore >= 0.0 && y->bore < y->radius))
    return ys_fail(root, "core.bore", "must be >= 0 and < core.radius = %g m (got %g)", y->radius,
                   y->bore);
  if (!(y->modulus > 0.0))
    return ys_fail(root, "core.modulus", "must be > 0 Pa (got %g)", y->modulus);
  if (!(y->poisson > -1.0 && y->poisson < 0.5))
    return ys_fail(root, "core.poisson", "must lie in (-1, 0.5) (got %g)", y->poisson);
  c->kind = RS_CORE_TUBE;
  c->bore = y->bore;
  c->modulus = y->modulus;
  c->poisson = y->poisson;
  return RS_OK;
}

/* Final radius and layer count. Web length L on a core of radius r_c, caliper t:
 * the wound cross-section pi (r^2 - r_c^2) equals L t, so r = sqrt(r_c^2 + L t / pi). */
static rs_status resolve_winding(const yn *root, const ys_winding *y, rs_scene *s)
{
  int has_r = ys_has(root, "winding.final_radius"), has_L = ys_has(root, "winding.web_length");
  double rc = s->problem.core.radius, t = s->problem.material.caliper;
  if (has_r && has_L)
    return ys_fail(root, "winding.web_length",
                   "give either final_radius or web_length, not both");
  if (!has_r && !has_L)
    return ys_fail(root, "winding.final_radius",
                   "required: the roll size as final_radius (m) or web_length (m)");
  const char *key = has_r ? "winding.final_radius" : "winding.web_length";
  if (has_L) {
    if (!(y->web_length > 0.0))
      return ys_fail(root, key, "must be > 0 m (got %g)", y->web_length);
    s->web_length = y->web_length;
    s->problem.final_radius = sqrt(rc * rc + y->web_length * t / pi);
  } else {
    if (!(y->final_radius > rc))
      return ys_fail(root, key, "must be > the core radius %g m (got %g)", rc, y->final_radius);
    s->web_length = 0.0;
    s->problem.final_radius = y->final_radius;
  }
  double layers = round((s->problem.final_radius - rc) / t);
  if (layers < 1.0)
    return ys_fail(root, key,
                   "the roll would have no layers: %g m of build-up is less than half a "
                   "caliper (%g m)",
                   s->problem.final_radius - rc, t);
  if (layers > RS_MAX_LAYERS)
    return ys_fail(root, key, "the roll would have %.0f layers (at most %d)", layers,
                   RS_MAX_LAYERS);
  s->problem.n_layers = (int)layers;
  s->problem.accel_torque = 0.0;
  if (ys_has(root, "winding.accel_torque")) {
    if (!(y->accel_torque > 0.0))
      return ys_fail(root, "winding.accel_torque",
                     "must be > 0 N m/m (got %g; omit the key to skip the check)", y->accel_torque);
    if (!(s->problem.material.friction_layer > 0.0))
      return ys_fail(root, "winding.accel_torque",
                     "the interlayer slip check needs material.friction_layer (the web-on-web "
                     "friction coefficient)");
    s->problem.accel_torque = y->accel_torque;
  }
  return RS_OK;
}

static rs_status resolve_drum(const yn *root, const ys_drum *y, rs_drum *d)
{
  static const char *const ortho[] = {"nip.drum.E_r", "nip.drum.E_theta", "nip.drum.nu_rtheta",
                                      "nip.drum.G_rtheta"};
  memset(d, 0, sizeof *d);
  if (!(y->core_radius >= 0.0))
    return ys_fail(root, "nip.drum.core_radius", "must be >= 0 m (got %g)", y->core_radius);
  if (!(y->radius > y->core_radius))
    return ys_fail(root, "nip.drum.radius", "must be > nip.drum.core_radius = %g m (got %g)",
                   y->core_radius, y->radius);
  d->radius = y->radius;
  d->core_radius = y->core_radius;
  int any_ortho = 0;
  for (int i = 0; i < 4; ++i) any_ortho |= ys_has(root, ortho[i]);
  if (any_ortho) {
    if (ys_has(root, "nip.drum.E") || ys_has(root, "nip.drum.nu"))
      return ys_fail(root, ys_has(root, "nip.drum.E") ? "nip.drum.E" : "nip.drum.nu",
                     "give either E, nu (isotropic) or E_r, E_theta, nu_rtheta, G_rtheta "
                     "(orthotropic), not both");
    for (int i = 0; i < 4; ++i)
      if (!ys_has(root, ortho[i]))
        return ys_fail(root, ortho[i],
                       "an orthotropic drum needs E_r, E_theta, nu_rtheta and G_rtheta");
    if (!(y->E_r > 0.0)) return ys_fail(root, ortho[0], "must be > 0 Pa (got %g)", y->E_r);
    if (!(y->E_theta > 0.0)) return ys_fail(root, ortho[1], "must be > 0 Pa (got %g)", y->E_theta);
    if (!(y->nu_rtheta > -1.0 && y->nu_rtheta < 1.0))
      return ys_fail(root, ortho[2], "must lie in (-1, 1) (got %g)", y->nu_rtheta);
    if (!(y->G_rtheta > 0.0))
      return ys_fail(root, ortho[3], "must be > 0 Pa (got %g)", y->G_rtheta);
    d->orthotropic = 1;
    d->E_r = y->E_r;
    d->E_theta = y->E_theta;
    d->nu_rtheta = y->nu_rtheta;
    d->G_rtheta = y->G_rtheta;
    return RS_OK;
  }
  if (!ys_has(root, "nip.drum.E") || !ys_has(root, "nip.drum.nu"))
    return ys_fail(root, ys_has(root, "nip.drum.E") ? "nip.drum.nu" : "nip.drum.E",
                   "the drum needs E and nu (isotropic) or E_r, E_theta, nu_rtheta, G_rtheta "
                   "(orthotropic)");
  if (!(y->E > 0.0)) return ys_fail(root, "nip.drum.E", "must be > 0 Pa (got %g)", y->E);
  if (!(y->nu > -1.0 && y->nu < 0.5))
    return ys_fail(root, "nip.drum.nu", "must lie in (-1, 0.5) (got %g)", y->nu);
  d->E = y->E;
  d->nu = y->nu;
  return RS_OK;
}

static rs_status resolve_nip(const yn *root, const ys_nip *y, rs_scene *s)
{
  rs_nip_spec *n = &s->problem.nip;
  memset(n, 0, sizeof *n);
  n->model = RS_NIP_NONE;
  if (!ys_has(root, "nip") || y->model == RS_NIP_NONE) return RS_OK;
  n->model = (rs_nip_model_kind)y->model;
  const char *model = n->model == RS_NIP_CONTACT ? "contact" : "friction";

  if (!ys_has(root, "nip.load"))
    return ys_fail(root, "nip.load", "required by nip model %s (N/m, a number or a recipe)", model);
  rs_status st = ys_resolve_recipe(root, "nip.load", "nip load", &y->load, s->problem.core.radius,
                                   s->problem.final_radius, &n->load);
  if (st != RS_OK) return st;

  if (!ys_has(root, "nip.friction.roll"))
    return ys_fail(root, "nip.friction.roll",
                   "required by nip model %s (friction coefficient of the sheet on the roll)",
                   model);
  if (!(y->friction.roll >= 0.0))
    return ys_fail(root, "nip.friction.roll", "must be >= 0 (got %g)", y->friction.roll);
  n->mu_roll = y->friction.roll;
  if (ys_has(root, "nip.friction.drum")) {
    if (!(y->friction.drum >= 0.0))
      return ys_fail(root, "nip.friction.drum", "must be >= 0 (got %g)", y->friction.drum);
    n->mu_drum = y->friction.drum;
  } else if (n->model == RS_NIP_CONTACT) {
    return ys_fail(root, "nip.friction.drum",
                   "required by nip model contact (friction coefficient of the sheet on the "
                   "drum)");
  }

  n->winder = (rs_winder_kind)y->winder;
  n->torque_share = n->winder == RS_WINDER_CENTER_SURFACE ? y->torque_share : 0.0;
  if (ys_has(root, "nip.torque_share")) {
    if (!(y->torque_share >= 0.0 && y->torque_share <= 1.0))
      return ys_fail(root, "nip.torque_share", "must lie in [0, 1] (got %g)", y->torque_share);
    if (n->winder != RS_WINDER_CENTER_SURFACE)
      return ys_fail(root, "nip.torque_share", "only used with winder: center-surface");
  }
  if (ys_has(root, "nip.drum")) {
    if ((st = resolve_drum(root, &y->drum, &n->drum)) != RS_OK) return st;
  } else if (n->model == RS_NIP_CONTACT) {
    return ys_fail(root, "nip.drum",
                   "required by nip model contact: {radius, core_radius, E, nu} (or "
                   "E_r, E_theta, nu_rtheta, G_rtheta)");
  }
  if (!(y->nodes >= 3)) return ys_fail(root, "nip.nodes", "must be >= 3 (got %d)", y->nodes);
  if (!(y->terms >= 0)) return ys_fail(root, "nip.terms", "must be >= 0 (got %d)", y->terms);
  n->nodes = y->nodes;
  n->terms = y->terms;
  if (ys_has(root, "nip.update_every") && y->update != RS_NIP_UPDATE_EVERY)
    return ys_fail(root, "nip.update_every", "only used with update: every");
  if (ys_has(root, "nip.T0_rtol") && y->update != RS_NIP_UPDATE_ADAPTIVE)
    return ys_fail(root, "nip.T0_rtol", "only used with update: adaptive");
  if (y->update == RS_NIP_UPDATE_EVERY && !(y->update_every >= 1))
    return ys_fail(root, "nip.update_every", "must be >= 1 layer (got %d)", y->update_every);
  if (y->update == RS_NIP_UPDATE_ADAPTIVE && !(y->T0_rtol > 0.0 && y->T0_rtol < 0.5))
    return ys_fail(root, "nip.T0_rtol", "must lie in (0, 0.5) (got %g)", y->T0_rtol);
  n->update = (rs_nip_update_kind)y->update;
  n->update_every = y->update_every;
  n->T0_rtol = y->T0_rtol;
  return RS_OK;
}

static rs_status resolve_numerics(const yn *root, const ys_numerics *y, rs_numerics *n)
{
  if (y->layers_per_step < 1)
    return ys_fail(root, "numerics.layers_per_step", "must be >= 1 (got %d)", y->layers_per_step);
  if (!(y->rtol > 0.0 && y->rtol < 1.0))
    return ys_fail(root, "numerics.rtol", "must lie in (0, 1) (got %g)", y->rtol);
  if (!(y->atol >= 0.0))
    return ys_fail(root, "numerics.atol", "must be >= 0 (got %g)", y->atol);
  if (y->max_steps < 0)
    return ys_fail(root, "numerics.max_steps", "must be >= 0 (got %ld; 0 = engine default)",
                   y->max_steps);
  n->layers_per_step = y->layers_per_step;
  n->rtol = y->rtol;
  n->atol = y->atol;
  n->max_steps = y->max_steps;
  n->reuse = (rs_reuse)y->reuse;
  n->load_placement = (rs_load_placement)y->load_placement;
  return RS_OK;
}

static rs_status resolve_output(const yn *root, const ys_output *y, rs_scene *s)
{
  rs_output_spec *o = &s->output;
  rs_record_spec *rec = &s->problem.record;
  snprintf(o->file, sizeof o->file, "%s", y->file);
  if (y->history_every < 0)
    return ys_fail(root, "output.history_every", "must be >= 0 (got %d; 0 = no history)",
                   y->history_every);
  rec->history_every = y->history_every;
  rec->n_profiles = (int)y->nip_profiles_at_count;
  for (unsigned i = 0; i < y->nip_profiles_at_count; ++i) {
    double r = y->nip_profiles_at[i];
    if (!(r >= s->problem.core.radius && r <= s->problem.final_radius)) {
      char key[64];
      snprintf(key, sizeof key, "output.nip_profiles_at[%u]", i);
      return ys_fail(root, key, "must lie on the roll, in [%g, %g] m (got %g)", s->problem.core.radius,
                     s->problem.final_radius, r);
    }
    rec->nip_profiles_at[i] = r;
  }
  if (rec->n_profiles > 0 && s->problem.nip.model == RS_NIP_NONE)
    return ys_fail(root, "output.nip_profiles_at", "needs a nip (the scene has none)");
  return RS_OK;
}

rs_status ys_resolve(const yn *root, const ys_scene *y, rs_scene *s)
{
  rs_status st;
  snprintf(s->title, sizeof s->title, "%s", y->title ? y->title : "");
  if ((st = ys_resolve_material(root, &y->material, &s->problem.material)) != RS_OK) return st;
  if ((st = resolve_core(root, &y->core, &s->problem.core)) != RS_OK) return st;
  if ((st = resolve_winding(root, &y->winding, s)) != RS_OK) return st;
  if ((st = ys_resolve_recipe(root, "winding.tension", "tension", &y->winding.tension,
                              s->problem.core.radius, s->problem.final_radius, &s->problem.tension)) != RS_OK)
    return st;
  if ((st = resolve_nip(root, &y->nip, s)) != RS_OK) return st;
  if ((st = resolve_numerics(root, &y->numerics, &s->problem.numerics)) != RS_OK) return st;
  return resolve_output(root, &y->output, s);
}
