/* The winding nip contact solver (seed paper eqs. (12)-(22)) against identities, limits
 * and independent solutions: global equilibrium (20)-(21), the friction limits, the
 * frictionless cylinder contact when the sheet vanishes (Hertz and rs_contact_frictionless),
 * the NIT bound |T0 - Ti| <= mu+ P, no checkerboard, convergence in M, bad input. */
#include <stdlib.h>

#include "check.h"
#include "reelsim/nip_contact.h"

#define PI 3.14159265358979323846

typedef struct setup {
  double E_r, E_t, G, nu;   /* roll */
  double R, R0, Rd, Rd0;    /* roll and drum radii */
  double mu_roll, mu_drum;
  rs_winder_kind winder;
  double share;
  int M;
  double caliper, E_zd;     /* sheet */
} setup;

/* a paper roll (soft radially) on a steel drum, 100 um sheet */
static setup paper_roll(void)
{
  setup s = {3e7, 5e9, 3e7, 0.01, 0.5, 0.1, 0.3, 0.05, 0.19, 0.35, RS_WINDER_CENTER, 0.5, 64, 100e-6, 3e7};
  return s;
}

static rs_nip_contact *make(const setup *s)
{
  rs_nip_contact_config c = {0};
  CHECK(rs_ortho_isotropic(2.1e11, 0.3, 1, &c.drum) == RS_OK);
  c.drum_radius = s->Rd;
  c.drum_core_radius = s->Rd0;
  rs_sheet_constants k = {s->caliper, s->E_t, s->E_zd, s->E_t, s->nu, 0.3, s->nu, s->G, 1};
  CHECK(rs_sheet_from_constants(&k, &c.sheet) == RS_OK);
  c.mu_roll = s->mu_roll;
  c.mu_drum = s->mu_drum;
  c.winder = s->winder;
  c.torque_share = s->share;
  c.nodes = s->M;
  rs_nip_contact *nc = NULL;
  if (rs_nip_contact_create(&c, &nc) != RS_OK) {
    fprintf(stderr, "create: %s\n", rs_error_message());
    return NULL;
  }
  rs_ortho_engineering e = {s->E_r, s->E_t, s->E_t, s->nu * s->E_r / s->E_t, s->nu * s->E_r / s->E_t, 0.3, s->G};
  rs_ortho ro;
  CHECK(rs_ortho_from_engineering(&e, 1, &ro) == RS_OK);
  CHECK(rs_nip_contact_set_roll(nc, &ro, s->R, s->R0) == RS_OK);
  return nc;
}

static int solve(const setup *s, double P, double Ti, rs_nip_solution *out)
{
  rs_nip_contact *nc = make(s);
  if (!nc) return 0;
  rs_status st = rs_nip_contact_solve_load(nc, P, Ti, out);
  if (st) fprintf(stderr, "solve: %s\n", rs_error_message());
  rs_nip_contact_destroy(&nc);
  return st == RS_OK;
}

static double integral(const double *f, int n, double dx)
{
  double s = 0;
  for (int i = 0; i < n; ++i) s += f[i] * dx;
  return s;
}

static double winder_share(const setup *s)
{
  return s->winder == RS_WINDER_CENTER ? 1.0 : s->winder == RS_WINDER_SURFACE ? 0.0 : s->share;
}

/* eqs. (20)-(21) at the converged state, to round-off */
static void check_equilibrium(const setup *s, double P, double Ti)
{
  rs_nip_solution r = {0};
  CHECK(solve(s, P, Ti, &r));
  if (!r.M) return;
  int E = r.M - 1;
  double Iu = integral(r.shear_upper, E, r.dx), Il = integral(r.shear_lower, E, r.dx);
  double Ip = integral(r.pressure, r.M, r.dx);
  CHECK_LOG("T0 (N/m)", r.T0);
  CHECK_LOG("a (m)", r.a);
  CHECK_LOG("condition number", r.condition_number);
  CHECK_ABS(Iu - Il + r.T0, Ti, 1e-12 * (Ti + P));          /* sheet */
  CHECK_ABS(Iu + r.T0, winder_share(s) * Ti, 1e-12 * (Ti + P)); /* M1/R1 */
  CHECK_ABS(-Il, (1 - winder_share(s)) * Ti, 1e-12 * (Ti + P)); /* M2/R2 */
  CHECK_CLOSE(Ip, r.load, 1e-14);                            /* (21) */
  CHECK_CLOSE(r.load, P, 2e-9);
  CHECK(r.dissipation >= -1e-12 * fabs(r.dissipation) - 1e-30);
  CHECK(r.pressure[0] == 0 && r.pressure[r.M - 1] == 0);
  rs_nip_solution_free(&r);
}

static void equilibrium_center(void)
{
  setup s = paper_roll();
  check_equilibrium(&s, 1750, 350);
}
static void equilibrium_surface(void)
{
  setup s = paper_roll();
  s.winder = RS_WINDER_SURFACE;
  check_equilibrium(&s, 1750, 350);
}
static void equilibrium_center_surface(void)
{
  setup s = paper_roll();
  s.winder = RS_WINDER_CENTER_SURFACE;
  s.share = 0.5;
  check_equilibrium(&s, 3000, 350);
}

/* mu -> 0, center winding: no shear anywhere and T0 = Ti exactly */
static void frictionless_center(void)
{
  setup s = paper_roll();
  s.mu_roll = s.mu_drum = 0;
  rs_nip_solution r = {0};
  CHECK(solve(&s, 1750, 350, &r));
  double qmax = 0;
  for (int e = 0; e < r.M - 1; ++e) qmax = fmax(qmax, fmax(fabs(r.shear_upper[e]), fabs(r.shear_lower[e])));
  CHECK_LOG("T0 - Ti", r.T0 - 350);
  CHECK_ABS(r.T0, 350, 1e-12 * 350);
  CHECK(qmax == 0);
  rs_nip_solution_free(&r);
}

/* Large mu: full stick (no element slips). The full-stick shear is singular at the nip
 * edges (where p -> 0), so with mu = 50 the edge elements still slip; mu = 1e3 sticks
 * everywhere at M = 64. */
static void large_mu_full_stick(void)
{
  setup s = paper_roll();
  s.mu_roll = s.mu_drum = 1e3;
  rs_nip_solution r = {0};
  CHECK(solve(&s, 1750, 350, &r));
  int nslip = 0;
  for (int e = 0; e < r.M - 1; ++e) nslip += r.slip_upper[e] + r.slip_lower[e];
  CHECK_LOG("slipping elements", nslip);
  CHECK_LOG("NIT (N/m)", r.T0 - r.Ti);
  CHECK(nslip == 0);
  rs_nip_solution_free(&r);
}

/* every slip element carries |q| = mu pbar, every stick element |q| <= mu pbar, with pbar
 * the element mean (p_e + p_{e+1})/2 of the hat pressure; slip opposes the friction. */
static void check_friction_law(const rs_nip_solution *r, double mu_u, double mu_l, int *nslip_u,
                               int *nstick_u, int *nslip_l, int *nstick_l)
{
  *nslip_u = *nstick_u = *nslip_l = *nstick_l = 0;
  double pmax = 0;
  for (int i = 0; i < r->M; ++i) pmax = fmax(pmax, r->pressure[i]);
  for (int e = 0; e < r->M - 1; ++e) {
    double pb = 0.5 * (r->pressure[e] + r->pressure[e + 1]);
    /* friction on the cylinders: -tau+ (roll) and +tau- (drum) */
    double q[2] = {-r->shear_upper[e], r->shear_lower[e]}, mu[2] = {mu_u, mu_l};
    double srate[2] = {r->slip_rate_upper[e], r->slip_rate_lower[e]};
    unsigned char sl[2] = {r->slip_upper[e], r->slip_lower[e]};
    for (int k = 0; k < 2; ++k) {
      if (sl[k]) {
        CHECK_ABS(fabs(q[k]), mu[k] * pb, 1e-10 * mu[k] * pmax);
        CHECK(q[k] * srate[k] >= 0); /* dissipation >= 0 element by element */
        ++*(k ? nslip_l : nslip_u);
      } else {
        CHECK(fabs(q[k]) <= mu[k] * pb * (1 + 1e-7) + 1e-12 * mu[k] * pmax);
        ++*(k ? nstick_l : nstick_u);
      }
    }
  }
}

/* Partial slip on both contacts (stiffer roll, higher load): the friction law holds point
 * by point; the stick zones lie at the entry (leading edge, Carter 1926) and the slip
 * zones reach the exit, where the sheet leaves with T0. */
static void friction_law_and_slip_zones(void)
{
  setup s = paper_roll();
  s.E_r = 3e8;
  s.G = 3e8;
  s.E_zd = 3e8;
  s.mu_roll = 0.5;
  rs_nip_solution r = {0};
  CHECK(solve(&s, 6000, 350, &r));
  int su, tu, sl, tl;
  check_friction_law(&r, s.mu_roll, s.mu_drum, &su, &tu, &sl, &tl);
  CHECK_LOG("upper slip / stick elements", su * 1000 + tu);
  CHECK_LOG("lower slip / stick elements", sl * 1000 + tl);
  int E = r.M - 1;
  for (int k = 0; k < 2; ++k) {
    const unsigned char *f = k ? r.slip_lower : r.slip_upper;
    int st = k ? tl : tu, sp = k ? sl : su;
    if (st == 0 || sp == 0) continue;
    /* one stick zone, and the last element (exit) slips */
    int zones = 0;
    for (int e = 0; e < E; ++e) zones += !f[e] && (e == 0 || f[e - 1]);
    CHECK(zones == 1);
    CHECK(f[E - 1] == 1);
  }
  CHECK(tu > 0 && su > 0); /* both kinds present on the roll side: the case tests something */
  rs_nip_solution_free(&r);
}

/* A sheet of vanishing thickness and compliance, no friction: the pressure is the
 * frictionless two-cylinder contact of the cylinder module (same discretisation, to
 * round-off) and, for nearly solid isotropic cylinders, Hertz (Johnson 1985). */
static void thin_sheet_frictionless(void)
{
  const int M = 81;
  rs_nip_contact_config c = {0};
  CHECK(rs_ortho_isotropic(2.1e11, 0.3, 1, &c.drum) == RS_OK);
  c.drum_radius = 0.1;
  c.drum_core_radius = 0.001;
  c.sheet = (rs_sheet){1e-12, 0, 0, 0, 0};
  c.nodes = M;
  c.winder = RS_WINDER_CENTER;
  /* both solvers on the same series, so that only the sheet and the formulation differ */
  const rs_series_opts o = {0, 1e-7, 0, 1};
  c.series = o;
  rs_nip_contact *nc = NULL;
  CHECK(rs_nip_contact_create(&c, &nc) == RS_OK);
  rs_ortho ro;
  CHECK(rs_ortho_isotropic(7e10, 0.33, 1, &ro) == RS_OK);
  CHECK(rs_nip_contact_set_roll(nc, &ro, 0.15, 0.0015) == RS_OK);
  rs_nip_solution r = {0};
  double a = 1e-3;
  if (rs_nip_contact_solve_width(nc, a, 100, &r) != RS_OK) printf("  %s\n", rs_error_message());
  CHECK(r.M == M);
  /* the same bodies through rs_contact_frictionless */
  rs_cylinder *c1 = NULL, *c2 = NULL;
  CHECK(rs_cylinder_create(&ro, 0.15, 0.0015, &c1) == RS_OK);
  CHECK(rs_cylinder_create(&c.drum, 0.1, 0.001, &c2) == RS_OK);
  rs_contact_result f = {0};
  CHECK(rs_contact_frictionless(c1, c2, a, M, &o, &f) == RS_OK);
  double pm = 0, dp = 0;
  for (int i = 0; i < M; ++i) {
    pm = fmax(pm, f.p[i]);
    dp = fmax(dp, fabs(r.pressure[i] - f.p[i]));
  }
  CHECK_LOG("max |p - p_frictionless| / p0", dp / pm);
  CHECK_LT(dp / pm, 1e-9);
  CHECK_CLOSE(r.delta0, f.delta0, 1e-9);
  CHECK_ABS(r.T0, 100, 1e-12 * 100);
  /* Hertz: P = pi a^2 E* / (4 R*) */
  double Es = 1 / ((1 - 0.33 * 0.33) / 7e10 + (1 - 0.09) / 2.1e11), Rs = 1 / (1 / 0.15 + 1 / 0.1);
  double PH = PI * a * a * Es / (4 * Rs);
  CHECK_LOG("P / P_hertz - 1", r.load / PH - 1);
  CHECK_LT(fabs(r.load / PH - 1), 0.015); /* discretisation + a/R = 0.007 curvature */
  /* and the load search returns the Hertz half-width */
  CHECK(rs_nip_contact_solve_load(nc, PH, 100, &r) == RS_OK);
  CHECK_LOG("a / a_hertz - 1", r.a / a - 1);
  CHECK_LT(fabs(r.a / a - 1), 0.01);
  rs_contact_result_free(&f);
  rs_cylinder_destroy(&c1);
  rs_cylinder_destroy(&c2);
  rs_nip_solution_free(&r);
  rs_nip_contact_destroy(&nc);
}

/* NIT = T0 - Ti with a center-driven roll and a rider: |NIT| <= mu+ P always, equal
 * exactly when every upper element slips (in one direction). */
static void nit_bound(void)
{
  setup s = paper_roll();
  const double loads[] = {500, 1750, 6000, 20000};
  int seen_eq = 0, seen_lt = 0;
  for (int i = 0; i < 4; ++i) {
    rs_nip_solution r = {0};
    s.E_r = s.G = s.E_zd = 3e8;
    s.mu_roll = loads[i] < 5000 ? 0.3 : 0.5;
    CHECK(solve(&s, loads[i], 350, &r));
    double nit = r.T0 - r.Ti, bound = s.mu_roll * r.load;
    int all = 1; /* every upper element slips, all in one direction */
    for (int e = 0; e < r.M - 1; ++e)
      all &= r.slip_upper[e] && r.slip_rate_upper[e] * r.slip_rate_upper[0] > 0;
    printf("  P = %-8g mu+ = %g NIT = %.17g  mu P = %.17g  all upper slip: %d\n", loads[i],
           s.mu_roll, nit, bound, all);
    CHECK(fabs(nit) <= bound * (1 + 1e-12));
    if (all) {
      CHECK_CLOSE(fabs(nit), bound, 1e-10);
      ++seen_eq;
    } else {
      CHECK_LT(fabs(nit), bound * (1 - 1e-6));
      ++seen_lt;
    }
    rs_nip_solution_free(&r);
  }
  CHECK(seen_eq > 0 && seen_lt > 0); /* both branches exercised */
}

/* The staggered discretisation: no node-to-node oscillation in the converged shear (the
 * alternating component sum (-1)^e q_e / (M-1) is small against the mean |q|) and a
 * bounded condition number. */
static void no_checkerboard(void)
{
  setup s = paper_roll();
  s.mu_roll = s.mu_drum = 1e3; /* full stick: the case where the literal collocation fails */
  for (int pass = 0; pass < 2; ++pass) {
    rs_nip_solution r = {0};
    CHECK(solve(&s, 1750, 350, &r));
    int E = r.M - 1;
    for (int k = 0; k < 2; ++k) {
      /* interior (two elements off each edge, where the full-stick shear is singular):
       * detrended residual d_e = (q_{e-1} - 2 q_e + q_{e+1}) / 4 (a checkerboard
       * A (-1)^e gives d = -A (-1)^e), its alternating component against mean |q|, and
       * the sign changes of the first differences (a checkerboard changes at every step) */
      const double *q = k ? r.shear_lower : r.shear_upper;
      double alt = 0, mean = 0;
      int n = 0, flips = 0;
      for (int e = 3; e < E - 3; ++e, ++n) {
        alt += (e % 2 ? -1 : 1) * 0.25 * (q[e - 1] - 2 * q[e] + q[e + 1]);
        mean += fabs(q[e]);
        if ((q[e + 1] - q[e]) * (q[e] - q[e - 1]) < 0) ++flips;
      }
      alt = fabs(alt) / n;
      mean /= n;
      CHECK_LOG(k ? "alternating / mean |q| (lower)" : "alternating / mean |q| (upper)", alt / mean);
      CHECK_LOG(k ? "sign changes of dq (lower)" : "sign changes of dq (upper)", flips);
      CHECK_LT(alt / mean, 0.05); /* a checkerboard gives O(1) */
      CHECK(flips <= 6);          /* a checkerboard gives one per element (~57) */
    }
    CHECK_LOG("condition number", r.condition_number);
    CHECK_LT(r.condition_number, 1e8);
    rs_nip_solution_free(&r);
    s.mu_roll = 0.3; /* second pass: mixed stick/slip */
    s.mu_drum = 0.35;
    s.E_r = s.G = s.E_zd = 3e8;
  }
}

/* T0 converges as M grows; the observed order (about 2 here) is logged and must be at
 * least 1. */
static void convergence_in_M(void)
{
  setup s = paper_roll();
  s.E_r = s.G = s.E_zd = 3e8;
  s.mu_roll = 0.5; /* partial stick on both contacts: T0 is not simply Ti + mu P */
  const int Ms[] = {17, 33, 65, 129};
  double T[4];
  for (int i = 0; i < 4; ++i) {
    rs_nip_solution r = {0};
    s.M = Ms[i];
    CHECK(solve(&s, 6000, 350, &r));
    T[i] = r.T0;
    printf("  M = %-4d T0 = %.17g  a = %.17g\n", Ms[i], r.T0, r.a);
    rs_nip_solution_free(&r);
  }
  double p_last = 0;
  for (int i = 0; i + 2 < 4; ++i) {
    double d1 = fabs(T[i + 1] - T[i]), d2 = fabs(T[i + 2] - T[i + 1]);
    p_last = log(d1 / d2) / log(2.0);
    CHECK_LOG("observed order", p_last);
  }
  CHECK(p_last >= 1.0);
}

static void expect_input(rs_status st, const char *key)
{
  CHECK(st == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), key) != NULL);
  printf("  message: %s\n", rs_error_message());
}

static void bad_input(void)
{
  setup s = paper_roll();
  rs_nip_solution r = {0};
  rs_nip_contact *nc = make(&s);
  /* a load no half-width up to 0.2 min(R1, R2) can carry */
  expect_input(rs_nip_contact_solve_load(nc, 1e12, 350, &r), "nip.load");
  rs_nip_contact_destroy(&nc);
  /* negative friction */
  rs_nip_contact_config c = {0};
  CHECK(rs_ortho_isotropic(2.1e11, 0.3, 1, &c.drum) == RS_OK);
  c.drum_radius = 0.3;
  c.drum_core_radius = 0.05;
  c.sheet = (rs_sheet){50e-6, 2e-10, 0, 3e-8, 1e-8};
  c.nodes = 32;
  c.mu_roll = -0.1;
  expect_input(rs_nip_contact_create(&c, &nc), "nip.friction.roll");
  c.mu_roll = 0.2;
  c.mu_drum = -1;
  expect_input(rs_nip_contact_create(&c, &nc), "nip.friction.drum");
  /* a drum inside its core */
  c.mu_drum = 0.3;
  c.drum_core_radius = 0.4;
  expect_input(rs_nip_contact_create(&c, &nc), "nip.drum.core_radius");
  /* surface winder: the drum cannot carry Ti by friction when mu_drum P < Ti */
  s.winder = RS_WINDER_SURFACE;
  nc = make(&s);
  expect_input(rs_nip_contact_solve_load(nc, 500, 350, &r), "nip.friction.drum");
  CHECK(strstr(rs_error_message(), "nip.load") != NULL);
  rs_nip_contact_destroy(&nc);
  rs_nip_solution_free(&r);
}

/* The iteration terminates with RS_ERR_SOLVER and says what it tried when capped. */
static void iteration_cap(void)
{
  setup s = paper_roll();
  rs_nip_contact_config c = {0};
  CHECK(rs_ortho_isotropic(2.1e11, 0.3, 1, &c.drum) == RS_OK);
  c.drum_radius = s.Rd;
  c.drum_core_radius = s.Rd0;
  rs_sheet_constants k = {s.caliper, s.E_t, s.E_zd, s.E_t, s.nu, 0.3, s.nu, s.G, 1};
  CHECK(rs_sheet_from_constants(&k, &c.sheet) == RS_OK);
  c.mu_roll = 0.19;
  c.mu_drum = 0.35;
  c.nodes = 32;
  c.max_iterations = 1;
  rs_nip_contact *nc = NULL;
  CHECK(rs_nip_contact_create(&c, &nc) == RS_OK);
  rs_ortho_engineering e = {s.E_r, s.E_t, s.E_t, s.nu * s.E_r / s.E_t, s.nu * s.E_r / s.E_t, 0.3, s.G};
  rs_ortho ro;
  CHECK(rs_ortho_from_engineering(&e, 1, &ro) == RS_OK);
  CHECK(rs_nip_contact_set_roll(nc, &ro, s.R, s.R0) == RS_OK);
  rs_nip_solution r = {0};
  rs_status st = rs_nip_contact_solve_width(nc, 0.01, 350, &r);
  printf("  message: %s\n", rs_error_message());
  CHECK(st == RS_ERR_SOLVER);
  CHECK(strstr(rs_error_message(), "passes") != NULL);
  rs_nip_solution_free(&r);
  rs_nip_contact_destroy(&nc);
}

/* Warm start: solving the next layer (R + caliper) from the previous solution gives the
 * same answer as a cold solve, in fewer half-width trials. */
static void warm_equals_cold(void)
{
  setup s = paper_roll();
  rs_nip_contact *nc = make(&s);
  rs_nip_solution w = {0}, c = {0};
  CHECK(rs_nip_contact_solve_load(nc, 1750, 350, &w) == RS_OK);
  rs_ortho_engineering e = {s.E_r, s.E_t, s.E_t, s.nu * s.E_r / s.E_t, s.nu * s.E_r / s.E_t, 0.3, s.G};
  rs_ortho ro;
  CHECK(rs_ortho_from_engineering(&e, 1, &ro) == RS_OK);
  CHECK(rs_nip_contact_set_roll(nc, &ro, s.R + 1e-4, s.R0) == RS_OK);
  CHECK(rs_nip_contact_solve_load(nc, 1750, 350, &w) == RS_OK);
  int warm_tries = w.width_iterations;
  rs_nip_contact_forget(nc);
  CHECK(rs_nip_contact_solve_load(nc, 1750, 350, &c) == RS_OK);
  CHECK_LOG("warm half-width trials", warm_tries);
  CHECK_LOG("cold half-width trials", c.width_iterations);
  CHECK_CLOSE(w.T0, c.T0, 1e-7);
  CHECK_CLOSE(w.a, c.a, 1e-7);
  CHECK(warm_tries <= c.width_iterations);
  rs_nip_solution_free(&w);
  rs_nip_solution_free(&c);
  rs_nip_contact_destroy(&nc);
}

static const check_case cases[] = {
    {"equilibrium_center", equilibrium_center},
    {"equilibrium_surface", equilibrium_surface},
    {"equilibrium_center_surface", equilibrium_center_surface},
    {"frictionless_center", frictionless_center},
    {"large_mu_full_stick", large_mu_full_stick},
    {"friction_law_and_slip_zones", friction_law_and_slip_zones},
    {"thin_sheet_frictionless", thin_sheet_frictionless},
    {"nit_bound", nit_bound},
    {"no_checkerboard", no_checkerboard},
    {"convergence_in_M", convergence_in_M},
    {"bad_input", bad_input},
    {"iteration_cap", iteration_cap},
    {"warm_equals_cold", warm_equals_cold}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
