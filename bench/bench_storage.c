/* Benchmark: a week of storage in 10 stages (temperature and humidity swings) on the
 * 6054-layer newsprint reel of cases/newsprint-rider.yaml, against winding that reel.
 *   bench_storage [scene]     (default cases/newsprint-rider.yaml, run from the source tree)
 * Result and discussion: docs/performance.md, "Storage". */
#include <stdio.h>
#include <stdlib.h>

#include "reel/result_internal.h"
#include "reelsim/clock.h"
#include "reelsim/scene.h"
#include "reelsim/storage.h"

int main(int argc, char **argv)
{
  const char *path = argc > 1 ? argv[1] : "cases/newsprint-rider.yaml";
  rs_scene *scene = NULL;
  if (rs_scene_load(path, 0, NULL, &scene) != RS_OK) {
    fprintf(stderr, "%s\n", rs_error_message());
    return 1;
  }
  rs_problem *pb = malloc(sizeof *pb);
  *pb = *rs_scene_problem(scene);
  /* a week: 10 stages of 16.8 h, day and night, a damp spell (the newsprint model has
   * thermal and hygroscopic data) */
  static const double T[10] = {15, 30, 10, 25, 5, 20, 35, 18, 28, 23};
  static const double H[10] = {50, 40, 70, 80, 85, 60, 30, 55, 45, 50};
  pb->storage.n_stages = 10;
  for (int i = 0; i < 10; ++i) pb->storage.stage[i] = (rs_storage_stage){16.8, T[i], H[i]};

  rs_reel_result *res = NULL;
  rs_storage_result *sr = NULL;
  double t0 = rs_clock_wall();
  if (rs_reel_wind(pb, NULL, &res) != RS_OK) {
    fprintf(stderr, "%s\n", rs_error_message());
    return 1;
  }
  double t1 = rs_clock_wall();
  if (rs_storage_run(pb, res, &sr) != RS_OK) {
    fprintf(stderr, "%s\n", rs_error_message());
    return 1;
  }
  double t2 = rs_clock_wall();
  printf("layers %d: winding %.3f s; storage (10 stages, %.0f h) %.4f s = %.2f %% of the "
         "winding; %ld elastic solves, at most %d sub-steps a change\n",
         res->n_layers, t1 - t0, rs_storage_result_hours(sr, NULL)[rs_storage_result_stages(sr) - 1], t2 - t1,
         100.0 * (t2 - t1) / (t1 - t0), rs_storage_result_elastic_solves(sr), rs_storage_result_max_substeps(sr));
  printf("core pressure by stage (kPa):");
  for (int s = 0; s < rs_storage_result_stages(sr); ++s)
    printf(" %.1f", rs_storage_result_core_pressure(sr, NULL)[s] / 1e3);
  printf("\n");
  rs_storage_result_destroy(&sr);
  rs_reel_result_destroy(&res);
  free(pb);
  rs_scene_destroy(&scene);
  return 0;
}
