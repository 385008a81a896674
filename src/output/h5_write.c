/* rs_output_write: the layout of a reelsim HDF5 file (docs/output.md), and the layout of
 * one run that a comparison file repeats under /runs/<name> (h5_compare.c).
 *
 * The dataset names under /layers and /final are a contract: users' scripts read them.
 * Add new things beside them; never rename or change the sign of an existing one. */

#include "reelsim/output.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "output/h5_defects.h"
#include "output/h5_layout.h"
#include "output/h5_nip.h"
#include "output/h5_lanes.h"
#include "output/h5_util.h"
#include "reel/result_internal.h"
#include "util/atomic_file.h"
#include "reelsim/version.h"
#include "util/error.h"

/* The file records when it was made, in UTC so files from different machines sort. */
static void iso8601_now(char *buf, size_t len)
{
  time_t now = time(NULL);
  struct tm tm;
  if (now == (time_t)-1 || !gmtime_r(&now, &tm) || strftime(buf, len, "%Y-%m-%dT%H:%M:%SZ", &tm) == 0)
    snprintf(buf, len, "unknown");
}

rs_status rs_h5_write_file_attributes(hid_t file)
{
  char created[32];
  rs_status st;
  iso8601_now(created, sizeof created);
  if ((st = rs_h5_attr_string(file, "program", "reelsim")) != RS_OK) return st;
  if ((st = rs_h5_attr_string(file, "version", RS_VERSION_STRING)) != RS_OK) return st;
  return rs_h5_attr_string(file, "created", created);
}

/* What one run was and what it cost: on the root of a run file, on /runs/<name> of a
 * comparison. */
static rs_status write_run_attributes(hid_t loc, const rs_scene *scene, const rs_reel_result *res)
{
  int n = res->n_layers;
  /* With nothing wound the reel's outer radius is the core's. */
  double final_radius = n > 0 ? res->radius[n - 1] : rs_scene_problem(scene)->core.radius;
  rs_status st;
  if ((st = rs_h5_attr_string(loc, "title", rs_scene_title(scene))) != RS_OK) return st;
  if ((st = rs_h5_attr_string(loc, "scene_file", rs_scene_path(scene))) != RS_OK) return st;
  if ((st = rs_h5_attr_string(loc, "scene", rs_scene_resolved_text(scene))) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(loc, "layers", n)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(loc, "layers_planned", rs_scene_problem(scene)->n_layers)) != RS_OK) return st;
  /* 0: a run that stopped early, written on request (reelsim run --keep-partial) */
  if ((st = rs_h5_attr_int64(loc, "complete", n == rs_scene_problem(scene)->n_layers)) != RS_OK) return st;
  if ((st = rs_h5_attr_double(loc, "final_radius", final_radius)) != RS_OK) return st;
  if ((st = rs_h5_attr_double(loc, "core_pressure", res->core_pressure)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(loc, "increments", res->increments)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(loc, "cvode_steps", res->cvode_steps)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(loc, "rhs_evals", res->rhs_evals)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(loc, "full_integrations", res->full_integrations)) != RS_OK) return st;
  return rs_h5_attr_double(loc, "wall_seconds", res->wall_seconds);
}

/* /layers: what each layer was wound with, indexed from the core outwards. */
static rs_status write_layers(hid_t loc, const rs_reel_result *res)
{
  size_t n = (size_t)res->n_layers;
  hid_t g;
  rs_status st = rs_h5_group_create(loc, "layers", &g);
  if (st != RS_OK) return st;
  st = rs_h5_write_1d(g, "radius", res->radius, n, "m",
                      "outer radius of each layer; index 0 is the layer on the core");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "wound_on_tension", res->wound_on_tension, n, "N/m",
                        "wound-on tension T0 of each layer as it joined the roll (after the nip)");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "web_tension", res->web_tension, n, "N/m",
                        "web tension of each layer from the tension recipe (before the nip)");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "nip_load", res->nip_load, n, "N/m",
                        "nip load when each layer was wound on (0 without a nip)");
  if (st == RS_OK && res->wound_radius)
    st = rs_h5_write_1d(g, "wound_radius", res->wound_radius, n, "m",
                        "the roll's real outer radius when each layer went on: the core's "
                        "displacement, the calipers, the air films and the stack's radial "
                        "compression at that moment (what a diameter gauge reads against the "
                        "wound length)");
  if (st == RS_OK && res->air_film)
    st = rs_h5_write_1d(g, "air_film", res->air_film, n, "m",
                        "entrained air film under each layer in the wound reel: the film that "
                        "survived the roughness, compressed by the final pressure (isothermal)");
  if (st == RS_OK && res->air_film_entrained)
    st = rs_h5_write_1d(g, "air_film_entrained", res->air_film_entrained, n, "m",
                        "air film under each layer as it went on, at the ambient pressure (the "
                        "foil-bearing or nip film less the roughness cut-off)");
  H5Gclose(g);
  return st;
}

/* /final: the stresses in the finished reel. */
static rs_status write_final(hid_t loc, const rs_reel_result *res)
{
  size_t n = (size_t)res->n_layers;
  double *pressure = malloc((n ? n : 1) * sizeof *pressure);
  if (!pressure) return RS_ERROR(RS_ERR_MEMORY, "out of memory for %zu layers", n);
  /* 0 - x rather than -x: an unloaded layer (sigma_r = +0) gets pressure +0, not -0. */
  for (size_t i = 0; i < n; ++i) pressure[i] = 0.0 - res->sigma_r[i];
  hid_t g;
  rs_status st = rs_h5_group_create(loc, "final", &g);
  if (st != RS_OK) {
    free(pressure);
    return st;
  }
  st = rs_h5_write_1d(g, "sigma_r", res->sigma_r, n, "Pa",
                      "radial stress of each layer in the wound reel; compression negative");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "sigma_theta", res->sigma_theta, n, "Pa",
                        "hoop (tangential) stress of each layer in the wound reel; "
                        "compression negative");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "pressure", pressure, n, "Pa",
                        "interlayer pressure, -sigma_r; compression positive");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "radius", res->radius, n, "m",
                        "outer radius of each layer (the same as /layers/radius)");
  if (st == RS_OK && res->deformed_radius)
    st = rs_h5_write_1d(g, "deformed_radius", res->deformed_radius, n, "m",
                        "outer radius of each layer in the finished roll with the core's "
                        "displacement and the stack's radial compression (radius is the free "
                        "r_c + sum of calipers and films)");
  if (st == RS_OK && res->wound_in_tension)
    st = rs_h5_write_1d(g, "wound_in_tension", res->wound_in_tension, n, "N/m",
                        "wound-in tension of each layer, sigma_theta times the caliper (what WIT "
                        "gauges and pull-out methods measure)");
  if (st == RS_OK)
    st = rs_h5_write_scalar(g, "core_pressure", res->core_pressure, "Pa",
                            "pressure on the core in the wound reel; compression positive");
  H5Gclose(g);
  free(pressure);
  return st;
}

/* /final_at_speed: the roll spinning at the last layer's speed (centrifugal load on; /final
 * is then the roll at rest, after the stop). */
static rs_status write_final_at_speed(hid_t loc, const rs_reel_result *res)
{
  if (!res->at_speed_sigma_r || !res->at_speed_sigma_theta) return RS_OK;
  size_t n = (size_t)res->n_layers;
  hid_t g;
  rs_status st = rs_h5_group_create(loc, "final_at_speed", &g);
  if (st != RS_OK) return st;
  st = rs_h5_write_1d(g, "sigma_r", res->at_speed_sigma_r, n, "Pa",
                      "radial stress of each layer, the roll spinning at the last layer's "
                      "speed; compression negative");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "sigma_theta", res->at_speed_sigma_theta, n, "Pa",
                        "hoop stress of each layer, the roll spinning at the last layer's "
                        "speed; compression negative");
  if (st == RS_OK)
    st = rs_h5_write_scalar(g, "core_pressure", res->at_speed_core_pressure, "Pa",
                            "pressure on the core, the roll spinning; compression positive");
  H5Gclose(g);
  return st;
}

/* /history: the roll's stresses at stages of the winding (output.history_every > 0).
 * NaN marks the layers not yet wound at a stage; the last stage is /final. */
static rs_status write_history(hid_t loc, const rs_scene *scene, const rs_reel_result *res)
{
  size_t S = (size_t)res->n_stages, n = (size_t)res->n_layers;
  long long *layers = malloc((S ? S : 1) * sizeof *layers);
  if (!layers) return RS_ERROR(RS_ERR_MEMORY, "out of memory for %zu history stages", S);
  for (size_t s = 0; s < S; ++s) layers[s] = res->stage_layers[s];
  hid_t g;
  rs_status st = rs_h5_group_create(loc, "history", &g);
  if (st != RS_OK) {
    free(layers);
    return st;
  }
  st = rs_h5_attr_int64(g, "every", rs_scene_problem(scene)->record.history_every);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "stages", (long long)S);
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "outer_radius", res->stage_radius, S, "m",
                        "outer radius of the roll at each stage");
  if (st == RS_OK)
    st = rs_h5_write_1d_int64(g, "layers", layers, S, "",
                              "layers wound at each stage; the last stage is the final reel");
  if (st == RS_OK)
    st = rs_h5_write_2d_history(g, "sigma_r", res->stage_sigma_r, S, n, "Pa",
                                "radial stress of each layer (columns) at each stage (rows); "
                                "compression negative; NaN for layers not yet wound");
  if (st == RS_OK)
    st = rs_h5_write_2d_history(g, "sigma_theta", res->stage_sigma_theta, S, n, "Pa",
                                "hoop stress of each layer (columns) at each stage (rows); "
                                "compression negative; NaN for layers not yet wound");
  H5Gclose(g);
  free(layers);
  return st;
}

rs_status rs_h5_check_result(const rs_reel_result *res)
{
  if (res->n_layers < 0)
    return RS_ERROR(RS_ERR_INTERNAL, "result has %d layers", res->n_layers);
  if (res->n_stages < 0 ||
      (res->n_stages > 0 && (!res->stage_layers || !res->stage_radius || !res->stage_sigma_r ||
                             !res->stage_sigma_theta)))
    return RS_ERROR(RS_ERR_INTERNAL, "result with %d history stages lacks an array",
                    res->n_stages);
  if (res->n_layers > 0 &&
      (!res->radius || !res->wound_on_tension || !res->web_tension || !res->nip_load ||
       !res->sigma_r || !res->sigma_theta))
    return RS_ERROR(RS_ERR_INTERNAL, "result with %d layers lacks an array", res->n_layers);
  return RS_OK;
}

rs_status rs_h5_write_run(hid_t loc, const rs_scene *scene, const rs_reel_result *res)
{
  return rs_h5_write_run_assessed(loc, scene, res, NULL);
}

rs_status rs_h5_write_run_assessed(hid_t loc, const rs_scene *scene, const rs_reel_result *res,
                                   const rs_defect_report *defects)
{
  rs_status st = write_run_attributes(loc, scene, res);
  if (st == RS_OK) st = write_layers(loc, res);
  if (st == RS_OK) st = write_final(loc, res);
  if (st == RS_OK) st = write_final_at_speed(loc, res);
  if (st == RS_OK && rs_scene_problem(scene)->record.history_every > 0) st = write_history(loc, scene, res);
  if (st == RS_OK) st = rs_h5_write_defects(loc, scene, res, defects);
  if (st == RS_OK) st = rs_h5_write_nip(loc, scene, res);
  if (st == RS_OK) st = rs_h5_write_lanes(loc, res);
  return st;
}

/* Builds the whole file in memory (see h5_memfile.c) and hands back its bytes. */
static rs_status build_image(rs_h5_build_fn build, const void *ctx, void **image, size_t *size)
{
  hid_t file;
  rs_status st = rs_h5_memfile_create(&file);
  if (st != RS_OK) return st;
  st = rs_h5_write_file_attributes(file);
  if (st == RS_OK) st = build(file, ctx);
  if (st == RS_OK) st = rs_h5_memfile_image(file, image, size);
  if (H5Fclose(file) < 0 && st == RS_OK) {
    char detail[512];
    rs_h5_error_detail(detail, sizeof detail);
    st = RS_ERROR(RS_ERR_IO, "cannot close the in-memory HDF5 file: %s", detail);
    free(*image);
    *image = NULL;
  }
  return st;
}

rs_status rs_h5_write_staged(const char *path, rs_h5_build_fn build, const void *ctx)
{
  /* Check the target first: a typo in the directory should not cost the build. */
  rs_status st = rs_atomic_file_check_target(path);
  if (st != RS_OK) return st;
  void *image = NULL;
  size_t size = 0;
  rs_h5_quiet quiet;
  rs_h5_quiet_begin(&quiet);
  st = build_image(build, ctx, &image, &size);
  rs_h5_quiet_end(&quiet);
  if (st != RS_OK) return rs_error_wrap("cannot write output file '%s'", path);
  st = rs_atomic_file_write(path, image, size);
  free(image);
  return st;
}

rs_status rs_output_check_target(const char *path)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no output file name given");
  return rs_atomic_file_check_target(path);
}

typedef struct single_run {
  const rs_scene *scene;
  const rs_reel_result *res;
} single_run;

/* A run file: the run's layout on the root group. */
static rs_status build_single(hid_t file, const void *ctx)
{
  const single_run *run = ctx;
  return rs_h5_write_run(file, run->scene, run->res);
}

rs_status rs_output_write(const char *path, const rs_scene *scene, const rs_reel_result *res)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no output file name given");
  if (!scene || !res) return RS_ERROR(RS_ERR_INTERNAL, "no scene or no result to write");
  rs_status st = rs_h5_check_result(res);
  if (st != RS_OK) return st;
  single_run run = {scene, res};
  return rs_h5_write_staged(path, build_single, &run);
}
