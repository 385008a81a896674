/* The thin orthotropic sheet (seed paper eqs. (9)-(11), eq. (11) corrected): closed forms
 * of the thinning and the face strain, and the plane-strain reduction against an explicit
 * 3x3 inverse. */
#include "check.h"
#include "sheet/sheet.h"

static rs_sheet_constants paper(int plane_strain)
{
  rs_sheet_constants k = {100e-6, 5e9, 2e7, 2.5e9, 0.01, 0.3, 0.01, 1e8, plane_strain};
  return k;
}

/* Uniform pressure p, no tension: v+ - v- = -2h p / E_zd (plane stress). Pure tension N:
 * eps = N / (2h E_md) and v+ - v- = -nu N / E_md (Poisson thinning). */
static void closed_forms(void)
{
  rs_sheet_constants k = paper(0);
  rs_sheet s;
  CHECK(rs_sheet_from_constants(&k, &s) == RS_OK);
  CHECK_CLOSE(s.h, 50e-6, 1e-15);
  CHECK_CLOSE(rs_sheet_thinning(&s, 0, 1e5), -100e-6 * 1e5 / 2e7, 1e-14);
  CHECK_CLOSE(rs_sheet_strain(&s, 350, 0), 350 / (100e-6 * 5e9), 1e-14);
  CHECK_CLOSE(rs_sheet_thinning(&s, 350, 0), -0.01 * 350 / 5e9, 1e-14);
  CHECK_CLOSE(rs_sheet_tension_stress(&s, 350), 3.5e6, 1e-14);
  /* the face strain under pressure: eps = -c12 p = nu p / E_md (reciprocity) */
  CHECK_CLOSE(rs_sheet_strain(&s, 0, 1e5), 0.01 * 1e5 / 5e9, 1e-14);
  CHECK_CLOSE(s.c66, 1e-8, 1e-14);
}

/* Plane strain: c_ij = s_ij - s_i3 s_j3 / s33 must equal the inverse of the top-left 2x2
 * block of the stiffness S^-1 (eps_z = 0). Checked by inverting S by cofactors. */
static void plane_strain(void)
{
  rs_sheet_constants k = paper(1);
  rs_sheet s;
  CHECK(rs_sheet_from_constants(&k, &s) == RS_OK);
  double S[3][3] = {{1 / 5e9, -0.01 / 5e9, -0.3 / 5e9},
                    {-0.01 / 5e9, 1 / 2e7, -0.01 / 2.5e9},
                    {-0.3 / 5e9, -0.01 / 2.5e9, 1 / 2.5e9}};
  /* stiffness C = S^-1 by cofactors */
  double C[3][3], det = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      C[j][i] = S[i1][j1] * S[i2][j2] - S[i1][j2] * S[i2][j1];
    }
  for (int j = 0; j < 3; ++j) det += S[0][j] * C[j][0];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C[i][j] /= det;
  /* inverse of the 2x2 stiffness block = plane-strain compliance */
  double d2 = C[0][0] * C[1][1] - C[0][1] * C[1][0];
  CHECK_CLOSE(s.c11, C[1][1] / d2, 1e-12);
  CHECK_CLOSE(s.c22, C[0][0] / d2, 1e-12);
  CHECK_CLOSE(s.c12, -C[0][1] / d2, 1e-12);
  CHECK_LOG("c11 plane strain / plane stress", s.c11 * 5e9);
}

static void bad_constants(void)
{
  rs_sheet s;
  rs_sheet_constants k = paper(1);
  k.caliper = 0;
  CHECK(rs_sheet_from_constants(&k, &s) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "caliper") != NULL);
  k = paper(1);
  k.E_zd = -1;
  CHECK(rs_sheet_from_constants(&k, &s) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "E_zd") != NULL);
  k = paper(0);
  k.nu_md_zd = 1000; /* s11 s22 < s12^2 */
  CHECK(rs_sheet_from_constants(&k, &s) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "positive definite") != NULL);
}

static const check_case cases[] = {
    {"closed_forms", closed_forms}, {"plane_strain", plane_strain}, {"bad_constants", bad_constants}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
