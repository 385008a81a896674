/* After the winder (docs/storage.md): the state the roll is wound in (winding.temperature,
 * winding.humidity), the storage stages, the material's free strains and relaxation
 * (material.thermal, .hygroscopic, .viscoelastic) and the core's expansion (core.alpha,
 * core.beta), from the checked tree into the problem. Errors point at the key, in the
 * model file when the material came from one. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"

static const double absolute_zero = -273.15; /* C */

/* material.viscoelastic: equal lengths, tau > 0, fractions >= 0 summing below 1 */
static rs_status resolve_prony(const yn *root, rs_prony *p)
{
  static const char *const keys[] = {"material.viscoelastic.tau", "material.viscoelastic.E_theta",
                                     "material.viscoelastic.radial"};
  double *lists[3] = {p->tau, p->w_theta, p->w_radial};
  int n[3];
  memset(p, 0, sizeof *p);
  if (!rsi_ys_has(root, "material.viscoelastic")) return RS_OK;
  for (int k = 0; k < 3; ++k) n[k] = rsi_ys_nums(root, keys[k], lists[k], RS_PRONY_MAX);
  for (int k = 1; k < 3; ++k)
    if (n[k] != n[0])
      return rsi_ys_fail(root, keys[k], "must have one entry per relaxation time (tau has %d, this "
                     "has %d)", n[0], n[k]);
  for (int i = 0; i < n[0]; ++i) {
    char key[96];
    if (!(p->tau[i] > 0.0)) {
      snprintf(key, sizeof key, "%s[%d]", keys[0], i);
      return rsi_ys_fail(root, key, "must be > 0 h (got %g)", p->tau[i]);
    }
    for (int k = 1; k < 3; ++k)
      if (!(lists[k][i] >= 0.0)) {
        snprintf(key, sizeof key, "%s[%d]", keys[k], i);
        return rsi_ys_fail(root, key, "must be >= 0 (a fraction of the modulus; got %g)", lists[k][i]);
      }
  }
  for (int k = 1; k < 3; ++k) {
    double sum = 0.0;
    for (int i = 0; i < n[0]; ++i) sum += lists[k][i];
    if (!(sum < 1.0))
      return rsi_ys_fail(root, keys[k], "the fractions must sum to less than 1 (the modulus that "
                     "remains at long times; got %g)", sum);
  }
  p->n = n[0];
  return RS_OK;
}

static rs_status check_temperature(const yn *root, const char *key, double T)
{
  if (!(T > absolute_zero))
    return rsi_ys_fail(root, key, "must be above absolute zero, %g C (got %g)", absolute_zero, T);
  return RS_OK;
}

static rs_status check_humidity(const yn *root, const char *key, double H)
{
  if (!(H >= 0.0 && H <= 100.0))
    return rsi_ys_fail(root, key, "must lie in [0, 100] %% RH (got %g)", H);
  return RS_OK;
}

static rs_status resolve_stages(const yn *root, const rs_material *m, rs_storage_spec *sp)
{
  const yn *list = rsi_yn_get(root, "storage");
  double T = sp->wind_temperature, H = sp->wind_humidity;
  rs_status st;
  sp->n_stages = 0;
  if (!list) return RS_OK;
  for (int i = 0; i < list->n && i < RS_STORAGE_MAX_STAGES; ++i) {
    char kh[64], kt[64], kr[64];
    snprintf(kh, sizeof kh, "storage[%d].hours", i);
    snprintf(kt, sizeof kt, "storage[%d].temperature", i);
    snprintf(kr, sizeof kr, "storage[%d].humidity", i);
    rs_storage_stage *s = &sp->stage[i];
    s->hours = rsi_ys_num(root, kh);
    if (!(s->hours >= 0.0)) return rsi_ys_fail(root, kh, "must be >= 0 h (got %g)", s->hours);
    if (rsi_ys_has(root, kt)) {
      double Tn = rsi_ys_num(root, kt);
      if ((st = check_temperature(root, kt, Tn)) != RS_OK) return st;
      if (Tn != T && !m->has_thermal)
        return rsi_ys_fail(root, kt, "changes the temperature (%g -> %g C) but the material has no "
                       "material.thermal {alpha_r, alpha_theta} (1/K)", T, Tn);
      T = Tn;
    }
    if (rsi_ys_has(root, kr)) {
      double Hn = rsi_ys_num(root, kr);
      if ((st = check_humidity(root, kr, Hn)) != RS_OK) return st;
      if (Hn != H && !m->has_hygroscopic)
        return rsi_ys_fail(root, kr, "changes the humidity (%g -> %g %% RH) but the material has no "
                       "material.hygroscopic {beta_r, beta_theta} (1/%% RH)", H, Hn);
      H = Hn;
    }
    s->temperature = T;
    s->humidity = H;
    sp->n_stages = i + 1;
  }
  return RS_OK;
}

rs_status rsi_ys_resolve_storage(const yn *root, rs_scene *s)
{
  rs_material *m = &s->problem.material;
  rs_storage_spec *sp = &s->problem.storage;
  rs_status st;
  memset(sp, 0, sizeof *sp);
  m->has_thermal = rsi_ys_has(root, "material.thermal");
  m->alpha_r = rsi_ys_num(root, "material.thermal.alpha_r");
  m->alpha_theta = rsi_ys_num(root, "material.thermal.alpha_theta");
  m->has_hygroscopic = rsi_ys_has(root, "material.hygroscopic");
  m->beta_r = rsi_ys_num(root, "material.hygroscopic.beta_r");
  m->beta_theta = rsi_ys_num(root, "material.hygroscopic.beta_theta");
  if ((st = resolve_prony(root, &m->viscoelastic)) != RS_OK) return st;
  sp->core_alpha = rsi_ys_num(root, "core.alpha");
  sp->core_beta = rsi_ys_num(root, "core.beta");
  sp->wind_temperature = rsi_ys_num(root, "winding.temperature");
  sp->wind_humidity = rsi_ys_num(root, "winding.humidity");
  if ((st = check_temperature(root, "winding.temperature", sp->wind_temperature)) != RS_OK)
    return st;
  if ((st = check_humidity(root, "winding.humidity", sp->wind_humidity)) != RS_OK) return st;
  return resolve_stages(root, m, sp);
}
