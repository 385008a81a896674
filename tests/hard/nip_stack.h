/* The contact nip's hard cases' common set-up and checks (hard/test_hard_nip.c,
 * test_hard_nip_reel.c): a roll, sheet and drum stack, the solver made from it, one solve,
 * and check_nip, which holds a converged nip to eqs. (20)-(21), Coulomb's law element by
 * element and finite output. Needs check.h included first. */
#ifndef RS_TESTS_HARD_NIP_STACK_H
#define RS_TESTS_HARD_NIP_STACK_H

#include <math.h>
#include <stdlib.h>

#include "nip/nip_contact.h"

#define PI 3.14159265358979323846

typedef struct stack {
  rs_ortho roll, drum;
  double R, R0, Rd, Rd0; /* m */
  rs_sheet sheet;
  double mu_roll, mu_drum;
  rs_winder_kind winder;
  double share;
  int M, max_iterations;
  long terms; /* 0: the solver's default series */
} stack;

static inline rs_ortho iso(double E, double nu)
{
  rs_ortho o;
  CHECK(rs_ortho_isotropic(E, nu, 1, &o) == RS_OK);
  return o;
}

/* a paper roll: E_r radial, E_t = E_cd, Hakiel's nu (nu_rt = nu E_r / E_t), plane strain */
static inline rs_ortho paper_roll(double E_r, double E_t, double G)
{
  const double nu = 0.01;
  rs_ortho_engineering e = {E_r, E_t, E_t, nu * E_r / E_t, nu * E_r / E_t, 0.3, G};
  rs_ortho o;
  CHECK(rs_ortho_from_engineering(&e, 1, &o) == RS_OK);
  return o;
}

/* the validation tests' paper roll (tests/validation/test_nip_contact.c): R = 0.5 m on a
 * 0.1 m core, steel drum R = 0.3 m, 100 um sheet, center winder with a rider */
static inline stack paper_stack(void)
{
  stack s;
  memset(&s, 0, sizeof s);
  s.roll = paper_roll(3e7, 5e9, 3e7);
  s.drum = iso(2.1e11, 0.3);
  s.R = 0.5;
  s.R0 = 0.1;
  s.Rd = 0.3;
  s.Rd0 = 0.05;
  rs_sheet_constants k = {100e-6, 5e9, 3e7, 5e9, 0.01, 0.3, 0.01, 3e7, 1};
  CHECK(rs_sheet_from_constants(&k, &s.sheet) == RS_OK);
  s.mu_roll = 0.19;
  s.mu_drum = 0.35;
  s.winder = RS_WINDER_CENTER;
  s.share = 0.5;
  s.M = 64;
  return s;
}

/* a sheet of vanishing thickness and compliance between nearly solid isotropic cylinders
 * (aluminium roll R = 0.15 m, steel drum R = 0.1 m, cores 1 % of the radius): Hertz */
static inline stack hertz_stack(void)
{
  stack s = paper_stack();
  s.roll = iso(7e10, 0.33);
  s.R = 0.15;
  s.R0 = 0.0015;
  s.drum = iso(2.1e11, 0.3);
  s.Rd = 0.1;
  s.Rd0 = 0.001;
  s.sheet = (rs_sheet){1e-12, 0, 0, 0, 0};
  s.mu_roll = s.mu_drum = 0;
  return s;
}

static inline double hertz_estar(void) { return 1 / ((1 - 0.33 * 0.33) / 7e10 + (1 - 0.09) / 2.1e11); }
static inline double rstar(const stack *s) { return 1 / (1 / s->R + 1 / s->Rd); }

static inline rs_nip_contact *make(const stack *s)
{
  rs_nip_contact_config c;
  memset(&c, 0, sizeof c);
  c.drum = s->drum;
  c.drum_radius = s->Rd;
  c.drum_core_radius = s->Rd0;
  c.sheet = s->sheet;
  c.mu_roll = s->mu_roll;
  c.mu_drum = s->mu_drum;
  c.winder = s->winder;
  c.torque_share = s->share;
  c.nodes = s->M;
  c.max_iterations = s->max_iterations;
  if (s->terms > 0) {
    c.series.terms = s->terms;
    c.series.accelerate = 1;
  }
  rs_nip_contact *nc = NULL;
  if (rs_nip_contact_create(&c, &nc) != RS_OK) {
    printf("  create: %s\n", rs_error_message());
    return NULL;
  }
  if (rs_nip_contact_set_roll(nc, &s->roll, s->R, s->R0) != RS_OK) {
    printf("  set_roll: %s\n", rs_error_message());
    rs_nip_contact_destroy(&nc);
  }
  return nc;
}

/* solves for the load; prints the error and returns its status on failure */
static inline rs_status solve(const stack *s, double P, double Ti, rs_nip_solution *out)
{
  rs_nip_contact *nc = make(s);
  if (!nc) return RS_ERR_INPUT;
  rs_status st = rs_nip_contact_solve_load(nc, P, Ti, out);
  if (st) printf("  solve (P = %g N/m, Ti = %g N/m): %s\n", P, Ti, rs_error_message());
  rs_nip_contact_destroy(&nc);
  return st;
}

static inline double share_of(const stack *s)
{
  return s->winder == RS_WINDER_CENTER ? 1.0 : s->winder == RS_WINDER_SURFACE ? 0.0 : s->share;
}

static inline int all_finite(const double *v, int n)
{
  for (int i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

static inline double pmax_of(const rs_nip_solution *r)
{
  double m = 0;
  for (int i = 0; i < r->M; ++i) m = fmax(m, r->pressure[i]);
  return m;
}

typedef struct nip_counts {
  int slip_u, slip_l;      /* slipping elements, upper and lower contact */
  int edge_u, edge_l;      /* ... of them within 20 % of the contact width from an edge */
} nip_counts;

/* Everything a converged nip must satisfy whatever the data: every number finite;
 * eqs. (20)-(21): the load to the search tolerance, int p dx = load, sheet equilibrium
 * T0 - int (q1 + q2) = Ti, winder torque T0 + int tau+ = share Ti, the drum's share
 * -int tau- = (1 - share) Ti; Coulomb element by element (|q| <= mu pbar, = where slipping,
 * slip in the direction of the friction: dissipation >= 0); |T0 - share Ti| = |int tau+|
 * <= mu_roll P (the friction-nip limit). */
static inline void check_nip(const stack *s, const rs_nip_solution *r, double P, nip_counts *cnt)
{
  const int M = r->M, E = M - 1;
  memset(cnt, 0, sizeof *cnt);
  CHECK(M == s->M);
  if (M != s->M) return;
  int fin = isfinite(r->a) && isfinite(r->T0) && isfinite(r->xi1) && isfinite(r->xi2) &&
            isfinite(r->delta0) && isfinite(r->eps0) && isfinite(r->load) && isfinite(r->dissipation) &&
            isfinite(r->condition_number) && all_finite(r->x, M) && all_finite(r->pressure, M) &&
            all_finite(r->x_shear, E) && all_finite(r->shear_upper, E) &&
            all_finite(r->shear_lower, E) && all_finite(r->slip_rate_upper, E) &&
            all_finite(r->slip_rate_lower, E);
  CHECK(fin);
  double Iu = 0, Il = 0, Ip = 0, Ti = r->Ti, sh = share_of(s), scale = Ti + P;
  for (int e = 0; e < E; ++e) {
    Iu += r->shear_upper[e] * r->dx;
    Il += r->shear_lower[e] * r->dx;
  }
  for (int i = 0; i < M; ++i) Ip += r->pressure[i] * r->dx;
  CHECK_CLOSE(r->load, P, 2e-9);
  CHECK_CLOSE(Ip, r->load, 1e-13);
  CHECK_ABS(Iu - Il + r->T0, Ti, 1e-12 * scale);
  CHECK_ABS(Iu + r->T0, sh * Ti, 1e-12 * scale);
  CHECK_ABS(-Il, (1 - sh) * Ti, 1e-12 * scale);
  CHECK(fabs(r->T0 - sh * Ti) <= s->mu_roll * r->load * (1 + 1e-12) + 1e-12 * scale);
  CHECK(r->pressure[0] == 0 && r->pressure[M - 1] == 0);
  double pm = pmax_of(r);
  /* the round-off of the shears: 1e-12 of p_max and of the tension over the contact (a
   * slip element of a frictionless contact has the exact shear 0, the solve gives ~1e-17
   * p_max, of either sign, when it refines from a kept LU with a rank-k correction) */
  double qfloor = 1e-12 * (pm + (fabs(Ti) + fabs(r->T0)) / (2 * r->a)), sabs = 0;
  for (int e = 0; e < E; ++e) sabs += r->dx * (fabs(r->slip_rate_upper[e]) + fabs(r->slip_rate_lower[e]));
  CHECK(r->dissipation >= -1e-12 * fabs(r->dissipation) - qfloor * sabs - 1e-300);
  int bad_slip = 0, bad_stick = 0, bad_dir = 0, negp = 0;
  for (int i = 0; i < M; ++i) negp += r->pressure[i] < -1e-12 * pm;
  for (int e = 0; e < E; ++e) {
    double pb = 0.5 * (r->pressure[e] + r->pressure[e + 1]);
    double q[2] = {-r->shear_upper[e], r->shear_lower[e]}, mu[2] = {s->mu_roll, s->mu_drum};
    double sr[2] = {r->slip_rate_upper[e], r->slip_rate_lower[e]};
    unsigned char sl[2] = {r->slip_upper[e], r->slip_lower[e]};
    int edge = e < E / 5 || e >= E - E / 5;
    for (int k = 0; k < 2; ++k) {
      if (sl[k]) {
        bad_slip += !(fabs(fabs(q[k]) - mu[k] * pb) <= 1e-10 * mu[k] * pm + qfloor);
        bad_dir += !(q[k] * sr[k] >= 0 || fabs(q[k]) <= qfloor);
        if (k) {
          cnt->slip_l++;
          cnt->edge_l += edge;
        } else {
          cnt->slip_u++;
          cnt->edge_u += edge;
        }
      } else {
        /* the solver's acceptance: the limit to 1e-8 mu p_max, and the round-off of the
         * shears (1e-12 of p_max and of the tension over the contact): a stuck element of
         * a frictionless contact (the rider's, defining xi2) has the exact shear 0 */
        bad_stick += !(fabs(q[k]) <= mu[k] * pb + 1e-8 * mu[k] * pm + qfloor);
      }
    }
  }
  CHECK(negp == 0);
  CHECK(bad_slip == 0);
  CHECK(bad_stick == 0);
  CHECK(bad_dir == 0);
  CHECK(r->iterations >= 1 && r->iterations <= (s->max_iterations > 0 ? s->max_iterations : 4 * M + 40));
}

#endif
