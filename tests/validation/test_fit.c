/* The stack fit (src/fit/stack_fit.c): data made from known parameters plus Gaussian noise
 * are fitted back within their 95 % confidence intervals, for every law, and the intervals
 * shrink in proportion as the noise does; data that cannot determine a law are refused. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "reelsim/fit.h"

enum { NPTS = 40 };

static double gauss(uint64_t *s) /* Box-Muller on a 64-bit LCG: deterministic */
{
  double u[2];
  for (int i = 0; i < 2; ++i) {
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    u[i] = ((*s >> 11) + 0.5) / 9007199254740992.0;
  }
  return sqrt(-2 * log(u[0])) * cos(6.283185307179586 * u[1]);
}

/* fits `truth` from NPTS pressures up to 1 MPa with strain noise sigma; returns the
 * largest |fitted - true| / half width (<= 1: every parameter in its interval) and the
 * half widths in hw */
static double recover(const rs_radial_law *truth, int terms, double sigma, uint64_t seed,
                      double *hw, int *np)
{
  double P[NPTS], e[NPTS], th[RS_FIT_MAX_PARAMS];
  for (int i = 0; i < NPTS; ++i) {
    P[i] = 1e6 * pow((i + 1.0) / NPTS, 2.0);
    e[i] = rs_radial_strain(truth, P[i]) + sigma * gauss(&seed);
    if (e[i] < 0) e[i] = 0;
  }
  rs_fit_stack_result r;
  CHECK(rs_fit_stack(NPTS, P, e, truth->law, terms, &r) == RS_OK);
  int p = r.n_params;
  for (int k = 0; k < p; ++k)
    th[k] = truth->law == RS_RADIAL_LINEAR ? truth->E_r
          : truth->law == RS_RADIAL_PFEIFFER ? (k ? truth->K2 : truth->K1)
          : truth->law == RS_RADIAL_HAKIEL ? truth->C[k] : truth->E[k];
  double worst = 0.0;
  for (int k = 0; k < p; ++k) {
    hw[k] = r.half_width[k];
    worst = fmax(worst, fabs(r.value[k] - th[k]) / r.half_width[k]);
    printf("  sigma %.0e %-10s true %-12.6g fitted %-12.6g +- %.3g\n", sigma, r.name[k], th[k],
           r.value[k], r.half_width[k]);
  }
  printf("  RMS %.3g (noise %.1e)\n", r.rms, sigma);
  CHECK_CLOSE(r.rms, sigma, 0.35);
  *np = p;
  return worst;
}

static void recovery(const rs_radial_law *truth, int terms)
{
  double hw1[RS_FIT_MAX_PARAMS], hw2[RS_FIT_MAX_PARAMS];
  int p = 0;
  const double w1 = recover(truth, terms, 5e-4, 33, hw1, &p);
  const double w2 = recover(truth, terms, 5e-5, 33, hw2, &p);
  CHECK_LT(w1, 1.0);
  CHECK_LT(w2, 1.0);
  for (int k = 0; k < p; ++k) CHECK_CLOSE(hw1[k] / hw2[k], 10.0, 0.1); /* in proportion */
}

static void recover_linear(void)
{
  rs_radial_law L = {.law = RS_RADIAL_LINEAR, .E_r = 1.2e7};
  CHECK(rs_radial_law_prepare(&L) == RS_OK);
  recovery(&L, 0);
}

static void recover_pfeiffer(void)
{
  rs_radial_law L = {.law = RS_RADIAL_PFEIFFER, .K1 = 8e3, .K2 = 55};
  CHECK(rs_radial_law_prepare(&L) == RS_OK);
  recovery(&L, 0);
}

static void recover_hakiel(void)
{
  rs_radial_law L = {.law = RS_RADIAL_HAKIEL, .n_coef = 3, .C = {4e5, 40.0, 1e-5}};
  CHECK(rs_radial_law_prepare(&L) == RS_OK);
  recovery(&L, 3);
}

static void recover_table(void)
{
  /* the fit's points: P_max (k/3)^2 with P_max = 1 MPa, the data's last pressure */
  rs_radial_law L = {.law = RS_RADIAL_TABLE, .n_points = 4};
  const double E[] = {5e5, 6e6, 2.2e7, 5e7};
  for (int k = 0; k < 4; ++k) {
    L.P[k] = 1e6 * (k / 3.0) * (k / 3.0);
    L.E[k] = E[k];
  }
  CHECK(rs_radial_law_prepare(&L) == RS_OK);
  recovery(&L, 4);
}

/* too few points, no pressure range, an undetermined table: RS_ERR_INPUT with a reason */
static void refuses(void)
{
  rs_fit_stack_result r;
  const double P2[] = {1e4, 2e4}, e2[] = {0.01, 0.015};
  CHECK(rs_fit_stack(2, P2, e2, RS_RADIAL_PFEIFFER, 0, &r) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "at least 3") != NULL);
  const double P4[] = {1e5, 1e5, 1e5, 1e5}, e4[] = {0.01, 0.011, 0.012, 0.01};
  CHECK(rs_fit_stack(4, P4, e4, RS_RADIAL_LINEAR, 0, &r) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "no pressure range") != NULL);
  /* a table of 8 points from 6 pressures: fewer distinct pressures than parameters */
  const double P6[] = {1e4, 2e4, 4e4, 8e4, 1.6e5, 3.2e5, 3.2e5, 3.2e5, 3.2e5};
  const double e6[] = {0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.06, 0.06, 0.06};
  CHECK(rs_fit_stack(9, P6, e6, RS_RADIAL_TABLE, 8, &r) == RS_ERR_INPUT);
  printf("%s\n", rs_error_message());
}

static const check_case cases[] = {
    {"recover_linear", recover_linear}, {"recover_pfeiffer", recover_pfeiffer},
    {"recover_hakiel", recover_hakiel}, {"recover_table", recover_table},
    {"refuses", refuses},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
