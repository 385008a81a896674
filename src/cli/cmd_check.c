/* reelsim check: load, check, and show a scene without winding it. */
#include <stdio.h>

#include "cli/cli.h"
#include "reelsim/scene.h"

int cli_check(const cli_args *a)
{
  rs_scene *scene = NULL;
  rs_status st = rs_scene_load(a->scene, a->n_sets, a->sets, &scene);
  if (st != RS_OK) return cli_fail_status(st);
  cli_scene_warnings(scene);
  if (!a->quiet) {
    printf("%s\n", rs_scene_title(scene));
    printf("scene %s: ok\n", rs_scene_path(scene));
    printf("active effects:\n");
    rs_scene_print_effects(scene, stdout);
    printf("\nresolved scene:\n%s", rs_scene_resolved_text(scene));
  }
  rs_scene_destroy(&scene);
  return CLI_EXIT_OK;
}
