/* Lumped increments, before and after (docs/accuracy.md, "Lumping layers"): the error of
 * numerics.layers_per_step = m against layer-by-layer Hakiel accretion, and its cost, for
 * the first scheme (a block integrated once with its load at its outer radius, kept as the
 * tests' reference: tests/roll_frozen.h) and the engine's corrected one.
 *
 *   bench_lumping [layers] [rtol] [data-file]
 *
 * The roll is the newsprint-rider physics (Pfeiffer K1 = 5 kPa, K2 = 60, E_theta 3.5 GPa,
 * caliper 70 um, r_c 76.2 mm, E_c 1 GPa, T0 = 682.5 N/m); default 6054 layers (the whole
 * 0.5 m reel), rtol 1e-6. Prints a table; with a data file also writes it for gnuplot
 * (columns: scheme m cpu_s steps err_core err_peak err_sigma_r err_sigma_theta). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench_newsprint.h"
#include "../tests/roll_frozen.h"

static double cpu_now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static rs_roll *wind(const rs_roll_params *p, int n, int m, double T0, double *cpu, int frozen)
{
  rs_roll *roll = NULL;
  if (rs_roll_create(p, &roll)) {
    fprintf(stderr, "%s\n", rs_error_message());
    exit(1);
  }
  double *T = malloc((size_t)m * sizeof *T);
  for (int i = 0; i < m; ++i) T[i] = T0;
  double t0 = cpu_now();
  for (int done = 0; done < n;) {
    int k = n - done < m ? n - done : m;
    if ((frozen ? roll_add_layers_frozen : rs_roll_add_layers)(roll, k, T)) {
      fprintf(stderr, "%s at %s\n", rs_error_message(), rs_error_where());
      exit(1);
    }
    done += k;
  }
  *cpu = cpu_now() - t0;
  free(T);
  return roll;
}

int main(int argc, char **argv)
{
  const int n = argc > 1 ? atoi(argv[1]) : 6054;
  const double rtol = argc > 2 ? atof(argv[2]) : 1e-6, T0 = BENCH_NEWSPRINT_T0;
  FILE *data = argc > 3 ? fopen(argv[3], "w") : NULL;
  rs_roll_params p = bench_newsprint_params(n, rtol);
  if (rs_radial_law_prepare(&p.radial)) return 1;

  double cpu_ref;
  rs_roll *ref = wind(&p, n, 1, T0, &cpu_ref, 0);
  rs_roll_stats sref;
  rs_roll_get_stats(ref, &sref);
  const double *sr0 = rs_roll_sigma_r(ref), *st0 = rs_roll_sigma_theta(ref);
  double peak0 = rs_roll_core_pressure(ref);
  for (int j = 0; j < n; ++j) peak0 = fmax(peak0, -sr0[j]);
  printf("%d layers, rtol %g: layer by layer %.3f s CPU, %ld CVODE steps, core pressure %.6e Pa\n",
         n, rtol, cpu_ref, sref.cvode_steps, rs_roll_core_pressure(ref));
  printf("%-9s %4s %9s %10s %8s %10s %10s %10s %10s\n", "scheme", "m", "cpu s", "steps", "speed-up",
         "core", "peak", "sigma_r", "sigma_t");
  static const int ms[] = {2, 3, 5, 10, 20, 50, 100};
  for (int scheme = 0; scheme < 2; ++scheme) {
    for (size_t i = 0; i < sizeof ms / sizeof *ms; ++i) {
      double cpu;
      rs_roll *r = wind(&p, n, ms[i], T0, &cpu, scheme == 0);
      rs_roll_stats s;
      rs_roll_get_stats(r, &s);
      const double *sr = rs_roll_sigma_r(r), *st = rs_roll_sigma_theta(r);
      double peak = rs_roll_core_pressure(r), er = 0, et = 0;
      for (int j = 0; j < n; ++j) {
        peak = fmax(peak, -sr[j]);
        er = fmax(er, fabs(sr[j] - sr0[j]) / fabs(sr0[j]));
        et = fmax(et, fabs(st[j] - st0[j]) / (T0 / p.caliper));
      }
      double ec = fabs(rs_roll_core_pressure(r) / rs_roll_core_pressure(ref) - 1);
      double ep = fabs(peak / peak0 - 1);
      const char *name = scheme == 0 ? "frozen" : "corrected";
      printf("%-9s %4d %9.3f %10ld %8.2f %10.2e %10.2e %10.2e %10.2e\n", name, ms[i], cpu,
             s.cvode_steps, cpu_ref / cpu, ec, ep, er, et);
      if (data)
        fprintf(data, "%d %d %.6g %ld %.6e %.6e %.6e %.6e\n", scheme, ms[i], cpu, s.cvode_steps,
                ec, ep, er, et);
      rs_roll_destroy(&r);
    }
    if (data) fprintf(data, "\n\n");
  }
  if (data) fclose(data);
  rs_roll_destroy(&ref);
  return 0;
}
