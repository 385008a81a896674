/* Radial laws, cores and recipes against independent statements of the same physics. */
#include <math.h>

#include "check.h"
#include "reelsim/core.h"
#include "reelsim/material.h"
#include "reelsim/recipe.h"

/* Pfeiffer's stack law P(eps) = K1 (exp(K2 eps) - 1): its tangent dP/deps, by central
 * differences, must equal the engine's E_r(P) = K2 (P + K1). */
static void pfeiffer_is_tangent_of_stack_law(void)
{
  rs_radial_law law = {.law = RS_RADIAL_PFEIFFER, .K1 = 5e3, .K2 = 60};
  CHECK(rs_radial_law_prepare(&law) == RS_OK);
  for (double eps = 0.0; eps <= 0.12; eps += 0.02) {
    double h = 1e-6, P = law.K1 * (exp(law.K2 * eps) - 1.0);
    double dP = law.K1 * (exp(law.K2 * (eps + h)) - exp(law.K2 * (eps - h))) / (2 * h);
    CHECK_CLOSE(rs_radial_modulus(&law, P), dP, 1e-7);
  }
}

static void hakiel_polynomial(void)
{
  rs_radial_law law = {.law = RS_RADIAL_HAKIEL, .C = {1e5, 20.0, -1e-6, 2e-13}, .n_coef = 4};
  CHECK(rs_radial_law_prepare(&law) == RS_OK);
  double P = 3.3e5;
  CHECK_CLOSE(rs_radial_modulus(&law, P), 1e5 + 20.0 * P - 1e-6 * P * P + 2e-13 * P * P * P, 1e-15);
  law.C[0] = -1.0;
  CHECK(rs_radial_law_prepare(&law) == RS_ERR_INPUT);
}

/* Monotone cubic through measured points: exact at the points, never outside the range of
 * its neighbours (no overshoot on monotone data), held constant outside the table. */
static void table_monotone(void)
{
  rs_radial_law law = {.law = RS_RADIAL_TABLE, .n_points = 5,
                       .P = {0, 1e4, 2e4, 1e5, 1e6}, .E = {2e5, 3e5, 1.2e6, 1.3e6, 9e6}};
  CHECK(rs_radial_law_prepare(&law) == RS_OK);
  for (int i = 0; i < law.n_points; ++i) CHECK_CLOSE(rs_radial_modulus(&law, law.P[i]), law.E[i], 1e-14);
  int monotone = 1;
  double prev = rs_radial_modulus(&law, 0.0);
  for (int k = 1; k <= 20000; ++k) {
    double e = rs_radial_modulus(&law, 1e6 * k / 20000.0);
    monotone &= e >= prev - 1e-9 * fabs(prev);
    prev = e;
  }
  CHECK(monotone);
  CHECK_CLOSE(rs_radial_modulus(&law, 5e6), 9e6, 0);
  CHECK_CLOSE(rs_radial_modulus(&law, -10.0), 2e5, 0);
  law.P[2] = 5e3; /* unsorted */
  CHECK(rs_radial_law_prepare(&law) == RS_ERR_INPUT);
}

/* Tube core: Lame's thick cylinder (plane stress) under external pressure p, bore free:
 * sigma_r = A - B/r^2, sigma_theta = A + B/r^2, sigma_r(a) = 0, sigma_r(b) = -p,
 * u(b) = b (sigma_theta - nu sigma_r)/E. The engine's E_c must give u(b) = b sigma_r(b)/E_c. */
static void tube_core_is_lame(void)
{
  const double E = 3e9, nu = 0.3, b = 0.0762, p = 1e5;
  const double bores[] = {0.0, 0.02, 0.05, 0.07};
  for (int i = 0; i < 4; ++i) {
    double a = bores[i];
    double A = -p * b * b / (b * b - a * a), B = A * a * a;
    double sr = A - B / (b * b), st = A + B / (b * b);
    double u = b * (st - nu * sr) / E;
    rs_core core = {.kind = RS_CORE_TUBE, .radius = b, .bore = a, .modulus = E, .poisson = nu};
    CHECK_CLOSE(rs_core_stiffness(&core), b * sr / u, 1e-12);
  }
  rs_core solid = {.kind = RS_CORE_TUBE, .radius = b, .bore = 0, .modulus = E, .poisson = nu};
  CHECK_CLOSE(rs_core_stiffness(&solid), E / (1 - nu), 1e-14);
  rs_core rigid = {.kind = RS_CORE_RIGID, .radius = b};
  CHECK(isinf(rs_core_stiffness(&rigid)));
}

static void recipes(void)
{
  const double r0 = 0.0762, r1 = 0.5;
  rs_recipe lin = {.law = RS_RECIPE_LINEAR, .start = 400, .end = 250, .k = NAN};
  CHECK(rs_recipe_prepare(&lin, r0, r1) == RS_OK);
  CHECK_CLOSE(rs_recipe_eval(&lin, r0), 400, 1e-15);
  CHECK_CLOSE(rs_recipe_eval(&lin, r1), 250, 1e-15);
  CHECK_CLOSE(rs_recipe_eval(&lin, 0.5 * (r0 + r1)), 325, 1e-14);
  CHECK_CLOSE(rs_recipe_min(&lin), 250, 0);

  /* hyperbolic taper given by its end value: T(r1) = end, and T = start (1 - k (1 - r0/r)) */
  rs_recipe hyp = {.law = RS_RECIPE_HYPERBOLIC, .start = 350, .end = 200, .k = NAN};
  CHECK(rs_recipe_prepare(&hyp, r0, r1) == RS_OK);
  CHECK_CLOSE(rs_recipe_eval(&hyp, r1), 200, 1e-13);
  CHECK_CLOSE(rs_recipe_eval(&hyp, 0.3), 350 * (1 - hyp.k * (1 - r0 / 0.3)), 1e-15);
  rs_recipe hypk = {.law = RS_RECIPE_HYPERBOLIC, .start = 350, .end = NAN, .k = 0.5};
  CHECK(rs_recipe_prepare(&hypk, r0, r1) == RS_OK);
  CHECK_CLOSE(hypk.end, 350 * (1 - 0.5 * (1 - r0 / r1)), 1e-15);

  /* constant torque: T r is constant */
  rs_recipe tq = {.law = RS_RECIPE_TORQUE, .start = 300, .k = NAN};
  CHECK(rs_recipe_prepare(&tq, r0, r1) == RS_OK);
  for (double r = r0; r <= r1; r += 0.05) CHECK_CLOSE(rs_recipe_eval(&tq, r) * r, 300 * r0, 1e-14);
  CHECK_CLOSE(rs_recipe_min(&tq), 300 * r0 / r1, 1e-14);

  rs_recipe tab = {.law = RS_RECIPE_TABLE, .n_points = 3, .r = {0.1, 0.2, 0.4}, .value = {300, 100, 200}, .k = NAN};
  CHECK(rs_recipe_prepare(&tab, r0, r1) == RS_OK);
  CHECK_CLOSE(rs_recipe_eval(&tab, 0.15), 200, 1e-14);
  CHECK_CLOSE(rs_recipe_eval(&tab, 0.05), 300, 0);
  CHECK_CLOSE(rs_recipe_eval(&tab, 0.45), 200, 0);
  CHECK_CLOSE(rs_recipe_min(&tab), 100, 0);
  tab.r[2] = 0.15;
  CHECK(rs_recipe_prepare(&tab, r0, r1) == RS_ERR_INPUT);
}

/* One law of each kind (Hakiel's with 3 and 4 terms), for the checks that the array forms
 * give what the one-point forms give */
enum { RS_EVERY_LAW = 5 };
static void every_law(rs_radial_law laws[RS_EVERY_LAW])
{
  const rs_radial_law all[RS_EVERY_LAW] = {
      {.law = RS_RADIAL_LINEAR, .E_r = 3e6},
      {.law = RS_RADIAL_PFEIFFER, .K1 = 5e3, .K2 = 60},
      {.law = RS_RADIAL_HAKIEL, .C = {1.0e6, 60.0, 2.0e-6}, .n_coef = 3},
      {.law = RS_RADIAL_HAKIEL, .C = {1e5, 20.0, -1e-6, 2e-13}, .n_coef = 4},
      {.law = RS_RADIAL_TABLE, .n_points = 3, .P = {0, 1e4, 1e6}, .E = {2e5, 3e5, 9e6}},
  };
  for (int i = 0; i < RS_EVERY_LAW; ++i) laws[i] = all[i];
}

/* rs_radial_modulus_stress_n at n radial stresses: P = -sigma exactly and E_r bit for bit
 * what the law gives at P (rs_radial_modulus, one pressure at a time), for every law; the
 * index of the first modulus that is not positive, or -1. */
static void modulus_of_stresses(void)
{
  enum { N = 37 };
  rs_radial_law laws[RS_EVERY_LAW];
  every_law(laws);
  double sigma[N], P[N], E[N];
  for (int i = 0; i < N; ++i) sigma[i] = i == 3 ? 25.0 : -1.7e4 * i * i; /* one in tension */
  for (size_t l = 0; l < sizeof laws / sizeof laws[0]; ++l) {
    CHECK(rs_radial_law_prepare(&laws[l]) == RS_OK);
    CHECK(rs_radial_modulus_stress_n(&laws[l], sigma, P, E, N) == -1);
    int same = 1;
    for (int i = 0; i < N; ++i)
      same &= P[i] == -sigma[i] && E[i] == rs_radial_modulus(&laws[l], -sigma[i]);
    CHECK(same);
  }
  /* E_r = 1e6 - P^2 is negative above 1 kPa: the first such stress is at i = 8 */
  rs_radial_law bad = {.law = RS_RADIAL_HAKIEL, .C = {1e6, 0.0, -1.0}, .n_coef = 3};
  for (int i = 0; i < N; ++i) sigma[i] = -130.0 * i;
  CHECK(rs_radial_modulus_stress_n(&bad, sigma, P, E, N) == 8);
  CHECK(E[7] > 0.0 && !(E[8] > 0.0));
}

/* rs_radial_strain_steps: each step bit for bit rs_radial_strain_step's (the moduli of the
 * Gauss points formed as one array), for every law, over more steps than one block, with a
 * step of no length and one backwards (0); summed, Pfeiffer's closed form
 * eps(P) = ln(1 + P/K1)/K2. */
static void strain_steps_batched(void)
{
  enum { N = 150 };
  rs_radial_law laws[RS_EVERY_LAW];
  every_law(laws);
  const double Pmax = 4e5;
  double P[N + 1], d[N];
  for (int i = 0; i <= N; ++i) P[i] = Pmax * (double)i * i / ((double)N * N);
  P[41] = P[40];     /* a step of no length */
  P[71] = P[70] / 2; /* and one backwards, then a longer one up */
  for (size_t l = 0; l < sizeof laws / sizeof laws[0]; ++l) {
    CHECK(rs_radial_law_prepare(&laws[l]) == RS_OK);
    rs_radial_strain_steps(&laws[l], P, N, d);
    int same = 1;
    for (int i = 0; i < N; ++i) same &= d[i] == rs_radial_strain_step(&laws[l], P[i], P[i + 1]);
    CHECK(same);
    CHECK(d[40] == 0.0 && d[70] == 0.0);
  }
  for (int i = 0; i <= N; ++i) P[i] = Pmax * (double)i * i / ((double)N * N);
  rs_radial_strain_steps(&laws[1], P, N, d);
  double eps = 0.0;
  for (int i = 0; i < N; ++i) eps += d[i];
  CHECK_CLOSE(eps, log(1.0 + Pmax / laws[1].K1) / laws[1].K2, 1e-9);
}

static const check_case cases[] = {
    {"pfeiffer_is_tangent_of_stack_law", pfeiffer_is_tangent_of_stack_law},
    {"hakiel_polynomial", hakiel_polynomial},
    {"table_monotone", table_monotone},
    {"tube_core_is_lame", tube_core_is_lame},
    {"recipes", recipes},
    {"modulus_of_stresses", modulus_of_stresses},
    {"strain_steps_batched", strain_steps_batched},
};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
