/* A uniform change of temperature and humidity of the stored roll (Qualls & Good 1997:
 * thermal and hygroscopic winding stresses; docs/storage.md, "The change").
 *
 * Free strains of the change dT (K), dH (% RH):
 *     web  e_r = alpha_r dT + beta_r dH,   e_theta = alpha_theta dT + beta_theta dH
 *     core e_c = core.alpha dT + core.beta dH
 * The stack is nonlinear (E_r depends on the pressure the change itself alters), so the
 * change is applied in m equal sub-steps, each by the midpoint rule: a predictor with the
 * moduli at the sub-step's start, then the sub-step again with the moduli at the
 * predictor's half-way pressures (second order in 1/m). m = 1, 2, 4, ... until two
 * successive answers agree within rtol of the largest radial and hoop stresses; the finer
 * one is kept. A linear stack needs m = 1 (its two answers agree to round-off). */
#include <math.h>
#include <string.h>

#include "storage/storage_internal.h"
#include "util/error.h"
#include "storage/storage_result.h"

enum { MAX_SUBSTEPS = 1 << 12 };

/* The work array, rows of n + 1: 0, 1: the elastic solver's; 2: E_r; 3: dsr; 4: dst;
 * 5-8: rs_storage_change's. */
static double *work(rs_storage_roll *roll, int i) { return roll->work + (size_t)i * (roll->n + 1); }

static rs_status substep(rs_storage_roll *roll, double de_r, double de_t, double de_c)
{
  const int n = roll->n;
  double *E_r = work(roll, 2), *dsr = work(roll, 3), *dst = work(roll, 4);
  rs_storage_load ld = {.E_r = E_r, .de_r_all = de_r, .de_theta_all = de_t, .de_core = de_c};
  rs_storage_turn_moduli(roll, NULL, 0.0, E_r);
  rs_status st = rs_storage_elastic(roll, &ld, dsr, dst);
  if (st != RS_OK) return st;
  rs_storage_turn_moduli(roll, dsr, 0.5, E_r);
  if ((st = rs_storage_elastic(roll, &ld, dsr, dst)) != RS_OK) return st;
  for (int k = 0; k <= n; ++k) roll->sr[k] += dsr[k];
  for (int k = 0; k < n; ++k) roll->st[k] += dst[k];
  return RS_OK;
}

rs_status rs_storage_change_steps(rs_storage_roll *roll, double T, double H, int steps)
{
  const rs_material *m = &roll->problem->material;
  const rs_storage_spec *c = &roll->problem->storage;
  const double dT = T - roll->temperature, dH = H - roll->humidity;
  const double e_r = (m->has_thermal ? m->alpha_r * dT : 0.0) +
                     (m->has_hygroscopic ? m->beta_r * dH : 0.0);
  const double e_t = (m->has_thermal ? m->alpha_theta * dT : 0.0) +
                     (m->has_hygroscopic ? m->beta_theta * dH : 0.0);
  const double e_c = c->core_alpha * dT + c->core_beta * dH;
  if (steps > roll->max_substeps) roll->max_substeps = steps;
  if (e_r != 0.0 || e_t != 0.0 || e_c != 0.0)
    for (int i = 0; i < steps; ++i) {
      rs_status st = substep(roll, e_r / steps, e_t / steps, e_c / steps);
      if (st != RS_OK) return st;
    }
  roll->temperature = T;
  roll->humidity = H;
  return RS_OK;
}

static double max_abs(const double *x, int n)
{
  double v = 0.0;
  for (int i = 0; i < n; ++i) v = fmax(v, fabs(x[i]));
  return v;
}

static double max_diff(const double *x, const double *y, int n)
{
  double v = 0.0;
  for (int i = 0; i < n; ++i) v = fmax(v, fabs(x[i] - y[i]));
  return v;
}

rs_status rs_storage_change(rs_storage_roll *roll, double T, double H, double rtol)
{
  const int n = roll->n;
  const rs_material *m = &roll->problem->material;
  const rs_storage_spec *c = &roll->problem->storage;
  const double dT = T - roll->temperature, dH = H - roll->humidity;
  const int moves = (dT != 0.0 && (m->has_thermal || c->core_alpha != 0.0)) ||
                    (dH != 0.0 && (m->has_hygroscopic || c->core_beta != 0.0));
  if (!moves) return rs_storage_change_steps(roll, T, H, 1);
  /* the state before (rows 5, 6) and the previous answer (rows 7, 8) */
  double *sr0 = work(roll, 5), *st0 = work(roll, 6), *sr_prev = work(roll, 7),
         *st_prev = work(roll, 8);
  const double T0 = roll->temperature, H0 = roll->humidity;
  memcpy(sr0, roll->sr, (size_t)(n + 1) * sizeof(double));
  memcpy(st0, roll->st, (size_t)n * sizeof(double));
  for (int steps = 1;; steps *= 2) {
    memcpy(roll->sr, sr0, (size_t)(n + 1) * sizeof(double));
    memcpy(roll->st, st0, (size_t)n * sizeof(double));
    roll->temperature = T0;
    roll->humidity = H0;
    rs_status st = rs_storage_change_steps(roll, T, H, steps);
    if (st != RS_OK) return st;
    if (steps > 1) {
      const double scale_r = fmax(max_abs(roll->sr, n + 1), max_abs(sr0, n + 1));
      const double scale_t = fmax(max_abs(roll->st, n), max_abs(st0, n));
      if (max_diff(roll->sr, sr_prev, n + 1) <= rtol * scale_r &&
          max_diff(roll->st, st_prev, n) <= rtol * scale_t)
        return RS_OK;
    }
    if (steps >= MAX_SUBSTEPS)
      return RS_ERROR(RS_ERR_SOLVER,
                      "storage: the change %g -> %g C, %g -> %g %% RH did not converge in %d "
                      "sub-steps (radial stresses still differ by more than rtol = %g)",
                      T0, T, H0, H, steps, rtol);
    memcpy(sr_prev, roll->sr, (size_t)(n + 1) * sizeof(double));
    memcpy(st_prev, roll->st, (size_t)n * sizeof(double));
  }
}
