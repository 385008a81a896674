/* The roll in storage: faces, stresses and the stack's tangent modulus per turn. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reel/result_internal.h"
#include "reelsim/core.h"
#include "reelsim/material.h"
#include "storage/storage_internal.h"
#include "util/error.h"
#include "storage/storage_result.h"

rs_status rs_storage_roll_init(rs_storage_roll *roll, const rs_problem *problem,
                               const rs_reel_result *wound)
{
  memset(roll, 0, sizeof *roll);
  const int n = wound->n_layers;
  if (n < 1) return RS_ERROR(RS_ERR_INPUT, "storage: the wound roll has no layers");
  roll->problem = problem;
  roll->n = n;
  const size_t m = (size_t)n + 1;
  roll->s = malloc(m * sizeof(double));
  roll->sr = malloc(m * sizeof(double));
  roll->st = malloc((size_t)n * sizeof(double));
  roll->work = malloc(9 * m * sizeof(double));
  roll->pbuf = malloc(m * sizeof(double));
  if (!roll->s || !roll->sr || !roll->st || !roll->work || !roll->pbuf) {
    rs_storage_roll_free(roll);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory for a roll of %d layers in storage", n);
  }
  roll->s[0] = problem->core.radius;
  roll->sr[0] = -wound->core_pressure;
  for (int k = 1; k <= n; ++k) {
    roll->s[k] = wound->radius[k - 1];
    roll->sr[k] = wound->sigma_r[k - 1];
    roll->st[k - 1] = wound->sigma_theta[k - 1];
    if (!(roll->s[k] > roll->s[k - 1])) {
      rs_storage_roll_free(roll);
      return RS_ERROR(RS_ERR_INTERNAL, "storage: layer radii not increasing at layer %d", k);
    }
  }
  const double E_c = rs_core_stiffness(&problem->core);
  roll->E_c_inv = isinf(E_c) ? 0.0 : 1.0 / E_c;
  roll->temperature = problem->storage.wind_temperature;
  roll->humidity = problem->storage.wind_humidity;
  return RS_OK;
}

void rs_storage_roll_free(rs_storage_roll *roll)
{
  free(roll->s);
  free(roll->sr);
  free(roll->st);
  free(roll->work);
  free(roll->pbuf);
  roll->s = roll->sr = roll->st = roll->work = roll->pbuf = NULL;
}

/* E_r of turn k at its mean face pressure (the stack law clamps P < 0, layers pulled
 * apart, to P = 0). */
void rs_storage_turn_moduli(const rs_storage_roll *roll, const double *dsr, double frac,
                            double *E_r)
{
  const int n = roll->n;
  const double *sr = roll->sr;
  double *P = roll->pbuf;
  for (int k = 0; k < n; ++k) P[k] = -0.5 * (sr[k] + sr[k + 1]);
  if (dsr)
    for (int k = 0; k < n; ++k) P[k] -= 0.5 * frac * (dsr[k] + dsr[k + 1]);
  rs_radial_modulus_n(&roll->problem->material.radial, P, E_r, n);
}
