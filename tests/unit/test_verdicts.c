/* The starring and cinching verdicts (docs/defects.md, sections 2 and 4) against closed
 * forms: the ring on a foundation and its single-layer limit sqrt(E_theta E_r / 3), the
 * rings-on-springs stack against one ring and against a rigid packet, the strength
 * criterion and the zone's extent, the slip margin of a uniform-pressure roll by hand, the
 * rigid-body inertia torque, surface winding, the capstan bound at the outermost interface. */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/defects.h"
#include "reelsim/scene.h"

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

static const double pi = 3.14159265358979323846;

/* n layers of caliper 1 mm on a 0.1 m core, P = 1e5 Pa everywhere, sigma_theta = +1 MPa,
 * web tension 300 N/m. */
static rs_reel_result *profile(int n)
{
  rs_reel_result *r = calloc(1, sizeof *r);
  r->n_layers = n;
  r->core_radius = 0.1;
  r->core_pressure = 1.0e5;
  size_t sz = (size_t)n * sizeof(double);
  r->radius = malloc(sz);
  r->sigma_r = malloc(sz);
  r->sigma_theta = malloc(sz);
  r->web_tension = malloc(sz);
  for (int j = 0; j < n; ++j) {
    r->radius[j] = 0.1 + (j + 1) * 1.0e-3;
    r->sigma_r[j] = -1.0e5;
    r->sigma_theta[j] = 1.0e6;
    r->web_tension[j] = 300.0;
  }
  return r;
}

static rs_defect_report *assess(const rs_reel_result *r, const rs_defect_limits *lim)
{
  rs_defect_report *rep = NULL;
  CHECK(rs_defects_assess(r, lim, &rep) == RS_OK);
  return rep;
}

/* N_cr = min_m D (m^2-1)/R^2 + k R^2/(m^2-1) against every m from 2 to 2000 by brute force,
 * and, for one bonded layer on one caliper of stack (k = E_r / t) on a ring large enough for
 * its many waves, the single-layer critical stress sqrt(E_theta E_r / 3). */
static void ring_single_layer_limit(void)
{
  const double E = 3.5e9, E_r = 6.0e7, t = 70e-6, D = E * t * t * t / 12.0, k = E_r / t;
  const double R_small[] = {2e-3, 5e-3, 0.02};
  for (size_t i = 0; i < 3; ++i) {
    double R = R_small[i], best = INFINITY;
    int bm = 0, m = 0;
    for (int q = 2; q <= 2000; ++q) {
      double x = (double)q * q - 1.0, N = D * x / (R * R) + k * R * R / x;
      if (N < best) best = N, bm = q;
    }
    double N = rs_defect_ring_critical_force(D, k, R, &m);
    CHECK_LOG("R (m)", R);
    CHECK_LOG("mode", m);
    CHECK(m == bm);
    CHECK_CLOSE(N, best, 1e-15);
  }
  int m = 0;
  double sigma = rs_defect_ring_critical_force(D, k, 10.0, &m) / t;
  CHECK_LOG("mode at R = 10 m", m);
  CHECK_LOG("N_cr / t (Pa)", sigma);
  CHECK_LOG("sqrt(E_theta E_r / 3) (Pa)", rs_defect_critical_hoop_stress(E, E_r));
  CHECK_CLOSE(sigma, sqrt(E * E_r / 3.0), 1e-9);
  CHECK(rs_defect_ring_critical_force(0.0, k, 1.0, &m) == 0.0 && m == 0);
}

/* The rings-on-springs stack of one ring is the ring formula (to the bisection's 1e-13). */
static void ring_stack_one_ring(void)
{
  const double D = 1.0e-4, k = 2.0e9, R = 0.09, N = 1.0e4;
  const double rs = R;
  rs_ring_stack s = {.n = 1, .D = &D, .rho = &R, .N = &N, .k = &k, .r_spring = &rs};
  int m = 0, peak = -1, mr = 0;
  double lambda = rs_defect_ring_stack_critical(&s, &m, &peak);
  double want = rs_defect_ring_critical_force(D, k, R, &mr);
  CHECK_LOG("lambda N (N/m)", lambda * N);
  CHECK_LOG("N_cr (N/m)", want);
  CHECK_CLOSE(lambda * N, want, 1e-11);
  CHECK(m == mr && peak == 0);
}

/* n rings at one radius joined by springs far stiffer than the foundation move as one:
 * as the springs stiffen the stack's critical total force goes to the ring formula's with
 * D = n D_1 (a slipping packet), its error falling as 1/k. */
static void ring_stack_rigid_packet(void)
{
  enum { n = 12 };
  const double D1 = 1.0e-4, k0 = 3.0e8, R = 0.1, N1 = 500.0;
  double D[n], rho[n], N[n], k[n], rs[n], err[5];
  int mr = 0;
  const double want = rs_defect_ring_critical_force(n * D1, k0, R, &mr);
  CHECK_LOG("packet N_cr (N/m)", want);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < n; ++j) {
      D[j] = D1;
      rho[j] = R;
      N[j] = N1;
      k[j] = j ? 1.0e10 * pow(10.0, i) : k0;
      rs[j] = R;
    }
    rs_ring_stack s = {.n = n, .D = D, .rho = rho, .N = N, .k = k, .r_spring = rs};
    int m = 0, peak = 0;
    double lambda = rs_defect_ring_stack_critical(&s, &m, &peak);
    err[i] = lambda * n * N1 / want - 1.0;
    CHECK_LOG("interlayer k (Pa/m)", k[1]);
    CHECK_LOG("stack's critical force / packet's - 1", err[i]);
    CHECK_LOG("mode", m);
    if (i >= 2) CHECK(m == mr);
  }
  for (int i = 1; i < 5; ++i) CHECK_LT(fabs(err[i]), 0.2 * fabs(err[i - 1]));
  CHECK_LT(fabs(err[4]), 1e-5);
}

/* The scan's shortcut (modes above the bending bound are not tested) is exact: the least
 * factor and its mode, bit for bit, as a scan that tests every mode in full (the form
 * assembled, every LDL^T pivot; written out here) on wound-like stacks: compression near
 * the core and tension above it, soft and stiff springs, thin and thick webs. */
static int ref_definite(const rs_ring_stack *s, double m, double lambda)
{
  const double x = m * m - 1.0;
  double d = 0.0;
  for (int j = 0; j < s->n; ++j) {
    const double r2 = s->rho[j] * s->rho[j];
    double a = s->rho[j] * (s->D[j] * x * x / (r2 * r2) - lambda * s->N[j] * x / r2) +
               s->r_spring[j] * s->k[j];
    if (j + 1 < s->n) a += s->r_spring[j + 1] * s->k[j + 1];
    if (j > 0) {
      const double b = -s->r_spring[j] * s->k[j];
      a -= b * b / d;
    }
    d = a;
    if (!(d > 0.0)) return 0;
  }
  return 1;
}

static double ref_factor(const rs_ring_stack *s, double m, double cap, double rtol)
{
  if (ref_definite(s, m, cap)) return cap;
  double lo = 0.0, hi = cap;
  for (int it = 0; it < 200 && hi - lo > rtol * hi; ++it) {
    double mid = 0.5 * (lo + hi);
    if (ref_definite(s, m, mid)) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

static double ref_critical(const rs_ring_stack *s, int *mode)
{
  double best = 1e12, prev = 2.0, bm = 0.0, lo_m = 2.0, hi_m = 2.0;
  for (double m = 2.0; m < 2e6; m = m < 32.0 ? m + 1.0 : floor(m * 1.04)) {
    double f = ref_factor(s, m, best, 1e-4);
    if (f < best) best = f, bm = m, lo_m = prev;
    if (bm == prev) hi_m = m;
    prev = m;
  }
  if (hi_m < bm) hi_m = bm;
  for (double m = lo_m; bm > 0.0 && m <= hi_m; m += 1.0) {
    double f = ref_factor(s, m, best, 1e-4);
    if (f < best) best = f, bm = m;
  }
  if (bm > 0.0) best = ref_factor(s, bm, best * (1.0 + 1e-3), 1e-13);
  *mode = (int)bm;
  return best;
}

enum { STACK_N = 400 };
typedef struct test_stack {
  double D[STACK_N], rho[STACK_N], N[STACK_N], k[STACK_N], rs[STACK_N];
} test_stack;

/* STACK_N rings of caliper t on springs E_r / t, wavy so that no two rows are alike;
 * `stiff` 0: no bending and no springs; `tension` 1: every ring in tension (every 7th
 * unloaded), 0: compressed at the core, in tension beyond a third of the stack. */
static rs_ring_stack stack_fill(test_stack *b, double t, double E_r, int stiff, int tension)
{
  const double Et = 4e9, Dl = Et * t * t * t / 12.0;
  for (int j = 0; j < STACK_N; ++j) {
    b->rho[j] = 0.0762 + (j + 0.5) * t;
    b->rs[j] = 0.0762 + j * t;
    b->D[j] = stiff ? Dl * (1.0 + 0.3 * sin(0.1 * j)) : 0.0;
    b->k[j] = stiff ? (j ? E_r : 0.5 * E_r) * (1.0 + 0.5 * cos(0.07 * j)) / t : 0.0;
    b->N[j] = tension ? -2e6 * t * (1.0 + 0.2 * sin(0.3 * j)) * (j % 7 == 0 ? 0.0 : 1.0)
                      : 2e6 * t * (1.0 - 3.0 * j / STACK_N) * (1.0 + 0.2 * sin(0.3 * j));
  }
  return (rs_ring_stack){.n = STACK_N, .D = b->D, .rho = b->rho, .N = b->N, .k = b->k,
                         .r_spring = b->rs};
}

static const double stack_calipers[] = {70e-6, 1.5e-6, 1e-3}, stack_E_r[] = {3e5, 2e7, 1e9};

static void ring_stack_scan_exact(void)
{
  test_stack b;
  for (int c = 0; c < 3; ++c)
    for (int e = 0; e < 3; ++e) {
      const rs_ring_stack s = stack_fill(&b, stack_calipers[c], stack_E_r[e], 1, 0);
      int m = 0, mref = 0;
      const double f = rs_defect_ring_stack_critical(&s, &m, NULL);
      const double fref = ref_critical(&s, &mref);
      CHECK_LOG("caliper (m)", stack_calipers[c]);
      CHECK_LOG("E_r (Pa)", stack_E_r[e]);
      CHECK_LOG("least factor", f);
      CHECK_LOG("reference", fref);
      CHECK_LOG("mode", m);
      CHECK(f == fref && m == mref);
    }
}

/* A stack with no ring in compression cannot buckle: the scan's answer (none below the
 * cap, mode 0) without its passes, the same as the reference scan's; and a form singular
 * even unloaded (no springs, no bending) still goes through the scan, as the reference. */
static void ring_stack_in_tension_exact(void)
{
  test_stack b;
  for (int c = 0; c < 3; ++c)
    for (int e = 0; e < 4; ++e) {
      const rs_ring_stack s = stack_fill(&b, stack_calipers[c], stack_E_r[e % 3], e < 3, 1);
      int m = -1, mref = -1;
      const double f = rs_defect_ring_stack_critical(&s, &m, NULL);
      const double fref = ref_critical(&s, &mref);
      CHECK_LOG(e < 3 ? "least factor, in tension" : "least factor, singular unloaded", f);
      CHECK(f == fref && m == mref);
      if (e < 3) CHECK(f == 1e12 && m == 0);
    }
}

/* (a) A hoop strength: the layers over it flagged, the margin strength / compression, the
 * criterion named; (c) the zone's extent from the core. */
static void starring_strength_and_zone(void)
{
  rs_reel_result *r = profile(40);
  rs_radial_law law = {.law = RS_RADIAL_LINEAR, .E_r = 2.0e7};
  CHECK(rs_radial_law_prepare(&law) == RS_OK);
  rs_defect_limits lim = {.E_theta = 3.0e9, .radial = &law, .caliper = 1e-3,
                          .hoop_strength = 2.0e7};
  for (int j = 5; j < 12; ++j) r->sigma_theta[j] = -1.0e7;
  r->sigma_theta[8] = -2.5e7;
  rs_defect_report *rep = assess(r, &lim);
  CHECK(rep->starring.verdict == RS_DEFECT_RISK);
  CHECK(rep->starring.criterion == RS_STARRING_STRENGTH);
  CHECK(strcmp(rs_starring_criterion_name(rep->starring.criterion), "hoop_strength") == 0);
  CHECK_CLOSE(rep->starring.margin_min, 0.8, 1e-15);
  CHECK(rep->starring.layers == 1 && rep->starring.ranges[0].first == 8);
  CHECK(rep->starring.zones == 1 && rep->starring.compressed == 7);
  CHECK(rep->starring.zone_first == 5 && rep->starring.zone_last == 11);
  CHECK_CLOSE(rep->starring.zone_from_core, 5e-3, 1e-12);
  CHECK_CLOSE(rep->starring.zone_to_core, 12e-3, 1e-12);
  CHECK_CLOSE(rep->starring.force, 1e-3 * (6 * 1.0e7 + 2.5e7), 1e-14);
  CHECK(rep->starring.bonded == 1); /* no friction given, no gap: the zone sticks */
  rs_defect_report_destroy(&rep);
  /* under the strength: ok, the packet (far stiffer) does not decide */
  r->sigma_theta[8] = -1.0e7;
  rep = assess(r, &lim);
  CHECK(rep->starring.verdict == RS_DEFECT_OK && rep->starring.layers == 0);
  CHECK_CLOSE(rep->starring.strength_margin, 2.0, 1e-15);
  CHECK(rep->starring.criterion == RS_STARRING_STRENGTH);
  rs_defect_report_destroy(&rep);
  free(r->radius), free(r->sigma_r), free(r->sigma_theta), free(r->web_tension), free(r);
}

/* (b) The same zone bonded (friction holds) and slipping (its interfaces opened): the
 * slipping packet's margin is far lower, and a gap makes the layers slip. */
static void starring_bonded_and_slipping(void)
{
  rs_reel_result *r = profile(60);
  rs_radial_law law = {.law = RS_RADIAL_LINEAR, .E_r = 2.0e7};
  CHECK(rs_radial_law_prepare(&law) == RS_OK);
  rs_defect_limits lim = {.E_theta = 3.0e9, .radial = &law, .caliper = 1e-3};
  for (int j = 0; j < 20; ++j) r->sigma_theta[j] = -3.0e6;
  rs_defect_report *rep = assess(r, &lim);
  double bonded = rep->starring.packet_margin;
  CHECK(rep->starring.bonded == 1 && rep->starring.criterion == RS_STARRING_PACKET);
  CHECK_LOG("bonded margin", bonded);
  CHECK_LOG("bonded mode", rep->starring.mode);
  rs_defect_report_destroy(&rep);
  for (int j = 0; j < 19; ++j) r->sigma_r[j] = 0.0; /* opened interfaces */
  rep = assess(r, &lim);
  CHECK(rep->starring.bonded == 0);
  CHECK_LOG("slipping margin", rep->starring.packet_margin);
  CHECK_LOG("slipping mode", rep->starring.mode);
  CHECK_LT(rep->starring.packet_margin, 0.1 * bonded);
  CHECK(rep->starring.verdict == (rep->starring.packet_margin < 1.0 ? RS_DEFECT_RISK : RS_DEFECT_OK));
  rs_defect_report_destroy(&rep);
  /* no compression: ok, nothing weighed; no radial law: not assessed */
  for (int j = 0; j < 20; ++j) r->sigma_theta[j] = 1.0e6;
  rep = assess(r, &lim);
  CHECK(rep->starring.verdict == RS_DEFECT_OK && rep->starring.compressed == 0);
  rs_defect_report_destroy(&rep);
  lim.radial = NULL;
  rep = assess(r, &lim);
  CHECK(rep->starring.verdict == RS_DEFECT_NOT_ASSESSED);
  rs_defect_report_destroy(&rep);
  free(r->radius), free(r->sigma_r), free(r->sigma_theta), free(r->web_tension), free(r);
}

/* Uniform P on a center-wound roll: interface r carries T R + M (R^4 - r^4) / (R^4 - r_c^4)
 * and holds mu P 2 pi r^2. By hand at the first interface (r = 0.101 m, R = 0.2 m,
 * T R = 60 N m/m, M = 1000 N m/m, mu = 0.25, P = 1e5 Pa):
 * f_in = (0.101^4 - 0.1^4) / (0.2^4 - 0.1^4) = 0.0027069, torque 60 + 1000 (1 - f_in)
 * = 1057.29 N m/m, capacity 0.25e5 2 pi 0.101^2 = 1602.37 N m/m: margin 1.5155. */
static void slip_uniform_pressure(void)
{
  const int n = 100;
  rs_reel_result *r = profile(n);
  rs_defect_limits lim = {.accel_torque = 1000.0, .friction_layer = 0.25, .core_share = 1.0};
  rs_defect_report *rep = assess(r, &lim);
  double f_in = (pow(0.101, 4) - 1e-4) / (pow(0.2, 4) - 1e-4);
  double M = 300.0 * 0.2 + 1000.0 * (1.0 - f_in), cap = 0.25 * 1e5 * 2.0 * pi * 0.101 * 0.101;
  CHECK_LOG("f_in at the first interface", f_in);
  CHECK_LOG("torque there (N m/m)", M);
  CHECK_LOG("capacity there (N m/m)", cap);
  CHECK_LOG("margin", rep->slip.margin_min);
  CHECK(rep->slip.verdict == RS_DEFECT_OK);
  CHECK(rep->slip.margin_radius == r->radius[0]);
  CHECK_CLOSE(rep->slip.margin_min, cap / M, 1e-13);
  CHECK_CLOSE(rep->slip.margin_min, 1.5155, 1e-4); /* the hand value */
  CHECK_CLOSE(rep->slip.margin_torque, M, 1e-13);
  CHECK_CLOSE(rep->slip.tension_torque, 60.0, 1e-15);
  rs_defect_report_destroy(&rep);
  /* a torque four times the capacity at the first interface: it slips there, the
   * interfaces outside r* = where capacity = torque do not */
  lim.accel_torque = 4.0 * cap;
  rep = assess(r, &lim);
  CHECK(rep->slip.verdict == RS_DEFECT_RISK && rep->slip.n_ranges == 1);
  int k = 0;
  for (int j = 0; j < n - 1; ++j) {
    double rr = r->radius[j], fi = (pow(rr, 4) - 1e-4) / (pow(0.2, 4) - 1e-4);
    k += 0.25e5 * 2.0 * pi * rr * rr < 60.0 + 4.0 * cap * (1.0 - fi);
  }
  CHECK_LOG("interfaces that slip", k);
  CHECK(rep->slip.layers == k && rep->slip.ranges[0].first == 0 && k > 1 && k < n - 1);
  rs_defect_report_destroy(&rep);
  free(r->radius), free(r->sigma_r), free(r->sigma_theta), free(r->web_tension), free(r);
}

/* winding.acceleration a: alpha = a / R and the rigid-body inertia I = sum over the layers
 * of the annuli's rho pi (r_j^4 - r_(j-1)^4) / 2 (summed here layer by layer): the core
 * interface of a center-wound roll carries T R + I alpha, a surface-wound roll's outermost
 * interface I_in alpha and its core interface nothing (the core's own inertia left out). */
static void slip_inertia_torque(void)
{
  const int n = 100;
  rs_reel_result *r = profile(n);
  const double rho = 800.0, a = 2.0, R = 0.2;
  rs_defect_limits lim = {.acceleration = a, .density = rho, .friction_layer = 0.3,
                          .core_share = 1.0, .core_friction = 0.2};
  double I = 0.0, prev = 0.1;
  for (int j = 0; j < n; ++j) {
    I += rho * pi * (pow(r->radius[j], 4) - pow(prev, 4)) / 2.0;
    prev = r->radius[j];
  }
  rs_defect_report *rep = assess(r, &lim);
  CHECK_LOG("I (kg m^2/m)", I);
  CHECK_LOG("inertia torque (N m/m)", rep->slip.torque);
  CHECK_CLOSE(rep->slip.alpha, a / R, 1e-15);
  CHECK_CLOSE(rep->slip.torque, I * a / R, 1e-13);
  double M_core = 60.0 + I * a / R, cap = 0.2 * 1e5 * 2.0 * pi * 0.01;
  CHECK_CLOSE(rep->slip.core_margin, cap / M_core, 1e-13);
  CHECK_CLOSE(rs_defect_interface_torque(1.0, 60.0, I * a / R, 0.1, 0.1, R), M_core, 1e-15);
  CHECK_CLOSE(rs_defect_interface_torque(1.0, 60.0, I * a / R, R, 0.1, R), 60.0, 1e-15);
  rs_defect_report_destroy(&rep);
  /* surface winding: the outermost interface (r = 0.199 m) carries I_in alpha */
  lim.core_share = 0.0;
  double I_in = I - rho * pi * (pow(0.2, 4) - pow(0.199, 4)) / 2.0;
  CHECK_CLOSE(rs_defect_interface_torque(0.0, 60.0, I * a / R, 0.199, 0.1, R), I_in * a / R,
              1e-12);
  rep = assess(r, &lim);
  CHECK(isinf(rep->slip.core_margin)); /* no torque through the core interface */
  double rm = rep->slip.margin_radius, f = (pow(rm, 4) - 1e-4) / (pow(R, 4) - 1e-4);
  CHECK_CLOSE(rep->slip.margin_torque, f * I * a / R, 1e-12);
  rs_defect_report_destroy(&rep);
  free(r->radius), free(r->sigma_r), free(r->sigma_theta), free(r->web_tension), free(r);
}

/* The outermost wraps take the torque entering at the surface by capstan friction: with
 * T0 = 450 N/m wound on and the tension's torque T R (T = 300 N/m) the capstan needs
 * k_c = ceil(ln(1 + T / T0) / (2 pi mu)) wraps: 1 at mu = 0.3, 2 at 0.05, 5 at 0.02 (by
 * hand: ln(5/3) = 0.5108). The check starts under them: the interfaces above are not
 * flagged even where their pressure is only the last layer's T0 / r. */
static void slip_capstan_outermost(void)
{
  const int n = 50;
  rs_reel_result *r = profile(n);
  r->wound_on_tension = malloc((size_t)n * sizeof(double));
  for (int j = 0; j < n; ++j) r->wound_on_tension[j] = 450.0;
  const double mu[] = {0.3, 0.05, 0.02};
  const int want[] = {1, 2, 5};
  for (int i = 0; i < 3; ++i) {
    const int first = n - 2 - want[i]; /* the interface under the capstan wraps */
    for (int j = 0; j < n - 1; ++j) r->sigma_r[j] = j >= first ? -450.0 / r->radius[j] : -1.0e6;
    rs_defect_limits lim = {.friction_layer = mu[i], .core_share = 1.0};
    rs_defect_report *rep = assess(r, &lim);
    CHECK_LOG("mu", mu[i]);
    CHECK_LOG("capstan wraps", rep->slip.capstan_layers);
    CHECK(rep->slip.capstan_layers == want[i]);
    double M = 300.0 * r->radius[n - 1];
    double m_first = rs_defect_slip_capacity(mu[i], 450.0 / r->radius[first], r->radius[first]) / M;
    CHECK_LOG("margin there", m_first);
    CHECK(rep->slip.margin_radius == r->radius[first]);
    CHECK_CLOSE(rep->slip.margin_min, m_first, 1e-14);
    rs_defect_report_destroy(&rep);
  }
  CHECK_CLOSE(log(5.0 / 3.0), 0.5108256237659907, 1e-15);
  free(r->wound_on_tension);
  free(r->radius), free(r->sigma_r), free(r->sigma_theta), free(r->web_tension), free(r);
}

/* The scene keys: material.hoop_strength, core.friction, winding.acceleration and their
 * refusals; the winder's core share. */
static void verdict_scene_keys(void)
{
  const char *sets[] = {"material.hoop_strength=2e7", "core.friction=0.25",
                        "material.friction_layer=0.3", "material.density=650",
                        "winding.acceleration=1.5"};
  rs_scene *sc = NULL;
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", 5, sets, &sc) == RS_OK);
  if (!sc) return;
  rs_defect_limits lim;
  rs_defect_limits_from_problem(rs_scene_problem(sc), &lim);
  CHECK(lim.hoop_strength == 2e7 && lim.core_friction == 0.25 && lim.acceleration == 1.5);
  CHECK(lim.density == 650.0 && lim.core_share == 1.0 && lim.caliper == 70e-6);
  rs_scene_destroy(&sc);
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-surface.yaml", 0, NULL, &sc) == RS_OK);
  if (sc) {
    double s = rs_defect_core_share(rs_scene_problem(sc));
    CHECK_LOG("core share of newsprint-surface", s);
    CHECK(s == 0.0);
    rs_scene_destroy(&sc);
  }
  const char *bad[][3] = {{"material.hoop_strength=0", NULL, NULL},
                          {"core.friction=-1", NULL, NULL},
                          {"winding.acceleration=1", "material.friction_layer=0.3", NULL},
                          {"winding.acceleration=1", "material.density=650", NULL},
                          {"winding.acceleration=1", "material.density=650",
                           "winding.accel_torque=5"}};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    int k = bad[i][2] ? 3 : bad[i][1] ? 2 : 1;
    const char *with[4] = {bad[i][0], bad[i][1], bad[i][2], "material.friction_layer=0.3"};
    if (i == 4) k = 4;
    CHECK(rs_scene_load(RS_ROOT_DIR "/cases/newsprint-rider.yaml", k, with, &sc) == RS_ERR_INPUT);
    printf("  %s -> %s\n", bad[i][0], rs_error_message());
    rs_scene_destroy(&sc);
  }
}

static const check_case cases[] = {
    {"ring_single_layer_limit", ring_single_layer_limit},
    {"ring_stack_one_ring", ring_stack_one_ring},
    {"ring_stack_rigid_packet", ring_stack_rigid_packet},
    {"ring_stack_scan_exact", ring_stack_scan_exact},
    {"ring_stack_in_tension_exact", ring_stack_in_tension_exact},
    {"starring_strength_and_zone", starring_strength_and_zone},
    {"starring_bonded_and_slipping", starring_bonded_and_slipping},
    {"slip_uniform_pressure", slip_uniform_pressure},
    {"slip_inertia_torque", slip_inertia_torque},
    {"slip_capstan_outermost", slip_capstan_outermost},
    {"verdict_scene_keys", verdict_scene_keys},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
