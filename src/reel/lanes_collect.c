/* Lanes across the width: the result (lanes.h). Each lane's finished roll goes into the
 * lanes' record (layers x lanes, row k = layer k); the reel's own per-layer arrays become
 * the width-weighted means of the lanes' (sum w_i v_i / W), so that the summary, the
 * defects and /layers read a mean roll, equal to the 1-D roll to round-off when the lanes
 * are uniform. The nip record, history and profiles are those of the lane nearest the
 * middle of the width. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "reel/lanes.h"
#include "reel/result_internal.h"
#include "util/error.h"

rs_lanes_result *rs_lanes_result_new(int n, int N, int with_nip)
{
  rs_lanes_result *lr = calloc(1, sizeof *lr);
  if (!lr) return NULL;
  const size_t per = (size_t)n, grid = (size_t)n * (size_t)(N > 0 ? N : 1);
  lr->count = n;
  lr->x = calloc(per, sizeof(double));
  lr->width = calloc(per, sizeof(double));
  lr->caliper = calloc(per, sizeof(double));
  lr->core_pressure = calloc(per, sizeof(double));
  lr->outer_radius = calloc(per, sizeof(double));
  lr->wound_on_tension = calloc(grid, sizeof(double));
  lr->web_tension = calloc(grid, sizeof(double));
  lr->slack = calloc(grid, 1);
  lr->strain = calloc((size_t)(N > 0 ? N : 1), sizeof(double));
  lr->sigma_r = calloc(grid, sizeof(double));
  lr->sigma_theta = calloc(grid, sizeof(double));
  lr->radius = calloc(grid, sizeof(double));
  if (with_nip) lr->nip_load = calloc(grid, sizeof(double));
  if (!lr->x || !lr->width || !lr->caliper || !lr->core_pressure || !lr->outer_radius ||
      !lr->wound_on_tension || !lr->web_tension || !lr->slack || !lr->strain || !lr->sigma_r ||
      !lr->sigma_theta || !lr->radius || (with_nip && !lr->nip_load))
    rs_lanes_result_destroy(&lr);
  return lr;
}

/* mean[j] = sum_i w_i v_i[j] / W over the lanes' arrays (the field at offset `off` of each
 * lane's result), j < n; 0 (nothing written) when a lane has no such array */
static int width_mean(const rs_problem *pb, rs_lane *lane, size_t off, int n, double W,
                       double *mean)
{
  const int m = pb->lanes.count;
  for (int i = 0; i < m; ++i)
    if (!*(double **)((char *)lane[i].res + off)) return 0;
  for (int j = 0; j < n; ++j) {
    double sum = 0.0;
    for (int i = 0; i < m; ++i) sum += pb->lanes.width[i] * (*(double **)((char *)lane[i].res + off))[j];
    mean[j] = sum / W;
  }
  return 1;
}

/* each lane's final state into the record (deformed radii per layer: the gauges') */
static void lanes_final(const rs_problem *pb, rs_lane *lane, rs_lanes_result *lr, int n)
{
  const int m = pb->lanes.count;
  for (int i = 0; i < m; ++i) {
    const rs_reel_result *r = lane[i].res;
    lr->x[i] = pb->lanes.x[i];
    lr->width[i] = pb->lanes.width[i];
    lr->caliper[i] = lane[i].pb.material.caliper;
    lr->core_pressure[i] = r->core_pressure;
    const double *rad = r->deformed_radius ? r->deformed_radius : r->radius;
    lr->outer_radius[i] = n > 0 ? rad[n - 1] : pb->core.radius;
    for (int j = 0; j < n; ++j) {
      const size_t at = (size_t)j * m + i;
      lr->sigma_r[at] = r->sigma_r[j];
      lr->sigma_theta[at] = r->sigma_theta[j];
      lr->radius[at] = rad[j];
      lr->wound_on_tension[at] = r->wound_on_tension[j];
    }
  }
}

rs_status rs_lanes_collect(const rs_problem *pb, rs_lane *lane, rs_lanes_result *lr,
                           rs_reel_result **out)
{
  const int m = pb->lanes.count;
  int n = pb->n_layers, mid = 0;
  double W = 0.0;
  for (int i = 0; i < m; ++i) {
    if (!lane[i].res) {
      rs_lanes_result_destroy(&lr);
      return RS_ERROR(RS_ERR_MEMORY, "lane %d has no result", i + 1);
    }
    n = lane[i].res->n_layers < n ? lane[i].res->n_layers : n;
    W += pb->lanes.width[i];
  }
  const double centre = 0.5 * (pb->lanes.x[0] - 0.5 * pb->lanes.width[0] + pb->lanes.x[m - 1] +
                               0.5 * pb->lanes.width[m - 1]);
  for (int i = 1; i < m; ++i)
    if (fabs(pb->lanes.x[i] - centre) < fabs(pb->lanes.x[mid] - centre)) mid = i;
  lr->n_layers = n;
  lanes_final(pb, lane, lr, n);
  rs_reel_result *res = lane[mid].res;
  lane[mid].res = NULL;
  const size_t offs[] = {offsetof(rs_reel_result, radius), offsetof(rs_reel_result, wound_on_tension),
                         offsetof(rs_reel_result, web_tension), offsetof(rs_reel_result, nip_load),
                         offsetof(rs_reel_result, sigma_r), offsetof(rs_reel_result, sigma_theta),
                         offsetof(rs_reel_result, deformed_radius),
                         offsetof(rs_reel_result, wound_radius),
                         offsetof(rs_reel_result, wound_in_tension),
                         offsetof(rs_reel_result, at_speed_sigma_r),
                         offsetof(rs_reel_result, at_speed_sigma_theta)};
  /* the middle lane's own arrays are read as one of the lanes: put it back while averaging */
  rs_reel_result *keep = calloc(1, sizeof *keep);
  if (!keep) {
    rs_reel_result_destroy(&res);
    rs_lanes_result_destroy(&lr);
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the lanes' mean");
  }
  *keep = *res;
  lane[mid].res = keep;
  for (size_t k = 0; k < sizeof offs / sizeof offs[0]; ++k) {
    double *dst = *(double **)((char *)res + offs[k]);
    if (!dst) continue;
    double *copy = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
    if (!copy) continue;
    if (width_mean(pb, lane, offs[k], n, W, copy)) memcpy(dst, copy, (size_t)n * sizeof(double));
    free(copy);
  }
  double pc = 0.0, pcs = 0.0;
  for (int i = 0; i < m; ++i) {
    pc += pb->lanes.width[i] * lane[i].res->core_pressure;
    pcs += pb->lanes.width[i] * lane[i].res->at_speed_core_pressure;
  }
  res->core_pressure = pc / W;
  res->at_speed_core_pressure = pcs / W;
  res->n_layers = n;
  free(keep);
  lane[mid].res = NULL;
  res->lanes = lr;
  *out = res;
  return RS_OK;
}
