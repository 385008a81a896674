/* Benchmark: the Pfeiffer newsprint reel (cases/newsprint-rider.yaml physics) wound layer
 * by layer, and how the wall time grows with the number of layers.
 *   bench_roll [layers] [rtol]      (default 6054 layers, rtol 1e-6)
 * Result and discussion: docs/performance.md. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench_newsprint.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double wind(int n, double rtol, rs_roll_stats *stats, double *core)
{
  rs_roll_params p = bench_newsprint_params(n, rtol);
  rs_roll *roll = NULL;
  double T0 = BENCH_NEWSPRINT_T0, t0 = now();
  if (rs_roll_create(&p, &roll)) return NAN;
  for (int k = 0; k < n; ++k)
    if (rs_roll_add_layers(roll, 1, &T0)) {
      fprintf(stderr, "failed: %s\n", rs_error_message());
      break;
    }
  double dt = now() - t0;
  rs_roll_get_stats(roll, stats);
  *core = rs_roll_core_pressure(roll);
  rs_roll_destroy(&roll);
  return dt;
}

int main(int argc, char **argv)
{
  int n = argc > 1 ? atoi(argv[1]) : 6054;
  double rtol = argc > 2 ? atof(argv[2]) : 1e-6;
  printf("%8s %10s %12s %14s %12s %14s %8s %10s\n", "layers", "wall (s)", "s/layer^2", "cvode steps",
         "steps/incr", "core P (Pa)", "rhs/step", "from core");
  for (int m = n / 8; m <= n; m *= 2) {
    rs_roll_stats st;
    double core, dt = wind(m, rtol, &st, &core);
    printf("%8d %10.4f %12.3e %14ld %12.1f %14.6e %8.2f %10ld\n", m, dt, dt / ((double)m * m),
           st.cvode_steps, (double)st.cvode_steps / st.increments, core,
           (double)st.rhs_evals / st.cvode_steps, st.full_integrations);
    if (m * 2 > n && m != n) m = n / 2;
  }
  return 0;
}
