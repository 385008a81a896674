/* A small gauge perturbation on a linear stack against a linearised calculation of its
 * own (issue: lanes across the width; docs/lanes.md, "Validation").
 *
 * Two lanes of equal width, calipers t (1 + delta) and t (1 - delta), on the linear-law web
 * of tests/cli/scenes/small.yaml (E_r, E_theta constant, rigid core, 200 layers, T = 200
 * N/m). For a linear stack the roll's response to a layer is in closed form (Altmann's
 * linear accretion): with g^2 = E_theta / E_r the increment ds = A r^(g-1) + B r^(-g-1)
 * that meets ds(s) = -T/s at the radius s = r_c + m t the layer m goes on at (its load on
 * the roll beneath it) and the rigid core's r ds' = (nu - 1) ds at r_c gives each node
 * j <= m (radius r_j = r_c + j t) the pressure
 *     dP_j = (T/s) (s/r_j) [(r_j/s)^g + beta (r_c^2/(r_j s))^g] / [1 + beta (r_c/s)^(2g)],
 *     beta = (g - 1 - kappa) / (g + 1 + kappa),   kappa = nu - 1,
 * and the lane's radius before layer k is r_c + k t - t sum_j (P_j + P_j+1) / (2 E_r), the
 * lanes' tensions from the coupling's formula (sum w_i T_i = Tbar W). The calculation is
 * carried in dual numbers (value, d/d delta): the exact first-order response at delta = 0
 * of each lane's T_i at every layer, its core pressure and its final radius, which shares
 * no code with the engine (CVODE) or the lanes' driver. The code's response
 * (X(delta) - X(0)) / delta must converge to it, its error O(delta) (the response's
 * O(delta^2)): halving delta halves it (T_i's quarters). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reel/result_internal.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

typedef struct dual {
  double v, d;
} dual;

static dual dl(double v, double d) { return (dual){v, d}; }
static dual add(dual a, dual b) { return dl(a.v + b.v, a.d + b.d); }
static dual sub(dual a, dual b) { return dl(a.v - b.v, a.d - b.d); }
static dual mul(dual a, dual b) { return dl(a.v * b.v, a.d * b.v + a.v * b.d); }
static dual dvd(dual a, dual b) { return dl(a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)); }
static dual scl(double c, dual a) { return dl(c * a.v, c * a.d); }
static dual pw(dual a, double g) { return dl(pow(a.v, g), g * pow(a.v, g - 1.0) * a.d); }

enum { NMAX = 400 };

typedef struct lin_lane {
  dual tau;          /* caliper */
  dual P[NMAX + 1];  /* pressure at the nodes, Pa (node 0 the core) */
  dual T[NMAX];      /* web tension of each layer, N/m */
} lin_lane;

/* the lane's radius with k layers: r_c + k tau - tau sum (P_j + P_j+1) / (2 E_r), P_k = 0 */
static dual lin_radius(const lin_lane *L, int k, double rc, double Er)
{
  dual comp = dl(0.0, 0.0);
  for (int j = 0; j < k; ++j) comp = add(comp, add(L->P[j], j + 1 < k ? L->P[j + 1] : dl(0.0, 0.0)));
  return sub(add(dl(rc, 0.0), scl(k, L->tau)), scl(0.5 / Er, mul(L->tau, comp)));
}

/* layer k at tension T on the lane: every node j <= k gains dP_j */
static void lin_load(lin_lane *L, int k, dual T, double rc, double g, double beta)
{
  const dual s = add(dl(rc, 0.0), scl(k, L->tau)), rc_ = dl(rc, 0.0);
  const dual den = add(dl(1.0, 0.0), scl(beta, pw(dvd(rc_, s), 2.0 * g)));
  for (int j = 0; j <= k; ++j) {
    const dual r = add(rc_, scl(j, L->tau));
    const dual num = add(pw(dvd(r, s), g), scl(beta, pw(dvd(scl(rc, rc_), mul(r, s)), g)));
    L->P[j] = add(L->P[j], mul(dvd(T, r), dvd(num, den)));
  }
}

/* the two lanes wound by the coupling (equal widths, Tbar constant) */
static void lin_wind(const rs_problem *pb, lin_lane *L, int N)
{
  const double rc = pb->core.radius, t = pb->material.caliper, Et = pb->material.E_theta;
  const double Er = pb->material.radial.E_r, g = sqrt(Et / Er), kappa = pb->material.nu_rtheta - 1.0;
  const double beta = (g - 1.0 - kappa) / (g + 1.0 + kappa), Tbar = pb->tension.start;
  memset(L, 0, 2 * sizeof *L);
  L[0].tau = dl(t, t);
  L[1].tau = dl(t, -t);
  for (int k = 0; k < N; ++k) {
    const dual R0 = lin_radius(&L[0], k, rc, Er), R1 = lin_radius(&L[1], k, rc, Er);
    const dual Rbar = scl(0.5, add(R0, R1));
    const dual a0 = scl(Et, L[0].tau), a1 = scl(Et, L[1].tau);
    const dual x0 = sub(dvd(R0, Rbar), dl(1.0, 0.0)), x1 = sub(dvd(R1, Rbar), dl(1.0, 0.0));
    /* sum a_i (e + x_i) = 2 Tbar */
    const dual e = dvd(sub(dl(2.0 * Tbar, 0.0), add(mul(a0, x0), mul(a1, x1))), add(a0, a1));
    L[0].T[k] = mul(a0, add(e, x0));
    L[1].T[k] = mul(a1, add(e, x1));
    lin_load(&L[0], k, L[0].T[k], rc, g, beta);
    lin_load(&L[1], k, L[1].T[k], rc, g, beta);
  }
}

static rs_reel_result *wind_two(rs_problem *pb, double delta)
{
  memset(&pb->lanes, 0, sizeof pb->lanes);
  pb->lanes.count = 2;
  for (int i = 0; i < 2; ++i) {
    pb->lanes.width[i] = 0.5;
    pb->lanes.x[i] = 0.25 + 0.5 * i;
    pb->lanes.caliper[i] = 1.0 + (i ? -delta : delta);
    pb->lanes.tension[i] = 1.0;
  }
  rs_reel_result *res = NULL;
  rs_status st = rs_reel_wind(pb, NULL, &res);
  if (st) printf("  error: %s\n", rs_error_message());
  CHECK(st == RS_OK && res && res->lanes);
  if (st || !res || !res->lanes) rs_reel_result_destroy(&res);
  return res;
}

static void gauge_perturbation_linear(void)
{
  const char *sets[] = {"numerics.rtol=1e-10"};
  rs_scene *sc = NULL;
  CHECK(rs_scene_load(RS_TESTS_DIR "/cli/scenes/small.yaml", 1, sets, &sc) == RS_OK);
  if (!sc) return;
  rs_problem pb = *rs_scene_problem(sc);
  rs_scene_destroy(&sc);
  const int N = pb.n_layers;
  CHECK(N <= NMAX && pb.material.radial.law == RS_RADIAL_LINEAR &&
        pb.tension.law == RS_RECIPE_CONSTANT && !isfinite(rs_core_stiffness(&pb.core)));
  if (N > NMAX) return;
  lin_lane *L = malloc(2 * sizeof *L);
  lin_wind(&pb, L, N);
  double dTmax = 0.0;
  for (int k = 0; k < N; ++k) dTmax = fmax(dTmax, fabs(L[0].T[k].d));
  const dual Rend = lin_radius(&L[0], N, pb.core.radius, pb.material.radial.E_r);
  CHECK_LOG("linear: max |dT_1/d delta| (N/m)", dTmax);
  CHECK_LOG("linear: d P_core,1 / d delta (Pa)", L[0].P[0].d);
  CHECK_LOG("linear: d R_1 / d delta (m)", Rend.d);
  rs_reel_result *base = wind_two(&pb, 0.0);
  const double deltas[] = {4e-4, 2e-4, 1e-4};
  double err[3][3] = {{0}};
  for (int q = 0; q < 3 && base; ++q) {
    const double d = deltas[q];
    rs_reel_result *res = wind_two(&pb, d);
    if (!res) continue;
    const rs_lanes_result *lr = res->lanes, *lb = base->lanes;
    for (int k = 0; k < N; ++k) {
      const double slope = (lr->web_tension[(size_t)k * 2] - lb->web_tension[(size_t)k * 2]) / d;
      err[q][0] = fmax(err[q][0], fabs(slope - L[0].T[k].d) / dTmax);
    }
    err[q][1] = fabs((lr->core_pressure[0] - lb->core_pressure[0]) / d - L[0].P[0].d) / fabs(L[0].P[0].d);
    err[q][2] = fabs((lr->outer_radius[0] - lb->outer_radius[0]) / d - Rend.d) / fabs(Rend.d);
    printf("  delta %-8g relative error of the response: T_i %.3e  core pressure %.3e  R_i %.3e\n", d,
           err[q][0], err[q][1], err[q][2]);
    rs_reel_result_destroy(&res);
  }
  for (int x = 0; x < 3; ++x) {
    /* the linear response's error a small fraction of delta, and at least halved with it
     * (the core pressure and R_i: halved, second order in the response; T_i: quartered, as
     * swapping the lanes flips delta and the tensions' sum is held) */
    CHECK_LT(err[0][x], 2.0 * deltas[0]);
    CHECK(err[1][x] < 0.6 * err[0][x] && err[2][x] < 0.6 * err[1][x]);
    if (x > 0) CHECK(err[1][x] > 0.4 * err[0][x] && err[2][x] > 0.4 * err[1][x]);
  }
  rs_reel_result_destroy(&base);
  free(L);
}

static const check_case cases[] = {{"gauge_perturbation_linear", gauge_perturbation_linear}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
