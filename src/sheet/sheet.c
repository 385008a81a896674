/* Thin orthotropic sheet of the seed paper (eqs. (9)-(11)); see sheet/sheet.h. */
#include "sheet/sheet.h"
#include "util/error.h"

#include <math.h>

static int positive(double v) { return isfinite(v) && v > 0; }

/* Plane strain reduction c_ij = s_ij - s_i3 s_j3 / s_33 (axes 1 = MD, 2 = ZD, 3 = CD);
 * the 3-D compliance must be positive definite for the sheet to store energy. */
rs_status rs_sheet_from_constants(const rs_sheet_constants *k, rs_sheet *out)
{
  if (!k || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!positive(k->caliper)) return RS_ERROR(RS_ERR_INPUT, "sheet caliper must be > 0 (got %g m)", k->caliper);
  if (!positive(k->E_md)) return RS_ERROR(RS_ERR_INPUT, "sheet E_md must be > 0 (got %g Pa)", k->E_md);
  if (!positive(k->E_zd)) return RS_ERROR(RS_ERR_INPUT, "sheet E_zd must be > 0 (got %g Pa)", k->E_zd);
  if (!positive(k->G_md_zd)) return RS_ERROR(RS_ERR_INPUT, "sheet G_md_zd must be > 0 (got %g Pa)", k->G_md_zd);
  if (!isfinite(k->nu_md_zd)) return RS_ERROR(RS_ERR_INPUT, "sheet nu_md_zd is not finite");
  double s11 = 1 / k->E_md, s22 = 1 / k->E_zd, s12 = -k->nu_md_zd / k->E_md;
  double c11 = s11, c12 = s12, c22 = s22;
  if (k->plane_strain) {
    if (!positive(k->E_cd)) return RS_ERROR(RS_ERR_INPUT, "sheet E_cd must be > 0 (got %g Pa)", k->E_cd);
    if (!isfinite(k->nu_md_cd) || !isfinite(k->nu_cd_zd))
      return RS_ERROR(RS_ERR_INPUT, "sheet Poisson ratios must be finite");
    double s33 = 1 / k->E_cd, s13 = -k->nu_md_cd / k->E_md, s23 = -k->nu_cd_zd / k->E_cd;
    /* positive definite 3x3: leading minors */
    double m2 = s11 * s22 - s12 * s12;
    double m3 = s11 * (s22 * s33 - s23 * s23) - s12 * (s12 * s33 - s23 * s13) +
                s13 * (s12 * s23 - s22 * s13);
    if (!(m2 > 0 && m3 > 0))
      return RS_ERROR(RS_ERR_INPUT, "sheet constants are not positive definite (Poisson ratios "
                      "nu_md_zd = %g, nu_md_cd = %g, nu_cd_zd = %g too large)",
                      k->nu_md_zd, k->nu_md_cd, k->nu_cd_zd);
    c11 = s11 - s13 * s13 / s33;
    c12 = s12 - s13 * s23 / s33;
    c22 = s22 - s23 * s23 / s33;
  } else if (!(s11 * s22 - s12 * s12 > 0)) {
    return RS_ERROR(RS_ERR_INPUT, "sheet constants are not positive definite (nu_md_zd = %g)",
                    k->nu_md_zd);
  }
  out->h = 0.5 * k->caliper;
  out->c11 = c11;
  out->c12 = c12;
  out->c22 = c22;
  out->c66 = 1 / k->G_md_zd;
  return RS_OK;
}

double rs_sheet_tension_stress(const rs_sheet *s, double N) { return N / (2 * s->h); }

/* eq. (11) corrected: v+ - v- = 2h (c12 sigma_x + c22 sigma_pm), sigma_x = N/(2h), sigma_pm = -p */
double rs_sheet_thinning(const rs_sheet *s, double N, double p)
{
  return s->c12 * N - 2 * s->h * s->c22 * p;
}

/* eq. (10) at y = +-h: eps = c11 sigma_x + c12 sigma_pm */
double rs_sheet_strain(const rs_sheet *s, double N, double p)
{
  return s->c11 * N / (2 * s->h) - s->c12 * p;
}
