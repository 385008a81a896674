/* Nip contact solve time (M = 64), targets: < 20 ms cold, < 2 ms warm.
 * cold   : a fresh handle (kernels, Hertz guess, full-stick start).
 * same   : the same nip again on the warm handle (kernels and active set reused).
 * layer  : the next layer (roll radius + one caliper) from the previous solution, as the
 *          reel calls it: new roll kernels at each half-width tried.
 * Median of repeats; results in docs/performance.md. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "reelsim/nip_contact.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

int main(void)
{
  rs_material m = {0};
  snprintf(m.name, sizeof m.name, "bench paper");
  m.caliper = 100e-6;
  m.E_theta = 5e9;
  m.nu_rtheta = 0.01;
  m.nu_md_cd = 0.3;
  m.radial.law = RS_RADIAL_PFEIFFER;
  m.radial.K1 = 1e4;
  m.radial.K2 = 50;
  rs_nip_spec sp = {0};
  sp.model = RS_NIP_CONTACT;
  sp.mu_roll = 0.19;
  sp.mu_drum = 0.35;
  sp.winder = RS_WINDER_CENTER;
  sp.drum = (rs_drum){0.3, 0.05, 0, 2.1e11, 0.3, 0, 0, 0, 0};
  sp.nodes = 64;
  enum { REP = 15 };
  double tc[REP], ts[REP], tl[REP];
  rs_nip_solution s = {0};
  int widths_cold = 0, widths_layer = 0, solves_layer = 0;
  for (int r = 0; r < REP; ++r) {
    rs_nip_contact *nc = NULL;
    if (rs_nip_contact_create_from_spec(&sp, &m, &nc)) {
      fprintf(stderr, "%s\n", rs_error_message());
      return 1;
    }
    rs_nip_state st = {0.5, 0.1, 350, 1750, 0, 0};
    double t0 = now();
    if (rs_nip_contact_solve_state(nc, &st, &s)) return fprintf(stderr, "%s\n", rs_error_message()), 1;
    double t1 = now();
    widths_cold = s.width_iterations;
    if (rs_nip_contact_solve_state(nc, &st, &s)) return 1;
    double t2 = now();
    st.roll_radius += m.caliper;
    if (rs_nip_contact_solve_state(nc, &st, &s)) return 1;
    double t3 = now();
    widths_layer = s.width_iterations;
    solves_layer = s.total_solves;
    tc[r] = t1 - t0;
    ts[r] = t2 - t1;
    tl[r] = t3 - t2;
    rs_nip_contact_destroy(&nc);
  }
  qsort(tc, REP, sizeof *tc, cmp);
  qsort(ts, REP, sizeof *ts, cmp);
  qsort(tl, REP, sizeof *tl, cmp);
  printf("nip contact, M = 64, center winder, P = 1750 N/m, R = 0.5 m (median of %d)\n", REP);
  printf("  cold                 %8.3f ms  (half-widths tried %d)\n", 1e3 * tc[REP / 2], widths_cold);
  printf("  warm, same nip       %8.3f ms\n", 1e3 * ts[REP / 2]);
  printf("  warm, next layer     %8.3f ms  (half-widths %d, linear solves %d)\n", 1e3 * tl[REP / 2],
         widths_layer, solves_layer);
  printf("  T0 = %.6f N/m, a = %.6f mm, condition number %.3g\n", s.T0, 1e3 * s.a, s.condition_number);
  rs_nip_solution_free(&s);
  return 0;
}
