/* A loaded scene as the problem the reel winds. */
#include "reelsim/reel.h"
#include "reelsim/scene.h"

const rs_problem *rs_scene_problem(const rs_scene *scene)
{
  return scene ? &scene->problem : NULL;
}

rs_status rs_scene_wind(const rs_scene *scene, const rs_reel_options *opts, rs_reel_result **out)
{
  if (!scene) {
    *out = NULL;
    return RS_ERROR(RS_ERR_INTERNAL, "rs_scene_wind: no scene");
  }
  return rs_reel_wind(&scene->problem, opts, out);
}
