/* The thin orthotropic sheet in the nip (seed paper, eqs. (9)-(11)).
 *
 * Axes: x = machine direction (MD, the direction of travel), y = thickness (ZD), z = cross
 * direction (CD). The sheet is 2h thick (caliper = 2h). With the postulated stresses (9)
 *   sigma_x = N(x) / (2h),  N(x) = Ti - int_{-a}^{x} (tau+ - tau-) dxi   (N/m, web tension)
 *   sigma_y = sigma_pm(x)  (the same on both faces: thin sheet; compression negative)
 * integrating dv/dy = c12 sigma_x + c22 sigma_y (eq. (10)) through the thickness gives
 *   v(x, y) = [c12 sigma_x + c22 sigma_pm] y + f(x)
 * (the paper's printed eq. (11) lost the factor y on the c12 term), so the sheet's change
 * of thickness is
 *   v+ - v- = 2h (c12 sigma_x + c22 sigma_pm) = c12 N + 2h c22 sigma_pm,
 * and both faces stretch alike (O(h^2) terms dropped, as in the paper):
 *   eps+ = eps- = c11 sigma_x + c12 sigma_pm.
 * The through-thickness shear compliance c66 enters only f(x), which cancels in v+ - v-;
 * it is kept for completeness. docs/nip.md has the derivation.
 *
 * The compliances are PLANE STRAIN (eps_z = 0: the nip is a long line contact): with the
 * 3-D compliance s (axes 1 = MD, 2 = ZD, 3 = CD), c_ij = s_ij - s_i3 s_j3 / s_33. */
#ifndef RS_SHEET_SHEET_H
#define RS_SHEET_SHEET_H

#include "reelsim/status.h"


/* Engineering constants of the sheet. Poisson convention nu_ij = -eps_j / eps_i under a
 * uniaxial stress in direction i (so nu_ij / E_i = nu_ji / E_j). nu_md_zd is the ratio the
 * Hakiel core condition calls nu (material.nu_rtheta): eps_zd = -nu_md_zd sigma_md / E_md. */
typedef struct rs_sheet_constants {
  double caliper;   /* m, 2h */
  double E_md;      /* Pa, machine direction (the roll's E_theta) */
  double E_zd;      /* Pa, thickness direction (compare the roll's radial modulus E_r) */
  double E_cd;      /* Pa, cross direction (plane strain only) */
  double nu_md_zd;  /* MD stress -> ZD strain */
  double nu_md_cd;  /* MD stress -> CD strain (plane strain only) */
  double nu_cd_zd;  /* CD stress -> ZD strain (plane strain only) */
  double G_md_zd;   /* Pa, through-thickness shear modulus (c66 only) */
  int plane_strain; /* 1: eps_z = 0 (the nip); 0: plane stress (sigma_z = 0) */
} rs_sheet_constants;

typedef struct rs_sheet {
  double h;                  /* m, half thickness */
  double c11, c12, c22, c66; /* 1/Pa, eq. (10) */
} rs_sheet;

/* RS_ERR_INPUT (naming the constant) unless the moduli and caliper are positive and the
 * 3-D compliance is positive definite. */
rs_status rs_sheet_from_constants(const rs_sheet_constants *k, rs_sheet *out);

/* sigma_x = N / (2h), Pa, for a web tension N in N/m. */
double rs_sheet_tension_stress(const rs_sheet *s, double N);

/* v+ - v- = c12 N - 2h c22 p (m): thickness change under web tension N (N/m) and face
 * pressure p (Pa, compression positive, so sigma_pm = -p). Negative = thinner. */
double rs_sheet_thinning(const rs_sheet *s, double N, double p);

/* eps+ = eps- = c11 N / (2h) - c12 p: MD strain of both faces (tension positive). */
double rs_sheet_strain(const rs_sheet *s, double N, double p);

#endif
