/* The winding nip contact solver on a paper roll against a steel drum, its numerics: no
 * kink on a thin roll, no checkerboard, convergence in M, bad input refused, the iteration
 * cap, warm starts equal to cold ones and along a reel, the stiff drum's series (the
 * identities, limits and independent solutions: test_nip_contact.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "nip/contact_internal.h"
#include "nip/nip_contact.h"
#include "validation/nip_setup.h"

#ifndef RESCALE_TEST_DR
#define RESCALE_TEST_DR 0.0015
#endif

/* A roll thinner than 1 % of its radius is modelled with the thickness sqrt(t^2 + t_min^2),
 * t_min = 0.01 R (docs/nip.md): T0(R) must be smooth where the first version's
 * min(core, 0.99 R) switched, R = core / 0.99. There, with fixed load and surface pressure
 * (newsprint, M = 24, the inputs of the reel test's scene), the old clamp changed the T0
 * increment per 20 um step from 0.002 to 1.1 N/m; now neighbouring increments differ by
 * less than half the largest one. */
/* a newsprint-like stack (Pfeiffer K1 5e3, K2 60, 70 um, E_theta 3.5 GPa) of shear modulus G */
static rs_material newsprint(double G)
{
  rs_material m = {0};
  snprintf(m.name, sizeof m.name, "newsprint");
  m.caliper = 70e-6;
  m.E_theta = 3.5e9;
  m.G_rtheta = G;
  m.nu_rtheta = 0.01;
  m.nu_md_cd = 0.3;
  m.radial.law = RS_RADIAL_PFEIFFER;
  m.radial.K1 = 5e3;
  m.radial.K2 = 60;
  return m;
}

/* A contact nip against a steel drum of radius 0.3 m over a rigid core of radius
 * drum_core (m; the cover is the rest), the roll's friction 0.19, the drum's 0.35, on
 * `nodes` nodes */
static rs_nip_spec steel_drum_contact(rs_winder_kind winder, double drum_core, int nodes)
{
  rs_nip_spec sp = {0};
  sp.model = RS_NIP_CONTACT;
  sp.mu_roll = 0.19;
  sp.mu_drum = 0.35;
  sp.winder = winder;
  sp.drum = (rs_drum){0.3, drum_core, 0, 2.1e11, 0.3, 0, 0, 0, 0};
  sp.nodes = nodes;
  return sp;
}

static void thin_roll_no_kink(void)
{
  rs_material m = newsprint(1e9);
  rs_nip_spec sp = steel_drum_contact(RS_WINDER_CENTER, 0.05, 24);
  rs_nip_contact *nc = NULL;
  CHECK(rs_nip_contact_create_from_spec(&sp, &m, &nc) == RS_OK);
  const double core = 0.0762, Rc = core / 0.99;
  double T[7], dmax = 0, jump = 0;
  for (int k = 0; k < 7; ++k) {
    rs_nip_state st = {Rc + (k - 3) * 20e-6, core, 350, 985, 0, 6800};
    rs_nip_solution r = {0};
    CHECK(rs_nip_contact_solve_state(nc, &st, &r) == RS_OK);
    T[k] = r.T0;
    rs_nip_solution_free(&r);
  }
  for (int k = 1; k < 7; ++k) {
    printf("  R = core/0.99 %+d x 20 um: T0 = %.10f  increment %.3e\n", k - 3, T[k], T[k] - T[k - 1]);
    dmax = fmax(dmax, fabs(T[k] - T[k - 1]));
    if (k > 1) jump = fmax(jump, fabs((T[k] - T[k - 1]) - (T[k - 1] - T[k - 2])));
  }
  CHECK_LOG("largest change of the increment / largest increment", jump / dmax);
  CHECK_LT(jump, 0.5 * dmax);
  rs_nip_contact_destroy(&nc);
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
  /* cold, the LCP's set needs one confirming pass; warm from a much narrower nip, the
   * iteration needs more than one */
  CHECK(rs_nip_contact_solve_width(nc, 0.002, 350, &r) == RS_OK);
  rs_status st = rs_nip_contact_solve_width(nc, 0.01, 350, &r);
  printf("  message: %s\n", rs_error_message());
  CHECK(st == RS_ERR_SOLVER);
  CHECK(strstr(rs_error_message(), "passes") != NULL);
  rs_nip_solution_free(&r);
  rs_nip_contact_destroy(&nc);
}

/* Warm start: layer after layer (R + one caliper each, as a reel calls it: the half-width
 * predicted from the previous layers, the kept factorization refined by GMRES) gives the
 * same answer as a cold solve of the last layer (LCP start, new LU), in fewer half-width
 * trials; the last layers need one trial each. */
static void warm_equals_cold(void)
{
  setup s = paper_roll();
  s.E_r = s.G = s.E_zd = 3e8; /* partial stick on both contacts */
  s.mu_roll = 0.5;
  rs_nip_contact *nc = make(&s);
  rs_nip_solution w = {0}, c = {0};
  CHECK(rs_nip_contact_solve_load(nc, 6000, 350, &w) == RS_OK);
  rs_ortho ro = roll_of(&s);
  int last_tries = 0;
  for (int layer = 1; layer <= 10; ++layer) {
    CHECK(rs_nip_contact_set_roll(nc, &ro, s.R + layer * 1e-4, s.R0) == RS_OK);
    CHECK(rs_nip_contact_solve_load(nc, 6000, 350, &w) == RS_OK);
    if (layer == 1) CHECK_LOG("warm half-width trials, first layer", w.width_iterations);
    last_tries = w.width_iterations;
  }
  rs_nip_contact_forget(nc);
  CHECK(rs_nip_contact_solve_load(nc, 6000, 350, &c) == RS_OK);
  CHECK_LOG("warm half-width trials, 10th layer", last_tries);
  CHECK_LOG("cold half-width trials", c.width_iterations);
  CHECK_LOG("T0 warm - cold (N/m)", w.T0 - c.T0);
  CHECK_LOG("a warm / cold - 1", w.a / c.a - 1);
  CHECK_CLOSE(w.T0, c.T0, 1e-7);
  CHECK_CLOSE(w.a, c.a, 1e-7);
  CHECK(last_tries == 1);
  CHECK(last_tries < c.width_iterations);
  rs_nip_solution_free(&w);
  rs_nip_solution_free(&c);
  rs_nip_contact_destroy(&nc);
}

/* The warm load search along a reel (docs/nip.md, "Load -> half-width"): on a thin roll
 * (R = 0.4 .. 2.8 mm above the core in steps of two calipers, where the slope d ln P / d ln a
 * falls fastest, as on cases/newsprint-surface.yaml's first layers) the first step's slope,
 * extrapolated from the last two searches' final secants, saves half-widths: 33 in 15 warm
 * searches, 38 with the slope the previous search started from; and each warm solve agrees
 * with a cold one (a new handle) to the search's tolerance. */
static void warm_search_along_reel(void)
{
  rs_material m = newsprint(5e7);
  rs_nip_spec sp = steel_drum_contact(RS_WINDER_SURFACE, 0.28, 64);
  rs_nip_contact *nc = NULL, *cold = NULL;
  CHECK(rs_nip_contact_create_from_spec(&sp, &m, &nc) == RS_OK);
  rs_nip_solution w = {0}, c = {0};
  int most = 0, total = 0;
  double worst = 0;
  for (int k = 0; k < 18; ++k) {
    rs_nip_state st = {0.0766 + 1.4e-4 * k, 0.0762, 350, 1750, 0, 2e5};
    CHECK(rs_nip_contact_solve_state(nc, &st, &w) == RS_OK);
    CHECK(rs_nip_contact_create_from_spec(&sp, &m, &cold) == RS_OK);
    CHECK(rs_nip_contact_solve_state(cold, &st, &c) == RS_OK);
    rs_nip_contact_destroy(&cold);
    worst = fmax(worst, fabs(w.T0 / c.T0 - 1));
    if (k >= 3) {
      most = w.width_iterations > most ? w.width_iterations : most;
      total += w.width_iterations;
    }
  }
  CHECK_LOG("most half-widths a warm search (4th on)", most);
  CHECK_LOG("half-widths, 15 warm searches", total);
  CHECK_LOG("largest |T0 warm / cold - 1|", worst);
  CHECK(most <= 3);
  CHECK(total <= 34);
  CHECK_LT(worst, 3e-6); /* two searches each within load_rtol = 1e-6 of the load */
  rs_nip_solution_free(&w);
  rs_nip_solution_free(&c);
  rs_nip_contact_destroy(&nc);
}

/* The default series gives a body much stiffer than the other fewer terms (contact.c,
 * body_terms): the steel drum under the newsprint roll (H11 4e4 times smaller) 64 instead of
 * 256. The reference is the same nip with nip.terms = 256 given, which holds for both
 * bodies: T0 and the half-width agree far inside the load search's tolerance (1e-6). */
static void stiff_drum_terms(void)
{
  rs_material m = newsprint(5e7);
  rs_nip_spec sp = steel_drum_contact(RS_WINDER_SURFACE, 0.28, 64), full = sp;
  full.terms = 256;
  double worst_T0 = 0, worst_a = 0;
  long drum_terms = 0, roll_terms = 0;
  for (int k = 0; k < 3; ++k) {
    rs_nip_state st = {0.08 + 0.15 * k, 0.0762, 350, 1750, 0, 2e5};
    rs_nip_contact *nc = NULL, *ref = NULL;
    rs_nip_solution w = {0}, r = {0};
    CHECK(rs_nip_contact_create_from_spec(&sp, &m, &nc) == RS_OK);
    CHECK(rs_nip_contact_create_from_spec(&full, &m, &ref) == RS_OK);
    /* the load search's tolerance tightened, so that the comparison sees the kernels */
    nc->cfg.load_rtol = ref->cfg.load_rtol = 1e-12;
    CHECK(rs_nip_contact_solve_state(nc, &st, &w) == RS_OK);
    CHECK(rs_nip_contact_solve_state(ref, &st, &r) == RS_OK);
    worst_T0 = fmax(worst_T0, fabs(w.T0 / r.T0 - 1));
    worst_a = fmax(worst_a, fabs(w.a / r.a - 1));
    drum_terms = nc->ker[1][KP].terms;
    roll_terms = nc->ker[0][KP].terms;
    CHECK(ref->ker[1][KP].terms == 256 && ref->ker[0][KP].terms == 256);
    CHECK(nc->ker[1][KQU].terms == drum_terms && nc->ker[1][KQE].terms == drum_terms);
    rs_nip_solution_free(&w);
    rs_nip_solution_free(&r);
    rs_nip_contact_destroy(&nc);
    rs_nip_contact_destroy(&ref);
  }
  CHECK_LOG("drum terms", (double)drum_terms);
  CHECK_LOG("roll terms", (double)roll_terms);
  CHECK_LOG("largest |T0 / T0_256 - 1|", worst_T0);
  CHECK_LOG("largest |a / a_256 - 1|", worst_a);
  CHECK(drum_terms == 64 && roll_terms == 256);
  CHECK_LT(worst_T0, 1e-7);
  CHECK_LT(worst_a, 1e-7);
}

/* The stiff drum's kernels rescaled from a nearby half-width (contact.c, rs_kernels_rescale)
 * instead of summed: a warm handle that solved at R1 and then solves at R2, whose half-width
 * lies near the largest drift the bound allows, rescales the drum's kernels, and its T0 and
 * a are those of a fresh handle that sums them at R2 within the stated 1e-7 (the bound's
 * RESCALE_TOL; load_rtol 1e-12 so that the comparison sees the kernels). A solve far away
 * sums them anew. */
static void stiff_drum_rescaled(void)
{
  rs_material m = newsprint(5e7);
  rs_nip_spec sp = steel_drum_contact(RS_WINDER_SURFACE, 0.28, 64);
  const double R1 = 0.2, R2 = R1 + RESCALE_TEST_DR, R3 = 0.45;
  rs_nip_contact *nc = NULL, *ref = NULL;
  rs_nip_solution w = {0}, r = {0};
  CHECK(rs_nip_contact_create_from_spec(&sp, &m, &nc) == RS_OK);
  CHECK(rs_nip_contact_create_from_spec(&sp, &m, &ref) == RS_OK);
  nc->cfg.load_rtol = ref->cfg.load_rtol = 1e-12;
  ref->no_rescale = 1;
  rs_nip_state s1 = {R1, 0.0762, 350, 1750, 0, 2e5}, s2 = s1, s3 = s1;
  s2.roll_radius = R2;
  s3.roll_radius = R3;
  CHECK(rs_nip_contact_solve_state(nc, &s1, &w) == RS_OK);
  const double a1 = nc->ref_a[1];
  const long summed = nc->stats_rescaled;
  CHECK(rs_nip_contact_solve_state(nc, &s2, &w) == RS_OK);
  CHECK(rs_nip_contact_solve_state(ref, &s2, &r) == RS_OK);
  const double share = nc->H11[1] / (nc->H11[0] + nc->H11[1]);
  const double allowed = 1e-7 / (share * 1.5 * w.a / 0.02), drift = fabs(log(w.a / a1));
  CHECK_LOG("drum's share of the compliance", share);
  CHECK_LOG("half-width drift |ln(a2 / a1)|", drift);
  CHECK_LOG("largest drift rescaled", allowed);
  CHECK_LOG("kernel sets rescaled", (double)(nc->stats_rescaled - summed));
  CHECK_LOG("|T0 / T0_summed - 1|", fabs(w.T0 / r.T0 - 1));
  CHECK_LOG("|a / a_summed - 1|", fabs(w.a / r.a - 1));
  CHECK(nc->stats_rescaled > summed && ref->stats_rescaled == 0);
  CHECK(nc->ref_a[1] == a1);
  CHECK(drift > 0.5 * allowed && drift < allowed);
  CHECK_LT(fabs(w.T0 / r.T0 - 1), 1e-7);
  CHECK_LT(fabs(w.a / r.a - 1), 1e-7);
  /* measured 2.6e-12; the box shear's qu rescaled without lam gives 1.1e-10, pu without lam
   * moves a by 1.8e-7 (test_cylinder.rescale_halfplane_bound checks every rule) */
  CHECK_LT(fabs(w.T0 / r.T0 - 1), 2e-11);
  const long before = nc->stats_rescaled;
  CHECK(rs_nip_contact_solve_state(nc, &s3, &w) == RS_OK);
  CHECK(nc->ref_a[1] != a1); /* far away: summed anew, the new reference */
  CHECK_LOG("kernel sets rescaled at R3", (double)(nc->stats_rescaled - before));
  rs_nip_solution_free(&w);
  rs_nip_solution_free(&r);
  rs_nip_contact_destroy(&nc);
  rs_nip_contact_destroy(&ref);
}

/* The factorizations a solve makes for itself in single precision, refined by GMRES to the
 * same residual (contact_linear.c): a warm chain of solves along a roll against the same
 * chain factored in double (lin.double_only set), T0, a, the load and the pressure within
 * 1e-11 (measured 5e-13; taking the single-precision LU's solve as the answer would be
 * ~1e-7 off). */
static void single_precision_lu(void)
{
  rs_material m = newsprint(5e7);
  rs_nip_spec sp = steel_drum_contact(RS_WINDER_SURFACE, 0.28, 64);
  rs_nip_contact *nc[2] = {NULL, NULL};
  for (int h = 0; h < 2; ++h) CHECK(rs_nip_contact_create_from_spec(&sp, &m, &nc[h]) == RS_OK);
  if (!nc[0] || !nc[1]) goto out;
  nc[1]->lin.double_only = 1;
  nc[0]->cfg.load_rtol = nc[1]->cfg.load_rtol = 1e-12; /* the searches land alike */
  double worst = 0;
  for (int k = 0; k < 6; ++k) {
    rs_nip_state st = {0.08 + 0.07 * k, 0.0762, 350, 1750, 0, 2e5};
    rs_nip_solution r[2] = {{0}, {0}};
    for (int h = 0; h < 2; ++h) CHECK(rs_nip_contact_solve_state(nc[h], &st, &r[h]) == RS_OK);
    double pm = 0, dp = 0;
    for (int i = 0; i < r[1].M; ++i) {
      pm = fmax(pm, fabs(r[1].pressure[i]));
      dp = fmax(dp, fabs(r[0].pressure[i] - r[1].pressure[i]));
    }
    printf("  R %.2f: T0 %.2e a %.2e load %.2e p %.2e\n", st.roll_radius, fabs(r[0].T0 / r[1].T0 - 1),
           fabs(r[0].a / r[1].a - 1), fabs(r[0].load / r[1].load - 1), dp / pm);
    worst = fmax(worst, fmax(fabs(r[0].T0 / r[1].T0 - 1), fabs(r[0].a / r[1].a - 1)));
    worst = fmax(worst, fmax(fabs(r[0].load / r[1].load - 1), dp / pm));
    for (int h = 0; h < 2; ++h) rs_nip_solution_free(&r[h]);
  }
  { /* a fresh factorization's own solve (the kept LU dropped) against LAPACK's dgesv */
    const int n = nc[0]->n;
    double *A = malloc((size_t)n * n * sizeof *A), *b = malloc((size_t)n * sizeof *b), dz = 0, zm = 0;
    lapack_int *ip = malloc((size_t)n * sizeof *ip);
    memcpy(A, nc[0]->A, (size_t)n * n * sizeof *A);
    memcpy(b, nc[0]->rhs, (size_t)n * sizeof *b);
    nc[0]->lin.valid = 0;
    CHECK(rs_nipc_lin_solve(nc[0], nc[0]->k_a) == RS_OK);
    CHECK(nc[0]->lin.single && nc[0]->lin.fresh);
    CHECK(LAPACKE_dgesv(LAPACK_COL_MAJOR, n, 1, A, n, ip, b, n) == 0);
    for (int i = 0; i < n; ++i) {
      dz = fmax(dz, fabs(nc[0]->z[i] - b[i]));
      zm = fmax(zm, fabs(b[i]));
    }
    CHECK_LOG("fresh single-precision LU refined, against dgesv", dz / zm);
    CHECK_LT(dz / zm, 1e-11);
    free(A);
    free(b);
    free(ip);
  }
  CHECK_LOG("factorizations, single / all", (double)nc[0]->stats_lu_single / (double)nc[0]->stats_lu);
  CHECK_LOG("GMRES iterations, single", (double)nc[0]->stats_gmres_it);
  CHECK_LOG("GMRES iterations, double", (double)nc[1]->stats_gmres_it);
  CHECK_LOG("largest relative difference (T0, a, load, pressure)", worst);
  CHECK(nc[0]->stats_lu_single > 0 && nc[1]->stats_lu_single == 0 && !nc[0]->lin.double_only);
  CHECK_LT(worst, 1e-11);
out:
  for (int h = 0; h < 2; ++h) rs_nip_contact_destroy(&nc[h]);
}

/* A system too ill-conditioned for a single-precision LU (condition number 1e10: the
 * converged nip's matrix replaced by I - (1 - 1e-10) u u^T, u a unit vector with all
 * entries nonzero): GMRES cannot refine from it, so the solve falls back to dgetrf, and
 * keeps to double precision on that handle; the answer's residual as a direct solve's. */
static void single_precision_fallback(void)
{
  rs_material m = newsprint(5e7);
  rs_nip_spec sp = steel_drum_contact(RS_WINDER_SURFACE, 0.28, 64);
  rs_nip_contact *nc = NULL;
  rs_nip_solution r = {0};
  CHECK(rs_nip_contact_create_from_spec(&sp, &m, &nc) == RS_OK);
  rs_nip_state st = {0.2, 0.0762, 350, 1750, 0, 2e5};
  CHECK(rs_nip_contact_solve_state(nc, &st, &r) == RS_OK);
  if (!nc) return;
  const int n = nc->n;
  double *u = malloc((size_t)n * sizeof *u), *Az = malloc((size_t)n * sizeof *Az);
  for (int i = 0; i < n; ++i) u[i] = 1.0 + 0.5 * sin(1.7 * i);
  double nu = 0;
  for (int i = 0; i < n; ++i) nu += u[i] * u[i];
  nu = sqrt(nu);
  for (int i = 0; i < n; ++i) u[i] /= nu;
  for (int c = 0; c < n; ++c)
    for (int i = 0; i < n; ++i) nc->A[(size_t)c * n + i] = (i == c) - (1 - 1e-10) * u[i] * u[c];
  for (int i = 0; i < n; ++i) nc->rhs[i] = cos(0.3 * i);
  nc->lin.valid = 0;
  const long single0 = nc->stats_lu_single, lu0 = nc->stats_lu;
  CHECK(rs_nipc_lin_solve(nc, r.a) == RS_OK);
  double res = 0, an = 0, zn = 0; /* backward error: |A z - b| / (|A| |z|), infinity norms */
  for (int i = 0; i < n; ++i) {
    double ai = 0;
    Az[i] = 0;
    for (int c = 0; c < n; ++c) {
      Az[i] += nc->A[(size_t)c * n + i] * nc->z[c];
      ai += fabs(nc->A[(size_t)c * n + i]);
    }
    res = fmax(res, fabs(Az[i] - nc->rhs[i]));
    an = fmax(an, ai);
    zn = fmax(zn, fabs(nc->z[i]));
  }
  const double bn = an * zn;
  CHECK_LOG("factorizations: single, double", (double)(nc->stats_lu_single - single0));
  CHECK_LOG("factorizations: all", (double)(nc->stats_lu - lu0));
  CHECK_LOG("backward error |A z - b| / (|A| |z|)", res / bn);
  CHECK(nc->stats_lu_single - single0 == 1 && nc->stats_lu - lu0 == 2);
  CHECK(nc->lin.double_only && !nc->lin.single);
  CHECK_LT(res / bn, 1e-12);
  free(u);
  free(Az);
  rs_nip_solution_free(&r);
  rs_nip_contact_destroy(&nc);
}

static const check_case cases[] = {
    {"thin_roll_no_kink", thin_roll_no_kink},
    {"no_checkerboard", no_checkerboard},
    {"convergence_in_M", convergence_in_M},
    {"bad_input", bad_input},
    {"iteration_cap", iteration_cap},
    {"warm_equals_cold", warm_equals_cold},
    {"warm_search_along_reel", warm_search_along_reel},
    {"stiff_drum_terms", stiff_drum_terms},
    {"stiff_drum_rescaled", stiff_drum_rescaled},
    {"single_precision_lu", single_precision_lu},
    {"single_precision_fallback", single_precision_fallback},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
