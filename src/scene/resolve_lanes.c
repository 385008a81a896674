/* Lanes across the width (docs/lanes.md): the `lanes` block from the checked tree into the
 * problem's rs_lanes_spec. A scene without the block has count 0 and winds as before.
 *
 *   geometry   width + count (equal lanes) or edges (count + 1 increasing positions, m)
 *   caliper    a factor per lane, or caliper_profile [[x, factor], ...] piecewise linear in
 *              x, taken at the lane centres (held beyond its ends); neither: 1
 *   tension    tension_profile likewise (neither: 1)
 *   nip        uniform (default) or roller (needs a nip)
 * Errors (exit 2, at the key): edges not increasing, factors <= 0, a list whose length is not
 * the lane count, more than RS_LANES_MAX lanes, and what the lanes driver does not take. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"

enum { EDGES_MAX = 4096 };

/* x and width of each lane from width + count or from edges */
static rs_status lanes_geometry(const yn *root, rs_lanes_spec *L)
{
  const int has_edges = rsi_ys_has(root, "lanes.edges");
  if (has_edges && (rsi_ys_has(root, "lanes.width") || rsi_ys_has(root, "lanes.count")))
    return rsi_ys_fail(root, "lanes.edges", "give either edges or width and count, not both");
  if (has_edges) {
    double e[EDGES_MAX];
    const int n = rsi_ys_nums(root, "lanes.edges", e, EDGES_MAX) - 1;
    if (n < 1) return rsi_ys_fail(root, "lanes.edges", "needs at least 2 edges (one lane)");
    if (n > RS_LANES_MAX)
      return rsi_ys_fail(root, "lanes.edges", "%d lanes: at most %d", n, RS_LANES_MAX);
    for (int i = 0; i < n; ++i) {
      if (!(e[i + 1] > e[i]))
        return rsi_ys_fail(root, "lanes.edges",
                       "edges must increase: edge %d (%g m) is not above edge %d (%g m)", i + 2,
                       e[i + 1], i + 1, e[i]);
      L->x[i] = 0.5 * (e[i] + e[i + 1]);
      L->width[i] = e[i + 1] - e[i];
    }
    L->count = n;
    return RS_OK;
  }
  if (!rsi_ys_has(root, "lanes.width") || !rsi_ys_has(root, "lanes.count"))
    return rsi_ys_fail(root, rsi_ys_has(root, "lanes.width") ? "lanes.count" : "lanes.width",
                   "required by lanes: width (m) and count, or edges (m)");
  const double W = rsi_ys_num(root, "lanes.width");
  const long long n = rsi_ys_int(root, "lanes.count");
  if (!(W > 0.0 && W < INFINITY)) return rsi_ys_fail(root, "lanes.width", "must be > 0 m (got %g)", W);
  if (n < 1 || n > RS_LANES_MAX)
    return rsi_ys_fail(root, "lanes.count", "must be 1 to %d lanes (got %lld)", RS_LANES_MAX, n);
  for (int i = 0; i < (int)n; ++i) {
    L->width[i] = W / (double)n;
    L->x[i] = W * (i + 0.5) / (double)n;
  }
  L->count = (int)n;
  return RS_OK;
}

/* a factor per lane: the list `key` (one per lane) or the profile `pkey` at the centres */
static rs_status lanes_factor(const yn *root, const rs_lanes_spec *L, const char *key,
                              const char *pkey, double *out)
{
  char at[64];
  for (int i = 0; i < L->count; ++i) out[i] = 1.0;
  if (key && rsi_ys_has(root, key) && rsi_ys_has(root, pkey))
    return rsi_ys_fail(root, pkey, "give either %s or %s, not both", key + 6, pkey + 6);
  if (key && rsi_ys_has(root, key)) {
    double f[EDGES_MAX];
    const int n = rsi_ys_nums(root, key, f, EDGES_MAX);
    if (n != L->count)
      return rsi_ys_fail(root, key, "has %d factors for %d lanes (one per lane)", n, L->count);
    for (int i = 0; i < n; ++i) {
      snprintf(at, sizeof at, "%s[%d]", key, i);
      if (!(f[i] > 0.0)) return rsi_ys_fail(root, at, "a factor must be > 0 (got %g)", f[i]);
      out[i] = f[i];
    }
    return RS_OK;
  }
  if (!rsi_ys_has(root, pkey)) return RS_OK;
  double x[RS_TABLE_MAX], f[RS_TABLE_MAX];
  const int n = rsi_ys_pairs(root, pkey, x, f, RS_TABLE_MAX);
  for (int k = 0; k < n; ++k) {
    snprintf(at, sizeof at, "%s[%d]", pkey, k);
    if (!(f[k] > 0.0)) return rsi_ys_fail(root, at, "a factor must be > 0 (got %g)", f[k]);
    if (k > 0 && !(x[k] > x[k - 1]))
      return rsi_ys_fail(root, at, "x must increase: %g m is not above %g m", x[k], x[k - 1]);
  }
  for (int i = 0; i < L->count; ++i) {
    const double c = L->x[i];
    int k = 0;
    while (k + 1 < n && x[k + 1] <= c) ++k;
    if (c <= x[0] || n == 1) out[i] = f[0];
    else if (k + 1 >= n) out[i] = f[n - 1];
    else out[i] = f[k] + (f[k + 1] - f[k]) * (c - x[k]) / (x[k + 1] - x[k]);
  }
  return RS_OK;
}

/* What the lanes driver does not take (src/reel/lanes.c): several layers per increment (the
 * lanes are coupled layer by layer). */
static rs_status lanes_limits(const yn *root, const rs_scene *s)
{
  const rs_problem *p = &s->problem;
  if (p->numerics.layers_per_step > 1)
    return rsi_ys_fail(root, "numerics.layers_per_step",
                   "must be 1 with lanes (the lanes are coupled layer by layer; got %d)",
                   p->numerics.layers_per_step);
  if (p->lanes.nip == RS_LANES_NIP_ROLLER && p->nip.model == RS_NIP_NONE)
    return rsi_ys_fail(root, "lanes.nip", "roller shares the nip's load: the scene has no nip");
  return RS_OK;
}

rs_status rsi_ys_resolve_lanes(const yn *root, rs_scene *s)
{
  rs_lanes_spec *L = &s->problem.lanes;
  memset(L, 0, sizeof *L);
  if (!rsi_ys_has(root, "lanes")) return RS_OK;
  rs_lanes_spec spec = {0};
  rs_status st = lanes_geometry(root, &spec);
  if (!st) st = lanes_factor(root, &spec, "lanes.caliper", "lanes.caliper_profile", spec.caliper);
  if (!st) st = lanes_factor(root, &spec, NULL, "lanes.tension_profile", spec.tension);
  if (st) return st;
  spec.nip = (rs_lanes_nip)rsi_ys_enum(root, "lanes.nip");
  *L = spec;
  if ((st = lanes_limits(root, s))) memset(L, 0, sizeof *L);
  return st;
}
