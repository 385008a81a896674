/* Entrained air (docs/roll-model.md, "Entrained air"; docs/validation.md, "Speed
 * effects"): the film laws against their closed forms and the foil bearing's constant, the
 * roughness cut-off, the isothermal air in series with the stack, and the TopWeb example. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/material.h"
#include "roll_helpers.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

/* The foil bearing's constant is the curvature the film's inlet meniscus tends to: with
 * h = h0 H and x = h0 (T / (6 mu U))^(1/3) xi, Reynolds' equation and the tensioned foil give
 * H''' = (H - 1) / H^3, and far from the wrap H'' -> K with h0 = K R (6 mu U / T)^(2/3)
 * (Bretherton 1961; Landau & Levich 1942). RK4 from the flat film, H = 1 + d e^xi. */
static double foil_constant(double xi_end)
{
  double y[3] = {1.0 + 1e-6, 1e-6, 1e-6};
  const double h = 1e-3;
  for (long i = 0; i < (long)(xi_end / h); ++i) {
    double k[4][3], z[3];
    for (int s = 0; s < 4; ++s) {
      const double c = s == 0 ? 0.0 : s == 3 ? 1.0 : 0.5;
      for (int q = 0; q < 3; ++q) z[q] = y[q] + (s ? c * h * k[s - 1][q] : 0.0);
      k[s][0] = z[1];
      k[s][1] = z[2];
      k[s][2] = (z[0] - 1.0) / (z[0] * z[0] * z[0]);
    }
    for (int q = 0; q < 3; ++q) y[q] += h / 6.0 * (k[0][q] + 2 * k[1][q] + 2 * k[2][q] + k[3][q]);
  }
  return y[2];
}

static void film_law(void)
{
  const double K = foil_constant(200.0);
  CHECK_LOG("foil bearing constant H''(inf), xi = 200", K);
  CHECK_CLOSE(K, 0.643, 1e-3);
  /* the law as coded against its closed form, and its scalings */
  const double mu = 1.8e-5, R = 0.2, U = 2.0 * 50.0 / 60.0, T = 150.0;
  const double h = rs_air_foil_film(R, U, T, mu), ref = 0.643 * R * pow(6.0 * mu * U / T, 2.0 / 3.0);
  CHECK_LOG("h0, R = 0.2 m, U = 1.667 m/s, T = 150 N/m (m)", h);
  CHECK_CLOSE(h, ref, 1e-14);
  CHECK_CLOSE(rs_air_foil_film(2.0 * R, U, T, mu), 2.0 * h, 1e-14);
  CHECK_CLOSE(rs_air_foil_film(R, 8.0 * U, T, mu), 4.0 * h, 1e-14);
  CHECK_CLOSE(rs_air_foil_film(R, U, 8.0 * T, mu), 0.25 * h, 1e-14);
  CHECK(rs_air_foil_film(R, 0.0, T, mu) == 0.0);
  /* the nip's film: Martin's closed form, R_eq the reduced radius */
  const double hn = rs_air_nip_film(0.3, 0.1, 10.0, 2000.0, mu);
  CHECK_CLOSE(hn, 4.9 * mu * 10.0 * 0.075 / 2000.0, 1e-14);
  CHECK(rs_air_nip_film(0.3, 0.1, 10.0, 0.0, mu) == INFINITY);
}

static void roughness_cutoff(void)
{
  const double s = 0.5e-6;
  CHECK(rs_air_surviving_film(1.4e-6, s, 3.0) == 0.0);
  CHECK(rs_air_surviving_film(1.5e-6, s, 3.0) == 0.0); /* at the cut-off: nothing */
  CHECK_CLOSE(rs_air_surviving_film(5.0e-6, s, 3.0), 3.5e-6, 1e-15);
  CHECK(rs_air_surviving_film(5.0e-6, 0.0, 3.0) == 5.0e-6);
  /* continuous across the cut-off */
  CHECK_LT(rs_air_surviving_film(1.5e-6 * (1.0 + 1e-12), s, 3.0), 1e-17);
}

/* h p = const for the trapped air; the series law's film part is -dh/dP */
static void compression_identity(void)
{
  const double pa = 101325.0, h = 20e-6, t = 70e-6, Er = 2e6;
  const double Ps[] = {10.0, 1e3, 1e5, 3e6}; /* > the difference step: P < 0 counts as 0 */
  for (int i = 0; i < 4; ++i) {
    const double hc = rs_air_compressed_film(h, Ps[i], pa);
    CHECK_CLOSE(hc * (pa + Ps[i]), h * pa, 1e-15);
    const double dP = 1e-6 * (pa + Ps[i]);
    const double dh = (rs_air_compressed_film(h, Ps[i] + dP, pa) -
                       rs_air_compressed_film(h, Ps[i] - dP, pa)) / (2.0 * dP);
    const double E = rs_air_series_modulus(Er, t, h, Ps[i], pa);
    CHECK_CLOSE(t / E - t / Er, -dh, 1e-7);
  }
  CHECK(rs_air_compressed_film(h, -5e4, pa) == rs_air_compressed_film(h, 0.0, pa)); /* P < 0: 0 */
  CHECK_CLOSE(rs_air_compressed_film(h, 0.0, pa), h, 1e-15);
  /* limits: no film is the stack law itself, bit for bit; a vanishing film tends to it */
  CHECK(rs_air_series_modulus(Er, t, 0.0, 1e5, pa) == Er);
  CHECK_CLOSE(rs_air_series_modulus(Er, t, 1e-15, 0.0, pa), Er, 1e-6);
  /* a film much softer than the stack: t p_a / h */
  CHECK_CLOSE(rs_air_series_modulus(1e30, t, h, 0.0, pa), t * pa / h, 1e-12);
}

/* The engine with films: a film whose compliance h p_a / (p_a + P)^2 is constant (p_a far
 * above every pressure) is, in series with a linear stack E_r, the linear stack
 * t / (t / E_r + c): with c = t / E_r the roll with films is the roll of E_r / 2. */
static void roll_series(void)
{
  const int n = 300;
  const double rc = 0.0762, t = 70e-6, Et = 3.5e9, Er = 2e6, pa = 1e15, h = (t / Er) * pa;
  rs_roll_params a = linear_params(rc, t, Et, Er, INFINITY, n);
  rs_roll_params b = linear_params(rc, t, Et, 0.5 * Er, INFINITY, n);
  double *film = malloc((size_t)(n + 1) * sizeof *film);
  CHECK(film != NULL);
  for (int j = 0; j <= n; ++j) film[j] = h;
  a.air_film = film;
  a.air_pressure = pa;
  rs_roll *ra = wind(&a, n, 1, 350.0), *rb = wind(&b, n, 1, 350.0);
  CHECK(ra && rb);
  const double *sa = rs_roll_sigma_r(ra), *sb = rs_roll_sigma_r(rb);
  double err = 0.0, scale = 0.0;
  for (int j = 0; j < n; ++j) {
    err = fmax(err, fabs(sa[j] - sb[j]));
    scale = fmax(scale, fabs(sb[j]));
  }
  CHECK_LOG("max |sigma_r(films) - sigma_r(E_r / 2)| / max |sigma_r|", err / scale);
  CHECK_LT(err / scale, 1e-7);
  CHECK_CLOSE(rs_roll_core_pressure(ra), rs_roll_core_pressure(rb), 1e-7);
  rs_roll_destroy(&ra);
  rs_roll_destroy(&rb);
  free(film);
}

static rs_scene *load(const char *text, int nset, const char **sets)
{
  rs_scene *sc = NULL;
  rs_status st = rs_scene_load_text("air.yaml", text, strlen(text), nset, sets, &sc);
  if (st) printf("  %s\n", rs_error_message());
  CHECK(st == RS_OK);
  return sc;
}

#define MAT "material: {caliper: 70e-6, E_theta: 3.5e9, density: 800, radial: {law: pfeiffer, K1: 5e3, K2: 60}}\n" \
            "core: {radius: 0.0762}\n"

/* A roughness no film clears: every film is cut, the stresses and layers are the reel's
 * without air bit for bit, and the radii agree to round-off. */
static void all_cut_is_no_air(void)
{
  rs_scene *a = load(MAT "winding: {final_radius: 0.12, tension: 350, speed: 10}\nair: {roughness: 1e-3}\n", 0, NULL);
  rs_scene *b = load(MAT "winding: {final_radius: 0.12, tension: 350, speed: 10}\n", 0, NULL);
  rs_reel_result *ra = NULL, *rb = NULL;
  CHECK(rs_scene_wind(a, NULL, &ra) == RS_OK);
  CHECK(rs_scene_wind(b, NULL, &rb) == RS_OK);
  CHECK(ra->n_layers == rb->n_layers);
  const size_t sz = (size_t)rb->n_layers * sizeof(double);
  CHECK(memcmp(ra->sigma_r, rb->sigma_r, sz) == 0);
  CHECK(memcmp(ra->sigma_theta, rb->sigma_theta, sz) == 0);
  CHECK(ra->core_pressure == rb->core_pressure);
  for (int j = 0; j < ra->n_layers; ++j) CHECK(ra->air_film[j] == 0.0);
  CHECK_CLOSE(ra->radius[ra->n_layers - 1], rb->radius[rb->n_layers - 1], 1e-13);
  CHECK(rb->air_film == NULL);
  rs_reel_result_destroy(&ra);
  rs_reel_result_destroy(&rb);
  rs_scene_destroy(&a);
  rs_scene_destroy(&b);
}

/* The reel with air: radius = r_c + sum (t + h_j(P_j)), each film h_j(P_j) (p_a + P_j) =
 * h_j p_a, the roll stops at its size, softer (lower pressure) and wider than without. */
static void reel_identities(void)
{
  rs_scene *a = load(MAT "winding: {final_radius: 0.15, tension: 350, speed: 20}\n"
                         "air: {roughness: 0.5e-6}\n", 0, NULL);
  rs_scene *b = load(MAT "winding: {final_radius: 0.15, tension: 350, speed: 20}\n", 0, NULL);
  rs_reel_result *ra = NULL, *rb = NULL;
  CHECK(rs_scene_wind(a, NULL, &ra) == RS_OK);
  CHECK(rs_scene_wind(b, NULL, &rb) == RS_OK);
  const rs_problem *p = rs_scene_problem(a);
  const double t = p->material.caliper, pa = p->air.pressure;
  const int n = ra->n_layers;
  double r = ra->core_radius, hmax = 0.0;
  for (int j = 0; j < n; ++j) {
    const double P = j ? -ra->sigma_r[j - 1] : ra->core_pressure;
    CHECK_CLOSE(ra->air_film[j] * (pa + fmax(P, 0.0)), ra->air_film_entrained[j] * pa, 1e-14);
    CHECK(ra->air_film[j] <= ra->air_film_entrained[j]);
    r += t + ra->air_film[j];
    hmax = fmax(hmax, ra->air_film_entrained[j]);
  }
  CHECK_CLOSE(ra->radius[n - 1], r, 1e-13);
  CHECK_LOG("layers with air / without", (double)n / rb->n_layers);
  CHECK_LOG("outer radius with air (m)", ra->radius[n - 1]);
  CHECK_LOG("core pressure with air / without", ra->core_pressure / rb->core_pressure);
  CHECK(n < rb->n_layers);
  CHECK_LT(fabs(ra->radius[n - 1] - 0.15), 0.5 * (t + hmax) + 1e-12);
  CHECK_LT(ra->core_pressure, rb->core_pressure);
  CHECK(rs_reel_result_air_film(ra, NULL) == ra->air_film);
  CHECK(!isnan(rs_reel_result_air_wound_length(ra)) && isnan(rs_reel_result_air_wound_length(rb)));
  CHECK(rs_reel_result_air_film(rb, NULL) == NULL);
  rs_reel_result_destroy(&ra);
  rs_reel_result_destroy(&rb);
  rs_scene_destroy(&a);
  rs_scene_destroy(&b);
}

/* The foil law alone, no compression: the roll of L metres whose every turn adds t + h0(R)
 * (R the radius beneath), stopped at the turn nearest L; the diameter (m). */
static double foil_only_diameter(double rc, double t, double L, double mu, double U, double T)
{
  double R = rc, wound = 0.0;
  for (;;) {
    const double h = rs_air_foil_film(R, U, T, mu), turn = 2.0 * 3.14159265358979323846 * (R + h + 0.5 * t);
    if (wound > 0.0 && wound + 0.5 * turn > L) return 2.0 * R;
    wound += turn;
    R += h + t;
  }
}

static double topweb_diameter(const char *set, rs_reel_result **out)
{
  char path[4096];
  snprintf(path, sizeof path, "%s/cases/pet-topweb-air.yaml", RS_ROOT_DIR);
  rs_scene *sc = NULL;
  const char *sets[1] = {set};
  CHECK(rs_scene_load(path, set ? 1 : 0, sets, &sc) == RS_OK);
  rs_reel_result *res = NULL;
  CHECK(rs_scene_wind(sc, NULL, &res) == RS_OK);
  rs_reel_sizes z;
  rs_reel_sizes_of(res, rs_scene_problem(sc), &z);
  CHECK_CLOSE(z.wound_length, 3000.0, 1e-3); /* within half a turn */
  rs_scene_destroy(&sc);
  *out = res;
  return z.diameter;
}

/* TopWeb (Rheologic's roll-winding example): 636 mm without air, 660.7 mm with it. */
static void topweb(void)
{
  rs_reel_result *res = NULL;
  const double D = topweb_diameter(NULL, &res);
  const double V = 50.0 / 60.0, D_foil = foil_only_diameter(0.075, 100e-6, 3000.0, 1.8e-5, 2.0 * V, 150.0);
  CHECK_LOG("diameter with air, U = 2V (mm)", D * 1e3);
  CHECK_LOG("foil law alone, uncompressed, U = 2V (mm)", D_foil * 1e3);
  CHECK_LOG("against TopWeb's 660.7 mm", D / 0.6607 - 1.0);
  /* the trapped air compresses: below the foil law alone, well above the roll without air */
  CHECK_LT(D, D_foil);
  CHECK_LT(0.650, D);
  CHECK_LT(fabs(D / 0.6607 - 1.0), 0.03);
  rs_reel_result_destroy(&res);
  /* TopWeb's figure (and the 667 mm for the foil law alone) count one surface's
   * speed, U = V: air.moving_surfaces = 1 */
  const double D1 = topweb_diameter("air.moving_surfaces=1", &res);
  const double D1_foil = foil_only_diameter(0.075, 100e-6, 3000.0, 1.8e-5, V, 150.0);
  CHECK_LOG("diameter with air, U = V (mm)", D1 * 1e3);
  CHECK_LOG("foil law alone, uncompressed, U = V (mm)", D1_foil * 1e3);
  CHECK_LOG("against TopWeb's 660.7 mm", D1 / 0.6607 - 1.0);
  CHECK_LT(fabs(D1 / 0.6607 - 1.0), 0.02);
  CHECK_LT(fabs(D1_foil / 0.667 - 1.0), 0.002);
  rs_reel_result_destroy(&res);
}

static void refused(void)
{
  rs_scene *sc = NULL;
  const char *t1 = MAT "winding: {final_radius: 0.12, tension: 350, speed: 10}\nair: {}\n";
  CHECK(rs_scene_load_text("air.yaml", t1, strlen(t1), 0, NULL, &sc) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "air.roughness") != NULL);
  const char *t2 = MAT "winding: {final_radius: 0.12, tension: 350}\nair: {roughness: 1e-6}\n";
  CHECK(rs_scene_load_text("air.yaml", t2, strlen(t2), 0, NULL, &sc) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "winding.speed") != NULL);
  const char *t_ms = MAT "winding: {final_radius: 0.12, tension: 350, speed: 10}\nair: {roughness: 1e-6, moving_surfaces: 3}\n";
  CHECK(rs_scene_load_text("air.yaml", t_ms, strlen(t_ms), 0, NULL, &sc) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "air.moving_surfaces") != NULL);
  const char *t3 = "material: {caliper: 70e-6, E_theta: 3.5e9, roughness: 2e-7, radial: {law: linear, E_r: 1e6}}\n"
                   "core: {radius: 0.0762}\nwinding: {final_radius: 0.1, tension: 350, speed: 10}\nair: true\n";
  sc = load(t3, 0, NULL);
  CHECK(rs_scene_problem(sc)->air.on == 1 && rs_scene_problem(sc)->air.roughness == 2e-7);
  CHECK(rs_scene_problem(sc)->air.viscosity == 1.8e-5 && rs_scene_problem(sc)->air.pressure == 101325.0);
  rs_scene_destroy(&sc);
  const char *t4 = MAT "winding: {final_radius: 0.12, tension: 350, speed: 10}\nair: false\n";
  sc = load(t4, 0, NULL);
  CHECK(rs_scene_problem(sc)->air.on == 0);
  rs_scene_destroy(&sc);
  const char *t5 = MAT "winding: {final_radius: 0.12, tension: 350, speed: 10}\nnip: {model: friction, load: 1000, friction: {roll: 0.2}}\n"
                       "air: {roughness: 1e-6}\n";
  CHECK(rs_scene_load_text("air.yaml", t5, strlen(t5), 0, NULL, &sc) == RS_ERR_INPUT);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), "air.nip_radius") != NULL);
}

/* ---- hard cases: very high speed, a very smooth film, a heavy nip ---------------------- */
static void check_sane(const rs_reel_result *r, const rs_reel_result *ref)
{
  for (int j = 0; j < r->n_layers; ++j) {
    CHECK_FINITE(r->sigma_r[j]);
    CHECK_FINITE(r->sigma_theta[j]);
    CHECK(r->air_film[j] >= 0.0 && r->air_film[j] <= r->air_film_entrained[j]);
    CHECK(r->sigma_r[j] <= 0.0);
  }
  CHECK_FINITE(r->core_pressure);
  CHECK(r->core_pressure > 0.0 && r->core_pressure <= ref->core_pressure);
  CHECK(r->radius[r->n_layers - 1] > 0.0);
}

static void hard_fast(void)
{
  rs_scene *a = load(MAT "winding: {final_radius: 0.2, tension: 350, speed: 40}\ncentrifugal: {}\n"
                         "air: {roughness: 0.5e-6}\n", 0, NULL);
  rs_scene *b = load(MAT "winding: {final_radius: 0.2, tension: 350, speed: 40}\ncentrifugal: {}\n", 0, NULL);
  rs_reel_result *ra = NULL, *rb = NULL;
  CHECK(rs_scene_wind(a, NULL, &ra) == RS_OK);
  CHECK(rs_scene_wind(b, NULL, &rb) == RS_OK);
  check_sane(ra, rb);
  CHECK(ra->at_speed_sigma_r != NULL);
  for (int j = 0; j < ra->n_layers; ++j) CHECK_FINITE(ra->at_speed_sigma_r[j]);
  CHECK_LOG("40 m/s: layers with air / without", (double)ra->n_layers / rb->n_layers);
  CHECK_LOG("40 m/s: largest film as wound (m)", ra->air_film_entrained[ra->n_layers - 1]);
  CHECK(ra->n_layers < rb->n_layers);
  /* the reel stops when the roll as wound reaches 0.2 m; the last layers' own pressure then
   * compresses the films beneath (here about 1 % of the air) */
  CHECK_LOG("40 m/s: final radius - 0.2 m", ra->radius[ra->n_layers - 1] - 0.2);
  CHECK_LT(fabs(ra->radius[ra->n_layers - 1] - 0.2), 0.01 * (0.2 - 0.0762));
  rs_reel_result_destroy(&ra);
  rs_reel_result_destroy(&rb);
  rs_scene_destroy(&a);
  rs_scene_destroy(&b);
}

static void hard_smooth(void)
{
  /* roughness 0: the whole foil-bearing film stays; films thicker than the web */
  rs_scene *a = load(MAT "winding: {final_radius: 0.3, tension: 50, speed: 30}\nair: {roughness: 0}\n", 0, NULL);
  rs_scene *b = load(MAT "winding: {final_radius: 0.3, tension: 50, speed: 30}\n", 0, NULL);
  rs_reel_result *ra = NULL, *rb = NULL;
  CHECK(rs_scene_wind(a, NULL, &ra) == RS_OK);
  CHECK(rs_scene_wind(b, NULL, &rb) == RS_OK);
  check_sane(ra, rb);
  const int n = ra->n_layers;
  const rs_problem *p = rs_scene_problem(a);
  const double R = ra->radius[n - 2];
  /* R: the radius beneath in the finished roll, its films compressed a little more than
   * when the last layer went on */
  CHECK_CLOSE(ra->air_film_entrained[n - 1], rs_air_foil_film(R, 60.0, 50.0, 1.8e-5), 1e-4);
  CHECK_LOG("smooth: outer film / caliper", ra->air_film_entrained[n - 1] / p->material.caliper);
  CHECK_LOG("smooth: layers with air / without", (double)n / rb->n_layers);
  CHECK(ra->air_film_entrained[n - 1] > p->material.caliper);
  rs_reel_result_destroy(&ra);
  rs_reel_result_destroy(&rb);
  rs_scene_destroy(&a);
  rs_scene_destroy(&b);
}

static void hard_nip(void)
{
  /* a heavy nip lets through 4.9 mu V R_eq / w, far below 3 sigma: no air, the reel as
   * without air to round-off; a light one lets some through, less than the foil film */
  const char *heavy = MAT "winding: {final_radius: 0.15, tension: 350, speed: 20}\n"
                          "nip: {model: friction, load: 5000, friction: {roll: 0.2}}\n";
  char text[1024];
  snprintf(text, sizeof text, "%sair: {roughness: 0.3e-6, nip_radius: 0.1}\n", heavy);
  rs_scene *a = load(text, 0, NULL), *b = load(heavy, 0, NULL);
  rs_reel_result *ra = NULL, *rb = NULL;
  CHECK(rs_scene_wind(a, NULL, &ra) == RS_OK);
  CHECK(rs_scene_wind(b, NULL, &rb) == RS_OK);
  check_sane(ra, rb);
  CHECK(ra->n_layers == rb->n_layers);
  for (int j = 0; j < ra->n_layers; ++j) CHECK(ra->air_film[j] == 0.0);
  CHECK_CLOSE(ra->core_pressure, rb->core_pressure, 1e-9);
  CHECK_CLOSE(ra->radius[ra->n_layers - 1], rb->radius[rb->n_layers - 1], 1e-12);
  rs_reel_result_destroy(&ra);
  rs_scene_destroy(&a);
  const char *light = MAT "winding: {final_radius: 0.15, tension: 350, speed: 20}\n"
                          "nip: {model: friction, load: 20, friction: {roll: 0.2}}\n"
                          "air: {roughness: 0.01e-6, nip_radius: 0.1}\n";
  a = load(light, 0, NULL);
  CHECK(rs_scene_wind(a, NULL, &ra) == RS_OK);
  check_sane(ra, rb);
  const int n = ra->n_layers;
  const double R = ra->radius[n - 2], Req = R * 0.1 / (R + 0.1);
  const double want = 4.9 * 1.8e-5 * 20.0 * Req / 20.0 - 0.03e-6;
  CHECK_LOG("light nip: outer film as wound (m)", ra->air_film_entrained[n - 1]);
  CHECK_CLOSE(ra->air_film_entrained[n - 1], want, 1e-4); /* R as in hard_smooth */
  CHECK_LT(ra->air_film_entrained[n - 1], rs_air_foil_film(R, 40.0, 350.0, 1.8e-5));
  rs_reel_result_destroy(&ra);
  rs_reel_result_destroy(&rb);
  rs_scene_destroy(&a);
  rs_scene_destroy(&b);
}

/* a web tension of 0: past the roll's size (a taper's end) the reel has stopped; before it
 * (a table dropping to 0) the run stops there, exit 3, keeping the finished layers */
static void hard_slack(void)
{
  rs_scene *a = load(MAT "winding: {final_radius: 0.1, tension: {law: linear, start: 350, end: 0}, speed: 20}\n"
                         "air: {roughness: 0.5e-6}\n", 0, NULL);
  rs_reel_result *r = NULL;
  CHECK(rs_scene_wind(a, NULL, &r) == RS_OK);
  CHECK_LOG("taper to 0: layers", r->n_layers);
  CHECK_LOG("taper to 0: outer radius (m)", r->radius[r->n_layers - 1]);
  CHECK_LT(fabs(r->radius[r->n_layers - 1] - 0.1), 1e-3);
  for (int j = 0; j < r->n_layers; ++j) CHECK_FINITE(r->air_film[j]);
  rs_reel_result_destroy(&r);
  rs_scene_destroy(&a);
  a = load(MAT "winding: {final_radius: 0.1, tension: {table: [[0.0762, 350], [0.09, 0], [0.1, 0]]}, "
               "speed: 20}\nair: {roughness: 0.5e-6}\n", 0, NULL);
  CHECK(rs_scene_wind(a, NULL, &r) == RS_ERR_SOLVER);
  printf("  %s\n", rs_error_message());
  CHECK(strstr(rs_error_message(), "slack web") != NULL);
  CHECK(r->n_layers > 100 && r->air_film != NULL);
  for (int j = 0; j < r->n_layers; ++j) CHECK_FINITE(r->air_film[j]);
  rs_reel_result_destroy(&r);
  rs_scene_destroy(&a);
}

static const check_case cases[] = {{"film_law", film_law},
                                   {"roughness_cutoff", roughness_cutoff},
                                   {"compression_identity", compression_identity},
                                   {"roll_series", roll_series},
                                   {"all_cut_is_no_air", all_cut_is_no_air},
                                   {"reel_identities", reel_identities},
                                   {"topweb", topweb},
                                   {"refused", refused},
                                   {"hard_fast", hard_fast},
                                   {"hard_smooth", hard_smooth},
                                   {"hard_nip", hard_nip},
                                   {"hard_slack", hard_slack}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
