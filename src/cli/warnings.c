/* The scene's slip warnings (values outside the range plants use, docs/scenes.md): on
 * stderr for every command that loads a scene; --json also carries them (summary_json.c). */
#include <stdio.h>

#include "cli/cli.h"
#include "reelsim/scene.h"

void cli_scene_warnings(const rs_scene *scene)
{
  for (int i = 0; i < rs_scene_warning_count(scene); ++i)
    fprintf(stderr, "reelsim: warning: %s\n", rs_scene_warning(scene, i));
}
