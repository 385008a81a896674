/* The C API refuses NULL where it needs a pointer (issue 36): an error recorded and
 * returned, never a crash, as its neighbours already did. */
#include "check.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

static const char *scene_text = "material: {caliper: 1.0e-4, E_theta: 4.0e9, radial: {law: linear, "
                                "E_r: 2.0e7}}\ncore: {radius: 0.05}\n"
                                "winding: {final_radius: 0.051, tension: 200}\n";

static void scene_wind_null_out(void)
{
  rs_scene *scene = NULL;
  CHECK(rs_scene_load_text("null.yaml", scene_text, strlen(scene_text), 0, NULL, &scene) == RS_OK);
  CHECK(rs_scene_wind(scene, NULL, NULL) == RS_ERR_INTERNAL);
  CHECK(strstr(rs_error_message(), "out is NULL") != NULL);
  rs_reel_result *res = (rs_reel_result *)1;
  CHECK(rs_scene_wind(NULL, NULL, &res) == RS_ERR_INTERNAL && res == NULL);
  /* still winds when asked properly */
  CHECK(rs_scene_wind(scene, NULL, &res) == RS_OK && res && rs_reel_result_n_layers(res) == 10);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&scene);
}

static void reel_wind_null(void)
{
  rs_reel_result *res = (rs_reel_result *)1;
  CHECK(rs_reel_wind(NULL, NULL, &res) == RS_ERR_INTERNAL && res == NULL);
  CHECK(strstr(rs_error_message(), "no problem") != NULL);
  rs_problem pb;
  memset(&pb, 0, sizeof pb);
  CHECK(rs_reel_wind(&pb, NULL, NULL) == RS_ERR_INTERNAL);
}

static void null_set_entry(void)
{
  const char *sets[] = {"winding.tension=150", NULL};
  rs_scene *scene = (rs_scene *)1;
  CHECK(rs_scene_load_text("null.yaml", scene_text, strlen(scene_text), 2, sets, &scene) ==
        RS_ERR_INTERNAL);
  CHECK(scene == NULL);
  CHECK(strstr(rs_error_message(), "sets[1] is NULL") != NULL);
  scene = (rs_scene *)1;
  CHECK(rs_scene_load("nowhere.yaml", 2, sets, &scene) == RS_ERR_INTERNAL && scene == NULL);
}

static const check_case cases[] = {{"scene_wind_null_out", scene_wind_null_out},
                                   {"reel_wind_null", reel_wind_null},
                                   {"null_set_entry", null_set_entry}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
