/* reelsim as a library: winds the reel a scene describes and prints its core pressure.
 *   wind_scene SCENE.yaml [key.path=value ...]    (overrides, as reelsim run --set) */
#include <stdio.h>

#include <reelsim/reelsim.h>

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: %s SCENE.yaml [key.path=value ...]\n", argv[0]);
    return 2;
  }
  printf("reelsim %s (headers %s)\n", rs_version(), RS_VERSION_STRING);

  rs_scene *scene = NULL;
  rs_reel_result *result = NULL;
  rs_reel_options opts = {0}; /* no progress callback */
  rs_status st = rs_scene_load(argv[1], argc - 2, (const char *const *)argv + 2, &scene);
  if (st == RS_OK) st = rs_scene_wind(scene, &opts, &result);
  if (st == RS_OK)
    printf("%d layers, core pressure %.1f Pa\n", rs_reel_result_n_layers(result),
           rs_reel_result_core_pressure(result));
  else
    fprintf(stderr, "wind_scene: %s\n", rs_error_message());

  rs_reel_result_destroy(&result);
  rs_scene_destroy(&scene);
  return rs_status_exit_code(st);
}
