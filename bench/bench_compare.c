/* Benchmark: reelsim compare's parallel winding (rs_reel_wind_many). K copies of a scene
 * wound on 1 thread, then on T threads, alternating, best of R rounds each; the speed-up
 * is the ratio of the two best wall times measured in the same run (the machine is
 * noisy: ratios within one run only).
 *   bench_compare SCENE [K] [T] [R]     (defaults: 4 copies, 2 threads, 3 rounds)
 * Result and discussion: docs/performance.md. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "reelsim/reel.h"
#include "reelsim/scene.h"

static double clock_s(clockid_t id)
{
  struct timespec ts;
  clock_gettime(id, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
static double now(void) { return clock_s(CLOCK_MONOTONIC); }

/* Wall time of winding k copies on `threads` threads; *cpu the process CPU time it took
 * (the same on 1 and 2 threads when the threads do not slow each other down). */
static double wind(const rs_scene *scene, int k, int threads, double *cpu)
{
  rs_reel_job *jobs = calloc((size_t)k, sizeof *jobs);
  for (int i = 0; i < k; ++i) jobs[i].problem = rs_scene_problem(scene);
  int used = 0;
  double t0 = now(), c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
  rs_reel_wind_many(k, jobs, threads, &used);
  double dt = now() - t0;
  *cpu = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
  for (int i = 0; i < k; ++i) {
    if (jobs[i].status != RS_OK) {
      fprintf(stderr, "job %d failed: %s\n", i + 1, jobs[i].message);
      exit(1);
    }
    rs_reel_result_destroy(&jobs[i].result);
  }
  free(jobs);
  return dt;
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: bench_compare SCENE [copies] [threads] [rounds]\n");
    return 2;
  }
  int k = argc > 2 ? atoi(argv[2]) : 4, t = argc > 3 ? atoi(argv[3]) : 2;
  int rounds = argc > 4 ? atoi(argv[4]) : 3;
  rs_scene *scene = NULL;
  if (rs_scene_load(argv[1], 0, NULL, &scene) != RS_OK) {
    fprintf(stderr, "%s\n", rs_error_message());
    return 2;
  }
  double best1 = 1e300, bestT = 1e300, cpu1 = 0, cpuT = 0;
  for (int r = 0; r < rounds; ++r) {
    double s1, sT, d1 = wind(scene, k, 1, &s1), dT = wind(scene, k, t, &sT);
    printf("round %d: 1 thread %.3f s (cpu %.3f s), %d threads %.3f s (cpu %.3f s)\n", r + 1,
           d1, s1, t, dT, sT);
    if (d1 < best1) best1 = d1, cpu1 = s1;
    if (dT < bestT) bestT = dT, cpuT = sT;
  }
  printf("%s, %d copies of %d layers\n", rs_scene_title(scene), k, rs_scene_problem(scene)->n_layers);
  printf("best: 1 thread %.3f s, %d threads %.3f s, speed-up %.2f\n", best1, t, bestT,
         best1 / bestT);
  printf("cpu time: %.3f s and %.3f s (ratio %.2f)\n", cpu1, cpuT, cpuT / cpu1);
  /* other work on the machine takes cores away from the threads: say how much there was */
  char load[128] = "";
  FILE *f = fopen("/proc/loadavg", "r");
  if (f && fgets(load, sizeof load, f)) printf("load average (1, 5, 15 min ...): %s", load);
  if (f) fclose(f);
  rs_scene_destroy(&scene);
  return 0;
}
