/* Entrained air in the reel (docs/roll-model.md, "Entrained air"). The roll's stress solve
 * puts each new node at the radius the layer goes on at, films included, and sees each
 * film as a compliance in series with the stack (src/roll/roll_air.c); the radii the reel
 * winds at, stops at and reports are the real ones, t + h_j(P_j) a layer. */
#include "reel/reel_air.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reel/result_internal.h"
#include "reelsim/material.h"
#include "util/error.h"

rs_status rs_reel_air_create(rs_reel_air *air, int N)
{
  memset(air, 0, sizeof *air);
  air->film = calloc((size_t)N + 1, sizeof(double));
  air->length = calloc((size_t)N, sizeof(double));
  air->node = calloc((size_t)N + 1, sizeof(double));
  if (!air->film || !air->length || !air->node) {
    rs_reel_air_free(air);
    return RS_ERROR(RS_ERR_MEMORY, "entrained air: out of memory (%d layers)", N);
  }
  return RS_OK;
}

void rs_reel_air_free(rs_reel_air *air)
{
  free(air->film);
  free(air->length);
  free(air->node);
  air->film = air->length = air->node = NULL;
}

/* The web wraps the roll at its tension Ti (the span's: the film forms before the web
 * meets the roll, upstream of any nip), web and roll surface both at V, so U = 2V (or V:
 * air.moving_surfaces). A nip
 * rolls on the roll at the same V: its film, if thinner, is what goes in. */
double rs_reel_air_film(const rs_problem *pb, double R, double Ti, double V, double w)
{
  const rs_air_spec *a = &pb->air;
  double h = Ti > 0.0 ? rs_air_foil_film(R, a->moving_surfaces * V, Ti, a->viscosity) : INFINITY;
  if (pb->nip.model != RS_NIP_NONE)
    h = fmin(h, rs_air_nip_film(R, a->nip_radius, V, w, a->viscosity));
  if (!(V > 0.0)) h = 0.0;
  return rs_air_surviving_film(h, a->roughness, a->cutoff);
}

/* node j's pressure: the core's under layer 0, else the radial stress of layer j - 1 */
double rs_reel_air_begin(rs_reel_air *air, const rs_problem *pb, const rs_roll *roll, int n)
{
  const double pa = pb->air.pressure, *sr = rs_roll_sigma_r(roll);
  const double *restrict f = air->film + 1; /* node j + 1 is under sigma_r[j] */
  double gaps = n > 0 ? rs_air_compressed_film(air->film[0], rs_roll_core_pressure(roll), pa) : 0.0;
  /* rs_air_compressed_film inline, in four sums: the loop vectorises (every layer at every
   * increment) */
  double a[4] = {0.0, 0.0, 0.0, 0.0};
  int j = 0;
  for (; j + 3 < n - 1; j += 4)
    for (int l = 0; l < 4; ++l) {
      const double P = -sr[j + l];
      a[l] += f[j + l] * pa / (pa + (P > 0.0 ? P : 0.0));
    }
  for (; j < n - 1; ++j) {
    const double P = -sr[j];
    a[0] += f[j] * pa / (pa + (P > 0.0 ? P : 0.0));
  }
  gaps += (a[0] + a[1]) + (a[2] + a[3]);
  air->radius = pb->core.radius + n * pb->material.caliper + gaps;
  return air->radius;
}

int rs_reel_air_stop(const rs_reel_air *air, const rs_problem *pb, int j, double R, double h)
{
  if (j == 0) return 0;
  const double t = pb->material.caliper;
  if (pb->web_length > 0.0) {
    const double half = 3.14159265358979323846 * (R + h + 0.5 * t); /* half this layer */
    return air->length[j - 1] + half > pb->web_length;
  }
  return R + 0.5 * (h + t) > pb->final_radius;
}

void rs_reel_air_wound(rs_reel_air *air, int j, double R, double h, double t)
{
  air->film[j] = h;
  air->node[j + 1] = R + (h + t); /* as the reel's radius goes on from R */
  air->length[j] = (j ? air->length[j - 1] : 0.0) + 2.0 * 3.14159265358979323846 * (R + h + 0.5 * t);
}

rs_status rs_reel_air_entrained(const rs_reel_air *air, rs_reel_result *res)
{
  const int n = res->n_layers;
  res->air_film_entrained = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
  if (!res->air_film_entrained)
    return RS_ERROR(RS_ERR_MEMORY, "entrained air: out of memory (%d layers)", n);
  memcpy(res->air_film_entrained, air->film, (size_t)n * sizeof(double));
  return RS_OK;
}

rs_status rs_reel_air_finish(const rs_reel_air *air, const rs_problem *pb, rs_reel_result *res)
{
  const int n = res->n_layers;
  const double pa = pb->air.pressure, t = pb->material.caliper;
  rs_status st = res->air_film_entrained ? RS_OK : rs_reel_air_entrained(air, res);
  if (st) return st;
  res->air_film = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
  if (!res->air_film) return RS_ERROR(RS_ERR_MEMORY, "entrained air: out of memory (%d layers)", n);
  double r = res->core_radius;
  for (int j = 0; j < n; ++j) {
    const double P = j ? -res->sigma_r[j - 1] : res->core_pressure;
    res->air_film[j] = rs_air_compressed_film(air->film[j], P, pa);
    r += t + res->air_film[j];
    res->radius[j] = r;
  }
  res->air_wound_length = n > 0 ? air->length[n - 1] : 0.0;
  return RS_OK;
}
