/* rs_output_write: the layout of a reelsim HDF5 file (docs/output.md).
 *
 * The dataset names under /layers and /final are a contract: users' scripts read them.
 * Add new things beside them; never rename or change the sign of an existing one. */

#include "reelsim/output.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "output/h5_defects.h"
#include "output/h5_util.h"
#include "output/staging.h"
#include "reelsim_version.h"

/* The file records when it was made, in UTC so files from different machines sort. */
static void iso8601_now(char *buf, size_t len)
{
  time_t now = time(NULL);
  struct tm tm;
  if (now == (time_t)-1 || !gmtime_r(&now, &tm) || strftime(buf, len, "%Y-%m-%dT%H:%M:%SZ", &tm) == 0)
    snprintf(buf, len, "unknown");
}

static rs_status write_root_attributes(hid_t file, const rs_scene *scene,
                                       const rs_reel_result *res)
{
  char created[32];
  int n = res->n_layers;
  /* With nothing wound the reel's outer radius is the core's. */
  double final_radius = n > 0 ? res->radius[n - 1] : scene->core.radius;
  rs_status st;
  iso8601_now(created, sizeof created);
  if ((st = rs_h5_attr_string(file, "program", "reelsim")) != RS_OK) return st;
  if ((st = rs_h5_attr_string(file, "version", RS_VERSION_STRING)) != RS_OK) return st;
  if ((st = rs_h5_attr_string(file, "created", created)) != RS_OK) return st;
  if ((st = rs_h5_attr_string(file, "title", scene->title)) != RS_OK) return st;
  if ((st = rs_h5_attr_string(file, "scene_file", scene->path)) != RS_OK) return st;
  if ((st = rs_h5_attr_string(file, "scene", scene->resolved_text)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(file, "layers", n)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(file, "layers_planned", scene->n_layers)) != RS_OK) return st;
  /* 0: a run that stopped early, written on request (reelsim run --keep-partial) */
  if ((st = rs_h5_attr_int64(file, "complete", n == scene->n_layers)) != RS_OK) return st;
  if ((st = rs_h5_attr_double(file, "final_radius", final_radius)) != RS_OK) return st;
  if ((st = rs_h5_attr_double(file, "core_pressure", res->core_pressure)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(file, "increments", res->increments)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(file, "cvode_steps", res->cvode_steps)) != RS_OK) return st;
  if ((st = rs_h5_attr_int64(file, "rhs_evals", res->rhs_evals)) != RS_OK) return st;
  return rs_h5_attr_double(file, "wall_seconds", res->wall_seconds);
}

/* /layers: what each layer was wound with, indexed from the core outwards. */
static rs_status write_layers(hid_t file, const rs_reel_result *res)
{
  size_t n = (size_t)res->n_layers;
  hid_t g;
  rs_status st = rs_h5_group_create(file, "layers", &g);
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
  H5Gclose(g);
  return st;
}

/* /final: the stresses in the finished reel. */
static rs_status write_final(hid_t file, const rs_reel_result *res)
{
  size_t n = (size_t)res->n_layers;
  double *pressure = malloc((n ? n : 1) * sizeof *pressure);
  if (!pressure) return RS_ERROR(RS_ERR_MEMORY, "out of memory for %zu layers", n);
  /* 0 - x rather than -x: an unloaded layer (sigma_r = +0) gets pressure +0, not -0. */
  for (size_t i = 0; i < n; ++i) pressure[i] = 0.0 - res->sigma_r[i];
  hid_t g;
  rs_status st = rs_h5_group_create(file, "final", &g);
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
  if (st == RS_OK)
    st = rs_h5_write_scalar(g, "core_pressure", res->core_pressure, "Pa",
                            "pressure on the core in the wound reel; compression positive");
  H5Gclose(g);
  free(pressure);
  return st;
}

/* /history: the roll's stresses at stages of the winding (output.history_every > 0).
 * NaN marks the layers not yet wound at a stage; the last stage is /final. */
static rs_status write_history(hid_t file, const rs_scene *scene, const rs_reel_result *res)
{
  size_t S = (size_t)res->n_stages, n = (size_t)res->n_layers;
  long long *layers = malloc((S ? S : 1) * sizeof *layers);
  if (!layers) return RS_ERROR(RS_ERR_MEMORY, "out of memory for %zu history stages", S);
  for (size_t s = 0; s < S; ++s) layers[s] = res->stage_layers[s];
  hid_t g;
  rs_status st = rs_h5_group_create(file, "history", &g);
  if (st != RS_OK) {
    free(layers);
    return st;
  }
  st = rs_h5_attr_int64(g, "every", scene->output.history_every);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "stages", (long long)S);
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "outer_radius", res->stage_radius, S, "m",
                        "outer radius of the roll at each stage");
  if (st == RS_OK)
    st = rs_h5_write_1d_int64(g, "layers", layers, S, "",
                              "layers wound at each stage; the last stage is the final reel");
  if (st == RS_OK)
    st = rs_h5_write_2d_chunked(g, "sigma_r", res->stage_sigma_r, S, n, "Pa",
                                "radial stress of each layer (columns) at each stage (rows); "
                                "compression negative; NaN for layers not yet wound");
  if (st == RS_OK)
    st = rs_h5_write_2d_chunked(g, "sigma_theta", res->stage_sigma_theta, S, n, "Pa",
                                "hoop stress of each layer (columns) at each stage (rows); "
                                "compression negative; NaN for layers not yet wound");
  H5Gclose(g);
  free(layers);
  return st;
}

static rs_status check_result(const rs_reel_result *res)
{
  if (res->n_layers < 0)
    return RS_ERROR(RS_ERR_INTERNAL, "result has %d layers", res->n_layers);
  if (res->n_layers > 0 &&
      (!res->radius || !res->wound_on_tension || !res->web_tension || !res->nip_load ||
       !res->sigma_r || !res->sigma_theta))
    return RS_ERROR(RS_ERR_INTERNAL, "result with %d layers lacks an array", res->n_layers);
  if (res->n_stages < 0 ||
      (res->n_stages > 0 && (!res->stage_layers || !res->stage_radius || !res->stage_sigma_r ||
                             !res->stage_sigma_theta)))
    return RS_ERROR(RS_ERR_INTERNAL, "result with %d history stages lacks an array",
                    res->n_stages);
  return RS_OK;
}

/* Builds the whole file in memory (see h5_memfile.c) and hands back its bytes. */
static rs_status build_image(const rs_scene *scene, const rs_reel_result *res, void **image,
                             size_t *size)
{
  hid_t file;
  rs_status st = rs_h5_memfile_create(&file);
  if (st != RS_OK) return st;
  st = write_root_attributes(file, scene, res);
  if (st == RS_OK) st = write_layers(file, res);
  if (st == RS_OK) st = write_final(file, res);
  if (st == RS_OK && scene->output.history_every > 0) st = write_history(file, scene, res);
  if (st == RS_OK) st = rs_h5_write_defects(file, scene, res);
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

rs_status rs_output_write(const char *path, const rs_scene *scene, const rs_reel_result *res)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no output file name given");
  if (!scene || !res) return RS_ERROR(RS_ERR_INTERNAL, "no scene or no result to write");
  rs_status st = check_result(res);
  /* Check the target first: a typo in the directory should not cost the build. */
  if (st == RS_OK) st = rs_staging_check_target(path);
  if (st != RS_OK) return st;

  void *image = NULL;
  size_t size = 0;
  rs_h5_quiet quiet;
  rs_h5_quiet_begin(&quiet);
  st = build_image(scene, res, &image, &size);
  rs_h5_quiet_end(&quiet);
  if (st != RS_OK) return rs_error_wrap("cannot write output file '%s'", path);
  st = rs_staging_write(path, image, size);
  free(image);
  return st;
}
