/* What applications ask of a loaded scene: the problem it winds, winding it, its name and
 * what it says of itself. */
#include "reelsim/defects.h"
#include "reelsim/storage.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "scene/scene_type.h"
#include "util/error.h"
#include "util/path_stem.h"

const rs_problem *rs_scene_problem(const rs_scene *scene)
{
  return scene ? &scene->problem : NULL;
}

rs_status rs_scene_wind(const rs_scene *scene, const rs_reel_options *opts, rs_reel_result **out)
{
  if (!out) return RS_ERROR(RS_ERR_INTERNAL, "rs_scene_wind: out is NULL");
  if (!scene) {
    *out = NULL;
    return RS_ERROR(RS_ERR_INTERNAL, "rs_scene_wind: no scene");
  }
  return rs_reel_wind(&scene->problem, opts, out);
}

rs_status rs_scene_assess_defects(const rs_scene *scene, const rs_reel_result *res,
                                  rs_defect_report **out)
{
  *out = NULL;
  if (!scene) return RS_ERROR(RS_ERR_INTERNAL, "rs_scene_assess_defects: no scene");
  return rs_defects_of_problem(&scene->problem, res, out);
}

const char *rs_scene_path(const rs_scene *scene) { return scene ? scene->path : ""; }
const char *rs_scene_title(const rs_scene *scene) { return scene ? scene->title : ""; }
const char *rs_scene_output_file(const rs_scene *scene) { return scene ? scene->output.file : ""; }

const char *rs_scene_resolved_text(const rs_scene *scene)
{
  return scene && scene->resolved_text ? scene->resolved_text : "";
}

void rs_scene_name(const rs_scene *scene, char *buf, size_t size)
{
  if (!buf || size == 0) return;
  if (!scene) {
    buf[0] = '\0';
    return;
  }
  rs_path_stem(scene->path, buf, size);
}

int rs_scene_warning_count(const rs_scene *scene) { return scene ? scene->n_warnings : 0; }

const char *rs_scene_warning(const rs_scene *scene, int i)
{
  return scene && i >= 0 && i < scene->n_warnings ? scene->warnings[i] : "";
}
