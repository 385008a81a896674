/* /storage in a run file (docs/output.md, "Storage"): the roll at the end of every storage
 * stage (docs/storage.md), stage 0 being the wound roll (/final). */
#include <stdlib.h>

#include "output/h5_layout.h"
#include "output/h5_util.h"
#include "reel/result_internal.h"
#include "reelsim/output.h"
#include "reelsim/storage.h"
#include "util/error.h"
#include "storage/storage_result.h"

rs_status rs_h5_write_storage(hid_t loc, const rs_storage_result *sr)
{
  const size_t S = (size_t)sr->n_stages, n = (size_t)sr->n_layers;
  hid_t g;
  rs_status st = rs_h5_group_create(loc, "storage", &g);
  if (st != RS_OK) return st;
  st = rs_h5_attr_int64(g, "stages", (long long)S);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "elastic_solves", sr->elastic_solves);
  if (st == RS_OK) st = rs_h5_attr_double(g, "wall_seconds", sr->wall_seconds);
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "hours", sr->hours, S, "h",
                        "storage time at the end of each stage, cumulative; stage 0 (0 h) is "
                        "the wound roll");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "temperature", sr->temperature, S, "C",
                        "temperature of the roll in each stage (stage 0: winding.temperature)");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "humidity", sr->humidity, S, "%RH",
                        "relative humidity in each stage (stage 0: winding.humidity)");
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "core_pressure", sr->core_pressure, S, "Pa",
                        "pressure on the core at the end of each stage");
  if (st == RS_OK)
    st = rs_h5_write_2d_history(g, "sigma_r", sr->sigma_r, S, n, "Pa",
                                "radial stress of each layer (columns) at the end of each stage "
                                "(rows), at the layer's outer radius; compression negative");
  if (st == RS_OK)
    st = rs_h5_write_2d_history(g, "sigma_theta", sr->sigma_theta, S, n, "Pa",
                                "mean hoop stress of each layer (columns) at the end of each "
                                "stage (rows); compression negative");
  H5Gclose(g);
  return st;
}

rs_status rs_h5_check_storage(const rs_storage_result *sr, const rs_reel_result *res)
{
  if (sr && (sr->n_stages < 1 || sr->n_layers != res->n_layers))
    return RS_ERROR(RS_ERR_INTERNAL, "storage result of %d stages, %d layers for a reel of %d",
                    sr->n_stages, sr->n_layers, res->n_layers);
  return RS_OK;
}

typedef struct stored_run {
  const rs_scene *scene;
  const rs_reel_result *res;
  const rs_storage_result *storage;
  const rs_defect_report *defects; /* NULL: assessed while writing */
} stored_run;

static rs_status build_stored(hid_t file, const void *ctx)
{
  const stored_run *run = ctx;
  rs_status st = rs_h5_write_run_assessed(file, run->scene, run->res, run->defects);
  if (st == RS_OK && run->storage) st = rs_h5_write_storage(file, run->storage);
  return st;
}

rs_status rs_output_write_stored(const char *path, const rs_scene *scene,
                                 const rs_reel_result *res, const rs_storage_result *storage)
{
  return rs_output_write_assessed(path, scene, res, storage, NULL);
}

rs_status rs_output_write_assessed(const char *path, const rs_scene *scene,
                                   const rs_reel_result *res, const rs_storage_result *storage,
                                   const rs_defect_report *defects)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no output file name given");
  if (!scene || !res) return RS_ERROR(RS_ERR_INTERNAL, "no scene or no result to write");
  rs_status st = rs_h5_check_result(res);
  if (st != RS_OK) return st;
  if ((st = rs_h5_check_storage(storage, res)) != RS_OK) return st;
  stored_run run = {scene, res, storage, defects};
  return rs_h5_write_staged(path, build_stored, &run);
}
