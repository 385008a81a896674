/* Benchmark: a week of storage in 10 stages on the 6054-layer newsprint reel
 * (bench_newsprint.h physics), creep in both directions (cases/newsprint-storage-creep.yaml's
 * Prony terms), against the cost of winding it.
 *   bench_creep [layers] [rtol] [stages] [hours]   (default 6054, 1e-6, 10, 168)
 * Result and discussion: docs/performance.md ("Creep in storage"). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_newsprint.h"
#include "reelsim/status.h"
#include "storage/creep.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts); /* CPU time: the machine is shared */
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv)
{
  const int n = argc > 1 ? atoi(argv[1]) : 6054;
  const double rtol = argc > 2 ? atof(argv[2]) : 1e-6;
  const int stages = argc > 3 ? atoi(argv[3]) : 10;
  const double hours = argc > 4 ? atof(argv[4]) : 168.0;
  rs_roll_params rp = bench_newsprint_params(n, rtol);
  rs_roll *roll = NULL;
  double T0 = BENCH_NEWSPRINT_T0, t0 = now();
  if (rs_roll_create(&rp, &roll)) return 1;
  for (int k = 0; k < n; ++k)
    if (rs_roll_add_layers(roll, 1, &T0)) {
      fprintf(stderr, "failed: %s\n", rs_error_message());
      return 1;
    }
  const double t_wind = now() - t0;
  double core = rs_roll_core_pressure(roll);
  double *sr = malloc((size_t)n * sizeof(double)), *st = malloc((size_t)n * sizeof(double));
  memcpy(sr, rs_roll_sigma_r(roll), (size_t)n * sizeof(double));
  memcpy(st, rs_roll_sigma_theta(roll), (size_t)n * sizeof(double));
  const double core0 = core;
  rs_creep_params p = {.n_layers = n, .core_radius = rp.core_radius, .caliper = rp.caliper,
                       .E_theta = rp.E_theta, .nu_rtheta = rp.nu_rtheta, .radial = &rp.radial,
                       .core_stiffness = rp.core_stiffness, .rtol = rtol, .max_steps = 5000,
                       .n_terms = 3, .tau = {1.0, 24.0, 720.0},
                       .w_theta = {0.04, 0.06, 0.08}, .w_radial = {0.08, 0.10, 0.12}};
  rs_creep *c = NULL;
  t0 = now();
  if (rs_creep_create(&p, &c)) {
    fprintf(stderr, "failed: %s\n", rs_error_message());
    return 1;
  }
  for (int i = 0; i < stages; ++i)
    if (rs_creep_hold(c, hours / stages, &core, sr, st)) {
      fprintf(stderr, "failed: %s\n", rs_error_message());
      return 1;
    }
  const double t_creep = now() - t0;
  rs_creep_stats s;
  rs_creep_get_stats(c, &s);
  printf("layers %d, rtol %g: winding %.4f s CPU; %d stages over %g h: %.4f s CPU (%.2f of the winding)\n",
         n, rtol, t_wind, stages, hours, t_creep, t_creep / t_wind);
  printf("creep: %ld steps, %ld rhs, %ld Newton iterations, %ld GMRES iterations, %ld "
         "preconditioner solves, %ld error-test and %ld convergence failures\n",
         s.steps, s.rhs, s.nonlin_iters, s.lin_iters, s.prec_solves, s.err_fails, s.conv_fails);
  printf("core pressure %.1f kPa -> %.1f kPa (%.1f %%)\n", core0 / 1e3, core / 1e3,
         100.0 * (core / core0 - 1.0));
  rs_creep_destroy(&c);
  rs_roll_destroy(&roll);
  free(sr);
  free(st);
  return 0;
}
