/* Orthotropic constants: engineering constants -> A constants of eq. (2), and the
 * half-plane limit of the mode compliance. */
#include "cylinder/internal.h"
#include "util/error.h"

#include <math.h>

static int finite_pos(double v) { return isfinite(v) && v > 0; }

/* Plane stress: sigma_z = 0, [eps_r eps_t] = S [sigma_r sigma_t], S symmetric with
 * S_rt = -nu_rt/E_r = -nu_tr/E_t. Plane strain: eps_z = 0, so [sigma_r sigma_t] is the
 * top-left block of S3^{-1} applied to [eps_r eps_t] (S3 the 3x3 compliance). */
rs_status rs_ortho_from_engineering(const rs_ortho_engineering *e, int plane_strain, rs_ortho *out)
{
  if (!e || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!finite_pos(e->E_r) || !finite_pos(e->E_t) || !finite_pos(e->G_rt))
    return RS_ERROR(RS_ERR_INPUT, "moduli must be positive: E_r = %g, E_t = %g, G_rt = %g",
                    e->E_r, e->E_t, e->G_rt);
  double Srr = 1.0 / e->E_r, Stt = 1.0 / e->E_t, Srt = -e->nu_rt / e->E_r;
  double Arr, Att, Art;
  if (!plane_strain) {
    double det = Srr * Stt - Srt * Srt;
    if (!(det > 0))
      return RS_ERROR(RS_ERR_INPUT, "compliance not positive definite: nu_rt = %g too large "
                      "for E_r = %g, E_t = %g", e->nu_rt, e->E_r, e->E_t);
    Arr = Stt / det;
    Att = Srr / det;
    Art = -Srt / det;
  } else {
    if (!finite_pos(e->E_z))
      return RS_ERROR(RS_ERR_INPUT, "plane strain needs E_z > 0 (got %g)", e->E_z);
    double Szz = 1.0 / e->E_z, Srz = -e->nu_rz / e->E_r, Stz = -e->nu_tz / e->E_t;
    /* cofactors of the symmetric 3x3 [[Srr Srt Srz][Srt Stt Stz][Srz Stz Szz]] */
    double c11 = Stt * Szz - Stz * Stz;
    double c22 = Srr * Szz - Srz * Srz;
    double c12 = -(Srt * Szz - Stz * Srz);
    double c13 = Srt * Stz - Stt * Srz;
    double det = Srr * c11 + Srt * c12 + Srz * c13;
    if (!(det > 0) || !(c11 > 0) || !(Srr > 0) || !(c11 * c22 - c12 * c12 > 0))
      return RS_ERROR(RS_ERR_INPUT, "3x3 compliance not positive definite (nu_rt = %g, "
                      "nu_rz = %g, nu_tz = %g)", e->nu_rt, e->nu_rz, e->nu_tz);
    Arr = c11 / det;
    Att = c22 / det;
    Art = c12 / det;
  }
  out->A_rr = Arr;
  out->A_tt = Att;
  out->A_rt = Art;
  out->G_rt = e->G_rt;
  return RS_OK;
}

rs_status rs_ortho_isotropic(double E, double nu, int plane_strain, rs_ortho *out)
{
  if (!out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!finite_pos(E) || !(nu > -1.0 && nu < 0.5))
    return RS_ERROR(RS_ERR_INPUT, "isotropic constants out of range: E = %g, nu = %g", E, nu);
  if (plane_strain) {
    double f = E / ((1 + nu) * (1 - 2 * nu));
    out->A_rr = out->A_tt = f * (1 - nu);
    out->A_rt = f * nu;
  } else {
    double f = E / (1 - nu * nu);
    out->A_rr = out->A_tt = f;
    out->A_rt = f * nu;
  }
  out->G_rt = E / (2 * (1 + nu));
  return RS_OK;
}

rs_status rs_cyl_check_ortho(const rs_ortho *c)
{
  if (!c) return RS_ERROR(RS_ERR_INPUT, "NULL constants");
  if (!finite_pos(c->A_rr) || !finite_pos(c->A_tt) || !finite_pos(c->G_rt) || !isfinite(c->A_rt))
    return RS_ERROR(RS_ERR_INPUT, "constants must be finite and A_rr, A_tt, G_rt > 0 "
                    "(A_rr = %g, A_tt = %g, G_rt = %g)", c->A_rr, c->A_tt, c->G_rt);
  if (!(c->A_rr * c->A_tt > c->A_rt * c->A_rt * (1 + 1e-12)))
    return RS_ERROR(RS_ERR_INPUT, "not positive definite: A_rt^2 = %g >= A_rr A_tt = %g",
                    c->A_rt * c->A_rt, c->A_rr * c->A_tt);
  return RS_OK;
}

/* H = lim n C(n)/R: the algebraic part of the mode solution at 1/n = 0 (modes.c), which is
 * the orthotropic half-plane (Lekhnitskii 1963) in the scaled variables. */
rs_status rs_ortho_halfplane(const rs_ortho *c, double H[2][2])
{
  rs_status st = rs_cyl_check_ortho(c);
  if (st) return st;
  double Aref = fmax(c->A_rr, c->A_tt);
  rs_cyl_nd nd = {c->A_rr / Aref, c->A_rt / Aref, c->A_tt / Aref, c->G_rt / Aref};
  double F[2][2];
  st = rs_cyl_mode_algebraic(&nd, 0.0, F);
  if (st) return st;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) H[i][j] = F[i][j] / Aref;
  return RS_OK;
}
