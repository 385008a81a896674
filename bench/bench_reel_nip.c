/* Benchmark: the 6,054-layer newsprint reel with the contact nip (cases/newsprint-surface.yaml)
 * wound with the nip solved adaptively and at every layer, in one run (ratios are what
 * count on a shared machine). Result: docs/performance.md.
 *   bench_reel_nip [scene] [--no-every]     */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int run(const char *scene, int n_sets, const char **sets, const char *label)
{
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL;
  double t0 = now();
  rs_status st = rs_scene_load(scene, n_sets, sets, &sc);
  if (st == RS_OK) st = rs_scene_wind(sc, NULL, &res);
  double dt = now() - t0;
  if (st != RS_OK) {
    fprintf(stderr, "%s: %s\n", label, rs_error_message());
    rs_scene_destroy(&sc);
    rs_reel_result_destroy(&res);
    return 1;
  }
  printf("%-22s %8.2f s  layers %5d  nip solves %5ld (kept %5d, rewinds %3ld)  increments %6ld  "
         "core %.6e Pa  T0 %.4f..%.4f N/m\n",
         label, dt, res->n_layers, res->nip_solves, res->n_nip, res->nip_rejected, res->increments,
         res->core_pressure, res->wound_on_tension[0], res->wound_on_tension[res->n_layers - 1]);
  rs_scene_destroy(&sc);
  rs_reel_result_destroy(&res);
  return 0;
}

int main(int argc, char **argv)
{
  const char *scene = argc > 1 && argv[1][0] != '-' ? argv[1] : "cases/newsprint-surface.yaml";
  int every = !(argc > 1 && strcmp(argv[argc - 1], "--no-every") == 0);
  /* the engine's share: the same reel with the (free) friction nip at every layer */
  const char *none[] = {"nip.model=friction", "nip.update=every"};
  const char *adaptive[] = {"nip.update=adaptive"};
  const char *each[] = {"nip.update=every"};
  int bad = run(scene, 2, none, "friction nip (engine)");
  bad |= run(scene, 1, adaptive, "contact nip, adaptive");
  if (every) bad |= run(scene, 1, each, "contact nip, every layer");
  return bad;
}
