/* Frictionless contact of two cylinders on rigid cores against the Hertz line contact
 * (Johnson 1985, eq. 4.45 ff., plane strain):
 *   a^2 = 4 P R* / (pi E*),  p(x) = p0 sqrt(1 - x^2/a^2),  p0 = 2 P / (pi a),
 *   1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2,  1/R* = 1/R1 + 1/R2,
 * valid for a << R; the cores are small (R0/R = 0.01) so the bodies are nearly solid. */
#include "check.h"
#include "cylinder/cylinder.h"

#define PI 3.14159265358979323846

typedef struct pair {
  rs_cylinder *c1, *c2;
  double Estar, Rs;
} pair;

static pair make_pair(double E1, double nu1, double R1, double E2, double nu2, double R2, double rho0)
{
  pair p;
  rs_ortho o1, o2;
  CHECK(rs_ortho_isotropic(E1, nu1, 1, &o1) == RS_OK);
  CHECK(rs_ortho_isotropic(E2, nu2, 1, &o2) == RS_OK);
  CHECK(rs_cylinder_create(&o1, R1, rho0 * R1, &p.c1) == RS_OK);
  CHECK(rs_cylinder_create(&o2, R2, rho0 * R2, &p.c2) == RS_OK);
  p.Estar = 1 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
  p.Rs = 1 / (1 / R1 + 1 / R2);
  return p;
}

static void free_pair(pair *p)
{
  rs_cylinder_destroy(&p->c1);
  rs_cylinder_destroy(&p->c2);
}

/* relative load error and max profile error / p0 at half-width a */
static void hertz_errors(pair *pp, double a, int M, const rs_series_opts *o, double *eP, double *ep)
{
  rs_contact_result r = {0};
  CHECK(rs_contact_frictionless(pp->c1, pp->c2, a, M, o, &r) == RS_OK);
  double PH = PI * a * a * pp->Estar / (4 * pp->Rs), p0 = 2 * PH / (PI * a), em = 0;
  for (int i = 0; i < M; ++i) {
    double ph = p0 * sqrt(fmax(0.0, 1 - r.x[i] * r.x[i] / (a * a)));
    em = fmax(em, fabs(r.p[i] - ph));
  }
  *eP = r.P / PH - 1;
  *ep = em / p0;
  CHECK_ABS(r.eps0, 0.0, 1e-12 * a); /* symmetric contact: no shift */
  CHECK(r.delta0 > 0);
  rs_contact_result_free(&r);
}

static void hertz_case(double E2, double nu2)
{
  pair pp = make_pair(210e9, 0.3, 0.1, E2, nu2, 0.1, 0.01);
  rs_series_opts o = {0, 1e-8, 0, 1};
  double eP, ep;
  hertz_errors(&pp, 1e-3, 81, &o, &eP, &ep); /* a/R = 0.01 */
  CHECK_LOG("P/P_hertz - 1 (M = 81)", eP);
  CHECK_LOG("max |p - p_hertz| / p0 (M = 81)", ep);
  CHECK_LT(fabs(eP), 0.01);
  CHECK_LT(ep, 0.01);
  free_pair(&pp);
}

static void steel_steel(void) { hertz_case(210e9, 0.3); }
static void rubber_steel(void) { hertz_case(10e6, 0.45); }

/* The profile error falls as M grows, slowly (square-root edges): observed order from
 * M = 41, 81, 161, and the load error falls too. */
static void profile_order_in_M(void)
{
  pair pp = make_pair(210e9, 0.3, 0.1, 10e6, 0.45, 0.1, 0.01);
  rs_series_opts o = {0, 1e-9, 0, 1};
  int Ms[3] = {41, 81, 161};
  double eP[3], ep[3];
  for (int i = 0; i < 3; ++i) {
    hertz_errors(&pp, 1e-3, Ms[i], &o, &eP[i], &ep[i]);
    printf("  M = %3d: P/P_hertz - 1 = %+.4e, max profile error / p0 = %.4e\n", Ms[i], eP[i], ep[i]);
  }
  double q1 = log(ep[0] / ep[1]) / log(2.0), q2 = log(ep[1] / ep[2]) / log(2.0);
  CHECK_LOG("observed profile order, M 41 -> 81", q1);
  CHECK_LOG("observed profile order, M 81 -> 161", q2);
  /* observed: about 0.5 (the error sits at the square-root edge, ~ sqrt(dx/a)) */
  CHECK(q1 > 0.35 && q1 < 0.7);
  CHECK(q2 > 0.35 && q2 < 0.7);
  CHECK_LT(fabs(eP[1]), fabs(eP[0]));
  CHECK_LT(fabs(eP[2]), fabs(eP[1]));
  free_pair(&pp);
}

/* The load converges as the number of terms grows (plain series: slowly; the
 * accelerated one is converged already at 64 terms). */
static void terms_convergence(void)
{
  pair pp = make_pair(210e9, 0.3, 0.1, 210e9, 0.3, 0.1, 0.01);
  rs_contact_result r = {0};
  rs_series_opts oref = {1L << 18, 0, 0, 1};
  CHECK(rs_contact_frictionless(pp.c1, pp.c2, 1e-3, 81, &oref, &r) == RS_OK);
  double Pref = r.P;
  long Ns[4] = {1024, 4096, 16384, 65536};
  double prev = INFINITY;
  for (int i = 0; i < 4; ++i) {
    rs_series_opts o = {Ns[i], 0, 0, 0};
    CHECK(rs_contact_frictionless(pp.c1, pp.c2, 1e-3, 81, &o, &r) == RS_OK);
    double e = fabs(r.P / Pref - 1);
    printf("  plain series, N = %6ld: |P/P_ref - 1| = %.4e\n", Ns[i], e);
    CHECK_LT(e, prev);
    prev = e;
  }
  CHECK_LT(prev, 1e-2);
  double preva = INFINITY;
  long Na[3] = {16, 64, 256};
  for (int i = 0; i < 3; ++i) {
    rs_series_opts o = {Na[i], 0, 0, 1};
    CHECK(rs_contact_frictionless(pp.c1, pp.c2, 1e-3, 81, &o, &r) == RS_OK);
    double e = fabs(r.P / Pref - 1);
    printf("  accelerated,  N = %6ld: |P/P_ref - 1| = %.4e\n", Na[i], e);
    CHECK_LT(e, preva);
    preva = e;
  }
  CHECK_LT(preva, 1e-5);
  CHECK_LT(preva, prev); /* 256 accelerated terms beat 65536 plain ones */
  rs_contact_result_free(&r);
  free_pair(&pp);
}

/* A thin rubber cover (R0/R = 0.98, 2 mm on R = 0.1 m) on steel: at the load that gives
 * a = 1 mm on the solid-ish cylinder, the covered one is stiffer (narrower contact, higher
 * peak, smaller approach), and its solution converges as terms grow. */
static void thin_cover(void)
{
  pair solid = make_pair(210e9, 0.3, 0.1, 10e6, 0.45, 0.1, 0.01);
  rs_ortho st, rb;
  rs_ortho_isotropic(210e9, 0.3, 1, &st);
  rs_ortho_isotropic(10e6, 0.45, 1, &rb);
  rs_cylinder *cs = NULL, *cc = NULL;
  CHECK(rs_cylinder_create(&st, 0.1, 0.001, &cs) == RS_OK);
  CHECK(rs_cylinder_create(&rb, 0.1, 0.098, &cc) == RS_OK);
  rs_series_opts o = {0, 1e-9, 0, 1};
  rs_contact_result r1 = {0}, r2 = {0};
  CHECK(rs_contact_frictionless(solid.c1, solid.c2, 1e-3, 81, &o, &r1) == RS_OK);
  CHECK(rs_contact_frictionless_load(cs, cc, r1.P, 81, &o, 0, 1e-10, &r2) == RS_OK);
  CHECK_LOG("solid: a (m)", r1.a);
  CHECK_LOG("cover: a (m)", r2.a);
  CHECK_LOG("solid: delta0 (m)", r1.delta0);
  CHECK_LOG("cover: delta0 (m)", r2.delta0);
  CHECK_CLOSE(r2.P, r1.P, 1e-8);
  CHECK_LT(r2.a, 0.95 * r1.a);
  CHECK_LT(r2.delta0, r1.delta0);
  double pm1 = 0, pm2 = 0;
  for (int i = 0; i < 81; ++i) {
    pm1 = fmax(pm1, r1.p[i]);
    pm2 = fmax(pm2, r2.p[i]);
  }
  CHECK_LT(pm1, pm2);
  /* convergence in terms at fixed a */
  double a = r2.a, Pref;
  rs_series_opts oref = {1L << 18, 0, 0, 1};
  CHECK(rs_contact_frictionless(cs, cc, a, 81, &oref, &r2) == RS_OK);
  Pref = r2.P;
  double prevp = INFINITY, preva = INFINITY;
  long Ns[3] = {1024, 8192, 65536};
  for (int i = 0; i < 3; ++i) {
    rs_series_opts op = {Ns[i], 0, 0, 0}, oa = {Ns[i] / 16, 0, 0, 1};
    CHECK(rs_contact_frictionless(cs, cc, a, 81, &op, &r2) == RS_OK);
    double ep = fabs(r2.P / Pref - 1);
    CHECK(rs_contact_frictionless(cs, cc, a, 81, &oa, &r2) == RS_OK);
    double ea = fabs(r2.P / Pref - 1);
    printf("  cover: plain N = %6ld |dP/P| = %.3e; accelerated N = %5ld |dP/P| = %.3e\n", Ns[i],
           ep, Ns[i] / 16, ea);
    CHECK_LT(ep, prevp);
    CHECK(ea < preva || ea < 1e-12);
    prevp = ep;
    preva = ea;
  }
  CHECK_LT(prevp, 1e-2);
  CHECK_LT(preva, 1e-8);
  rs_contact_result_free(&r1);
  rs_contact_result_free(&r2);
  rs_cylinder_destroy(&cs);
  rs_cylinder_destroy(&cc);
  free_pair(&solid);
}

/* Paper-roll-like orthotropic roll (E_t = 3.5 GPa, E_r = 50 MPa, G = 100 MPa, R = 0.5 m,
 * core 0.05 m) on a steel drum (R = 0.3 m): converges in M and in terms; the load at
 * fine M is close to Hertz with 1/E* = (H11_roll + H11_drum)/2 (orthotropic half-planes). */
static void orthotropic_roll(void)
{
  rs_ortho_engineering e = {50e6, 3.5e9, 1.5e9, 0.3 * 50e6 / 3.5e9, 0.01, 0.3, 1e8};
  rs_ortho ro, so;
  CHECK(rs_ortho_from_engineering(&e, 1, &ro) == RS_OK);
  rs_ortho_isotropic(210e9, 0.3, 1, &so);
  rs_cylinder *roll = NULL, *drum = NULL;
  CHECK(rs_cylinder_create(&ro, 0.5, 0.05, &roll) == RS_OK);
  CHECK(rs_cylinder_create(&so, 0.3, 0.05, &drum) == RS_OK);
  double a = 5e-3, H1[2][2], H2[2][2];
  rs_ortho_halfplane(&ro, H1);
  rs_ortho_halfplane(&so, H2);
  double Estar = 2 / (H1[0][0] + H2[0][0]), Rs = 1 / (1 / 0.5 + 1 / 0.3);
  double PH = PI * a * a * Estar / (4 * Rs);
  rs_series_opts o = {0, 1e-9, 0, 1};
  rs_contact_result r = {0};
  int Ms[4] = {41, 81, 161, 321};
  double P[4];
  for (int i = 0; i < 4; ++i) {
    CHECK(rs_contact_frictionless(roll, drum, a, Ms[i], &o, &r) == RS_OK);
    P[i] = r.P;
    printf("  M = %3d: P = %.10g N/m, P/P_hertz - 1 = %+.4e, terms %ld\n", Ms[i], P[i],
           P[i] / PH - 1, r.terms);
  }
  double d1 = fabs(P[1] - P[0]), d2 = fabs(P[2] - P[1]), d3 = fabs(P[3] - P[2]);
  CHECK_LOG("observed order of P in M", log(d2 / d3) / log(2.0));
  CHECK_LT(d2, d1);
  CHECK_LT(d3, d2);
  /* finite-radius corrections are O(a/R*) = 2.7 %: not Hertz to 1 % here */
  CHECK_LT(fabs(P[3] / PH - 1), 0.03);
  /* terms */
  double Pref = P[1], prev = INFINITY;
  long Ns[3] = {2048, 16384, 131072};
  for (int i = 0; i < 3; ++i) {
    rs_series_opts op = {Ns[i], 0, 0, 0};
    CHECK(rs_contact_frictionless(roll, drum, a, 81, &op, &r) == RS_OK);
    double ep = fabs(r.P / Pref - 1);
    printf("  plain N = %6ld: |P/P_ref - 1| = %.3e\n", Ns[i], ep);
    CHECK_LT(ep, prev);
    prev = ep;
  }
  CHECK_LT(prev, 1e-2);
  rs_contact_result_free(&r);
  rs_cylinder_destroy(&roll);
  rs_cylinder_destroy(&drum);
}

/* P -> a inverts a -> P; impossible loads are input errors */
static void load_inverse(void)
{
  pair pp = make_pair(210e9, 0.3, 0.1, 10e6, 0.45, 0.15, 0.01);
  rs_series_opts o = {256, 0, 0, 1};
  rs_contact_result r = {0};
  double as[3] = {2e-4, 1e-3, 4e-3};
  for (int i = 0; i < 3; ++i) {
    CHECK(rs_contact_frictionless(pp.c1, pp.c2, as[i], 61, &o, &r) == RS_OK);
    double P = r.P;
    CHECK(rs_contact_frictionless_load(pp.c1, pp.c2, P, 61, &o, 0, 1e-12, &r) == RS_OK);
    CHECK_CLOSE(r.a, as[i], 1e-9);
    CHECK_CLOSE(r.P, P, 1e-9);
  }
  CHECK(rs_contact_frictionless_load(pp.c1, pp.c2, 1e9, 61, &o, 0, 0, &r) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "a_max") != NULL);
  CHECK(rs_contact_frictionless_load(pp.c1, pp.c2, -1, 61, &o, 0, 0, &r) == RS_ERR_INPUT);
  CHECK(rs_contact_frictionless(pp.c1, pp.c2, 1e-3, 2, &o, &r) == RS_ERR_INPUT);
  rs_contact_result_free(&r);
  free_pair(&pp);
}

static const check_case cases[] = {
    {"steel_steel", steel_steel},
    {"rubber_steel", rubber_steel},
    {"profile_order_in_M", profile_order_in_M},
    {"terms_convergence", terms_convergence},
    {"thin_cover", thin_cover},
    {"orthotropic_roll", orthotropic_roll},
    {"load_inverse", load_inverse},
};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
