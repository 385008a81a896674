/* The centrifugal load of a spinning roll (docs/roll-model.md, "Centrifugal load";
 * docs/validation.md, "Speed effects"). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reel/spin.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

/* Lekhnitskii's spinning orthotropic annulus a <= r <= b in one piece, constant g, body
 * force c r, the core u(a) = a E_c_inv sr(a), the outer face free:
 *   sr = A x^(g-1) + B x^(-g-1) + K c r^2,  st = g A x^(g-1) - g B x^(-g-1) + (3K + 1) c r^2,
 *   K = (3 + nu)/(g^2 - 9), x = r/a; A, B from sr(b) = 0 and (st - nu sr)(a) = E_t E_c_inv sr(a). */
static double annulus_sr(double a, double b, double g, double nu, double E_t, double E_c_inv,
                         double c, double r)
{
  const double K = (3.0 + nu) / (g * g - 9.0), eta = E_t * E_c_inv, xb = b / a;
  const double m11 = pow(xb, g - 1.0), m12 = pow(xb, -g - 1.0), r1 = -K * c * b * b;
  const double m21 = g - nu - eta, m22 = -g - nu - eta, r2 = (eta * K - 3.0 * K - 1.0 + nu * K) * c * a * a;
  const double det = m11 * m22 - m12 * m21;
  const double A = (r1 * m22 - m12 * r2) / det, B = (m11 * r2 - m21 * r1) / det, x = r / a;
  return A * pow(x, g - 1.0) + B * pow(x, -g - 1.0) + K * c * r * r;
}

/* The turn-by-turn solver on n equal turns against the closed form at every face. */
static double annulus_error(double g, double g_closed, double E_c_inv, int n)
{
  const double a = 0.05, b = 0.1, E_t = 5e9, nu = 0.3, c = 800.0 * (30.0 / b) * (30.0 / b);
  double *s = malloc((size_t)(n + 1) * sizeof *s), *Er = malloc((size_t)n * sizeof *Er),
         *cv = malloc((size_t)n * sizeof *cv), *dsr = malloc((size_t)(n + 1) * sizeof *dsr),
         *dst = malloc((size_t)n * sizeof *dst), *work = malloc((size_t)(2 * n + 2) * sizeof *work);
  CHECK(s && Er && cv && dsr && dst && work);
  for (int k = 0; k <= n; ++k) s[k] = a + (b - a) * k / n;
  for (int k = 0; k < n; ++k) {
    Er[k] = E_t / (g * g);
    cv[k] = c;
  }
  CHECK(rs_spin_field(n, s, Er, E_t, nu, E_c_inv, cv, dsr, dst, work) == RS_OK);
  double err = 0.0, scale = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double ref = annulus_sr(a, b, g_closed, nu, E_t, E_c_inv, c, s[k]);
    err = fmax(err, fabs(dsr[k] - ref));
    scale = fmax(scale, fabs(ref));
  }
  CHECK(scale > 0.0);
  free(s), free(Er), free(cv), free(dsr), free(dst), free(work);
  return err / scale;
}

static void annulus_closed_form(void)
{
  const double gs[] = {1.0, 1.5, 5.0, 40.0}, cores[] = {0.0, 1.0 / 1e9};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j) {
      double e = annulus_error(gs[i], gs[i], cores[j], 400);
      CHECK_LOG(j ? "g (elastic core)" : "g (rigid core)", gs[i]);
      CHECK_LOG("  max |sr error| / max |sr|", e);
      CHECK_LT(e, 1e-9);
    }
  /* g = 3: the particular solution's r^3 ln r case, no special code; against g = 3 + 1e-7 */
  double e3 = annulus_error(3.0, 3.0 + 1e-7, 0.0, 400);
  CHECK_LOG("g = 3 against the closed form at g = 3 + 1e-7", e3);
  CHECK_LT(e3, 1e-5);
}

static void set_speed(rs_problem *pb, double V)
{
  memset(&pb->speed, 0, sizeof pb->speed);
  pb->speed.law = RS_RECIPE_CONSTANT;
  pb->speed.start = pb->speed.end = V;
  pb->speed.k = NAN;
  CHECK(rs_recipe_prepare(&pb->speed, pb->core.radius, pb->final_radius) == RS_OK);
}

static void paper_problem(rs_problem *pb, int layers, double T, double V)
{
  memset(pb, 0, sizeof *pb);
  pb->material.caliper = 70e-6;
  pb->material.E_theta = 3.5e9;
  pb->material.nu_rtheta = 0.01;
  pb->material.density = 800.0;
  pb->material.radial.law = RS_RADIAL_PFEIFFER;
  pb->material.radial.K1 = 5e3;
  pb->material.radial.K2 = 60;
  pb->core.kind = RS_CORE_RIGID;
  pb->core.radius = 0.0762;
  pb->n_layers = layers;
  pb->final_radius = pb->core.radius + layers * pb->material.caliper;
  pb->tension.law = RS_RECIPE_CONSTANT;
  pb->tension.start = T;
  pb->tension.end = T;
  pb->tension.k = NAN;
  CHECK(rs_radial_law_prepare(&pb->material.radial) == RS_OK);
  CHECK(rs_recipe_prepare(&pb->tension, pb->core.radius, pb->final_radius) == RS_OK);
  pb->numerics.layers_per_step = 1;
  pb->numerics.rtol = 1e-8;
  set_speed(pb, V);
  pb->centrifugal = 1;
}

/* One layer on a rigid core, spinning: it presses (T0 - rho t V^2)/r_c and keeps T0/t;
 * stopped, the core holds it at its radius and it presses T0/r_c again. */
static void one_layer_rigid(void)
{
  rs_problem pb;
  const double T = 350.0, V = 40.0;
  paper_problem(&pb, 1, T, V);
  const double spin = pb.material.density * pb.material.caliper * V * V, rc = pb.core.radius;
  rs_reel_result *res = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &res) == RS_OK);
  CHECK_LOG("rho t V^2 (N/m)", spin);
  CHECK_CLOSE(res->at_speed_core_pressure, (T - spin) / rc, 1e-14);
  CHECK_CLOSE(res->at_speed_sigma_theta[0], T / pb.material.caliper, 1e-3);
  CHECK_LOG("at rest: core pressure / (T0/r_c) - 1", res->core_pressure / (T / rc) - 1.0);
  CHECK_CLOSE(res->core_pressure, T / rc, 1e-3);
  rs_reel_result_destroy(&res);
}

/* A linear speed recipe with start = end is the constant speed (to round-off); a rising
 * speed presses less at the outside than the constant start speed. */
static void speed_recipe(void)
{
  rs_problem pb;
  paper_problem(&pb, 300, 350.0, 30.0);
  rs_reel_result *c = NULL, *l = NULL, *up = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &c) == RS_OK);
  pb.speed.law = RS_RECIPE_LINEAR;
  CHECK(rs_recipe_prepare(&pb.speed, pb.core.radius, pb.final_radius) == RS_OK);
  CHECK(rs_reel_wind(&pb, NULL, &l) == RS_OK);
  for (int j = 0; j < 300; ++j) { /* the linear law's interpolation may round differently */
    CHECK_CLOSE(l->sigma_r[j], c->sigma_r[j], 1e-12);
    CHECK_CLOSE(l->at_speed_sigma_theta[j], c->at_speed_sigma_theta[j], 1e-12);
  }
  pb.speed.start = 10.0;
  CHECK(rs_recipe_prepare(&pb.speed, pb.core.radius, pb.final_radius) == RS_OK);
  CHECK(rs_reel_wind(&pb, NULL, &up) == RS_OK);
  CHECK_LOG("core pressure at rest, 30 m/s (Pa)", c->core_pressure);
  CHECK_LOG("core pressure at rest, 10 -> 30 m/s (Pa)", up->core_pressure);
  CHECK_LT(c->core_pressure, up->core_pressure); /* slower early layers press harder */
  rs_reel_result_destroy(&c);
  rs_reel_result_destroy(&l);
  rs_reel_result_destroy(&up);
}

/* V = 0 with the effect on: bit for bit the roll without it. */
static void zero_speed(void)
{
  rs_problem pb;
  paper_problem(&pb, 300, 350.0, 0.0);
  rs_reel_result *on = NULL, *off = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &on) == RS_OK);
  pb.centrifugal = 0;
  CHECK(rs_reel_wind(&pb, NULL, &off) == RS_OK);
  const size_t sz = 300 * sizeof(double);
  CHECK(on->at_speed_sigma_r && !off->at_speed_sigma_r);
  CHECK(memcmp(on->sigma_r, off->sigma_r, sz) == 0);
  CHECK(memcmp(on->sigma_theta, off->sigma_theta, sz) == 0);
  CHECK(memcmp(on->at_speed_sigma_r, off->sigma_r, sz) == 0);
  CHECK(memcmp(on->at_speed_sigma_theta, off->sigma_theta, sz) == 0);
  CHECK(on->core_pressure == off->core_pressure);
  rs_reel_result_destroy(&on);
  rs_reel_result_destroy(&off);
}

/* The roll's slowing as it grows, applied at 256 checkpoints (the default) against every
 * layer: converges as the checkpoints multiply. */
static void updates_converge(void)
{
  const int n = 1200;
  double diff[3];
  const int ups[3] = {64, 256, 1024};
  rs_reel_result *ref = NULL;
  rs_problem pb;
  paper_problem(&pb, n, 350.0 - 800.0 * 70e-6 * 900.0, 0.0); /* T - rho t V^2, V = 30 m/s */
  pb.centrifugal = 0;
  CHECK(rs_reel_wind(&pb, NULL, &ref) == RS_OK);
  pb.centrifugal = 1;
  set_speed(&pb, 30.0);
  rs_reel_result *exact = NULL;
  CHECK(rs_reel_wind(&pb, NULL, &exact) == RS_OK); /* only to own the arrays */
  pb.centrifugal = 1;
  double base[1200], spin = 0.0;
  memcpy(base, ref->sigma_r, sizeof base);
  free(exact->at_speed_sigma_r), free(exact->at_speed_sigma_theta);
  memcpy(exact->sigma_r, base, sizeof base);
  memcpy(exact->sigma_theta, ref->sigma_theta, sizeof base);
  exact->core_pressure = ref->core_pressure;
  CHECK(rs_spin_wound(&pb, exact, n) == RS_OK);
  for (int j = 0; j < n; ++j) spin = fmax(spin, fabs(exact->sigma_r[j] - base[j]));
  CHECK_LOG("largest sigma_r change by the spin, every layer (Pa)", spin);
  CHECK(spin > 0.0);
  for (int u = 0; u < 3; ++u) {
    rs_reel_result *r = NULL;
    pb.centrifugal = 0;
    CHECK(rs_reel_wind(&pb, NULL, &r) == RS_OK);
    pb.centrifugal = 1;
    CHECK(rs_spin_wound(&pb, r, ups[u]) == RS_OK);
    diff[u] = 0.0;
    for (int j = 0; j < n; ++j) diff[u] = fmax(diff[u], fabs(r->sigma_r[j] - exact->sigma_r[j]));
    diff[u] /= spin;
    CHECK_LOG("checkpoints", ups[u]);
    CHECK_LOG("  max |sigma_r - every layer's| / spin change", diff[u]);
    rs_reel_result_destroy(&r);
  }
  CHECK_LT(diff[1], diff[0]);
  CHECK_LT(diff[2], diff[1]);
  CHECK_LT(diff[1], 0.05);
  rs_reel_result_destroy(&ref);
  rs_reel_result_destroy(&exact);
}

static rs_status load(const char *text, rs_scene **sc)
{
  return rs_scene_load_text("spin.yaml", text, strlen(text), 0, NULL, sc);
}

#define MAT "material: {caliper: 70e-6, E_theta: 3.5e9, density: 800, radial: {law: linear, E_r: 1e6}}\n" \
            "core: {radius: 0.0762}\n"

/* Hard cases: at and near T0 = rho t V^2 (22.4 N/m at 20 m/s). */
static void limit_refused(void)
{
  rs_scene *sc = NULL;
  /* a taper 350 -> 10 N/m crosses 22.4 N/m inside the roll: refused at load, radius named */
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: {law: linear, start: 350, end: 10}, speed: 20}\n"
                 "centrifugal: {}\n", &sc) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "winding.speed") && strstr(rs_error_message(), "at r = "));
  printf("  %s\n", rs_error_message());
  /* exactly at the limit: refused */
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 22.4, speed: 20}\ncentrifugal: true\n", &sc) ==
        RS_ERR_INPUT);
  /* the effect without its data */
  CHECK(load("material: {caliper: 70e-6, E_theta: 3.5e9, radial: {law: linear, E_r: 1e6}}\n"
             "core: {radius: 0.0762}\nwinding: {final_radius: 0.1, tension: 350, speed: 20}\n"
             "centrifugal: {}\n", &sc) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "material.density") != NULL);
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 350}\ncentrifugal: {}\n", &sc) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "winding.speed") != NULL);
  /* centrifugal: false is no effect; true is {} */
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 350, speed: 20}\ncentrifugal: false\n", &sc) ==
        RS_OK);
  CHECK(rs_scene_problem(sc)->centrifugal == 0 && rs_recipe_eval(&rs_scene_problem(sc)->speed, 0.09) == 20.0);
  rs_scene_destroy(&sc);
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 350, speed: 20}\ncentrifugal: true\n", &sc) ==
        RS_OK);
  CHECK(rs_scene_problem(sc)->centrifugal == 1);
  rs_scene_destroy(&sc);
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 350, speed: 20}\ncentrifugal: yes\n", &sc) ==
        RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "centrifugal") != NULL);
  /* the recipe forms: a speed rising 5 -> 20 m/s (the limit at the outside) and a table */
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 22.41, speed: {law: linear, start: 5, end: 20}}\n"
                 "centrifugal: {}\n", &sc) == RS_OK);
  rs_scene_destroy(&sc);
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 22.41, speed: {table: [[0.0762, 5], [0.09, 20.1]]}}\n"
                 "centrifugal: {}\n", &sc) == RS_ERR_INPUT);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), "winding.speed") && strstr(rs_error_message(), "at r = 0.08"));
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 350, speed: -1}\ncentrifugal: {}\n", &sc) ==
        RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "m/s") != NULL);
  /* just above the limit: winds, finite, the outer layers nearly unloaded at speed */
  CHECK(load(MAT "winding: {final_radius: 0.1, tension: 22.41, speed: 20}\ncentrifugal: {}\n", &sc) ==
        RS_OK);
  rs_reel_result *res = NULL;
  CHECK(rs_reel_wind(rs_scene_problem(sc), NULL, &res) == RS_OK);
  for (int j = 0; j < res->n_layers; ++j) {
    CHECK_FINITE(res->sigma_r[j]);
    CHECK_FINITE(res->at_speed_sigma_r[j]);
    CHECK_FINITE(res->sigma_theta[j]);
    CHECK_FINITE(res->at_speed_sigma_theta[j]);
  }
  CHECK_FINITE(res->core_pressure);
  CHECK_LOG("core pressure at speed, T0 = 1.0004 rho t V^2 (Pa)", res->at_speed_core_pressure);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
  /* mid-run (the reel's own check, as with a nip's T0): stops with the finished layers */
  rs_problem pb;
  paper_problem(&pb, 400, 350.0, 20.0);
  pb.tension.law = RS_RECIPE_LINEAR;
  pb.tension.end = 10.0;
  CHECK(rs_recipe_prepare(&pb.tension, pb.core.radius, pb.final_radius) == RS_OK);
  CHECK(rs_reel_wind(&pb, NULL, &res) == RS_ERR_SOLVER);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), "r = ") != NULL);
  CHECK(res->n_layers > 300 && res->n_layers < 400);
  for (int j = 0; j < res->n_layers; ++j) CHECK_FINITE(res->at_speed_sigma_r[j]);
  rs_reel_result_destroy(&res);
}

static const check_case cases[] = {{"annulus_closed_form", annulus_closed_form},
                                   {"one_layer_rigid", one_layer_rigid},
                                   {"zero_speed", zero_speed},
                                   {"speed_recipe", speed_recipe},
                                   {"updates_converge", updates_converge},
                                   {"limit_refused", limit_refused}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
