/* What gauges read (src/reel/gauge.c): the stack strain of the laws, the deformed radius
 * against the closed form of a compressed annulus, and a shipped reel's diameter against
 * its compression summed by hand. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

/* Pfeiffer's strain in closed form, eps = ln(1 + P/K1)/K2, against the quadrature of
 * 1/E_r(P) = 1/(K2 (P + K1)); the quadratic Hakiel law against its arctangent form
 * int dp/(c0 + c1 p + c2 p^2) = 2/sqrt(D) [atan((2 c2 p + c1)/sqrt(D))], D = 4 c0 c2 - c1^2 > 0;
 * a table of one modulus against P/E. */
static void strain_closed_forms(void)
{
  rs_radial_law pf = {.law = RS_RADIAL_PFEIFFER, .K1 = 5e3, .K2 = 60};
  CHECK(rs_radial_law_prepare(&pf) == RS_OK);
  const double Ps[] = {1.0, 1e3, 5e4, 1e6, 3e7};
  for (int i = 0; i < 5; ++i) CHECK_CLOSE(rs_radial_strain(&pf, Ps[i]), log1p(Ps[i] / 5e3) / 60, 1e-11);
  rs_radial_law hk = {.law = RS_RADIAL_HAKIEL, .n_coef = 3, .C = {2e5, 2.0, 3e-5}};
  CHECK(rs_radial_law_prepare(&hk) == RS_OK);
  const double D = 4 * 2e5 * 3e-5 - 4.0, sD = sqrt(D);
  for (int i = 0; i < 5; ++i) {
    const double P = Ps[i];
    const double want = 2.0 / sD * (atan((2 * 3e-5 * P + 2.0) / sD) - atan(2.0 / sD));
    CHECK_CLOSE(rs_radial_strain(&hk, P), want, 1e-11);
  }
  rs_radial_law tb = {.law = RS_RADIAL_TABLE, .n_points = 3, .P = {0, 1e5, 2e5}, .E = {4e6, 4e6, 4e6}};
  CHECK(rs_radial_law_prepare(&tb) == RS_OK);
  CHECK_CLOSE(rs_radial_strain(&tb, 3.3e5), 3.3e5 / 4e6, 1e-13);
  CHECK(rs_radial_strain(&pf, -5.0) == 0.0);
}

/* An orthotropic annulus [a, b] (E_r, E_theta, nu = 0) on a core of modulus E_c under the
 * pressure p at b: sigma_r = A r^(g-1) + B r^(-g-1), g^2 = E_theta/E_r, sigma_theta =
 * d(r sigma_r)/dr, u = r sigma_theta/E_theta, u(a) = a sigma_r(a)/E_c, sigma_r(b) = -p.
 * As a roll: layers of caliper t from a to b, the last one a free ring on top pressing p
 * beneath it (its own compression t p/(2 E_r), the linear law's exact mean). The deformed
 * outer radius b + u(b) + t - t p/(2 E_r) against rs_reel_deformed_radius fed the closed
 * form's sigma_r at the nodes: second order in t (trapezoid rule). */
static double annulus_error(int n)
{
  const double a = 0.08, b = 0.2, Er = 5e6, Et = 4e9, Ec = 2e8, p = 4e5, g = sqrt(Et / Er);
  const double t = (b - a) / n;
  /* [a^(g-1), a^(-g-1); a^(g-1)(g/E_t - 1/E_c), a^(-g-1)(-g/E_t - 1/E_c)] [A B] = [?]:
   * row 1 the core: sigma_theta(a)/E_t - sigma_r(a)/E_c = 0; row 2 sigma_r(b) = -p */
  const double m11 = pow(a, g - 1) * (g / Et - 1 / Ec), m12 = pow(a, -g - 1) * (-g / Et - 1 / Ec);
  const double m21 = pow(b, g - 1), m22 = pow(b, -g - 1), det = m11 * m22 - m12 * m21;
  const double A = (-m12 * -p) / det, B = (m11 * -p) / det;
  rs_problem pb;
  memset(&pb, 0, sizeof pb);
  pb.material.caliper = t;
  pb.material.E_theta = Et;
  pb.material.radial.law = RS_RADIAL_LINEAR;
  pb.material.radial.E_r = Er;
  pb.core.kind = RS_CORE_ELASTIC;
  pb.core.radius = a;
  pb.core.stiffness = Ec;
  CHECK(rs_radial_law_prepare(&pb.material.radial) == RS_OK);
  const int N = n + 1;
  double *sr = malloc((size_t)N * sizeof *sr), *R = malloc((size_t)N * sizeof *R);
  for (int j = 0; j < N; ++j) {
    const double r = a + (j + 1) * t;
    sr[j] = j < n ? A * pow(r, g - 1) + B * pow(r, -g - 1) : 0.0;
  }
  const double Pc = -(A * pow(a, g - 1) + B * pow(a, -g - 1));
  CHECK(rs_reel_deformed_radius(&pb, Pc, sr, NULL, N, R) == RS_OK);
  const double st_b = g * (A * pow(b, g - 1) - B * pow(b, -g - 1));
  const double want = b + b * st_b / Et + t - t * p / (2 * Er);
  const double compression = (b + t) - want;
  double err = fabs(R[N - 1] - want) / compression;
  printf("n = %d: deformed %.12g m, closed form %.12g m, compression %.6g m, rel. error %.3g\n", n,
         R[N - 1], want, compression, err);
  free(sr);
  free(R);
  return err;
}

static void annulus_closed_form(void)
{
  const double e1 = annulus_error(400), e2 = annulus_error(800);
  CHECK_LT(e2, 1e-4);
  CHECK_CLOSE(e1 / e2, 4.0, 0.05); /* second order */
}

/* cases/newsprint-rider.yaml (Pfeiffer K1 = 5 kPa, K2 = 60; core E_c = 1e9 Pa): the deformed
 * radius of every layer against the sum by hand, r_c (1 - P_c/E_c) + sum t (1 - (eps_in +
 * eps_out)/2) with eps = ln(1 + P/K1)/K2 from the run's own pressures; the free radius
 * r_c + (j + 1) t unchanged; the wound radius of the last layer the finished roll's. */
static void shipped_by_hand(void)
{
  rs_scene *sc = NULL;
  const char *sets[] = {"numerics.rtol=1e-4"};
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 1, sets, &sc) == RS_OK);
  const rs_problem *pb = rs_scene_problem(sc);
  rs_reel_result *res = NULL;
  CHECK(rs_reel_wind(pb, NULL, &res) == RS_OK);
  const int n = res->n_layers;
  const double t = pb->material.caliper, K1 = 5e3, K2 = 60, Ec = 1e9, rc = 0.0762;
  CHECK(pb->material.radial.law == RS_RADIAL_PFEIFFER && pb->material.radial.K1 == K1);
  double r = rc * (1 - res->core_pressure / Ec), Pin = res->core_pressure, worst = 0.0;
  for (int j = 0; j < n; ++j) {
    const double Pout = j + 1 < n ? -res->sigma_r[j] : 0.0;
    r += t * (1 - 0.5 * (log1p(Pin / K1) + log1p(Pout / K1)) / K2);
    worst = fmax(worst, fabs(res->deformed_radius[j] - r));
    Pin = Pout;
    CHECK(res->radius[j] == rc + (j + 1) * t || fabs(res->radius[j] - (rc + (j + 1) * t)) < 1e-15);
  }
  printf("%d layers: deformed outer radius %.9g m (free %.9g m); worst |hand - engine| %.3g m\n",
         n, res->deformed_radius[n - 1], res->radius[n - 1], worst);
  CHECK_LT(worst, 1e-9);
  CHECK_CLOSE(res->wound_radius[n - 1], res->deformed_radius[n - 1], 1e-14);
  CHECK_CLOSE(res->wound_in_tension[10], res->sigma_theta[10] * t, 1e-15);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

/* The wound radius interpolated between 128 recorded states against the deformed radius of
 * the roll recomputed at every 50th layer from its stress history (rigid core: the stages
 * hold all the state there is): within 1e-6 of the compression. */
static void wound_radius_history(void)
{
  rs_scene *sc = NULL;
  const char *sets[] = {"numerics.rtol=1e-4", "output.history_every=50"};
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-taper.yaml", 2, sets, &sc) == RS_OK);
  const rs_problem *pb = rs_scene_problem(sc);
  rs_reel_result *res = NULL;
  CHECK(rs_reel_wind(pb, NULL, &res) == RS_OK);
  const int N = res->n_layers;
  double *R = malloc((size_t)N * sizeof *R), worst = 0.0, comp = 0.0;
  for (int s = 0; s < res->n_stages; ++s) {
    const int n = res->stage_layers[s];
    /* a rigid core does not move; the stages keep no core pressure, whose strain enters
     * half of layer 0's compression: the pressure on layer 0's outer face stands for it
     * (off by t dP/dr, ~1e-10 m here) */
    const double *sr = res->stage_sigma_r + (size_t)s * N;
    CHECK(rs_reel_deformed_radius(pb, -sr[0], sr, NULL, n, R) == RS_OK);
    worst = fmax(worst, fabs(res->wound_radius[n - 1] - R[n - 1]));
    if (getenv("RS_VERBOSE")) printf("%d %.3g\n", n, res->wound_radius[n - 1] - R[n - 1]);
    comp = fmax(comp, pb->core.radius + n * pb->material.caliper - R[n - 1]);
  }
  printf("%d stages: worst |wound - recomputed| %.3g m of a compression up to %.4g m\n",
         res->n_stages, worst, comp);
  CHECK_LT(worst, 1e-5 * comp);
  free(R);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

static const check_case cases[] = {
    {"strain_closed_forms", strain_closed_forms},
    {"annulus_closed_form", annulus_closed_form},
    {"shipped_by_hand", shipped_by_hand},
    {"wound_radius_history", wound_radius_history},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
