/* Hard cases for the contact nip (seed paper eqs. (12)-(22), docs/nip.md): the solver at the
 * edges of its physics and numerics, each with a stated expectation that does not come from
 * the solver itself (docs/robustness.md has the table with the measured values). Every
 * converged nip is also held to eqs. (20)-(21) (sheet, winder torque, load), Coulomb's law
 * element by element and finite output (check_nip).
 *
 *   rubber_cover_099        rubber cover R0/R = 0.5 .. 0.99 on a rigid core: a falls
 *                           monotonically (Rayleigh: more rigid material, stiffer) towards the
 *                           steel drum's; the default series against 4096 terms
 *   friction_zero           mu = 0: T0 = Ti, no shear, a and p independent of Ti, delta0
 *                           shifts by -c12 Ti; mu_roll = 0 on a surface winder: T0 = 0
 *                           (center-surface: share Ti); mu_drum = 0 there is refused
 *   friction_two            mu = 2: slip only at the edges, fewer slip elements as mu doubles,
 *                           T0 within 0.01 mu P of the full-stick limit (mu = 1e3)
 *   light_load_hertz        a/R = 1e-5 and 1e-6, 8 to 64 nodes, Ti >> P: Hertz, first order
 *                           in dx (a frictionless drum failed here: fixed)
 *   light_load_winkler      P = 1e-3 .. 1e-5 N/m on a paper stack: the sheet as a Winkler
 *                           layer between rigid cylinders, approached at first order in
 *                           a / (C E*)
 *   heavy_load              a/R = 0.05: Hertz (vanishing sheet) to 1 %; a paper stack at
 *                           a = 0.05 min(R1, R2) for all winders, load -> width -> load
 *   complex_roots_continuity  roll constants across the real/complex boundary of eq. (7)
 *                           (G* and the double roots of single modes): a and T0 continuous
 *   nodes_400               M = 400 (no LCP: active set from full stick): bounded passes,
 *                           a of second order in dx, T0 within a first-order bound
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "nip/nip_contact.h"
#include "hard/nip_stack.h"

/* ---- a thin rubber cover on the drum ---------------------------------------------------- */

/* A rubber-covered drum (E = 8 MPa, nu = 0.48, R = 0.1 m) on a rigid core, R0/R from 0.01
 * (solid rubber) to 0.99 (a 1 mm cover), against the paper roll; the limit is the steel
 * drum. Expectations: replacing rubber by rigid core only adds constraints, so the drum
 * gets stiffer (Rayleigh) and the contact narrower: a falls strictly with R0/R; it stays
 * above the steel drum's a, and the gap (a - a_steel)/(a_solid - a_steel) is below 0.3 at
 * R0/R = 0.99 (measured 0.25). A cover thinner than the contact is wide needs many series
 * terms (the cover's thickness is the length scale): the default 256 accelerated terms
 * against 4096 within 2e-3 in a and T0 (measured 1.1e-3, 1.0e-3; nip.terms raises it). */
static void rubber_cover_099(void)
{
  const double rho[] = {0.01, 0.5, 0.9, 0.95, 0.98, 0.99}, P = 1750, Ti = 350;
  const int n = (int)(sizeof rho / sizeof rho[0]);
  stack s = paper_stack();
  s.drum = iso(8e6, 0.48);
  s.Rd = 0.1;
  s.mu_drum = 0.6;
  double a[6], T0[6];
  nip_counts c;
  for (int i = 0; i < n; ++i) {
    s.Rd0 = rho[i] * s.Rd;
    rs_nip_solution r = {0};
    CHECK(solve(&s, P, Ti, &r) == RS_OK);
    check_nip(&s, &r, P, &c);
    a[i] = r.a;
    T0[i] = r.T0;
    printf("  R0/R = %-5g a = %.17g m  T0 = %.17g N/m  peak p = %.6g Pa  slip %d/%d  cond %.3g\n",
           rho[i], r.a, r.T0, pmax_of(&r), c.slip_u, c.slip_l, r.condition_number);
    if (i > 0) CHECK_LT(a[i], a[i - 1]);
    rs_nip_solution_free(&r);
  }
  /* the limit: the core's material, steel, as a solid drum */
  stack st = s;
  st.drum = iso(2.1e11, 0.3);
  st.Rd0 = 0.01 * st.Rd;
  rs_nip_solution r = {0};
  CHECK(solve(&st, P, Ti, &r) == RS_OK);
  check_nip(&st, &r, P, &c);
  double a_st = r.a, gap = (a[n - 1] - a_st) / (a[0] - a_st);
  CHECK_LOG("steel drum: a (m)", a_st);
  CHECK_LOG("steel drum: T0 (N/m)", r.T0);
  CHECK_LOG("gap (a - a_steel)/(a_solid - a_steel) at 0.99", gap);
  CHECK_LT(a_st, a[n - 1]);
  CHECK_LT(gap, 0.3);
  /* the series at R0/R = 0.99 */
  s.Rd0 = 0.99 * s.Rd;
  s.terms = 4096;
  CHECK(solve(&s, P, Ti, &r) == RS_OK);
  check_nip(&s, &r, P, &c);
  CHECK_LOG("0.99, 4096 terms: a (m)", r.a);
  CHECK_LOG("default / 4096 terms - 1: a", a[n - 1] / r.a - 1);
  CHECK_LOG("default / 4096 terms - 1: T0", T0[n - 1] / r.T0 - 1);
  CHECK_LT(fabs(a[n - 1] / r.a - 1), 2e-3);
  CHECK_LT(fabs(T0[n - 1] / r.T0 - 1), 2e-3);
  rs_nip_solution_free(&r);
}

/* ---- friction 0 and 2 ------------------------------------------------------------------ */

static double max_shear(const rs_nip_solution *r)
{
  double m = 0;
  for (int e = 0; e < r->M - 1; ++e) m = fmax(m, fmax(fabs(r->shear_upper[e]), fabs(r->shear_lower[e])));
  return m;
}

/* mu = 0 (the paper stack, P = 1750 N/m). Derived from eqs. (12)-(22):
 *  - center winder (rider M2 = 0): no shear can act (slip with mu = 0 carries none, and the
 *    one stuck rider element carries int tau- = 0), so N = Ti through the nip and T0 = Ti;
 *  - the tension then only thins the sheet uniformly, v+ - v- = c12 N (eq. (11) corrected),
 *    so p and a do not depend on Ti and the approach moves by exactly -c12 Ti;
 *  - surface winder, mu_roll = 0, mu_drum > 0: eq. (20) with M1 = 0 and no shear on the roll
 *    gives T0 = 0 (the drum carries all of Ti); center-surface: T0 = share Ti;
 *  - surface winder with mu_drum = 0: the drum cannot carry Ti: refused (RS_ERR_INPUT). */
static void friction_zero(void)
{
  const double P = 1750, Tis[] = {0, 350, 700};
  stack s = paper_stack();
  s.mu_roll = s.mu_drum = 0;
  rs_nip_solution r0 = {0}, r = {0};
  nip_counts c;
  CHECK(solve(&s, P, Tis[0], &r0) == RS_OK);
  check_nip(&s, &r0, P, &c);
  for (int i = 1; i < 3; ++i) {
    CHECK(solve(&s, P, Tis[i], &r) == RS_OK);
    check_nip(&s, &r, P, &c);
    double dp = 0;
    for (int j = 0; j < r.M; ++j) dp = fmax(dp, fabs(r.pressure[j] - r0.pressure[j]));
    printf("  Ti = %-4g T0 - Ti = %.3g  max|q| = %.3g Pa  a/a(Ti=0) - 1 = %.3g  max dp/pmax = %.3g\n"
           "          delta0 - delta0(Ti=0) = %.17g m, -c12 Ti = %.17g m\n",
           Tis[i], r.T0 - Tis[i], max_shear(&r), r.a / r0.a - 1, dp / pmax_of(&r0),
           r.delta0 - r0.delta0, -s.sheet.c12 * Tis[i]);
    CHECK_ABS(r.T0, Tis[i], 1e-12 * (P + Tis[i]));
    CHECK(max_shear(&r) <= 1e-10 * pmax_of(&r));
    CHECK(c.slip_u == r.M - 1); /* frictionless: every roll element slips */
    CHECK_CLOSE(r.a, r0.a, 2e-9);
    CHECK(dp <= 1e-8 * pmax_of(&r0));
    CHECK_CLOSE(r.delta0 - r0.delta0, -s.sheet.c12 * Tis[i], 1e-3);
  }
  /* surface and center-surface winders with a frictionless roll side */
  const rs_winder_kind w[2] = {RS_WINDER_SURFACE, RS_WINDER_CENTER_SURFACE};
  for (int k = 0; k < 2; ++k) {
    s.winder = w[k];
    s.mu_drum = 0.35;
    CHECK(solve(&s, P, 350, &r) == RS_OK);
    check_nip(&s, &r, P, &c);
    printf("  %s, mu_roll = 0: T0 = %.17g N/m (share Ti = %g)\n", k ? "center-surface" : "surface",
           r.T0, share_of(&s) * 350);
    CHECK_ABS(r.T0, share_of(&s) * 350, 1e-12 * (P + 350));
  }
  s.winder = RS_WINDER_SURFACE;
  s.mu_drum = 0;
  rs_nip_contact *nc = make(&s);
  rs_status st = rs_nip_contact_solve_load(nc, P, 350, &r);
  printf("  surface, mu_drum = 0: %s\n", rs_error_message());
  CHECK(st == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "nip.friction.drum") != NULL);
  rs_nip_contact_destroy(&nc);
  rs_nip_solution_free(&r);
  rs_nip_solution_free(&r0);
}

/* mu = 2 on both contacts, the three winders (paper stack, P = 1750 N/m). Not full stick:
 * the full-stick shear is singular at the nip edges, where p -> 0, so the edge elements
 * slip at any finite mu (tests/validation/test_nip_contact.c: still at mu = 50; none at
 * 1e3). What holds: the slip zones shrink to the edges as mu grows: fewer slip elements at
 * each doubling of mu (0.5, 1, 2), at mu = 2 every slipping element within 20 % of the
 * contact width from an edge, and T0 within 0.01 mu P of the full-stick limit (mu = 1e3,
 * no slip element); the friction-nip limit |T0 - share Ti| <= mu P (check_nip). */
static void friction_two(void)
{
  const double P = 1750, Ti = 350, mus[] = {0.5, 1, 2, 1e3};
  const rs_winder_kind w[3] = {RS_WINDER_CENTER, RS_WINDER_SURFACE, RS_WINDER_CENTER_SURFACE};
  for (int k = 0; k < 3; ++k) {
    stack s = paper_stack();
    s.winder = w[k];
    int nslip[4];
    double T0[4];
    nip_counts c[4];
    for (int i = 0; i < 4; ++i) {
      s.mu_roll = s.mu_drum = mus[i];
      rs_nip_solution r = {0};
      CHECK(solve(&s, P, Ti, &r) == RS_OK);
      check_nip(&s, &r, P, &c[i]);
      nslip[i] = c[i].slip_u + c[i].slip_l;
      T0[i] = r.T0;
      printf("  winder %d mu %-5g T0 = %.17g  slip elements %d + %d of %d (at the edges %d + %d)"
             "  Lemke pivots %d\n", k, mus[i], r.T0, c[i].slip_u, c[i].slip_l, r.M - 1,
             c[i].edge_u, c[i].edge_l, r.lcp_pivots);
      rs_nip_solution_free(&r);
    }
    CHECK_LT(nslip[1], nslip[0]);
    CHECK_LT(nslip[2], nslip[1]);
    CHECK(nslip[2] > 0); /* the edges still slip at mu = 2 */
    CHECK(c[2].edge_u == c[2].slip_u && c[2].edge_l == c[2].slip_l);
    CHECK(nslip[3] == 0);
    printf("  winder %d: |T0(mu 2) - T0(stick)| / (mu P) = %.17g\n", k, fabs(T0[2] - T0[3]) / (2 * P));
    CHECK_LT(fabs(T0[2] - T0[3]), 0.01 * 2 * P);
  }
}

/* ---- light and heavy loads ----------------------------------------------------------------- */

/* Light load, vanishing sheet, frictionless (the Hertz setting of tests/validation/
 * test_hertz.c), web tension 100 N/m against P ~ 1e-2 .. 1 N/m: a/R = 1e-5 and 1e-6 on 8, 16
 * and 64 nodes. Hertz (Johnson 1985, eq. 4.45) is exact as a/R -> 0, so: a/a_H - 1 is the
 * discretisation error alone, the same at both loads (to 1e-5), of first order in dx:
 * (M - 1)(a/a_H - 1) in [0.15, 0.35] (measured 0.26, 0.24, 0.23); the peak pressure within
 * 1 % of p0 = 2P/(pi a). With friction (mu = 0.3) on 8 nodes it converges too.
 * Bug found: with a frictionless drum the one stuck rider element (it defines xi2, its
 * exact shear is 0) carried a round-off shear ~1e-14 Ti/(2a), larger than the iteration's
 * round-off floor 1e-14 pmax when Ti >> P: "the drum contact would slip everywhere". */
static void light_load_hertz(void)
{
  const int Ms[] = {8, 16, 64};
  const double aRs[] = {1e-5, 1e-6}, Es = hertz_estar();
  for (int m = 0; m < 3; ++m) {
    double dev[2];
    for (int i = 0; i < 2; ++i) {
      stack s = hertz_stack();
      s.M = Ms[m];
      double a = aRs[i] * s.Rd, P = PI * a * a * Es / (4 * rstar(&s)), p0 = 2 * P / (PI * a);
      rs_nip_solution r = {0};
      nip_counts c;
      CHECK(solve(&s, P, 100, &r) == RS_OK);
      check_nip(&s, &r, P, &c);
      dev[i] = r.a / a - 1;
      printf("  M = %-3d a/R = %-6g P = %-10.4g a/a_H - 1 = %+.6e  (M-1)(a/a_H - 1) = %.4f  "
             "p_max/p0 - 1 = %+.3e  T0 - Ti = %.3g\n", Ms[m], aRs[i], P, dev[i],
             (Ms[m] - 1) * dev[i], pmax_of(&r) / p0 - 1, r.T0 - 100);
      CHECK((Ms[m] - 1) * dev[i] > 0.15 && (Ms[m] - 1) * dev[i] < 0.35);
      CHECK_LT(fabs(pmax_of(&r) / p0 - 1), 0.01);
      CHECK_ABS(r.T0, 100, 1e-10);
      rs_nip_solution_free(&r);
    }
    CHECK_ABS(dev[1], dev[0], 1e-5);
  }
  stack s = hertz_stack();
  s.M = 8;
  s.mu_roll = s.mu_drum = 0.3;
  double a = 1e-5 * s.Rd, P = PI * a * a * Es / (4 * rstar(&s));
  rs_nip_solution r = {0};
  nip_counts c;
  CHECK(solve(&s, P, 100, &r) == RS_OK);
  check_nip(&s, &r, P, &c);
  CHECK_LOG("mu 0.3, M = 8: a / a_H - 1", r.a / a - 1);
  rs_nip_solution_free(&r);
}

/* Light load on the paper stack, P = 1e-3 .. 1e-5 N/m under Ti = 350 N/m (Ti/(2a) is
 * 1e5-1e7 times the peak pressure). The cylinders' indentation ~ p a / E* is then small
 * against the sheet's thinning 2h c22 p = C p, so the limit is the sheet as a Winkler layer
 * between rigid cylinders: p = (a^2 - x^2)/(2 R* C), a_W = (3 P R* C / 2)^(1/3), approached
 * at first order in a/(C E*): (a/a_W - 1) / (a/(C E*)) in [0.2, 0.5] (measured 0.31-0.33,
 * M = 64), falling with P; the peak pressure below p_W. With friction on both contacts,
 * and with a frictionless rider (mu_drum = 0, the case of the bug in light_load_hertz:
 * it failed here at P = 1e-2 N/m before the fix); on 8 nodes a within 2 % of a_W. */
static void light_load_winkler(void)
{
  const double Ps[] = {1e-3, 1e-4, 1e-5}, mud[] = {0.35, 0.0};
  for (int f = 0; f < 2; ++f) {
    stack s = paper_stack();
    s.mu_drum = mud[f];
    double H1[2][2], H2[2][2];
    CHECK(rs_ortho_halfplane(&s.roll, H1) == RS_OK);
    CHECK(rs_ortho_halfplane(&s.drum, H2) == RS_OK);
    const double Es = 2 / (H1[0][0] + H2[0][0]), C = 2 * s.sheet.h * s.sheet.c22, Rs = rstar(&s);
    double prev = INFINITY;
    for (int i = 0; i < 3; ++i) {
      double aW = cbrt(1.5 * Ps[i] * Rs * C), pW = aW * aW / (2 * Rs * C);
      rs_nip_solution r = {0};
      nip_counts c;
      CHECK(solve(&s, Ps[i], 350, &r) == RS_OK);
      check_nip(&s, &r, Ps[i], &c);
      double x = r.a / (C * Es), e = r.a / aW - 1;
      printf("  mu_drum %-4g P = %-6g a/(C E*) = %.4e  a/a_W - 1 = %.6e  ratio %.4f  p_max/p_W - 1 "
             "= %+.4e  NIT/(mu P) = %.4f  Ti/(2a)/p_max = %.3g\n", mud[f], Ps[i], x, e, e / x,
             pmax_of(&r) / pW - 1, (r.T0 - 350) / (s.mu_roll * Ps[i]), 350 / (2 * r.a) / pmax_of(&r));
      CHECK(e / x > 0.2 && e / x < 0.5);
      CHECK_LT(e, prev);
      CHECK_LT(pmax_of(&r), pW);
      prev = e;
      rs_nip_solution_free(&r);
    }
    s.M = 8;
    double aW = cbrt(1.5 * Ps[2] * Rs * C);
    rs_nip_solution r = {0};
    nip_counts c;
    CHECK(solve(&s, Ps[2], 350, &r) == RS_OK);
    check_nip(&s, &r, Ps[2], &c);
    CHECK_LOG("M = 8, P = 1e-5: a/a_W - 1", r.a / aW - 1);
    CHECK_LT(fabs(r.a / aW - 1), 0.02);
    rs_nip_solution_free(&r);
  }
}

/* Heavy load, a/R = 0.05 of the smaller cylinder.
 *  - vanishing sheet, frictionless: Hertz holds to O(a/R): a and the peak pressure within
 *    1 % of Hertz on 64 nodes (measured 1.1e-3 and 3.0e-3);
 *  - the paper stack at a = 0.05 R_drum = 15 mm (P ~ 53 kN/m, from the half-width), all three
 *    winders: the load search returns that half-width (to 1e-8), everything of check_nip;
 *    at a/(C E*) = 80 the sheet's compliance is a small part, so Hertz with the orthotropic
 *    E* = 2/(H11_roll + H11_drum) holds to 1 % too (measured 0.17 %). */
static void heavy_load(void)
{
  stack s = hertz_stack();
  double a = 0.05 * s.Rd, P = PI * a * a * hertz_estar() / (4 * rstar(&s)), p0 = 2 * P / (PI * a);
  rs_nip_solution r = {0};
  nip_counts c;
  CHECK(solve(&s, P, 100, &r) == RS_OK);
  check_nip(&s, &r, P, &c);
  CHECK_LOG("Hertz stack, a/R = 0.05: P (N/m)", P);
  CHECK_LOG("a / a_H - 1", r.a / a - 1);
  CHECK_LOG("p_max / p0 - 1", pmax_of(&r) / p0 - 1);
  CHECK_LT(fabs(r.a / a - 1), 0.01);
  CHECK_LT(fabs(pmax_of(&r) / p0 - 1), 0.01);

  const rs_winder_kind w[3] = {RS_WINDER_CENTER, RS_WINDER_SURFACE, RS_WINDER_CENTER_SURFACE};
  for (int k = 0; k < 3; ++k) {
    stack p = paper_stack();
    p.winder = w[k];
    const double aw = 0.05 * fmin(p.R, p.Rd);
    rs_nip_contact *nc = make(&p);
    CHECK(rs_nip_contact_solve_width(nc, aw, 350, &r) == RS_OK);
    double Pw = r.load;
    rs_nip_contact_forget(nc);
    CHECK(rs_nip_contact_solve_load(nc, Pw, 350, &r) == RS_OK);
    check_nip(&p, &r, Pw, &c);
    double H1[2][2], H2[2][2];
    CHECK(rs_ortho_halfplane(&p.roll, H1) == RS_OK);
    CHECK(rs_ortho_halfplane(&p.drum, H2) == RS_OK);
    double aH = sqrt(4 * Pw * rstar(&p) / (PI * 2 / (H1[0][0] + H2[0][0])));
    printf("  winder %d: P(a = %g m) = %.17g N/m, load search a/a - 1 = %.3g, a/a_Hertz - 1 = %.4f, "
           "T0 = %.10g, NIT/(mu P) = %.4f, half-widths %d, cond %.3g\n", k, aw, Pw, r.a / aw - 1,
           r.a / aH - 1, r.T0, (r.T0 - share_of(&p) * 350) / (p.mu_roll * Pw), r.width_iterations,
           r.condition_number);
    CHECK_CLOSE(r.a, aw, 1e-8);
    CHECK_LT(fabs(r.a / aH - 1), 0.01);
    rs_nip_contact_destroy(&nc);
  }
  rs_nip_solution_free(&r);
}

/* ---- orthotropy with complex characteristic roots ------------------------------------------ */

/* eq. (7): sign of mu_n^2 - kappa_n (> 0: real roots, < 0: a complex pair), the paper's
 * formula (as tests/unit/test_cylinder.c) */
static double discriminant(const rs_ortho *o, double n)
{
  double mu = o->A_tt * o->G_rt - o->A_rt * (o->A_rt + 2 * o->G_rt) * n * n +
              o->A_rr * (o->G_rt + o->A_tt * n * n);
  double ka = 4 * o->A_rr * o->A_tt * o->G_rt * o->G_rt * (n * n - 1) * (n * n - 1);
  return mu * mu - ka;
}

/* G_rt at which mode n has a double root: mu_n = sqrt(kappa_n), i.e. (with q = sqrt(A_rr A_tt))
 * G (sqrt A_rr + sqrt A_tt)^2 + n^2 (q + A_rt)(q - A_rt - 2G) = 0; n -> inf: G* = (q - A_rt)/2.
 * Above it mode n has complex roots. 0 if no such G (low modes of a strongly orthotropic
 * body stay real). */
static double g_double_root(const rs_ortho *o, double n)
{
  double q = sqrt(o->A_rr * o->A_tt), s2 = o->A_rr + o->A_tt + 2 * q;
  if (n <= 0) return 0.5 * (q - o->A_rt);
  double den = 2 * n * n * (q + o->A_rt) - s2;
  return den > 0 ? n * n * (q + o->A_rt) * (q - o->A_rt) / den : 0.0;
}

typedef struct at_g { double a, T0; } at_g;

static at_g nip_at_g(stack *s, double G, double P)
{
  s->roll.G_rt = G;
  rs_nip_solution r = {0};
  nip_counts c;
  at_g v = {NAN, NAN};
  CHECK(solve(s, P, 350, &r) == RS_OK);
  check_nip(s, &r, P, &c);
  v.a = r.a;
  v.T0 = r.T0;
  rs_nip_solution_free(&r);
  return v;
}

/* A strongly orthotropic paper roll (E_theta/E_r = 167) whose shear modulus crosses the
 * real/complex boundary of eq. (7) inside a full nip solve (mu_roll 0.5, P = 1750 N/m, partial
 * slip on both contacts). The boundary is G* = (sqrt(A_rr A_tt) - A_rt)/2 for the high modes
 * (n -> inf) and G_n > G* for mode n (double root); the cylinder module's basis is built to
 * pass through a double root (src/cylinder/modes.c). Expectations: the root type really
 * changes (the paper's discriminant at n = 1e3, 1e5 and at the mode n itself); every solve
 * converges (G from G* / 4 to 8 G*, every solve held to check_nip); continuity: across each
 * boundary Gc, a and T0 change over Gc (1 -+ 1e-5) by at most 3e-3 of their change over
 * Gc (1 -+ 1e-2) (1e-3 for a function differentiable there; a jump would not shrink). */
static void complex_roots_continuity(void)
{
  const double P = 1750;
  stack s = paper_stack();
  s.mu_roll = 0.5;
  const double Gs = g_double_root(&s.roll, 0);
  int n0 = 2;
  while (g_double_root(&s.roll, n0) <= 0) ++n0;
  CHECK_LOG("G* (n -> inf, Pa)", Gs);
  CHECK_LOG("lowest mode with a double root", n0);
  CHECK_LOG("its G (Pa)", g_double_root(&s.roll, n0));
  /* the root type changes at each boundary */
  rs_ortho o = s.roll;
  o.G_rt = Gs * (1 - 1e-3);
  CHECK(discriminant(&o, 1e3) > 0 && discriminant(&o, 1e5) > 0);
  o.G_rt = Gs * (1 + 1e-3);
  CHECK(discriminant(&o, 1e5) < 0);
  for (int n = n0; n <= n0 + 1; ++n) {
    o.G_rt = g_double_root(&s.roll, n) * (1 - 1e-6);
    CHECK(discriminant(&o, n) > 0);
    o.G_rt = g_double_root(&s.roll, n) * (1 + 1e-6);
    CHECK(discriminant(&o, n) < 0);
  }
  /* a scan over the boundaries */
  for (int k = -8; k <= 12; k += 2) {
    double G = Gs * pow(2.0, k / 4.0);
    at_g v = nip_at_g(&s, G, P);
    printf("  G/G* = %-8.4f a = %.12g m  T0 = %.12g N/m\n", G / Gs, v.a, v.T0);
  }
  /* continuity across G*, G_n0, G_n0+1 */
  const double Gc[3] = {Gs, g_double_root(&s.roll, n0), g_double_root(&s.roll, n0 + 1)};
  for (int i = 0; i < 3; ++i) {
    at_g lo = nip_at_g(&s, Gc[i] * (1 - 1e-5), P), hi = nip_at_g(&s, Gc[i] * (1 + 1e-5), P);
    at_g LO = nip_at_g(&s, Gc[i] * (1 - 1e-2), P), HI = nip_at_g(&s, Gc[i] * (1 + 1e-2), P);
    at_g at = nip_at_g(&s, Gc[i], P);
    double ra = fabs(hi.a - lo.a) / fabs(HI.a - LO.a), rT = fabs(hi.T0 - lo.T0) / fabs(HI.T0 - LO.T0);
    printf("  boundary G/G* = %.6f: a %.12g, T0 %.12g; change over +-1e-5 / over +-1e-2: a %.4g, "
           "T0 %.4g\n", Gc[i] / Gs, at.a, at.T0, ra, rT);
    CHECK_LT(ra, 3e-3);
    CHECK_LT(rT, 3e-3);
    /* the value on the boundary itself lies between its neighbours */
    CHECK((at.a - lo.a) * (hi.a - at.a) >= 0);
  }
}

/* ---- many nodes ------------------------------------------------------------------------------ */

/* M = 400 nodes (1200 unknowns): beyond 257 nodes the LCP is not built (its dense tableau),
 * so the cold start is the active-set iteration from full stick (the paper's steps).
 * Stack with partial slip on both contacts (E_r = 3e8 Pa, mu_roll 0.5, P = 6000 N/m, as the
 * validation's convergence_in_M). Expectations: converges; the passes of all half-widths
 * together stay within one pass budget 4M + 40 (measured ~90); a converges at second order
 * in dx (observed order from M = 100, 200, 400 at least 1.5, measured 1.9); T0 is piecewise
 * smooth in the discretisation (each element that switches between stick and slip moves it
 * by O(dx)), so it is held to a first-order bound: |T0(M) - T0(400)| <= 0.05 T0 / (M - 1)
 * for M = 64, 128, 200 (measured constant 0.032 at M = 64). */
static void nodes_400(void)
{
  const int Ms[] = {64, 100, 128, 200, 400};
  double a[5], T0[5];
  for (int i = 0; i < 5; ++i) {
    stack s = paper_stack();
    s.roll = paper_roll(3e8, 5e9, 3e8);
    s.mu_roll = 0.5;
    s.M = Ms[i];
    rs_nip_solution r = {0};
    nip_counts c;
    CHECK(solve(&s, 6000, 350, &r) == RS_OK);
    check_nip(&s, &r, 6000, &c);
    a[i] = r.a;
    T0[i] = r.T0;
    printf("  M = %-4d a = %.17g  T0 = %.17g  slip %d + %d  passes %d (all half-widths %d, %d of "
           "them)  Lemke pivots %d  cond %.3g\n", Ms[i], r.a, r.T0, c.slip_u, c.slip_l, r.iterations,
           r.total_solves, r.width_iterations, r.lcp_pivots, r.condition_number);
    if (Ms[i] == 400) {
      CHECK(r.lcp_pivots == 0);
      CHECK_LT(r.total_solves, 4 * 400 + 40);
    }
    rs_nip_solution_free(&r);
  }
  /* M = 100, 200, 400: dx halves twice (ratios 199/99 and 399/199, mean used) */
  double order = log(fabs(a[3] - a[1]) / fabs(a[4] - a[3])) / log(0.5 * (199.0 / 99 + 399.0 / 199));
  CHECK_LOG("observed order of a, M = 100, 200, 400", order);
  CHECK(order > 1.5);
  for (int i = 0; i < 4; ++i) {
    if (Ms[i] == 100) continue;
    double C = fabs(T0[i] - T0[4]) * (Ms[i] - 1) / T0[4];
    printf("  M = %-4d |T0 - T0(400)| = %.3e N/m, (M - 1)|T0 - T0(400)|/T0 = %.4f\n", Ms[i],
           fabs(T0[i] - T0[4]), C);
    CHECK_LT(C, 0.05);
  }
}

static const check_case cases[] = {
    {"rubber_cover_099", rubber_cover_099},
    {"friction_zero", friction_zero},
    {"friction_two", friction_two},
    {"light_load_hertz", light_load_hertz},
    {"light_load_winkler", light_load_winkler},
    {"heavy_load", heavy_load},
    {"complex_roots_continuity", complex_roots_continuity},
    {"nodes_400", nodes_400},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
