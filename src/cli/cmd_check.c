/* reelsim check: load, check, and show a scene without winding it. */
#include <stdio.h>

#include <string.h>

#include "cli/cli.h"
#include "reelsim/scene.h"

int cli_check(const cli_args *a)
{
  rs_scene *scene = NULL;
  rs_status st = rs_scene_load(a->scene, a->n_sets, a->sets, &scene);
  if (st != RS_OK) return cli_fail_status(st);
  cli_scene_warnings(scene);
  if (!a->quiet) {
    char shown[1024];
    printf("%s\n", cli_shown(rs_scene_title(scene), shown, sizeof shown));
    printf("scene %s: ok\n", rs_scene_path(scene));
    printf("active effects:\n");
    rs_scene_print_effects(scene, stdout);
    printf("\nresolved scene:\n");
    /* line by line, each line's control characters escaped (a --set comment holds the
     * value as typed) */
    for (const char *p = rs_scene_resolved_text(scene); *p;) {
      size_t n = strcspn(p, "\n");
      char line[4096], out[4 * sizeof line + 8];
      snprintf(line, sizeof line, "%.*s", (int)(n < sizeof line ? n : sizeof line - 1), p);
      printf("%s\n", cli_shown(line, out, sizeof out));
      p += n + (p[n] == '\n');
    }
  }
  rs_scene_destroy(&scene);
  return CLI_EXIT_OK;
}
