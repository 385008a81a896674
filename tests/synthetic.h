/* Synthetic scenes, results and files for the reader, compare and plot tests: shapes an
 * engineer would recognise (pressure highest near the core, hoop stress crossing zero),
 * with a `variant` that changes every value so that runs are told apart. */
#ifndef RS_TESTS_SYNTHETIC_H
#define RS_TESTS_SYNTHETIC_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "scene/scene_type.h" /* the fields: these tests look inside */
#include "scratch.h" /* scratch_dir, scratch_join, ... for the files these tests write */

static inline rs_scene *syn_scene(const char *path, const char *title)
{
  rs_scene *s = calloc(1, sizeof *s);
  snprintf(s->path, sizeof s->path, "%s", path);
  snprintf(s->title, sizeof s->title, "%s", title);
  s->problem.core.radius = 0.05;
  s->problem.n_layers = 200;
  s->resolved_text = strdup("title: synthetic\n");
  return s;
}

static inline void syn_scene_free(rs_scene *s)
{
  if (!s) return;
  free(s->resolved_text);
  free(s);
}

static inline rs_reel_result *syn_result(int n, double variant)
{
  rs_reel_result *r = calloc(1, sizeof *r);
  r->n_layers = n;
  size_t sz = (size_t)(n > 0 ? n : 1) * sizeof(double);
  r->radius = malloc(sz);
  r->wound_on_tension = malloc(sz);
  r->web_tension = malloc(sz);
  r->nip_load = malloc(sz);
  r->sigma_r = malloc(sz);
  r->sigma_theta = malloc(sz);
  for (int j = 0; j < n; ++j) {
    double u = n > 1 ? (double)j / (n - 1) : 0.0; /* 0 at the core, 1 outside */
    r->radius[j] = 0.05 + (j + 1) * 1.0e-4;
    r->web_tension[j] = 200.0 * variant * (1.0 - 0.2 * u);
    r->nip_load[j] = 1000.0 * variant;
    r->wound_on_tension[j] = r->web_tension[j] + 0.2 * r->nip_load[j];
    r->sigma_r[j] = -2.0e5 * variant * (1.0 - u) * (1.0 + 0.5 * u);
    r->sigma_theta[j] = 1.0e6 * variant * (u - 0.3);
  }
  r->core_pressure = 2.1e5 * variant;
  r->core_radius = 0.05;
  r->increments = n;
  r->cvode_steps = 10L * n;
  r->rhs_evals = 30L * n;
  r->full_integrations = n / 4;
  r->wall_seconds = 0.25 * variant;
  return r;
}

#endif
