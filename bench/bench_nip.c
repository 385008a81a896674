/* Nip contact solve time (M = 64), targets: < 20 ms cold, < 2 ms warm.
 * cold   : a fresh handle (kernels, Hertz guess, full-stick start).
 * same   : the same nip again on the warm handle (kernels and active set reused).
 * layer  : the next layer (roll radius + one caliper) right after the cold solve: the
 *          previous solution is the only history.
 * reel   : a run of consecutive layers (R + one caliper each, same load), as the reel
 *          calls the nip: time per layer after the first two (history available).
 * Median of repeats; results in docs/performance.md.
 * Usage: bench_nip [repeats] [phase]  (phase: all, cold, layer, reel; for callgrind:
 *   valgrind --tool=callgrind --toggle-collect=phase_layer bench_nip 1 layer) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "nip/contact_internal.h" /* factorization / GMRES counters only */
#include "nip/nip_contact.h"

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

static rs_material mat;
static rs_nip_spec spec;
enum { REEL_LAYERS = 40 };

static void setup(void)
{
  memset(&mat, 0, sizeof mat);
  snprintf(mat.name, sizeof mat.name, "bench paper");
  mat.caliper = 100e-6;
  mat.E_theta = 5e9;
  mat.nu_rtheta = 0.01;
  mat.nu_md_cd = 0.3;
  mat.G_rtheta = 7e7; /* E_theta/70, paper's out-of-plane shear (models/newsprint.yaml) */
  mat.radial.law = RS_RADIAL_PFEIFFER;
  mat.radial.K1 = 1e4;
  mat.radial.K2 = 50;
  memset(&spec, 0, sizeof spec);
  spec.model = RS_NIP_CONTACT;
  spec.mu_roll = 0.19;
  spec.mu_drum = 0.35;
  spec.winder = RS_WINDER_CENTER;
  spec.drum = (rs_drum){0.3, 0.05, 0, 2.1e11, 0.3, 0, 0, 0, 0};
  spec.nodes = 64;
}

static void die(void)
{
  fprintf(stderr, "bench_nip: %s\n", rs_error_message());
  exit(1);
}

/* separate functions so that callgrind can count each phase (--toggle-collect) */
__attribute__((noinline)) void phase_cold(rs_nip_contact *nc, rs_nip_state *st, rs_nip_solution *s)
{
  if (rs_nip_contact_solve_state(nc, st, s)) die();
}
__attribute__((noinline)) void phase_same(rs_nip_contact *nc, rs_nip_state *st, rs_nip_solution *s)
{
  if (rs_nip_contact_solve_state(nc, st, s)) die();
}
__attribute__((noinline)) void phase_layer(rs_nip_contact *nc, rs_nip_state *st, rs_nip_solution *s)
{
  st->roll_radius += mat.caliper;
  if (rs_nip_contact_solve_state(nc, st, s)) die();
}
__attribute__((noinline)) void phase_reel(rs_nip_contact *nc, rs_nip_state *st, rs_nip_solution *s)
{
  st->roll_radius += mat.caliper;
  if (rs_nip_contact_solve_state(nc, st, s)) die();
}

int main(int argc, char **argv)
{
  int rep = argc > 1 ? atoi(argv[1]) : 15;
  const char *phase = argc > 2 ? argv[2] : "all";
  if (rep < 1) rep = 1;
  int all = !strcmp(phase, "all");
  setup();
  double *tc = calloc((size_t)rep, sizeof *tc), *ts = calloc((size_t)rep, sizeof *ts);
  double *tl = calloc((size_t)rep, sizeof *tl);
  double *tr = calloc((size_t)rep * REEL_LAYERS, sizeof *tr);
  rs_nip_solution s = {0};
  int widths_cold = 0, solves_cold = 0, widths_layer = 0, solves_layer = 0, nreel = 0;
  long lu_cold = 0, gm_cold = 0, lu_layer = 0, gm_layer = 0, lu_reel = 0, gm_reel = 0;
  long widths_reel = 0, solves_reel = 0;
  double T0_cold = 0, a_cold = 0, cond = 0, R_last = 0;
  for (int r = 0; r < rep; ++r) {
    rs_nip_contact *nc = NULL;
    if (rs_nip_contact_create_from_spec(&spec, &mat, &nc)) die();
    rs_nip_state st = {0.5, 0.1, 350, 1750, 0, 0};
    double t0 = now();
    phase_cold(nc, &st, &s);
    double t1 = now();
    widths_cold = s.width_iterations;
    solves_cold = s.total_solves;
    lu_cold = nc->stats_lu;
    gm_cold = nc->stats_gmres_it;
    T0_cold = s.T0;
    a_cold = s.a;
    cond = s.condition_number;
    if (all) phase_same(nc, &st, &s);
    double t2 = now();
    long lu0 = nc->stats_lu, gm0 = nc->stats_gmres_it;
    if (all || !strcmp(phase, "layer")) phase_layer(nc, &st, &s);
    double t3 = now();
    widths_layer = s.width_iterations;
    solves_layer = s.total_solves;
    lu_layer = nc->stats_lu - lu0;
    gm_layer = nc->stats_gmres_it - gm0;
    tc[r] = t1 - t0;
    ts[r] = t2 - t1;
    tl[r] = t3 - t2;
    if (all || !strcmp(phase, "reel"))
      for (int l = 0; l < REEL_LAYERS; ++l) {
        double t4 = now();
        long lu1 = nc->stats_lu, gm1 = nc->stats_gmres_it;
        phase_reel(nc, &st, &s);
        double t5 = now();
        if (l >= 2) {
          lu_reel += nc->stats_lu - lu1;
          gm_reel += nc->stats_gmres_it - gm1;
          tr[nreel++] = t5 - t4;
          widths_reel += s.width_iterations;
          solves_reel += s.total_solves;
        }
      }
    R_last = st.roll_radius;
    rs_nip_contact_destroy(&nc);
  }
  qsort(tc, (size_t)rep, sizeof *tc, cmp);
  qsort(ts, (size_t)rep, sizeof *ts, cmp);
  qsort(tl, (size_t)rep, sizeof *tl, cmp);
  qsort(tr, (size_t)nreel, sizeof *tr, cmp);
  printf("nip contact, M = 64, center winder, P = 1750 N/m, R = 0.5 m (median of %d)\n", rep);
  printf("  cold                 %8.3f ms  (half-widths %d, linear solves %d: LU %ld, GMRES it %ld)\n",
         1e3 * tc[rep / 2], widths_cold, solves_cold, lu_cold, gm_cold);
  if (all) printf("  warm, same nip       %8.3f ms\n", 1e3 * ts[rep / 2]);
  if (all || !strcmp(phase, "layer"))
    printf("  warm, next layer     %8.3f ms  (half-widths %d, linear solves %d: LU %ld, GMRES it %ld)\n",
           1e3 * tl[rep / 2], widths_layer, solves_layer, lu_layer, gm_layer);
  if (nreel)
    printf("  reel, per layer      %8.3f ms  (mean half-widths %.2f, linear solves %.2f: LU %.2f, "
           "GMRES it %.2f; %d layers)\n", 1e3 * tr[nreel / 2], (double)widths_reel / nreel,
           (double)solves_reel / nreel, (double)lu_reel / nreel, (double)gm_reel / nreel, nreel);
  printf("  cold: T0 = %.9f N/m, a = %.9f mm, condition number %.3g\n", T0_cold, 1e3 * a_cold, cond);
  printf("  last: T0 = %.9f N/m, a = %.9f mm, R = %.6f m\n", s.T0, 1e3 * s.a, R_last);
  rs_nip_solution_free(&s);
  free(tc);
  free(ts);
  free(tl);
  free(tr);
  return 0;
}
