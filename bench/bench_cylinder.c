/* Influence kernels of an orthotropic roll: time vs accuracy, plain and accelerated series.
 * Roll R = 0.5 m, core 0.05 m, a = 5 mm, M = 64 nodes (hat basis, all four kernels, i.e.
 * the four M x M influence matrices of eq. (19) by their 2M-1 distinct values).
 * Accuracy: max over the four kernels of max|k - k_ref| / max|k_ref|, k_ref accelerated
 * with 2^21 terms. Times exclude the one-time per-cylinder mode cache (reported apart).
 * Results: docs/cylinder.md. */
#include "cylinder/cylinder.h"

#include <math.h>
#include <stdio.h>
#include <time.h>

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double err_of(const rs_kernels *k, const rs_kernels *r, int M)
{
  const double *a[4] = {k->pu, k->pe, k->qu, k->qe}, *b[4] = {r->pu, r->pe, r->qu, r->qe};
  double worst = 0;
  for (int j = 0; j < 4; ++j) {
    double mx = 0, e = 0;
    for (int i = 0; i < 2 * M - 1; ++i) {
      mx = fmax(mx, fabs(b[j][i]));
      e = fmax(e, fabs(a[j][i] - b[j][i]));
    }
    worst = fmax(worst, e / mx);
  }
  return worst;
}

/* best of 5 repetitions of the mean time over >= 0.05 s */
static double time_call(rs_cylinder *c, double dx, int M, const rs_series_opts *o, rs_kernels *k)
{
  double best = INFINITY;
  for (int rep = 0; rep < 5; ++rep) {
    int calls = 0;
    double t0 = now(), t;
    do {
      if (rs_cylinder_kernels(c, RS_BASIS_HAT, dx, 0, M, RS_KERNEL_ALL, o, k)) return NAN;
      ++calls;
      t = now() - t0;
    } while (t < 0.05);
    best = fmin(best, t / calls);
  }
  return best;
}

static void run(const char *name, const rs_ortho *o)
{
  const int M = 64;
  const double R = 0.5, a = 5e-3, dx = 2 * a / (M - 1);
  rs_cylinder *c = NULL;
  if (rs_cylinder_create(o, R, 0.05, &c)) {
    printf("create failed: %s\n", rs_error_message());
    return;
  }
  double t0 = now();
  rs_cylinder_prepare(c, 1L << 21);
  double tcache = now() - t0;
  rs_kernels ref = {0}, k = {0};
  rs_series_opts oref = {1L << 21, 0, 0, 1};
  rs_cylinder_kernels(c, RS_BASIS_HAT, dx, 0, M, RS_KERNEL_ALL, &oref, &ref);
  printf("\n%s: R = %g m, a = %g m, M = %d; mode cache 0..2^21: %.3f s (%.0f ns/mode)\n", name,
         R, a, M, tcache, 1e9 * tcache / (1 << 21));
  printf("%8s | %12s %12s | %12s %12s\n", "terms", "plain [ms]", "plain err", "accel [ms]",
         "accel err");
  for (long N = 16; N <= (1L << 18); N *= 4) {
    rs_series_opts op = {N, 0, 0, 0}, oa = {N, 0, 0, 1};
    double tp = time_call(c, dx, M, &op, &k), ep = err_of(&k, &ref, M);
    double ta = time_call(c, dx, M, &oa, &k), ea = err_of(&k, &ref, M);
    printf("%8ld | %12.4f %12.3e | %12.4f %12.3e\n", N, 1e3 * tp, ep, 1e3 * ta, ea);
  }
  double tols[3] = {1e-3, 1e-6, 1e-9};
  for (int i = 0; i < 3; ++i) {
    rs_series_opts ot = {0, tols[i], 0, 1};
    double tt = time_call(c, dx, M, &ot, &k);
    printf("tol %.0e (accelerated, doubling from 64): %ld terms, %.4f ms, error %.3e\n", tols[i],
           k.terms, 1e3 * tt, err_of(&k, &ref, M));
  }
  /* cold: a fresh cylinder, 256 accelerated terms including its mode setup */
  rs_cylinder *c2 = NULL;
  rs_cylinder_create(o, R, 0.05, &c2);
  rs_series_opts o256 = {256, 0, 0, 1};
  t0 = now();
  rs_cylinder_kernels(c2, RS_BASIS_HAT, dx, 0, M, RS_KERNEL_ALL, &o256, &k);
  double tcold = now() - t0;
  printf("cold (new cylinder + 256 accelerated terms): %.4f ms, error %.3e\n", 1e3 * tcold,
         err_of(&k, &ref, M));
  rs_cylinder_destroy(&c2);
  rs_kernels_free(&ref);
  rs_kernels_free(&k);
  rs_cylinder_destroy(&c);
}

int main(void)
{
  rs_ortho iso, pap;
  rs_ortho_isotropic(210e9, 0.3, 1, &iso);
  rs_ortho_engineering e = {50e6, 3.5e9, 1.5e9, 0.3 * 50e6 / 3.5e9, 0.01, 0.3, 1e8};
  rs_ortho_from_engineering(&e, 1, &pap);
  run("paper roll (E_t 3.5 GPa, E_r 50 MPa, G 100 MPa, plane strain)", &pap);
  run("steel (E 210 GPa, nu 0.3, plane strain)", &iso);
  return 0;
}
