/* Storage after the winder (docs/storage.md, "What is verified"): the stress change of a
 * wound roll from a uniform temperature/humidity change against a closed form for a
 * linear roll, an independent shooting oracle turn by turn, the identity of a free
 * expansion, the convergence of the sub-steps on a nonlinear stack, the driver's stages,
 * and the published trend (Qualls & Good 1997: a PET roll heated on a steel core gains
 * core pressure). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/core.h"
#include "reelsim/reel.h"
#include "reelsim/storage.h"
#include "storage/storage_internal.h"
#include "storage/storage_result.h"

/* ---- a hand-made problem and wound roll ------------------------------------------------ */
typedef struct fake_roll {
  rs_problem pb;
  rs_reel_result res;
  double *radius, *sr, *st, *zero;
} fake_roll;

static void fake_init(fake_roll *f, int n, double rc, double t, double E_theta, double E_r,
                      double nu, double E_c)
{
  memset(f, 0, sizeof *f);
  f->pb.material.caliper = t;
  f->pb.material.E_theta = E_theta;
  f->pb.material.nu_rtheta = nu;
  f->pb.material.radial.law = RS_RADIAL_LINEAR;
  f->pb.material.radial.E_r = E_r;
  f->pb.core.radius = rc;
  if (isinf(E_c)) {
    f->pb.core.kind = RS_CORE_RIGID;
  } else {
    f->pb.core.kind = RS_CORE_ELASTIC;
    f->pb.core.stiffness = E_c;
  }
  f->pb.storage.wind_temperature = 23.0;
  f->pb.storage.wind_humidity = 50.0;
  f->pb.numerics.rtol = 1e-10;
  f->radius = calloc((size_t)n, sizeof(double));
  f->sr = calloc((size_t)n, sizeof(double));
  f->st = calloc((size_t)n, sizeof(double));
  f->zero = calloc((size_t)n, sizeof(double));
  for (int j = 0; j < n; ++j) f->radius[j] = rc + (j + 1) * t;
  f->res.n_layers = n;
  f->res.radius = f->radius;
  f->res.sigma_r = f->sr;
  f->res.sigma_theta = f->st;
  f->res.wound_on_tension = f->res.web_tension = f->res.nip_load = f->zero;
  f->res.core_radius = rc;
}

static void fake_free(fake_roll *f)
{
  free(f->radius);
  free(f->sr);
  free(f->st);
  free(f->zero);
}

static void set_thermal(rs_problem *pb, double a_r, double a_t, double a_c)
{
  pb->material.has_thermal = 1;
  pb->material.alpha_r = a_r;
  pb->material.alpha_theta = a_t;
  pb->storage.core_alpha = a_c;
}

/* ---- the closed form: one orthotropic annulus [r_c, b] with uniform free strains e_r,
 * e_t on a core (1/E_c, e_c), outer face free (docs/storage.md, "A linear roll"):
 *   sigma_r = A (r/b)^(g-1) + B (r_c/r)^(g+1) + c0,  c0 = E_t (e_r - e_t) / (1 - g^2)
 *   sigma_theta = g A (r/b)^(g-1) - g B (r_c/r)^(g+1) + c0
 *   A + q B = -c0,  p a1 A - a2 B = R0,   p = (r_c/b)^(g-1), q = (r_c/b)^(g+1),
 *   a1 = (g - nu)/E_t - 1/E_c, a2 = (g + nu)/E_t + 1/E_c,
 *   R0 = e_c - e_t - c0 (1 - nu)/E_t + c0/E_c. */
typedef struct annulus {
  double rc, b, g, c0, A, B;
} annulus;

static annulus closed_form(double rc, double b, double E_t, double E_r, double nu, double E_c_inv,
                           double e_r, double e_t, double e_c)
{
  annulus s = {.rc = rc, .b = b, .g = sqrt(E_t / E_r)};
  const double g = s.g, p = pow(rc / b, g - 1.0), q = pow(rc / b, g + 1.0);
  s.c0 = E_t * (e_r - e_t) / (1.0 - g * g);
  const double a1 = (g - nu) / E_t - E_c_inv, a2 = (g + nu) / E_t + E_c_inv;
  const double R0 = e_c - e_t - s.c0 * (1.0 - nu) / E_t + s.c0 * E_c_inv;
  s.B = -(R0 + p * a1 * s.c0) / (p * q * a1 + a2);
  s.A = -s.c0 - q * s.B;
  return s;
}

static double cf_sr(const annulus *s, double r)
{
  return s->A * pow(r / s->b, s->g - 1.0) + s->B * pow(s->rc / r, s->g + 1.0) + s->c0;
}

/* runs one change on a linear roll and compares sigma_r at every face with the closed form */
static void linear_case(double a_r, double a_t, double a_c, double dT, double E_c,
                        double *core_change)
{
  const int n = 400;
  const double rc = 0.05, t = 50e-6, Et = 4.5e9, Er = 20e6, nu = 0.01;
  fake_roll f;
  fake_init(&f, n, rc, t, Et, Er, nu, E_c);
  set_thermal(&f.pb, a_r, a_t, a_c);
  rs_storage_roll roll;
  CHECK(rs_storage_roll_init(&roll, &f.pb, &f.res) == RS_OK);
  CHECK(rs_storage_change(&roll, 23.0 + dT, 50.0, 1e-10) == RS_OK);
  const annulus s = closed_form(rc, f.radius[n - 1], Et, Er, nu, roll.E_c_inv, a_r * dT,
                                a_t * dT, a_c * dT);
  double scale = fabs(cf_sr(&s, rc)), err = 0.0, err_t = 0.0, scale_t = 0.0;
  for (int k = 0; k <= n; ++k) err = fmax(err, fabs(roll.sr[k] - cf_sr(&s, roll.s[k])));
  for (int k = 1; k <= n; ++k) {
    const double exact = (roll.s[k] * cf_sr(&s, roll.s[k]) - roll.s[k - 1] * cf_sr(&s, roll.s[k - 1])) / t;
    err_t = fmax(err_t, fabs(roll.st[k - 1] - exact));
    scale_t = fmax(scale_t, fabs(exact));
  }
  printf("  core sigma_r change %.10g Pa (closed form %.10g); max error %.3g of it; hoop %.3g\n",
         roll.sr[0], cf_sr(&s, rc), err / scale, err_t / scale_t);
  CHECK_CLOSE(roll.sr[0], cf_sr(&s, rc), 1e-8);
  CHECK(err <= 1e-8 * scale);
  CHECK(err_t <= 1e-8 * scale_t);
  CHECK(roll.max_substeps <= 2); /* a linear stack needs no sub-steps */
  *core_change = -roll.sr[0];    /* the core pressure's change */
  rs_storage_roll_free(&roll);
  fake_free(&f);
}

/* Heating by 30 K, the web expanding alike in r and theta (1.7e-5/K): a core that expands
 * less (steel 1.2e-5) is left behind by the web and loses pressure. */
static void core_expands_less(void)
{
  double dp;
  linear_case(1.7e-5, 1.7e-5, 1.2e-5, 30.0, 5e9, &dp);
  CHECK_LT(dp, 0.0);
}

/* ... and one that expands more (aluminium 2.3e-5) presses on the web: gains pressure. */
static void core_expands_more(void)
{
  double dp;
  linear_case(1.7e-5, 1.7e-5, 2.3e-5, 30.0, 5e9, &dp);
  CHECK_LT(0.0, dp);
}

/* An anisotropic web (the stack expands 5x faster through its thickness than along the
 * web) on a rigid core: the particular solution of the eigenstrain at work. */
static void anisotropic_rigid(void)
{
  double dp;
  linear_case(8.5e-5, 1.7e-5, 0.0, -20.0, INFINITY, &dp);
  CHECK_FINITE(dp);
}

/* The web equally stiff in r and theta (g = 1 exactly: psi's limit ln(x)/2) */
static void isotropic_g1(void)
{
  const int n = 50;
  const double rc = 0.05, t = 1e-3, E = 2e9, nu = 0.3;
  fake_roll f;
  fake_init(&f, n, rc, t, E, E, nu, 1e10);
  set_thermal(&f.pb, 3e-5, 1e-5, 0.0);
  rs_storage_roll roll;
  CHECK(rs_storage_roll_init(&roll, &f.pb, &f.res) == RS_OK);
  CHECK(rs_storage_change(&roll, 73.0, 50.0, 1e-10) == RS_OK);
  /* the closed form at g = 1 + 1e-7: the family is continuous in g */
  const annulus s = closed_form(rc, f.radius[n - 1], E * (1 + 2e-7), E, nu, roll.E_c_inv,
                                3e-5 * 50, 1e-5 * 50, 0.0);
  printf("  core sigma_r %.12g, closed form at g = 1 + 1e-7: %.12g\n", roll.sr[0], cf_sr(&s, rc));
  CHECK_CLOSE(roll.sr[0], cf_sr(&s, rc), 1e-6);
  rs_storage_roll_free(&roll);
  fake_free(&f);
}

/* ---- an independent oracle: (sigma_r, u/r) carried from the core through every turn by
 * the annulus solution (the transfer of tests/validation/ring_statics.h extended by the
 * free strains), two shots (the free strains with sigma_r(r_c) = 0; a unit core stress
 * without them) matched to the free outer face. Long double; fine for small g^2 t/r. */
static void shoot(int n, const double *s, const double *E_r, double Et, double nu, double Ec_inv,
                  double e_r, double e_t, double e_c, int with_strain, double sr0,
                  long double *sr_out)
{
  long double sr = sr0, ur = with_strain ? e_c + Ec_inv * sr0 : Ec_inv * sr0;
  const long double de = with_strain ? (long double)e_r - e_t : 0.0L,
                    et = with_strain ? e_t : 0.0;
  sr_out[0] = sr;
  for (int k = 1; k <= n; ++k) {
    const long double g = sqrtl((long double)Et / E_r[k - 1]), x = (long double)s[k] / s[k - 1];
    const long double K = Et * de, P = powl(x, g - 1), Q = powl(x, -g - 1);
    const long double psi = (P - 1) / (g * g - 1);
    const long double st_a = Et * (ur - et) + nu * sr;
    const long double sum = sr, dif = (st_a - K / (1 + g)) / g;
    const long double al = (sum + dif) / 2, be = (sum - dif) / 2;
    const long double sr_b = al * P + be * Q + K * psi;
    const long double st_b = g * (al * P - be * Q) + K * (psi + P / (1 + g));
    ur = (st_b - nu * sr_b) / Et + et;
    sr = sr_b;
    sr_out[k] = sr;
  }
}

static void matches_shooting_oracle(void)
{
  const int n = 120;
  const double rc = 0.08, t = 100e-6, Et = 3e9, nu = 0.05, E_c = 2e9;
  fake_roll f;
  fake_init(&f, n, rc, t, Et, 1e6, nu, E_c);
  set_thermal(&f.pb, 6e-5, 1.5e-5, 5e-6);
  rs_storage_roll roll;
  CHECK(rs_storage_roll_init(&roll, &f.pb, &f.res) == RS_OK);
  double *E_r = malloc(n * sizeof(double)), *dsr = malloc((n + 1) * sizeof(double)),
         *dst = malloc(n * sizeof(double));
  /* turn moduli from 1 to 60 MPa and back (g from 55 to 7): a varying stack */
  for (int k = 0; k < n; ++k) E_r[k] = 1e6 + 59e6 * sin(3.14159 * (k + 0.5) / n);
  const double dT = 25.0;
  rs_storage_load ld = {.E_r = E_r, .de_r_all = 6e-5 * dT, .de_theta_all = 1.5e-5 * dT,
                        .de_core = 5e-6 * dT};
  CHECK(rs_storage_elastic(&roll, &ld, dsr, dst) == RS_OK);
  long double *a = malloc((n + 1) * sizeof(long double)), *b = malloc((n + 1) * sizeof(long double));
  shoot(n, roll.s, E_r, Et, nu, 1.0 / E_c, ld.de_r_all, ld.de_theta_all, ld.de_core, 1, 0.0, a);
  shoot(n, roll.s, E_r, Et, nu, 1.0 / E_c, 0, 0, 0, 0, 1.0, b);
  const long double p = -a[n] / b[n];
  double err = 0.0, scale = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double exact = (double)(a[k] + p * b[k]);
    err = fmax(err, fabs(dsr[k] - exact));
    scale = fmax(scale, fabs(exact));
  }
  printf("  core sigma_r change %.12g Pa, oracle %.12g; max error %.3g of the largest\n", dsr[0],
         (double)p, err / scale);
  CHECK_CLOSE(dsr[0], (double)p, 1e-8);
  CHECK(err <= 1e-8 * scale);
  free(a);
  free(b);
  free(E_r);
  free(dsr);
  free(dst);
  rs_storage_roll_free(&roll);
  fake_free(&f);
}

/* ---- wound rolls through the driver ----------------------------------------------------- */
static rs_problem pfeiffer_problem(int n)
{
  rs_problem pb;
  memset(&pb, 0, sizeof pb);
  pb.material.caliper = 70e-6;
  pb.material.E_theta = 3.5e9;
  pb.material.nu_rtheta = 0.01;
  pb.material.radial.law = RS_RADIAL_PFEIFFER;
  pb.material.radial.K1 = 200.0;
  pb.material.radial.K2 = 60.0;
  CHECK(rs_radial_law_prepare(&pb.material.radial) == RS_OK);
  pb.core.kind = RS_CORE_ELASTIC;
  pb.core.radius = 0.0762;
  pb.core.stiffness = 1e9;
  pb.final_radius = pb.core.radius + n * pb.material.caliper;
  pb.n_layers = n;
  pb.tension.law = RS_RECIPE_CONSTANT;
  pb.tension.start = pb.tension.end = 350.0;
  pb.tension.r0 = pb.core.radius;
  pb.tension.r1 = pb.final_radius;
  pb.numerics.layers_per_step = 1;
  pb.numerics.rtol = 1e-8;
  pb.numerics.reuse = RS_REUSE_ON;
  pb.storage.wind_temperature = 23.0;
  pb.storage.wind_humidity = 50.0;
  return pb;
}

/* web (r and theta) and core expand alike: a free expansion, no stress changes */
static void equal_expansion_nothing(void)
{
  rs_problem pb = pfeiffer_problem(300);
  rs_reel_result *res = NULL;
  rs_storage_result *sr = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &res) == RS_OK);
  pb.material.has_thermal = pb.material.has_hygroscopic = 1;
  pb.material.alpha_r = pb.material.alpha_theta = pb.storage.core_alpha = 1.3e-5;
  pb.material.beta_r = pb.material.beta_theta = pb.storage.core_beta = 2e-5;
  pb.storage.n_stages = 3;
  pb.storage.stage[0] = (rs_storage_stage){24.0, 60.0, 50.0};
  pb.storage.stage[1] = (rs_storage_stage){24.0, -10.0, 80.0};
  pb.storage.stage[2] = (rs_storage_stage){24.0, 23.0, 20.0};
  CHECK(rs_storage_run(&pb, res, &sr) == RS_OK);
  CHECK(sr && sr->n_stages == 4);
  double err = 0.0;
  for (int s = 1; sr && s < sr->n_stages; ++s) {
    err = fmax(err, fabs(sr->core_pressure[s] - res->core_pressure) / res->core_pressure);
    for (int j = 0; j < res->n_layers; ++j)
      err = fmax(err, fabs(sr->sigma_r[s * res->n_layers + j] - res->sigma_r[j]) /
                          res->core_pressure);
  }
  printf("  largest change %.3g of the core pressure\n", err);
  CHECK(err <= 1e-13);
  rs_storage_result_destroy(&sr);
  rs_reel_result_destroy(&res);
}

/* stage 0 is the wound roll; hours accumulate; an omitted value is the previous stage's */
static void driver_stages(void)
{
  rs_problem pb = pfeiffer_problem(200);
  rs_reel_result *res = NULL;
  rs_storage_result *sr = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &res) == RS_OK);
  pb.material.has_thermal = 1;
  pb.material.alpha_r = 4e-5;
  pb.material.alpha_theta = 8e-6;
  pb.storage.n_stages = 2;
  pb.storage.stage[0] = (rs_storage_stage){10.0, 40.0, 50.0};
  pb.storage.stage[1] = (rs_storage_stage){5.5, 40.0, 50.0};
  CHECK(rs_storage_run(&pb, res, &sr) == RS_OK);
  CHECK(sr->n_stages == 3 && sr->n_layers == 200);
  CHECK(sr->hours[0] == 0.0 && sr->hours[1] == 10.0 && sr->hours[2] == 15.5);
  CHECK(sr->temperature[0] == 23.0 && sr->temperature[2] == 40.0);
  CHECK(sr->core_pressure[0] == res->core_pressure);
  for (int j = 0; j < 200; ++j) {
    CHECK(sr->sigma_r[j] == res->sigma_r[j]);
    CHECK(sr->sigma_theta[j] == res->sigma_theta[j]);
  }
  /* no viscoelastic data: a hold changes nothing */
  CHECK(sr->core_pressure[2] == sr->core_pressure[1]);
  CHECK(sr->core_pressure[1] != sr->core_pressure[0]);
  for (int s = 0; s < 3; ++s) CHECK(sr->defects[s] != NULL);
  rs_storage_worst w;
  rs_storage_worst_stages(sr, &w);
  CHECK(w.core >= 0 && w.core <= 2);
  rs_storage_result_destroy(&sr);
  rs_reel_result_destroy(&res);
}

/* the sub-steps converge at second order on a nonlinear (Pfeiffer) stack */
static void substeps_converge(void)
{
  rs_problem pb = pfeiffer_problem(400);
  rs_reel_result *res = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &res) == RS_OK);
  pb.material.has_thermal = 1;
  pb.material.alpha_r = 2e-4; /* a large swing: the pressures change by tens of % */
  pb.material.alpha_theta = 1e-5;
  double p[7];
  for (int i = 0; i < 7; ++i) {
    rs_storage_roll roll;
    CHECK(rs_storage_roll_init(&roll, &pb, res) == RS_OK);
    CHECK(rs_storage_change_steps(&roll, 63.0, 50.0, 1 << i) == RS_OK);
    p[i] = -roll.sr[0];
    rs_storage_roll_free(&roll);
  }
  printf("  core pressure %.10g (wound) -> %.10g (64 steps)\n", res->core_pressure, p[6]);
  for (int i = 1; i < 5; ++i) {
    const double order = log2(fabs(p[i] - p[i - 1]) / fabs(p[i + 1] - p[i]));
    printf("  steps %d -> %d: change %.3g, observed order %.3f\n", 1 << i, 1 << (i + 1),
           p[i + 1] - p[i], order);
    if (i >= 2) {
      CHECK_LT(1.8, order);
      CHECK_LT(order, 2.2);
    }
  }
  CHECK_LT(0.05 * res->core_pressure, fabs(p[6] - res->core_pressure)); /* a real change */
  rs_reel_result_destroy(&res);
}

/* Qualls & Good (1997), thermal stresses in wound rolls: heating a roll changes its
 * pressures through two mismatches, the web's hoop expansion against the core's (a steel
 * core expands less than PET: pressure falls) and the stack's radial expansion, which
 * pushes the outer layers out against their hoop stiffness (pressure rises); a film
 * stack's radial coefficient (air and roughness between the layers) is several times the
 * film's in-plane one, and then the roll on a steel core gains pressure when heated and
 * loses it when cooled. Values (docs/storage.md): PET alpha_theta 1.7e-5/K, the stack's
 * alpha_r 1.5e-4/K (models/pet-film.yaml, illustrative), steel 1.2e-5/K; 23 -> 53 C and
 * 23 -> -7 C. With alpha_r = alpha_theta (no stack effect) the core mismatch alone acts
 * and heating lowers the pressure: both mechanisms, each with its sign. */
static void pet_run(double alpha_r, double p[4])
{
  rs_problem pb;
  memset(&pb, 0, sizeof pb);
  pb.material.caliper = 23e-6;
  pb.material.E_theta = 4.5e9;
  pb.material.nu_rtheta = 0.01;
  pb.material.radial.law = RS_RADIAL_HAKIEL;
  pb.material.radial.n_coef = 3;
  pb.material.radial.C[0] = 1e6;
  pb.material.radial.C[1] = 60.0;
  pb.material.radial.C[2] = 2e-6;
  CHECK(rs_radial_law_prepare(&pb.material.radial) == RS_OK);
  pb.core = (rs_core){.kind = RS_CORE_TUBE, .radius = 0.0762, .bore = 0.0662, .modulus = 200e9,
                      .poisson = 0.3};
  const int n = 1500;
  pb.final_radius = pb.core.radius + n * pb.material.caliper;
  pb.n_layers = n;
  pb.tension.law = RS_RECIPE_CONSTANT;
  pb.tension.start = pb.tension.end = 200.0;
  pb.tension.r0 = pb.core.radius;
  pb.tension.r1 = pb.final_radius;
  pb.numerics.layers_per_step = 1;
  pb.numerics.rtol = 1e-7;
  pb.numerics.reuse = RS_REUSE_ON;
  pb.storage.wind_temperature = 23.0;
  pb.storage.wind_humidity = 50.0;
  pb.material.has_thermal = 1;
  pb.material.alpha_r = alpha_r;
  pb.material.alpha_theta = 1.7e-5;
  pb.storage.core_alpha = 1.2e-5;
  pb.storage.n_stages = 3;
  pb.storage.stage[0] = (rs_storage_stage){24.0, 53.0, 50.0};
  pb.storage.stage[1] = (rs_storage_stage){24.0, 23.0, 50.0};
  pb.storage.stage[2] = (rs_storage_stage){24.0, -7.0, 50.0};
  rs_reel_result *res = NULL;
  rs_storage_result *sr = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &res) == RS_OK);
  CHECK(rs_storage_run(&pb, res, &sr) == RS_OK);
  for (int i = 0; i < 4; ++i) p[i] = sr ? sr->core_pressure[i] : NAN;
  printf("  alpha_r %.3g/K: core pressure wound %.6g Pa, at 53 C %.6g, back at 23 C %.6g, at "
         "-7 C %.6g\n", alpha_r, p[0], p[1], p[2], p[3]);
  rs_storage_result_destroy(&sr);
  rs_reel_result_destroy(&res);
}

static void pet_heated_on_steel(void)
{
  double p[4], q[4];
  pet_run(1.5e-4, p);
  CHECK_LT(p[0], p[1]);          /* heated: up */
  CHECK_LT(p[3], p[0]);          /* cooled: down */
  CHECK_CLOSE(p[2], p[0], 1e-6); /* elastic: back where it was */
  pet_run(1.7e-5, q);            /* an isotropic film: the core mismatch alone */
  CHECK_LT(q[1], q[0]);
  CHECK_LT(q[0], q[3]);
}

static const check_case cases[] = {
    {"core_expands_less", core_expands_less},
    {"core_expands_more", core_expands_more},
    {"anisotropic_rigid", anisotropic_rigid},
    {"isotropic_g1", isotropic_g1},
    {"matches_shooting_oracle", matches_shooting_oracle},
    {"equal_expansion_nothing", equal_expansion_nothing},
    {"driver_stages", driver_stages},
    {"substeps_converge", substeps_converge},
    {"pet_heated_on_steel", pet_heated_on_steel},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
