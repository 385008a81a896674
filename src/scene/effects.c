/* What a scene switches on, in words: one line per effect, for `reelsim check/run`. */
#include <math.h>
#include <stdio.h>

#include "reelsim/core.h"
#include "reelsim/material.h"
#include "reelsim/recipe.h"
#include "scene/scene_internal.h"

typedef char num_t[48];

static void print_storage(FILE *out, const rs_scene *s);
static void print_centrifugal(FILE *out, const rs_scene *s);
static void print_air(FILE *out, const rs_scene *s);

static const char *f(num_t buf, double v)
{
  ys_fmt(buf, sizeof(num_t), v);
  return buf;
}

static void print_recipe(FILE *out, const char *what, const rs_recipe *rc)
{
  num_t a, b, c;
  switch (rc->law) {
  case RS_RECIPE_CONSTANT: fprintf(out, "  - %s: constant %s N/m\n", what, f(a, rc->start)); return;
  case RS_RECIPE_LINEAR:
    fprintf(out, "  - %s: linear taper %s -> %s N/m\n", what, f(a, rc->start), f(b, rc->end));
    return;
  case RS_RECIPE_HYPERBOLIC:
    fprintf(out, "  - %s: hyperbolic taper %s -> %s N/m (k = %s)\n", what, f(a, rc->start),
            f(b, rs_recipe_eval(rc, rc->r1)), f(c, rc->k));
    return;
  case RS_RECIPE_TORQUE:
    fprintf(out, "  - %s: constant torque, %s N/m at the core -> %s N/m at the outside\n", what,
            f(a, rc->start), f(b, rs_recipe_eval(rc, rc->r1)));
    return;
  case RS_RECIPE_TABLE: {
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < rc->n_points; ++i) {
      lo = fmin(lo, rc->value[i]);
      hi = fmax(hi, rc->value[i]);
    }
    fprintf(out, "  - %s: table of %d points, %s .. %s N/m\n", what, rc->n_points, f(a, lo),
            f(b, hi));
    return;
  }
  }
}

static void print_radial(FILE *out, const rs_radial_law *law)
{
  num_t a, b;
  switch (law->law) {
  case RS_RADIAL_LINEAR: fprintf(out, "  - radial law: linear (E_r = %s Pa)\n", f(a, law->E_r)); return;
  case RS_RADIAL_PFEIFFER:
    fprintf(out, "  - radial law: pfeiffer (K1 = %s Pa, K2 = %s)\n", f(a, law->K1), f(b, law->K2));
    return;
  case RS_RADIAL_HAKIEL:
    fprintf(out, "  - radial law: hakiel (E_r = ");
    for (int i = 0; i < law->n_coef; ++i) {
      fprintf(out, "%s%s", i ? " + " : "", f(a, law->C[i]));
      if (i == 1) fprintf(out, " P");
      if (i > 1) fprintf(out, " P^%d", i);
    }
    fprintf(out, " Pa)\n");
    return;
  case RS_RADIAL_TABLE:
    fprintf(out, "  - radial law: table of %d points (E_r %s .. %s Pa, monotone cubic)\n",
            law->n_points, f(a, law->E[0]), f(b, law->E[law->n_points - 1]));
    return;
  }
}

static void print_core(FILE *out, const rs_core *c)
{
  num_t a, b, d, e, g;
  f(a, c->radius * 1e3);
  switch (c->kind) {
  case RS_CORE_RIGID: fprintf(out, "  - core: rigid (no core compliance), radius %s mm\n", a); return;
  case RS_CORE_ELASTIC:
    fprintf(out, "  - core: elastic (E_c = %s Pa), radius %s mm\n", f(b, c->stiffness), a);
    return;
  case RS_CORE_TUBE:
    fprintf(out, "  - core: tube (E = %s Pa, nu = %s, bore %s mm; E_c = %s Pa), radius %s mm\n",
            f(b, c->modulus), f(d, c->poisson), f(e, c->bore * 1e3), f(g, rs_core_stiffness(c)),
            a);
    return;
  }
}

static const char *winder_name(rs_winder_kind w)
{
  switch (w) {
  case RS_WINDER_CENTER: return "center";
  case RS_WINDER_SURFACE: return "surface";
  case RS_WINDER_CENTER_SURFACE: return "center-surface";
  }
  return "?";
}

/* The defect checks that have their optional limits (docs/defects.md); hoop compression
 * needs none and is always assessed. */
static void print_defect_checks(FILE *out, const rs_scene *s)
{
  num_t a, b;
  if (s->problem.material.pressure_limit > 0.0)
    fprintf(out, "  - pressure check: material.pressure_limit %s Pa (crushing/blocking)\n",
            f(a, s->problem.material.pressure_limit));
  if (s->problem.accel_torque > 0.0)
    fprintf(out,
            "  - interlayer slip check: winding.accel_torque %s N m/m, web-on-web friction %s\n",
            f(a, s->problem.accel_torque), f(b, s->problem.material.friction_layer));
  else if (s->problem.acceleration > 0.0)
    fprintf(out,
            "  - interlayer slip check: winding.acceleration %s m/s^2, web-on-web friction %s\n",
            f(a, s->problem.acceleration), f(b, s->problem.material.friction_layer));
  else if (s->problem.material.friction_layer > 0.0)
    fprintf(out, "  - interlayer slip check: the tension's torque, web-on-web friction %s\n",
            f(a, s->problem.material.friction_layer));
  if (s->problem.material.hoop_strength > 0.0)
    fprintf(out, "  - starring check: material.hoop_strength %s Pa\n",
            f(a, s->problem.material.hoop_strength));
  if (s->problem.core.rating > 0.0)
    fprintf(out, "  - core check: core.rating %s Pa\n", f(a, s->problem.core.rating));
}

void rs_scene_print_effects(const rs_scene *s, FILE *out)
{
  num_t a, b, c;
  const rs_material *m = &s->problem.material;
  fprintf(out, "  - material: %s from %s (caliper %s um, E_theta = %s Pa, nu_rtheta = %s)\n",
          m->name, s->material_source, f(a, m->caliper * 1e6), f(b, m->E_theta),
          f(c, m->nu_rtheta));
  print_radial(out, &m->radial);
  print_core(out, &s->problem.core);
  fprintf(out, "  - roll: %s -> %s mm, %s%d layers", f(a, s->problem.core.radius * 1e3),
          f(b, s->problem.final_radius * 1e3), s->problem.air.on ? "up to " : "",
          s->problem.n_layers);
  if (s->web_length > 0.0) fprintf(out, " (web length %s m)", f(c, s->web_length));
  if (s->problem.air.on) fprintf(out, "; with the air films the reel stops at the size");
  fprintf(out, "\n");
  print_recipe(out, "tension", &s->problem.tension);
  if (!ys_print_nips(out, s)) /* nip: as a list (effects_winder.c), else the one nip */
  switch (s->problem.nip.model) {
  case RS_NIP_NONE: fprintf(out, "  - nip: none (T0 = web tension)\n"); break;
  case RS_NIP_FRICTION:
    fprintf(out, "  - nip: friction (T0 = T + %s N)\n", f(a, s->problem.nip.mu_roll));
    print_recipe(out, "nip load N", &s->problem.nip.load);
    break;
  case RS_NIP_CONTACT:
    fprintf(out,
            "  - nip: contact model (%s winder, mu roll %s, mu drum %s, drum radius %s mm, "
            "%d nodes)\n",
            winder_name(s->problem.nip.winder), f(a, s->problem.nip.mu_roll), f(b, s->problem.nip.mu_drum),
            f(c, s->problem.nip.drum.radius * 1e3), s->problem.nip.nodes);
    print_recipe(out, "nip load", &s->problem.nip.load);
    if (m->G_rtheta > 0.0)
      fprintf(out, "  - nip stack shear modulus: G_rtheta = %s Pa (material)\n", f(a, m->G_rtheta));
    else
      fprintf(out, "  - nip stack shear modulus: material.G_rtheta not given: the contact nip "
                   "will refuse this material (docs/nip.md)\n");
    break;
  }
  ys_print_nip_saturation(out, s);
  if (s->problem.nip.model != RS_NIP_NONE) {
    if (s->problem.nip.update == RS_NIP_UPDATE_ADAPTIVE)
      fprintf(out, "  - nip updates: adaptive (solved where T0 changes; T0 within %s of itself)\n",
              f(a, s->problem.nip.T0_rtol));
    else if (s->problem.nip.update_every == 1)
      fprintf(out, "  - nip updates: every layer\n");
    else
      fprintf(out, "  - nip updates: every %d layers (T0 extrapolated in between)\n",
              s->problem.nip.update_every);
  }
  fprintf(out, "  - numerics: %d layer%s per step, rtol %s", s->problem.numerics.layers_per_step,
          s->problem.numerics.layers_per_step == 1 ? "" : "s", f(a, s->problem.numerics.rtol));
  if (s->problem.numerics.atol > 0.0) fprintf(out, ", atol %s", f(b, s->problem.numerics.atol));
  fprintf(out, s->problem.numerics.reuse == RS_REUSE_ON
                   ? ", deep solution reused and corrected for the drift (error held to rtol/50 x T0/s)"
               : s->problem.numerics.reuse == RS_REUSE_FIRST_ORDER
                   ? ", deep solution reused (error held to rtol/50 x T0/s at first order)"
                   : ", every increment integrated from the core");
  fprintf(out, s->problem.numerics.error_correction == RS_CORRECTION_ON
                   ? ", (w, ln y) corrected by the steps' defects\n"
                   : ", no error correction\n");
  fprintf(out, s->problem.numerics.load_placement == RS_LOAD_BENEATH
                   ? "  - load placement: beneath (a new layer joins at T0/t and presses T0/r on "
                     "the roll beneath it)\n"
                   : "  - load placement: hakiel (Hakiel 1987: a new layer's load -T0/s at its "
                     "own outer radius)\n");
  print_centrifugal(out, s);
  print_air(out, s);
  print_defect_checks(out, s);
  print_storage(out, s);
}

/* Winding at speed: listed only when the scene switches the centrifugal load on. */
static void print_centrifugal(FILE *out, const rs_scene *s)
{
  const rs_problem *p = &s->problem;
  if (!p->centrifugal) return;
  num_t a, b, c;
  double lo = INFINITY, vlo = INFINITY, vhi = -INFINITY;
  for (int j = 0; j < p->n_layers; ++j) {
    const double r = p->core.radius + (j + 1) * p->material.caliper, V = rs_recipe_eval(&p->speed, r);
    lo = fmin(lo, rs_recipe_eval(&p->tension, r));
    vlo = fmin(vlo, V);
    vhi = fmax(vhi, V);
  }
  const double spin = p->material.density * p->material.caliper * vhi * vhi;
  char d[2 * sizeof(num_t) + 8];
  if (vlo == vhi) snprintf(d, sizeof d, "%s", f(a, vhi));
  else snprintf(d, sizeof d, "%s .. %s", f(a, vlo), f(b, vhi));
  fprintf(out, "  - centrifugal load: speed %s m/s, rho t V^2 %s %s N/m taken off each layer's "
               "contact load (against the least web tension %s N/m%s); /final at rest, "
               "/final_at_speed spinning\n",
          d, vlo == vhi ? "=" : "up to", f(b, spin), f(c, lo),
          p->nip.model == RS_NIP_NONE ? "" : "; the nip's T0 checked as the reel finds it");
}

/* After the winder (docs/storage.md): listed only when the scene has storage stages. */
static void print_storage(FILE *out, const rs_scene *s)
{
  num_t a, b, c, d;
  const rs_storage_spec *sp = &s->problem.storage;
  const rs_material *m = &s->problem.material;
  if (sp->n_stages == 0) return;
  double hours = 0.0;
  for (int i = 0; i < sp->n_stages; ++i) hours += sp->stage[i].hours;
  fprintf(out, "  - storage: %d stage%s, %s h, wound at %s C and %s %% RH\n", sp->n_stages,
          sp->n_stages == 1 ? "" : "s", f(a, hours), f(b, sp->wind_temperature),
          f(c, sp->wind_humidity));
  if (m->has_thermal)
    fprintf(out, "  - thermal expansion: web alpha_r %s, alpha_theta %s, core %s 1/K\n",
            f(a, m->alpha_r), f(b, m->alpha_theta), f(c, sp->core_alpha));
  if (m->has_hygroscopic)
    fprintf(out, "  - hygroscopic expansion: web beta_r %s, beta_theta %s, core %s 1/%% RH\n",
            f(a, m->beta_r), f(b, m->beta_theta), f(c, sp->core_beta));
  if (m->viscoelastic.n > 0) {
    double wt = 0.0, wr = 0.0;
    for (int i = 0; i < m->viscoelastic.n; ++i) {
      wt += m->viscoelastic.w_theta[i];
      wr += m->viscoelastic.w_radial[i];
    }
    fprintf(out, "  - creep: Prony series of %d term%s (tau %s .. %s h; relaxes %s of E_theta, "
                 "%s of the stack law)\n",
            m->viscoelastic.n, m->viscoelastic.n == 1 ? "" : "s", f(a, m->viscoelastic.tau[0]),
            f(b, m->viscoelastic.tau[m->viscoelastic.n - 1]), f(c, wt), f(d, wr));
  }
}

/* Entrained air: listed only when the scene has an `air` block. The films are those the
 * laws give at the layers' radii without air (the run's own are in its summary and
 * /layers/air_film); `cut` counts the layers whose film the roughness takes. */
static void print_air(FILE *out, const rs_scene *s)
{
  const rs_problem *p = &s->problem;
  const rs_air_spec *a = &p->air;
  if (!a->on) return;
  num_t x, y, z, w;
  double lo = INFINITY, hi = -INFINITY;
  int cut = 0, nip_less = 0;
  for (int j = 0; j < p->n_layers; ++j) {
    const double R = p->core.radius + j * p->material.caliper, r = R + p->material.caliper;
    const double V = rs_recipe_eval(&p->speed, r), Ti = rs_recipe_eval(&p->tension, r);
    double h0 = rs_air_foil_film(R, a->moving_surfaces * V, Ti, a->viscosity);
    if (p->nip.model != RS_NIP_NONE) {
      const double hn = rs_air_nip_film(R, a->nip_radius, V, rs_recipe_eval(&p->nip.load, r),
                                        a->viscosity);
      nip_less += hn < h0;
      h0 = fmin(h0, hn);
    }
    const double h = rs_air_surviving_film(h0, a->roughness, a->cutoff);
    cut += h == 0.0;
    lo = fmin(lo, h);
    hi = fmax(hi, h);
  }
  char range[2 * sizeof(num_t) + 48];
  if (isfinite(hi)) snprintf(range, sizeof range, "%s .. %s um", f(x, lo * 1e6), f(y, hi * 1e6));
  else snprintf(range, sizeof range, "%s um .. unbounded (a web tension of 0)", f(x, lo * 1e6));
  fprintf(out, "  - entrained air: film %s as wound on (Knox-Sweeney foil bearing, U = 2V, "
               "mu = %s Pa s", range, f(z, a->viscosity));
  if (p->nip.model != RS_NIP_NONE)
    fprintf(out, "; the nip's film (roller radius %s mm) is less in %d of %d layers",
            f(w, a->nip_radius * 1e3), nip_less, p->n_layers);
  fprintf(out, "), roughness %s um: cut-off %s um %s; trapped air isothermal at %s Pa\n",
          f(x, a->roughness * 1e6), f(y, a->cutoff * a->roughness * 1e6),
          cut == 0 ? "does not act" : cut == p->n_layers ? "removes every film" : "acts",
          f(z, a->pressure));
  if (cut > 0 && cut < p->n_layers)
    fprintf(out, "    (no air film in %d of %d layers)\n", cut, p->n_layers);
}
