/* Entrained air at its radius (docs/roll-model.md, "Entrained air"; docs/validation.md,
 * "Speed effects"): the engine with its nodes at the real radii r_c + sum (t + h_j) against
 * an independent closed form, the exact ring-by-ring statics of the same build-up.
 *
 * The oracle (tests/validation/ring_statics.h, no engine code) winds a linear stack whose
 * every turn, film included, is an orthotropic annulus of pitch p = t + h: the web carries
 * the hoop force (E_theta' = E_theta t / p, nu' = nu t / p) and web and film the radial
 * compliance in series (p / E_r' = t / E_r + c, the film's c = h p_a / (p_a + P)^2, constant
 * where P << p_a: the tensions here are small enough, P / p_a < 1e-7). Its hoop stress is
 * the pitch's mean; the web's is that times p / t. Each layer presses T0 / R on the roll
 * beneath it at the real radius R. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "ring_statics.h"
#include "roll_helpers.h"

enum { N_LAYERS = 400 };

typedef struct air_case {
  double rc, t, Et, Er, nu, Ec, h, pa, T;
} air_case;

/* the engine: films h at every node, the nodes at r_c + j (t + h) (with radii) or at
 * r_c + j t (without: the films only in series, as before the radii were real) */
static rs_roll *wind_air(const air_case *c, int radii, int per_step, double rtol, double *film,
                         double *R)
{
  rs_roll_params p = linear_params(c->rc, c->t, c->Et, c->Er, c->Ec, N_LAYERS);
  p.nu_rtheta = c->nu;
  p.rtol = rtol;
  p.atol = rtol * 1e-2;
  for (int j = 0; j <= N_LAYERS; ++j) {
    film[j] = c->h;
    R[j] = c->rc + j * (c->t + c->h);
  }
  p.air_film = film;
  p.air_pressure = c->pa;
  p.air_radius = radii ? R : NULL;
  return wind(&p, N_LAYERS, per_step, c->T);
}

/* the largest differences of the engine from the oracle, relative to the core pressure
 * (sigma_r) and to T0 / t (sigma_theta, the web's) */
static void against_oracle(const air_case *c, const rs_roll *roll, double *e_r, double *e_t, double *e_core)
{
  const double p = c->t + c->h, cfilm = c->h / c->pa;
  ring_roll R = {.rc = c->rc, .t = p, .E_theta = c->Et * c->t / p, .E_r = p / (c->t / c->Er + cfilm),
                 .nu = c->nu * c->t / p, .core = isinf(c->Ec) ? RING_CORE_RIGID : RING_CORE_ELASTIC,
                 .E_c = c->Ec, .beneath = 1};
  double *T = malloc(N_LAYERS * sizeof(double)), *sr = malloc(N_LAYERS * sizeof(double)),
         *st = malloc(N_LAYERS * sizeof(double)), core = 0.0;
  for (int j = 0; j < N_LAYERS; ++j) T[j] = c->T;
  ring_wind(&R, N_LAYERS, T, sr, st, &core);
  const double *er = rs_roll_sigma_r(roll), *et = rs_roll_sigma_theta(roll);
  *e_r = *e_t = 0.0;
  for (int j = 0; j < N_LAYERS; ++j) {
    *e_r = fmax(*e_r, fabs(er[j] - sr[j]) / core);
    *e_t = fmax(*e_t, fabs(et[j] - st[j] * p / c->t) / (c->T / c->t));
  }
  *e_core = fabs(rs_roll_core_pressure(roll) / core - 1.0);
  free(T);
  free(sr);
  free(st);
}

static void run_case(const char *name, const air_case *c)
{
  double film[N_LAYERS + 1], R[N_LAYERS + 1], e_r, e_t, e_c;
  printf("  %s\n", name);
  /* at rtol 1e-10 the engine is the closed form (the films' compliance is constant) */
  rs_roll *roll = wind_air(c, 1, 1, 1e-10, film, R);
  CHECK(roll != NULL);
  if (!roll) return;
  against_oracle(c, roll, &e_r, &e_t, &e_c);
  CHECK_LOG("real radii, rtol 1e-10: core pressure, rel.", e_c);
  CHECK_LOG("  max |sigma_r - oracle| / core pressure", e_r);
  CHECK_LOG("  max |sigma_theta - oracle| / (T0/t)", e_t);
  CHECK_LT(e_c, 1e-7);
  CHECK_LT(e_r, 1e-7);
  CHECK_LT(e_t, 1e-7);
  /* the outer layer's face load T0 / R at its real radius: the hoop stress of the new
   * layer is T0 / t and the layer beneath carries -T0 / R_{n-1} */
  const double *sr = rs_roll_sigma_r(roll);
  CHECK(sr[N_LAYERS - 1] == 0.0);
  CHECK_CLOSE(rs_roll_sigma_theta(roll)[N_LAYERS - 1], c->T / c->t, 1e-9);
  CHECK_CLOSE(rs_roll_layer_radius(roll, N_LAYERS - 1), R[N_LAYERS], 1e-15);
  rs_roll_destroy(&roll);
  /* the engine's defaults (rtol 1e-4; reuse, lazy deep part, error correction) stay close */
  roll = wind_air(c, 1, 1, 1e-4, film, R);
  CHECK(roll != NULL);
  if (!roll) return;
  against_oracle(c, roll, &e_r, &e_t, &e_c);
  CHECK_LOG("real radii, rtol 1e-4: max |sigma_r - oracle| / core pressure", e_r);
  CHECK_LT(e_r, 1e-5);
  CHECK_LT(e_t, 1e-4);
  rs_roll_destroy(&roll);
  /* lumped increments (the block's loads each at its own real radius): first order in m - 1 */
  roll = wind_air(c, 1, 4, 1e-10, film, R);
  CHECK(roll != NULL);
  if (!roll) return;
  against_oracle(c, roll, &e_r, &e_t, &e_c);
  CHECK_LOG("real radii, 4 layers per step: core pressure, rel.", e_c);
  CHECK_LT(e_c, 1e-7); /* a constant modulus: the corrector changes nothing */
  rs_roll_destroy(&roll);
  /* the test can fail: the nodes one caliper apart (the films only in series) miss it */
  roll = wind_air(c, 0, 1, 1e-10, film, R);
  CHECK(roll != NULL);
  if (!roll) return;
  against_oracle(c, roll, &e_r, &e_t, &e_c);
  CHECK_LOG("nodes at r_c + j t: max |sigma_r - oracle| / core pressure", e_r);
  CHECK_LOG("  max |sigma_theta - oracle| / (T0/t)", e_t);
  CHECK(e_r > 1e-3 || e_t > 1e-3);
  rs_roll_destroy(&roll);
}

/* films as thick as the web (pitch 2t) on a rigid core: E_r' = E_r, E_theta' = E_theta / 2 */
static void film_as_web_rigid(void)
{
  const air_case c = {.rc = 0.05, .t = 100e-6, .Et = 3.5e9, .Er = 2e6, .nu = 0.0, .Ec = INFINITY,
                      .h = 100e-6, .pa = 2e6, .T = 1e-4};
  run_case("films h = t, rigid core", &c);
}

/* thin films (h = 0.2 t) on an elastic core with a large Poisson ratio: the core condition
 * homogenised over the first pitch, (E_theta / E_c + nu) t / p - 1 */
static void thin_film_elastic(void)
{
  const air_case c = {.rc = 0.0762, .t = 70e-6, .Et = 3.5e9, .Er = 1e6, .nu = 0.3, .Ec = 2e8,
                      .h = 14e-6, .pa = 5e6, .T = 1e-4};
  run_case("films h = 0.2 t, elastic core, nu = 0.3", &c);
}

static const check_case cases[] = {{"film_as_web_rigid", film_as_web_rigid},
                                   {"thin_film_elastic", thin_film_elastic}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
