/* The /lanes group (docs/output.md, "Lanes"): per lane (x, width, caliper, core pressure,
 * final outer radius) and layers x lanes (row k = layer k: wound-on and web tension, slack,
 * nip load; /lanes/final: the final stresses and deformed radii), the web's strain per
 * layer. */
#include "output/h5_lanes.h"

#include <stdlib.h>

#include "output/h5_util.h"
#include "reel/result_internal.h"
#include "util/error.h"

typedef struct lanes_column {
  const char *name;
  const double *data;
  size_t rows; /* 0: a 1-D dataset of `cols` */
  const char *units, *description;
} lanes_column;

static rs_status write_columns(hid_t g, const lanes_column *c, size_t count, size_t cols)
{
  rs_status st = RS_OK;
  for (size_t k = 0; st == RS_OK && k < count; ++k) {
    if (!c[k].data) continue;
    st = c[k].rows ? rs_h5_write_2d_chunked(g, c[k].name, c[k].data, c[k].rows, cols, c[k].units,
                                            c[k].description)
                   : rs_h5_write_1d(g, c[k].name, c[k].data, cols, c[k].units, c[k].description);
  }
  return st;
}

/* slack as 0/1 numbers, layers x lanes */
static rs_status write_slack(hid_t g, const rs_lanes_result *lr)
{
  const size_t n = (size_t)lr->n_layers * (size_t)lr->count;
  double *v = malloc((n ? n : 1) * sizeof *v);
  if (!v) return RS_ERROR(RS_ERR_MEMORY, "out of memory for /lanes/slack");
  for (size_t i = 0; i < n; ++i) v[i] = lr->slack[i] ? 1.0 : 0.0;
  rs_status st = rs_h5_write_2d_chunked(g, "slack", v, (size_t)lr->n_layers, (size_t)lr->count, "",
                                        "1 where the lane's web tension was 0 as the layer went "
                                        "on (slack: a baggy lane), else 0; layers x lanes");
  free(v);
  return st;
}

rs_status rs_h5_write_lanes(hid_t loc, const rs_reel_result *res)
{
  const rs_lanes_result *lr = res->lanes;
  if (!lr) return RS_OK;
  const size_t m = (size_t)lr->count, N = (size_t)lr->n_layers;
  hid_t g, f;
  rs_status st = rs_h5_group_create(loc, "lanes", &g);
  if (st) return st;
  const lanes_column top[] = {
      {"x", lr->x, 0, "m", "each lane's centre across the width"},
      {"width", lr->width, 0, "m", "each lane's width"},
      {"caliper", lr->caliper, 0, "m", "each lane's caliper"},
      {"core_pressure", lr->core_pressure, 0, "Pa", "each lane's core pressure, compression positive"},
      {"outer_radius", lr->outer_radius, 0, "m",
       "each lane's deformed outer radius at the end: the diameter profile across the width / 2"},
      {"wound_on_tension", lr->wound_on_tension, N, "N/m",
       "T0 of each lane as each layer went on: its web tension plus its nip-induced part; "
       "layers x lanes"},
      {"web_tension", lr->web_tension, N, "N/m",
       "each lane's share T_i of the web's tension as each layer went on; layers x lanes"},
      {"nip_load", lr->nip_load, N, "N/m", "each lane's nip line load as each layer went on; layers x lanes"}};
  st = write_columns(g, top, sizeof top / sizeof top[0], m);
  if (st == RS_OK) st = write_slack(g, lr);
  if (st == RS_OK)
    st = rs_h5_write_1d(g, "strain", lr->strain, N, "",
                        "the web's machine-direction strain e as each layer went on (on a "
                        "drum-driven winder e_d, its strain on the drum)");
  if (st == RS_OK) st = rs_h5_attr_int64(g, "count", lr->count);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "threads", lr->threads);
  if (st == RS_OK) st = rs_h5_attr_double(g, "tension_misfit", lr->Tbar_W_misfit);
  if (st == RS_OK && (st = rs_h5_group_create(g, "final", &f)) == RS_OK) {
    const lanes_column fin[] = {
        {"sigma_r", lr->sigma_r, N, "Pa", "final radial stress per layer and lane (compression < 0)"},
        {"sigma_theta", lr->sigma_theta, N, "Pa", "final hoop stress per layer and lane"},
        {"radius", lr->radius, N, "m",
         "final deformed outer radius of each layer per lane (core displacement, calipers, "
         "stack compression)"}};
    st = write_columns(f, fin, sizeof fin / sizeof fin[0], m);
    H5Gclose(f);
  }
  H5Gclose(g);
  return st;
}
