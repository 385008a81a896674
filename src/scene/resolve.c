/* The checked tree -> rs_scene: the core, the roll size, recipes, the nip, numerics and
 * output, each range-checked against the line it came from. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"

enum { RS_MAX_LAYERS = 10000000 };
/* Bounds on the size-like keys (docs/scenes.md, beside each key): nip.terms (the series of
 * docs/cylinder.md, measured to 65536 terms: 3 s per solve at 400 nodes), nip.nodes (dense
 * matrices of (3M)^2 doubles, one LU factorisation of which, uninterruptible, takes 0.3 s
 * at 512 and 3 s at 1024) and CVODE's steps per increment. */
enum { RS_NIP_MAX_TERMS = 65536, RS_NIP_MAX_NODES = 512 };
#define RS_MAX_CVODE_STEPS 100000000L
static const double pi = 3.14159265358979323846;

static rs_status resolve_core(const yn *root, rs_core *c)
{
  const double rating = rsi_ys_num(root, "core.rating"),
               stiffness = rsi_ys_num(root, "core.stiffness"),
               modulus = rsi_ys_num(root, "core.modulus"), poisson = rsi_ys_num(root, "core.poisson");
  int elastic = rsi_ys_has(root, "core.stiffness");
  int tube = rsi_ys_has(root, "core.bore") || rsi_ys_has(root, "core.modulus") ||
             rsi_ys_has(root, "core.poisson");
  double radius = 0.0, bore_given = 0.0;
  const char *size_key = NULL, *bore_key = NULL; /* which keys gave the outside and inside */
  int has_bore = 0;
  memset(c, 0, sizeof *c);
  rs_status st = rsi_ys_core_geometry(root, &radius, &size_key, &bore_given, &has_bore, &bore_key);
  if (st != RS_OK) return st;
  c->radius = radius;
  if (rsi_ys_has(root, "core.rating")) {
    if (!(rating > 0.0))
      return rsi_ys_fail(root, "core.rating", "must be > 0 Pa (got %g; omit the key to skip the check)",
                     rating);
    c->rating = rating;
  }
  if (elastic && tube)
    return rsi_ys_fail(root, "core.stiffness",
                   "give either stiffness (an elastic core) or bore, modulus and poisson "
                   "(a tube), not both");
  if (elastic) {
    if (!(stiffness > 0.0))
      return rsi_ys_fail(root, "core.stiffness", "must be > 0 Pa (got %g)", stiffness);
    c->kind = RS_CORE_ELASTIC;
    c->stiffness = stiffness;
    return RS_OK;
  }
  if (!tube) {
    c->kind = RS_CORE_RIGID;
    return RS_OK;
  }
  static const char *const tube_keys[] = {"core.bore", "core.modulus", "core.poisson"};
  for (int i = 0; i < 3; ++i)
    if (i == 0 ? !has_bore : !rsi_ys_has(root, tube_keys[i]))
      return rsi_ys_fail(root, tube_keys[i], "a tube core needs bore (or inner_diameter or wall), "
                                         "modulus and poisson");
  if (!(bore_given >= 0.0 && bore_given < radius))
    return rsi_ys_fail(root, bore_key, "must be >= 0 and < core.radius = %g m (got %g)", radius,
                   bore_given);
  if (!(modulus > 0.0))
    return rsi_ys_fail(root, "core.modulus", "must be > 0 Pa (got %g)", modulus);
  if (!(poisson > -1.0 && poisson < 0.5))
    return rsi_ys_fail(root, "core.poisson", "must lie in (-1, 0.5) (got %g)", poisson);
  c->kind = RS_CORE_TUBE;
  c->bore = bore_given;
  c->modulus = modulus;
  c->poisson = poisson;
  return RS_OK;
}

/* The cinching check's keys: core.friction (web on core), winding.acceleration (m/s^2 at
 * the surface, the speed change): the roll's inertia needs material.density, the check
 * material.friction_layer; one of it and winding.accel_torque. */
static rs_status resolve_acceleration(const yn *root, rs_scene *s)
{
  const char *key = "winding.acceleration";
  s->problem.acceleration = 0.0;
  s->problem.core_friction = 0.0;
  if (rsi_ys_has(root, "core.friction")) {
    const double mu = rsi_ys_num(root, "core.friction");
    if (!(mu > 0.0))
      return rsi_ys_fail(root, "core.friction", "must be > 0 (got %g; omit the key to skip the check)",
                     mu);
    s->problem.core_friction = mu;
  }
  if (!rsi_ys_has(root, key)) return RS_OK;
  const double a = rsi_ys_num(root, key);
  if (!(a > 0.0))
    return rsi_ys_fail(root, key, "must be > 0 m/s^2 (got %g; omit the key to skip the check)", a);
  if (rsi_ys_has(root, "winding.accel_torque"))
    return rsi_ys_fail(root, key, "give either winding.acceleration or winding.accel_torque, not both");
  if (!(s->problem.material.density > 0.0))
    return rsi_ys_fail(root, key, "the roll's inertia needs material.density (kg/m^3)");
  if (!(s->problem.material.friction_layer > 0.0))
    return rsi_ys_fail(root, key,
                   "the interlayer slip check needs material.friction_layer (the web-on-web "
                   "friction coefficient)");
  s->problem.acceleration = a;
  return RS_OK;
}

/* Final radius and layer count. Web length L on a core of radius r_c, caliper t:
 * the wound cross-section pi (r^2 - r_c^2) equals L t, so r = sqrt(r_c^2 + L t / pi).
 * The size is one of final_radius, final_diameter (d = 2 r) and web_length. */
static rs_status resolve_winding(const yn *root, rs_scene *s)
{
  const double web_length = rsi_ys_num(root, "winding.web_length"),
               accel_torque = rsi_ys_num(root, "winding.accel_torque");
  int has_r = rsi_ys_has(root, "winding.final_radius"), has_L = rsi_ys_has(root, "winding.web_length"),
      has_d = rsi_ys_has(root, "winding.final_diameter");
  double rc = s->problem.core.radius, t = s->problem.material.caliper;
  if (has_r && has_d)
    return rsi_ys_fail(root, "winding.final_diameter",
                   "give either winding.final_radius or winding.final_diameter, not both");
  if (has_r && has_L)
    return rsi_ys_fail(root, "winding.web_length",
                   "give either final_radius or web_length, not both");
  if (has_d && has_L)
    return rsi_ys_fail(root, "winding.web_length",
                   "give either final_diameter or web_length, not both");
  if (!has_r && !has_L && !has_d)
    return rsi_ys_fail(root, "winding.final_radius",
                   "required: the roll size as final_radius (m), final_diameter (m) or "
                   "web_length (m)");
  const char *key = has_r ? "winding.final_radius"
                          : has_d ? "winding.final_diameter" : "winding.web_length";
  const double final_radius = has_d ? 0.5 * rsi_ys_num(root, key) : rsi_ys_num(root, "winding.final_radius");
  if (has_L) {
    if (!(web_length > 0.0))
      return rsi_ys_fail(root, key, "must be > 0 m (got %g)", web_length);
    s->web_length = web_length;
    s->problem.web_length = web_length;
    s->problem.final_radius = sqrt(rc * rc + web_length * t / pi);
  } else {
    if (!(final_radius > rc)) {
      if (has_d)
        return rsi_ys_fail(root, key, "must be > the core diameter %g m (got %g)", 2.0 * rc,
                       2.0 * final_radius);
      return rsi_ys_fail(root, key, "must be > the core radius %g m (got %g)", rc, final_radius);
    }
    s->web_length = 0.0;
    s->problem.web_length = 0.0;
    s->problem.final_radius = final_radius;
  }
  double layers = round((s->problem.final_radius - rc) / t);
  if (layers < 1.0)
    return rsi_ys_fail(root, key,
                   "the roll would have no layers: %g m of build-up is less than half a "
                   "caliper (%g m)",
                   s->problem.final_radius - rc, t);
  if (layers > RS_MAX_LAYERS)
    return rsi_ys_fail(root, key, "the roll would have %.0f layers (at most %d)", layers,
                   RS_MAX_LAYERS);
  s->problem.n_layers = (int)layers;
  s->problem.accel_torque = 0.0;
  if (rsi_ys_has(root, "winding.accel_torque")) {
    if (!(accel_torque > 0.0))
      return rsi_ys_fail(root, "winding.accel_torque",
                     "must be > 0 N m/m (got %g; omit the key to skip the check)", accel_torque);
    if (!(s->problem.material.friction_layer > 0.0))
      return rsi_ys_fail(root, "winding.accel_torque",
                     "the interlayer slip check needs material.friction_layer (the web-on-web "
                     "friction coefficient)");
    s->problem.accel_torque = accel_torque;
  }
  return resolve_acceleration(root, s);
}

static rs_status resolve_drum(const yn *root, rs_drum *d)
{
  const double radius = rsi_ys_num(root, "nip.drum.radius"),
               core_radius = rsi_ys_num(root, "nip.drum.core_radius"), E = rsi_ys_num(root, "nip.drum.E"),
               nu = rsi_ys_num(root, "nip.drum.nu"), E_r = rsi_ys_num(root, "nip.drum.E_r"),
               E_theta = rsi_ys_num(root, "nip.drum.E_theta"),
               nu_rtheta = rsi_ys_num(root, "nip.drum.nu_rtheta"),
               G_rtheta = rsi_ys_num(root, "nip.drum.G_rtheta");
  static const char *const ortho[] = {"nip.drum.E_r", "nip.drum.E_theta", "nip.drum.nu_rtheta",
                                      "nip.drum.G_rtheta"};
  memset(d, 0, sizeof *d);
  if (!(core_radius >= 0.0))
    return rsi_ys_fail(root, "nip.drum.core_radius", "must be >= 0 m (got %g)", core_radius);
  if (!(radius > core_radius))
    return rsi_ys_fail(root, "nip.drum.radius", "must be > nip.drum.core_radius = %g m (got %g)",
                   core_radius, radius);
  d->radius = radius;
  d->core_radius = core_radius;
  int any_ortho = 0;
  for (int i = 0; i < 4; ++i) any_ortho |= rsi_ys_has(root, ortho[i]);
  if (any_ortho) {
    if (rsi_ys_has(root, "nip.drum.E") || rsi_ys_has(root, "nip.drum.nu"))
      return rsi_ys_fail(root, rsi_ys_has(root, "nip.drum.E") ? "nip.drum.E" : "nip.drum.nu",
                     "give either E, nu (isotropic) or E_r, E_theta, nu_rtheta, G_rtheta "
                     "(orthotropic), not both");
    for (int i = 0; i < 4; ++i)
      if (!rsi_ys_has(root, ortho[i]))
        return rsi_ys_fail(root, ortho[i],
                       "an orthotropic drum needs E_r, E_theta, nu_rtheta and G_rtheta");
    if (!(E_r > 0.0)) return rsi_ys_fail(root, ortho[0], "must be > 0 Pa (got %g)", E_r);
    if (!(E_theta > 0.0)) return rsi_ys_fail(root, ortho[1], "must be > 0 Pa (got %g)", E_theta);
    if (!(nu_rtheta > -1.0 && nu_rtheta < 1.0))
      return rsi_ys_fail(root, ortho[2], "must lie in (-1, 1) (got %g)", nu_rtheta);
    if (!(G_rtheta > 0.0))
      return rsi_ys_fail(root, ortho[3], "must be > 0 Pa (got %g)", G_rtheta);
    d->orthotropic = 1;
    d->E_r = E_r;
    d->E_theta = E_theta;
    d->nu_rtheta = nu_rtheta;
    d->G_rtheta = G_rtheta;
    return RS_OK;
  }
  if (!rsi_ys_has(root, "nip.drum.E") || !rsi_ys_has(root, "nip.drum.nu"))
    return rsi_ys_fail(root, rsi_ys_has(root, "nip.drum.E") ? "nip.drum.nu" : "nip.drum.E",
                   "the drum needs E and nu (isotropic) or E_r, E_theta, nu_rtheta, G_rtheta "
                   "(orthotropic)");
  if (!(E > 0.0)) return rsi_ys_fail(root, "nip.drum.E", "must be > 0 Pa (got %g)", E);
  if (!(nu > -1.0 && nu < 0.5))
    return rsi_ys_fail(root, "nip.drum.nu", "must lie in (-1, 0.5) (got %g)", nu);
  d->E = E;
  d->nu = nu;
  return RS_OK;
}

/* A surface (or center-surface) winder's drum carries (1 - share) Ti by friction alone, so
 * the contact nip has no stick/slip state unless mu_drum P > (1 - share) Ti (docs/nip.md,
 * "Winder"; the nip refuses it at the first solve where it fails). Tension and load are
 * recipes in the radius, so the condition is checked along the roll, as the reel will
 * meet it: the layer going on at roll radius R = r_c + j t has Ti(R + t) and P(R). A reel
 * of more than a million layers is checked at a million evenly spaced layers and the last. */
static rs_status check_drum_capacity(const yn *root, const rs_scene *s)
{
  const rs_problem *p = &s->problem;
  const rs_nip_spec *n = &p->nip;
  if (n->model != RS_NIP_CONTACT || n->winder == RS_WINDER_CENTER) return RS_OK;
  double share = n->winder == RS_WINDER_SURFACE ? 0.0 : n->torque_share;
  const double rc = p->core.radius, t = p->material.caliper;
  const int N = p->n_layers, stride = N > 1000000 ? (N + 999999) / 1000000 : 1;
  for (int j = 0;; j += stride) {
    if (j > N - 1) j = N - 1; /* the last layer always */
    double R = rc + j * t, Ti = rs_recipe_eval(&p->tension, R + t), P = rs_recipe_eval(&n->load, R);
    double carried = (1.0 - share) * Ti;
    if (carried > 0 && n->mu_drum * P <= carried * (1 + 1e-9)) {
      char a[4][32], what[256];
      rsi_ys_fmt(a[0], sizeof a[0], R);
      rsi_ys_fmt(a[1], sizeof a[1], n->mu_drum * P);
      rsi_ys_fmt(a[2], sizeof a[2], carried);
      rsi_ys_fmt(a[3], sizeof a[3], Ti);
      if (n->winder == RS_WINDER_SURFACE)
        snprintf(what, sizeof what, "winding.tension = %s N/m, all of which the drum carries "
                 "on a surface winder", a[3]);
      else
        snprintf(what, sizeof what, "(1 - nip.torque_share) x winding.tension = (1 - %g) x %s "
                 "= %s N/m, what the drum carries on a center-surface winder", share, a[3], a[2]);
      return rsi_ys_fail(root, "nip.friction.drum",
                     "the drum cannot carry the web by friction from roll radius r = %s m "
                     "(layer %d of %d) on: nip.friction.drum x nip.load = %g x %g = %s N/m is "
                     "not above %s; raise nip.load or nip.friction.drum, or lower "
                     "winding.tension",
                     a[0], j + 1, N, n->mu_drum, P, a[1], what);
    }
    if (j == N - 1) break;
  }
  return RS_OK;
}

/* nip.load: a recipe, required unless a two-drum winder's statics give it (by_winder). */
static rs_status resolve_nip_load(const yn *root, rs_scene *s, int by_winder, const char *model)
{
  rs_nip_spec *n = &s->problem.nip;
  if (by_winder && rsi_ys_has(root, "nip.load"))
    return rsi_ys_fail(root, "nip.load", "a drum of a two-drum winder carries the roll's weight: "
                   "its load comes from the winder's statics (remove the key)");
  if (!by_winder && !rsi_ys_has(root, "nip.load"))
    return rsi_ys_fail(root, "nip.load", "required by nip model %s (N/m, a number or a recipe)", model);
  if (by_winder) return RS_OK;
  return rsi_ys_resolve_recipe(root, "nip.load", "nip load", s->problem.core.radius,
                               s->problem.final_radius, &n->load);
}

/* nip.friction: the sheet on the roll (required) and on the drum (required by contact). */
static rs_status resolve_nip_friction(const yn *root, rs_nip_spec *n, const char *model)
{
  const double mu_roll = rsi_ys_num(root, "nip.friction.roll"),
               mu_drum = rsi_ys_num(root, "nip.friction.drum");
  if (!rsi_ys_has(root, "nip.friction.roll"))
    return rsi_ys_fail(root, "nip.friction.roll",
                   "required by nip model %s (friction coefficient of the sheet on the roll)",
                   model);
  if (!(mu_roll >= 0.0))
    return rsi_ys_fail(root, "nip.friction.roll", "must be >= 0 (got %g)", mu_roll);
  n->mu_roll = mu_roll;
  if (rsi_ys_has(root, "nip.friction.drum")) {
    if (!(mu_drum >= 0.0))
      return rsi_ys_fail(root, "nip.friction.drum", "must be >= 0 (got %g)", mu_drum);
    n->mu_drum = mu_drum;
  } else if (n->model == RS_NIP_CONTACT) {
    return rsi_ys_fail(root, "nip.friction.drum",
                   "required by nip model contact (friction coefficient of the sheet on the "
                   "drum)");
  }
  return RS_OK;
}

/* nip.winder, nip.torque_share (center-surface only) and nip.drum (required by contact). */
static rs_status resolve_nip_drive(const yn *root, rs_nip_spec *n)
{
  const double torque_share = rsi_ys_num(root, "nip.torque_share");
  n->winder = (rs_winder_kind)rsi_ys_enum(root, "nip.winder");
  n->torque_share = n->winder == RS_WINDER_CENTER_SURFACE ? torque_share : 0.0;
  if (rsi_ys_has(root, "nip.torque_share")) {
    if (!(torque_share >= 0.0 && torque_share <= 1.0))
      return rsi_ys_fail(root, "nip.torque_share", "must lie in [0, 1] (got %g)", torque_share);
    if (n->winder != RS_WINDER_CENTER_SURFACE)
      return rsi_ys_fail(root, "nip.torque_share", "only used with winder: center-surface");
  }
  if (rsi_ys_has(root, "nip.drum")) return resolve_drum(root, &n->drum);
  if (n->model == RS_NIP_CONTACT)
    return rsi_ys_fail(root, "nip.drum",
                   "required by nip model contact: {radius, core_radius, E, nu} (or "
                   "E_r, E_theta, nu_rtheta, G_rtheta)");
  return RS_OK;
}

/* The contact solve's size (nip.nodes, nip.terms) and how often the nip is solved
 * (nip.update with update_every or T0_rtol). */
static rs_status resolve_nip_solve(const yn *root, rs_nip_spec *n)
{
  const int update = rsi_ys_enum(root, "nip.update");
  const int nodes = (int)rsi_ys_int(root, "nip.nodes"), terms = (int)rsi_ys_int(root, "nip.terms"),
            update_every = (int)rsi_ys_int(root, "nip.update_every");
  const double T0_rtol = rsi_ys_num(root, "nip.T0_rtol");
  if (!(nodes >= 3)) return rsi_ys_fail(root, "nip.nodes", "must be >= 3 (got %d)", nodes);
  if (nodes > RS_NIP_MAX_NODES)
    return rsi_ys_fail(root, "nip.nodes", "at most %d nodes (got %d; 400 take seconds per solve)",
                   RS_NIP_MAX_NODES, nodes);
  if (!(terms >= 0)) return rsi_ys_fail(root, "nip.terms", "must be >= 0 (got %d)", terms);
  if (terms > RS_NIP_MAX_TERMS)
    return rsi_ys_fail(root, "nip.terms",
                   "at most %d series terms (got %d; the default 256 is within 1e-6, "
                   "docs/cylinder.md)", RS_NIP_MAX_TERMS, terms);
  n->nodes = nodes;
  n->terms = terms;
  if (rsi_ys_has(root, "nip.update_every") && update != RS_NIP_UPDATE_EVERY)
    return rsi_ys_fail(root, "nip.update_every", "only used with update: every");
  if (rsi_ys_has(root, "nip.T0_rtol") && update != RS_NIP_UPDATE_ADAPTIVE)
    return rsi_ys_fail(root, "nip.T0_rtol", "only used with update: adaptive");
  if (update == RS_NIP_UPDATE_EVERY && !(update_every >= 1))
    return rsi_ys_fail(root, "nip.update_every", "must be >= 1 layer (got %d)", update_every);
  if (update == RS_NIP_UPDATE_ADAPTIVE && !(T0_rtol > 0.0 && T0_rtol < 0.5))
    return rsi_ys_fail(root, "nip.T0_rtol", "must lie in (0, 0.5) (got %g)", T0_rtol);
  n->update = (rs_nip_update_kind)update;
  n->update_every = update_every;
  n->T0_rtol = T0_rtol;
  return RS_OK;
}

/* The nip block; by_winder: the load comes from the winder's statics (a drum of a two-drum
 * winder). */
static rs_status resolve_nip(const yn *root, rs_scene *s, int by_winder)
{
  const int model_kind = rsi_ys_enum(root, "nip.model");
  rs_nip_spec *n = &s->problem.nip;
  memset(n, 0, sizeof *n);
  n->model = RS_NIP_NONE;
  if (!rsi_ys_has(root, "nip") || model_kind == RS_NIP_NONE) return RS_OK;
  n->model = (rs_nip_model_kind)model_kind;
  const char *model = n->model == RS_NIP_CONTACT ? "contact" : "friction";
  rs_status st = resolve_nip_load(root, s, by_winder, model);
  if (st == RS_OK) st = resolve_nip_friction(root, n, model);
  if (st == RS_OK) st = resolve_nip_drive(root, n);
  if (st == RS_OK) st = resolve_nip_solve(root, n);
  return st;
}

static rs_status resolve_numerics(const yn *root, rs_numerics *n)
{
  const int layers_per_step = (int)rsi_ys_int(root, "numerics.layers_per_step");
  const long max_steps = (long)rsi_ys_int(root, "numerics.max_steps");
  const double rtol = rsi_ys_num(root, "numerics.rtol"), atol = rsi_ys_num(root, "numerics.atol");
  if (layers_per_step < 1)
    return rsi_ys_fail(root, "numerics.layers_per_step", "must be >= 1 (got %d)", layers_per_step);
  if (!(rtol > 0.0 && rtol < 1.0))
    return rsi_ys_fail(root, "numerics.rtol", "must lie in (0, 1) (got %g)", rtol);
  if (!(atol >= 0.0))
    return rsi_ys_fail(root, "numerics.atol", "must be >= 0 (got %g)", atol);
  if (max_steps < 0)
    return rsi_ys_fail(root, "numerics.max_steps", "must be >= 0 (got %ld; 0 = engine default)",
                   max_steps);
  if (max_steps > RS_MAX_CVODE_STEPS)
    return rsi_ys_fail(root, "numerics.max_steps", "at most %ld steps per increment (got %ld)",
                   (long)RS_MAX_CVODE_STEPS, max_steps);
  n->layers_per_step = layers_per_step;
  n->rtol = rtol;
  n->atol = atol;
  n->max_steps = max_steps;
  n->reuse = (rs_reuse)rsi_ys_enum(root, "numerics.reuse");
  n->load_placement = (rs_load_placement)rsi_ys_enum(root, "numerics.load_placement");
  n->error_correction = (rs_correction)rsi_ys_enum(root, "numerics.error_correction");
  return RS_OK;
}

/* A relative path none of whose components is "..". */
static int output_path_contained(const char *p)
{
  if (p[0] == '/') return 0;
  for (const char *c = p; *c;) {
    size_t n = strcspn(c, "/");
    if (n == 2 && c[0] == '.' && c[1] == '.') return 0;
    c += n + (c[n] == '/');
  }
  return 1;
}

static rs_status resolve_output(const yn *root, rs_scene *s)
{
  double at[RS_MAX_PROFILES];
  const int n_at = rsi_ys_nums(root, "output.nip_profiles_at", at, RS_MAX_PROFILES);
  const int history_every = (int)rsi_ys_int(root, "output.history_every");
  rs_output_spec *o = &s->output;
  rs_record_spec *rec = &s->problem.record;
  snprintf(o->file, sizeof o->file, "%s", rsi_ys_str(root, "output.file"));
  /* A received scene must not write outside the folder it is run in: its own output.file
   * (not -o or --set) is a relative path without a ".." component. */
  const yn *file = rsi_yn_get(root, "output.file");
  if (file && !file->origin && !output_path_contained(o->file))
    return rsi_ys_fail(root, "output.file",
                   "a scene's own output file must stay in the folder it is run in (a relative "
                   "path without '..'; got '%s'): give -o FILE to write elsewhere", o->file);
  if (history_every < 0)
    return rsi_ys_fail(root, "output.history_every", "must be >= 0 (got %d; 0 = no history)",
                   history_every);
  rec->history_every = history_every;
  rec->n_profiles = n_at;
  for (int i = 0; i < n_at; ++i) {
    double r = at[i];
    if (!(r >= s->problem.core.radius && r <= s->problem.final_radius)) {
      char key[64];
      snprintf(key, sizeof key, "output.nip_profiles_at[%d]", i);
      return rsi_ys_fail(root, key, "must lie on the roll, in [%g, %g] m (got %g)", s->problem.core.radius,
                     s->problem.final_radius, r);
    }
    rec->nip_profiles_at[i] = r;
  }
  if (rec->n_profiles > 0 && s->problem.nip.model == RS_NIP_NONE)
    return rsi_ys_fail(root, "output.nip_profiles_at", "needs a nip (the scene has none)");
  return RS_OK;
}

/* A part of the scene checked: its input error noted (rsi_ys_note) and remembered in *bad. */
static rs_status part(rs_status st, rs_status *bad)
{
  rsi_ys_note(st);
  if (st == RS_ERR_INPUT) *bad = st;
  return st;
}

static int fatal(rs_status st) { return st != RS_OK && st != RS_ERR_INPUT; }

/* Every part is checked and its error noted, so a scene's range errors are reported
 * together; a part that needs another (the roll size needs the core and the caliper, the
 * recipes and the nip the roll size, the nip profiles the nip) is checked only when that
 * one is good. */
rs_status rsi_ys_resolve(const yn *root, rs_scene *s)
{
  rs_status bad = RS_OK, st;
  snprintf(s->title, sizeof s->title, "%s", rsi_ys_str(root, "title"));
  rs_status mat = part(rsi_ys_resolve_material(root, &s->problem.material), &bad);
  if (fatal(mat)) return mat;
  rs_status core = part(resolve_core(root, &s->problem.core), &bad);
  if (fatal(core)) return core;
  if (fatal(st = part(resolve_numerics(root, &s->problem.numerics), &bad))) return st;
  if (mat != RS_OK || core != RS_OK) return bad;
  if ((st = part(resolve_winding(root, s), &bad)) != RS_OK) return st;
  rs_status tension = part(rsi_ys_resolve_recipe(root, "winding.tension", "tension",
                                             s->problem.core.radius, s->problem.final_radius,
                                             &s->problem.tension),
                           &bad);
  if (fatal(tension)) return tension;
  /* the nip, or each nip of a list (resolve_winder.c, handed the one-nip steps) */
  if ((st = part(rsi_ys_resolve_nips(root, s, resolve_nip), &bad)) != RS_OK) return st;
  if (tension == RS_OK && fatal(st = part(rsi_ys_check_nips_capacity(root, s, check_drum_capacity), &bad)))
    return st;
  if (tension == RS_OK && fatal(st = part(rsi_ys_resolve_speed(root, s), &bad))) return st;
  if (mat == RS_OK && fatal(st = part(rsi_ys_resolve_storage(root, s), &bad))) return st;
  if (fatal(st = part(resolve_output(root, s), &bad))) return st;
  if (fatal(st = part(rsi_ys_resolve_lanes(root, s), &bad))) return st;
  return bad;
}
