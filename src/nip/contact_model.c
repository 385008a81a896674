/* The contact nip from a scene: the roll's constants from the material at the nip's
 * pressure level, the sheet, the drum, and the rs_nip seam (reelsim/nip.h).
 *
 * Radial modulus (docs/nip.md, "E_r choice"): the roll under the nip is compressed from
 * its interlayer pressure p_s (state->surface_pressure) by about the mean nip pressure
 * pbar = P / (2 a). The linear cylinder gets the SECANT stack modulus over that step,
 *   E_r = pbar / int_{p_s}^{p_s + pbar} dp / E_r(p),
 * with a the Hertz half-width of the two cylinders made with that E_r (a fixed point,
 * solved by iteration; the exact half-width differs from a_H by the shear and sheet terms,
 * a few per cent, and E_r depends on it only weakly). The sheet's thickness modulus is the
 * same E_r unless material.E_z is given.
 *
 * Transverse shear modulus: material.G_rtheta is required (docs/nip.md, "G_rtheta"). The
 * nip-induced tension depends on it (newsprint, 1000 N/m: NIT = 0.79 mu P with G = E_r,
 * 0.95 mu P with the sheet's 50 MPa) and no one default fits paper (tens of MPa), board
 * and film (GPa), so a material without it is refused rather than given a guess. */
#include "nip/contact_internal.h"
#include "util/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* 8-point Gauss-Legendre on 4 panels of the compliance 1/E_r(p) */
double rs_radial_secant_modulus(const rs_radial_law *law, double p0, double dp)
{
  if (!(dp > 0)) return rs_radial_modulus(law, p0);
  static const double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                               0.9602898564975363};
  static const double wg[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                               0.1012285362903763};
  const int panels = 4;
  double h = dp / panels, c = 0;
  for (int k = 0; k < panels; ++k) {
    double mid = p0 + (k + 0.5) * h;
    for (int g = 0; g < 4; ++g) {
      c += wg[g] / rs_radial_modulus(law, mid - 0.5 * h * xg[g]);
      c += wg[g] / rs_radial_modulus(law, mid + 0.5 * h * xg[g]);
    }
  }
  c *= 0.5 * h;
  return dp / c;
}

typedef struct roll_consts {
  double E_r, E_cd, G;
} roll_consts;

/* Roll constants in the cylinder's engineering convention (r = ZD, theta = MD, z = CD);
 * the material's nu_rtheta is Hakiel's nu (eps_r = -nu sigma_theta / E_theta), so
 * nu_rt = nu E_r / E_theta; the CD stress is assumed to squeeze the thickness alike:
 * nu_rz = nu E_r / E_cd. Plane strain (eps_z = 0). */
static rs_status roll_ortho(const rs_material *m, double E_r, rs_ortho *out, roll_consts *rc)
{
  rc->E_r = E_r;
  rc->E_cd = m->E_cd > 0 ? m->E_cd : m->E_theta;
  rc->G = m->G_rtheta;
  rs_ortho_engineering e = {E_r, m->E_theta, rc->E_cd, m->nu_rtheta * E_r / m->E_theta,
                            m->nu_rtheta * E_r / rc->E_cd, m->nu_md_cd, rc->G};
  rs_status st = rs_ortho_from_engineering(&e, 1, out);
  if (st) return rs_error_wrap("roll constants (material '%s', E_r = %g Pa)", m->name, E_r);
  return RS_OK;
}

static rs_status sheet_of(const rs_material *m, const roll_consts *rc, rs_sheet *out)
{
  rs_sheet_constants k = {m->caliper, m->E_theta, m->E_z > 0 ? m->E_z : rc->E_r, rc->E_cd,
                          m->nu_rtheta, m->nu_md_cd, m->nu_rtheta, rc->G, 1};
  rs_status st = rs_sheet_from_constants(&k, out);
  if (st) return rs_error_wrap("sheet of material '%s'", m->name);
  return RS_OK;
}

static rs_status drum_ortho(const rs_drum *d, rs_ortho *out)
{
  rs_status st;
  if (!d->orthotropic) {
    st = rs_ortho_isotropic(d->E, d->nu, 1, out);
  } else {
    /* given orthotropic constants are taken as the plane-strain effective ones */
    rs_ortho_engineering e = {d->E_r, d->E_theta, d->E_theta, d->nu_rtheta, 0, 0, d->G_rtheta};
    st = rs_ortho_from_engineering(&e, 0, out);
  }
  if (st) return rs_error_wrap("nip.drum");
  return RS_OK;
}

rs_status rs_nip_contact_create_from_spec(const rs_nip_spec *spec, const rs_material *mat,
                                          rs_nip_contact **out)
{
  if (!spec || !mat || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  *out = NULL;
  if (!(mat->caliper > 0)) return RS_ERROR(RS_ERR_INPUT, "material.caliper must be > 0");
  if (!(mat->E_theta > 0)) return RS_ERROR(RS_ERR_INPUT, "material.E_theta must be > 0");
  if (!(mat->G_rtheta > 0))
    return RS_ERROR(RS_ERR_INPUT,
                    "material.G_rtheta is required by the contact nip (material '%s': %s): "
                    "the stack's transverse shear modulus in Pa, on which the nip-induced "
                    "tension depends (paper: about E_theta/100 .. E_theta/50; film: "
                    "E/(2(1 + nu)); docs/nip.md)",
                    mat->name, mat->G_rtheta == 0 ? "not given" : "not > 0");
  if (!(mat->E_z >= 0)) return RS_ERROR(RS_ERR_INPUT, "material.E_z must be >= 0");
  if (!(mat->E_cd >= 0)) return RS_ERROR(RS_ERR_INPUT, "material.E_cd must be >= 0");
  if (!(spec->drum.radius > 0))
    return RS_ERROR(RS_ERR_INPUT, "nip.drum.radius must be > 0 (got %g m)", spec->drum.radius);
  if (!(spec->drum.core_radius > 0 && spec->drum.core_radius < spec->drum.radius))
    return RS_ERROR(RS_ERR_INPUT, "nip.drum.core_radius must lie in (0, nip.drum.radius = %g m) "
                    "(got %g m): the drum cannot be inside its core",
                    spec->drum.radius, spec->drum.core_radius);
  rs_material m = *mat;
  rs_status st = rs_radial_law_prepare(&m.radial);
  if (st) return rs_error_wrap("material.radial");
  /* a provisional sheet (the real one is set per state) so that create can check the rest */
  roll_consts rc;
  rs_ortho ro;
  st = roll_ortho(&m, rs_radial_modulus(&m.radial, 0.0), &ro, &rc);
  if (st) return st;
  rs_nip_contact_config cfg = {0};
  st = drum_ortho(&spec->drum, &cfg.drum);
  if (st) return st;
  st = sheet_of(&m, &rc, &cfg.sheet);
  if (st) return st;
  cfg.drum_radius = spec->drum.radius;
  cfg.drum_core_radius = spec->drum.core_radius;
  cfg.mu_roll = spec->mu_roll;
  cfg.mu_drum = spec->mu_drum;
  cfg.winder = spec->winder;
  cfg.torque_share = spec->torque_share;
  cfg.nodes = spec->nodes > 0 ? spec->nodes : 64;
  /* The load search's tolerance. A relative error e in the load moves T0 by about e
   * relative (the nip's tractions scale with its load): 1 % of the adaptive policy's T0
   * tolerance (1e-6 at the default 1e-4; the same for the other policies) keeps it out of
   * the policy's error budget. The search's own default, 1e-9, took a third half-width
   * per solve for digits nothing uses (docs/performance.md, the contact reel). */
  cfg.load_rtol = 1e-2 * (spec->update == RS_NIP_UPDATE_ADAPTIVE && spec->T0_rtol > 0 ? spec->T0_rtol
                                                                                      : 1e-4);
  if (spec->terms > 0) { /* the default's series (accelerated), shorter or longer */
    cfg.series.terms = spec->terms;
    cfg.series.accelerate = 1;
  }
  st = rs_nip_contact_create(&cfg, out);
  if (st) return st;
  (*out)->from_spec = 1;
  (*out)->mat = m;
  (*out)->spec = *spec;
  return RS_OK;
}

/* h(x) = ln E_n(e^x) - x: E_n(E) the secant modulus over [p_s, p_s + P/(2 a_H(E))], a_H
 * the Hertz half-width of the roll with E_r = E on the drum (H2: the drum's half-plane). */
static rs_status radial_misfit(const rs_nip_contact *nc, double P, double Rs, double ps,
                               const double H2[2][2], double x, double *h)
{
  const rs_material *m = &nc->mat;
  double E = exp(x), H1[2][2];
  rs_ortho ro;
  roll_consts rc;
  rs_status st = roll_ortho(m, E, &ro, &rc);
  if (!st) st = rs_ortho_halfplane(&ro, H1);
  if (st) return st;
  double Estar = 2.0 / (H1[0][0] + H2[0][0]);
  double aH = sqrt(4 * P * Rs / (PI * Estar));
  double En = rs_radial_secant_modulus(&m->radial, ps, P / (2 * aH));
  if (!(En > 0) || !isfinite(En))
    return RS_ERROR(RS_ERR_INPUT, "material.radial gives E_r = %g Pa at %g Pa", En, ps + P / (2 * aH));
  *h = log(En) - x;
  return RS_OK;
}

/* E_r = secant modulus over [p_s, p_s + P/(2 a_H)], a_H(E_r) the Hertz half-width: the
 * fixed point h(ln E_r) = 0. E_r rises with pbar and pbar falls with E_r, so h falls with
 * slope between -1 and 0: the damped step x + h/2 is a contraction (it took ~50 steps to
 * 1e-10); the secant steps through the last two points, each kept inside the bracket the
 * signs of h give, take 5 - 7 to round-off. */
static rs_status nip_radial_modulus(const rs_nip_contact *nc, double P, double Rs, double ps,
                                    double *E_r)
{
  double H2[2][2], x0 = log(rs_radial_modulus(&nc->mat.radial, ps)), h0, h1;
  rs_status st = rs_ortho_halfplane(&nc->cfg.drum, H2);
  if (!st) st = radial_misfit(nc, P, Rs, ps, H2, x0, &h0);
  if (st) return st;
  double x1 = x0 + 0.5 * h0, lo = h0 > 0 ? x0 : -INFINITY, hi = h0 > 0 ? INFINITY : x0;
  for (int it = 0; it < 100; ++it) {
    if (h0 == 0) {
      x1 = x0;
      break;
    }
    if ((st = radial_misfit(nc, P, Rs, ps, H2, x1, &h1))) return st;
    if (h1 > 0) lo = x1 > lo ? x1 : lo;
    if (h1 < 0) hi = x1 < hi ? x1 : hi;
    double x2 = h1 != h0 ? x1 - h1 * (x1 - x0) / (h1 - h0) : x1 + 0.5 * h1;
    if (!(x2 > lo && x2 < hi)) x2 = isfinite(lo) && isfinite(hi) ? 0.5 * (lo + hi) : x1 + 0.5 * h1;
    if (h1 == 0 || fabs(x2 - x1) <= 1e-14 * fmax(1.0, fabs(x1))) {
      x1 = h1 == 0 ? x1 : x2;
      break;
    }
    x0 = x1;
    h0 = h1;
    x1 = x2;
  }
  *E_r = exp(x1);
  return RS_OK;
}

rs_status rs_nip_contact_solve_state(rs_nip_contact *nc, const rs_nip_state *s, rs_nip_solution *out)
{
  if (!nc || !s || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!nc->from_spec) return RS_ERROR(RS_ERR_INPUT, "nip contact was not made from a scene");
  /* equal radii: the bare core, before the first layer (modelled as the thinnest roll) */
  if (!(s->roll_radius > 0 && s->core_radius > 0 && s->core_radius <= s->roll_radius))
    return RS_ERROR(RS_ERR_INPUT, "roll radius %g m must not be below the core radius %g m",
                    s->roll_radius, s->core_radius);
  if (!(isfinite(s->nip_load) && s->nip_load > 0))
    return RS_ERROR(RS_ERR_INPUT, "nip.load must be > 0 (got %g N/m)", s->nip_load);
  /* The cylinder solution is tested for R0/R <= 0.99, so a roll thinner than 1 % of its
   * radius (the first layers, the bare core) is modelled as one of thickness
   * sqrt(t^2 + t_min^2), t = R - core, t_min = 0.01 R: never below t_min, the true
   * thickness within 0.5 % from t = 10 t_min on, and smooth in R. (A hard min(core, 0.99 R)
   * put a kink into T0(R) where it switched: with partial stick T0 depends on the roll's
   * stiffness, which changes fast with the thickness of a thin roll, ~56 N/m per mm at
   * 0.8 mm for the newsprint scene.) docs/nip.md. */
  double R = s->roll_radius, t = R - s->core_radius, tmin = 0.01 * R;
  double R0 = R - sqrt(t * t + tmin * tmin);
  double Rs = 1.0 / (1.0 / R + 1.0 / nc->R[1]);
  double ps = s->surface_pressure > 0 ? s->surface_pressure : 0.0, E_r = 0;
  rs_status st = nip_radial_modulus(nc, s->nip_load, Rs, ps, &E_r);
  if (st) return st;
  rs_ortho ro;
  roll_consts rc;
  st = roll_ortho(&nc->mat, E_r, &ro, &rc);
  if (!st) st = sheet_of(&nc->mat, &rc, &nc->cfg.sheet);
  if (!st) st = rs_nip_contact_set_roll(nc, &ro, R, R0);
  if (!st) st = rs_nip_contact_solve_load(nc, s->nip_load, s->web_tension, out);
  if (st) return rs_error_wrap("nip at roll radius %g m", R);
  out->E_r = E_r;
  return RS_OK;
}

/* ---- the rs_nip seam --------------------------------------------------------------------- */

typedef struct seam_ctx {
  rs_nip_contact *nc;
  rs_nip_solution sol;
} seam_ctx;

static rs_status seam_wot(void *ctx, const rs_nip_state *st, double *T0)
{
  seam_ctx *c = ctx;
  rs_status s = rs_nip_contact_solve_state(c->nc, st, &c->sol);
  if (s) return s;
  *T0 = c->sol.T0;
  return RS_OK;
}

static void seam_destroy(void *ctx)
{
  seam_ctx *c = ctx;
  if (!c) return;
  rs_nip_contact_destroy(&c->nc);
  rs_nip_solution_free(&c->sol);
  free(c);
}

static void seam_report(void *ctx, rs_nip_report *rep)
{
  const seam_ctx *c = ctx;
  rep->a = c->sol.a;
  rep->load = c->sol.load;
  rep->iterations = c->sol.iterations;
}

static const rs_nip_solution *seam_solution(void *ctx)
{
  const seam_ctx *c = ctx;
  return c->sol.M > 0 ? &c->sol : NULL;
}

static const rs_nip_ops contact_ops = {.name = "contact", .wound_on_tension = seam_wot,
                                       .destroy = seam_destroy, .report = seam_report,
                                       .solution = seam_solution};

rs_status rs_nip_contact_nip_create(const rs_nip_spec *spec, const rs_material *mat, rs_nip **out)
{
  *out = NULL;
  seam_ctx *c = calloc(1, sizeof *c);
  if (!c) return RS_ERROR(RS_ERR_MEMORY, "nip contact seam");
  rs_status st = rs_nip_contact_create_from_spec(spec, mat, &c->nc);
  if (st) {
    free(c);
    return st;
  }
  return rs_nip_wrap(&contact_ops, c, out);
}
