/* The roll engine against the exact statics of real layers (tests/validation/ring_statics.h:
 * every turn an orthotropic annulus, Lekhnitskii's closed form per turn, the core a state
 * or a real tube), and the two load placements' common thin-layer limit.
 *
 *   ring_rigid, ring_elastic, ring_tube      the default (load beneath) to 1e-6, 400 layers
 *   ring_hakiel                               Hakiel's placement against the same oracle
 *   paper_2000_published                      the 2000-layer paper-like roll: core ~137.5 kPa,
 *                                             mid-roll hoop ~ -85 kPa (two independent codes)
 *   tube_400_sign                             400 layers on a steel tube: hoop ~ -84 kPa
 *                                             beneath, +29 kPa with Hakiel's placement
 *   thin_layer_limit                          both placements converge to one limit as the
 *                                             caliper is halved, at first order */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "reelsim/core.h"
#include "roll/roll.h"
#include "ring_statics.h"
#include "roll_helpers.h"

/* The paper-like web of issue 20: t = 70 um, E_theta = 3.5 GPa, E_r = 1 MPa, T = 350 N/m. */
enum { PAPER_N = 400 };
static const double PAPER_RC = 0.0762, PAPER_T = 70e-6, PAPER_ET = 3.5e9, PAPER_ER = 1e6,
                    PAPER_TENSION = 350.0;

typedef struct diff {
  double core;  /* |engine - oracle| / oracle, core pressure */
  double sr;    /* max |d sigma_r| / oracle core pressure */
  double st;    /* max |d sigma_theta| / (T/t) */
} diff;

/* Winds the engine and the oracle with the same parameters and compares. */
static diff engine_vs_oracle(const rs_roll_params *p, const ring_roll *R, int n, double T,
                             double *core_out, double *mid_hoop_out)
{
  diff d = {INFINITY, INFINITY, INFINITY};
  double *Tk = malloc((size_t)n * sizeof(double)), *sr = malloc((size_t)n * sizeof(double));
  double *st = malloc((size_t)n * sizeof(double)), core;
  for (int i = 0; i < n; ++i) Tk[i] = T;
  ring_wind(R, n, Tk, sr, st, &core);
  rs_roll *roll = wind(p, n, 1, T);
  if (roll) {
    const double *er = rs_roll_sigma_r(roll), *et = rs_roll_sigma_theta(roll);
    d.core = fabs(rs_roll_core_pressure(roll) - core) / core;
    d.sr = d.st = 0.0;
    for (int j = 0; j < n; ++j) {
      d.sr = fmax(d.sr, fabs(er[j] - sr[j]) / core);
      d.st = fmax(d.st, fabs(et[j] - st[j]) / (T / p->caliper));
    }
    CHECK_LOG("core pressure, engine (Pa)", rs_roll_core_pressure(roll));
    CHECK_LOG("core pressure, ring statics (Pa)", core);
    CHECK_LOG("mid-roll hoop, engine (Pa)", et[n / 2 - 1]);
    CHECK_LOG("mid-roll hoop, ring statics (Pa)", st[n / 2 - 1]);
    CHECK_LOG("core rel diff", d.core);
    CHECK_LOG("max |sigma_r diff| / core pressure", d.sr);
    CHECK_LOG("max |sigma_theta diff| / (T/t)", d.st);
    if (core_out) *core_out = rs_roll_core_pressure(roll);
    if (mid_hoop_out) *mid_hoop_out = et[n / 2 - 1];
  }
  rs_roll_destroy(&roll);
  free(Tk);
  free(sr);
  free(st);
  return d;
}

static rs_roll_params paper_params(double Ec, int n)
{
  rs_roll_params p = linear_params(PAPER_RC, PAPER_T, PAPER_ET, PAPER_ER, Ec, n);
  p.rtol = 1e-10;
  p.atol = 1e-12;
  return p;
}

static ring_roll paper_ring(void)
{
  ring_roll R = {PAPER_RC, PAPER_T, PAPER_ET, PAPER_ER, 0.0, RING_CORE_RIGID, 0, 0, 0, 0, 1};
  return R;
}

static void check_within(diff d, double tol)
{
  CHECK_LT(d.core, tol);
  CHECK_LT(d.sr, tol);
  CHECK_LT(d.st, tol);
}

static void ring_rigid(void)
{
  rs_roll_params p = paper_params(INFINITY, PAPER_N);
  ring_roll R = paper_ring();
  check_within(engine_vs_oracle(&p, &R, PAPER_N, PAPER_TENSION, NULL, NULL), 1e-6);
}

static void ring_elastic(void)
{
  rs_roll_params p = paper_params(1e9, PAPER_N);
  p.nu_rtheta = 0.01;
  ring_roll R = paper_ring();
  R.core = RING_CORE_ELASTIC;
  R.E_c = 1e9;
  R.nu = 0.01;
  check_within(engine_vs_oracle(&p, &R, PAPER_N, PAPER_TENSION, NULL, NULL), 1e-6);
}

/* A steel tube (E = 200 GPa, nu = 0.3, wall 6 mm): the engine takes its effective
 * stiffness from rs_core_stiffness's plane-stress formula; the oracle winds onto the tube
 * itself, an isotropic annulus with a free bore. */
static rs_core steel_tube(void)
{
  rs_core c = {RS_CORE_TUBE, PAPER_RC, 0, PAPER_RC - 0.006, 200e9, 0.3, 0};
  return c;
}

/* the oracle's roll on that tube itself */
static ring_roll paper_ring_on_tube(const rs_core *core)
{
  ring_roll R = paper_ring();
  R.core = RING_CORE_TUBE;
  R.bore = core->bore;
  R.E_tube = core->modulus;
  R.nu_tube = core->poisson;
  return R;
}

static void ring_tube(void)
{
  rs_core core = steel_tube();
  rs_roll_params p = paper_params(rs_core_stiffness(&core), PAPER_N);
  ring_roll R = paper_ring_on_tube(&core);
  check_within(engine_vs_oracle(&p, &R, PAPER_N, PAPER_TENSION, NULL, NULL), 1e-6);
}

static void ring_hakiel(void)
{
  rs_roll_params p = paper_params(1e9, PAPER_N);
  p.placement = RS_LOAD_HAKIEL;
  ring_roll R = paper_ring();
  R.core = RING_CORE_ELASTIC;
  R.E_c = 1e9;
  R.beneath = 0;
  check_within(engine_vs_oracle(&p, &R, PAPER_N, PAPER_TENSION, NULL, NULL), 1e-6);
}

/* Issue 20's figures from two independent linear accretion codes (a 1-D finite-element roll
 * and an exact ring-by-ring solution) for 2000 layers on a rigid core of radius 76.2 mm:
 * core pressure ~137.5 kPa, mid-roll hoop stress ~ -85 kPa; reelsim with Hakiel's
 * placement gave 133.1 kPa and -15.5 kPa. "About" is read as 1 % for the core pressure and
 * 2 % for the hoop stress, a small residual (1.7 % of T/t). */
static void paper_2000_published(void)
{
  const int n = 2000;
  rs_roll_params p = paper_params(INFINITY, n);
  p.rtol = 1e-8;
  ring_roll R = paper_ring();
  double core = 0.0, hoop = 0.0;
  check_within(engine_vs_oracle(&p, &R, n, PAPER_TENSION, &core, &hoop), 1e-6);
  CHECK_CLOSE(core, 137.5e3, 0.01);
  CHECK_CLOSE(hoop, -85e3, 0.02);
  p.placement = RS_LOAD_HAKIEL;
  R.beneath = 0;
  check_within(engine_vs_oracle(&p, &R, n, PAPER_TENSION, &core, &hoop), 1e-6);
  CHECK_CLOSE(core, 133.1e3, 0.001);
  CHECK_CLOSE(hoop, -15.5e3, 0.01);
}

/* Issue 20: 400 layers on a steel tube core: mid-roll hoop ~ -84 kPa from both independent
 * codes; Hakiel's placement gives +30 kPa (the sign flips). */
static void tube_400_sign(void)
{
  rs_core core = steel_tube();
  rs_roll_params p = paper_params(rs_core_stiffness(&core), PAPER_N);
  ring_roll R = paper_ring_on_tube(&core);
  double hoop_beneath, hoop_hakiel;
  check_within(engine_vs_oracle(&p, &R, PAPER_N, PAPER_TENSION, NULL, &hoop_beneath), 1e-6);
  p.placement = RS_LOAD_HAKIEL;
  R.beneath = 0;
  check_within(engine_vs_oracle(&p, &R, PAPER_N, PAPER_TENSION, NULL, &hoop_hakiel), 1e-6);
  CHECK_CLOSE(hoop_beneath, -84e3, 0.02);
  CHECK_CLOSE(hoop_hakiel, 30e3, 0.05);
}

/* Both placements tend to one continuum limit as the caliper t -> 0 at fixed web stress
 * T/t (5 MPa) and fixed radii (r_c = 50 mm -> 60 mm; linear roll, g = 30, elastic core).
 * Read: the core pressure and the hoop stress of the layer whose outer radius is 55 mm,
 * at t = 200, 100, 50, 25, 12.5 um.
 *  - core pressure: each placement's observed order from three successive calipers,
 *    log2((Q_t - Q_t/2) / (Q_t/2 - Q_t/4)), is first (0.8 .. 1.2; measured 0.995 .. 1.005),
 *    from opposite sides; their difference halves with t (ratio 1.7 .. 2.3) and their
 *    Richardson-extrapolated limits 2 Q_t/2 - Q_t agree to 1/10 of the difference left
 *    at the finest caliper;
 *  - hoop stress: Hakiel's placement converges at first order (its point value at the
 *    outer radius carries a first-order term as large as the residual itself: 502 kPa at
 *    200 um against a limit of 256 kPa); the turn-mean hoop stress of the default is
 *    within 2 % of Hakiel's distance from the limit at every caliper (measured 0.07 .. 0.4 %),
 *    the limit being Hakiel's extrapolated one, and the difference halves with t. */
static void thin_layer_limit(void)
{
  enum { NT = 5 };
  const double rc = 0.05, r1 = 0.06, rm = 0.055, stress = 5e6, Et = 3.5e9, Er = Et / 900.0;
  double core[2][NT], hoop[2][NT];
  for (int pl = 0; pl < 2; ++pl)
    for (int i = 0; i < NT; ++i) {
      const double t = 200e-6 / (1 << i);
      const int n = (int)lround((r1 - rc) / t), jm = (int)lround((rm - rc) / t) - 1;
      rs_roll_params p = linear_params(rc, t, Et, Er, 5e8, n);
      p.rtol = 1e-10;
      p.placement = pl ? RS_LOAD_HAKIEL : RS_LOAD_BENEATH;
      rs_roll *roll = wind(&p, n, 1, stress * t);
      if (!roll) return;
      core[pl][i] = rs_roll_core_pressure(roll);
      hoop[pl][i] = rs_roll_sigma_theta(roll)[jm];
      printf("  %-7s t = %-9.4g core %.10g Pa  hoop at r = %.4g m: %.10g Pa\n",
             pl ? "hakiel" : "beneath", t, core[pl][i], rs_roll_layer_radius(roll, jm),
             hoop[pl][i]);
      rs_roll_destroy(&roll);
    }
  const double(*Q[2])[NT] = {core, hoop};
  const char *what[2] = {"core pressure", "hoop stress at 55 mm"};
  for (int q = 0; q < 2; ++q) {
    for (int pl = q; pl < 2; ++pl) /* the order of both core pressures, Hakiel's hoop */
      for (int i = 0; i + 2 < NT; ++i) {
        const double *v = Q[q][pl];
        const double order = log2((v[i] - v[i + 1]) / (v[i + 1] - v[i + 2]));
        printf("  %s, %s: observed order %.4f\n", what[q], pl ? "hakiel" : "beneath", order);
        CHECK(order > 0.8 && order < 1.2);
      }
    for (int i = 0; i + 1 < NT; ++i) {
      const double d0 = Q[q][0][i] - Q[q][1][i], d1 = Q[q][0][i + 1] - Q[q][1][i + 1];
      printf("  %s: placements differ by %.6g, then %.6g (ratio %.4f)\n", what[q], d0, d1,
             d0 / d1);
      CHECK(d0 / d1 > 1.7 && d0 / d1 < 2.3);
    }
  }
  const double gap = fabs(core[0][NT - 1] - core[1][NT - 1]);
  const double lim_b = 2 * core[0][NT - 1] - core[0][NT - 2];
  const double lim_h = 2 * core[1][NT - 1] - core[1][NT - 2];
  CHECK_LOG("core pressure, extrapolated limit, beneath", lim_b);
  CHECK_LOG("core pressure, extrapolated limit, hakiel", lim_h);
  CHECK_LT(fabs(lim_b - lim_h), 0.1 * gap);
  const double lim = 2 * hoop[1][NT - 1] - hoop[1][NT - 2];
  CHECK_LOG("hoop stress, Hakiel's extrapolated limit", lim);
  for (int i = 0; i < NT; ++i) {
    const double eb = fabs(hoop[0][i] - lim), eh = fabs(hoop[1][i] - lim);
    printf("  hoop stress distance from the limit: beneath %.6g, hakiel %.6g\n", eb, eh);
    CHECK_LT(eb, 0.02 * eh);
  }
}

static const check_case cases[] = {
    {"ring_rigid", ring_rigid},
    {"ring_elastic", ring_elastic},
    {"ring_tube", ring_tube},
    {"ring_hakiel", ring_hakiel},
    {"paper_2000_published", paper_2000_published},
    {"tube_400_sign", tube_400_sign},
    {"thin_layer_limit", thin_layer_limit},
};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
