/* The storage driver (docs/storage.md): stage 0 is the wound roll; each stage then brings
 * the roll to its temperature and humidity (thermal.c) and holds it there for its hours
 * (creep.c), and the defect rules are applied to the state it leaves. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reel/result_internal.h"
#include "reelsim/clock.h"
#include "reelsim/storage.h"
#include "storage/storage_internal.h"
#include "util/error.h"
#include "storage/storage_result.h"

int rs_storage_requested(const rs_problem *problem)
{
  return problem && problem->storage.n_stages > 0;
}

void rs_storage_result_destroy(rs_storage_result **res)
{
  if (!res || !*res) return;
  rs_storage_result *r = *res;
  if (r->defects)
    for (int s = 0; s < r->n_stages; ++s) rs_defect_report_destroy(&r->defects[s]);
  free(r->defects);
  free(r->hours);
  free(r->temperature);
  free(r->humidity);
  free(r->core_pressure);
  free(r->sigma_r);
  free(r->sigma_theta);
  free(r);
  *res = NULL;
}

static rs_storage_result *result_new(int S, int N)
{
  rs_storage_result *r = calloc(1, sizeof *r);
  if (!r) return NULL;
  r->n_layers = N;
  const size_t ss = (size_t)S, sn = (size_t)S * (size_t)(N > 0 ? N : 1);
  r->hours = calloc(ss, sizeof(double));
  r->temperature = calloc(ss, sizeof(double));
  r->humidity = calloc(ss, sizeof(double));
  r->core_pressure = calloc(ss, sizeof(double));
  r->sigma_r = calloc(sn, sizeof(double));
  r->sigma_theta = calloc(sn, sizeof(double));
  r->defects = calloc(ss, sizeof(rs_defect_report *));
  if (!r->hours || !r->temperature || !r->humidity || !r->core_pressure || !r->sigma_r ||
      !r->sigma_theta || !r->defects) {
    rs_storage_result_destroy(&r);
    return NULL;
  }
  return r;
}

/* Stage s as a reel result (radius from `wound`, the stage's stresses and core pressure):
 * a view into both, valid while they live; nothing to free. The winding-only fields
 * (tensions, history, nip) are those of `wound`. */
static void stage_view(const rs_storage_result *res, const rs_reel_result *wound, int s,
                       rs_reel_result *view)
{
  *view = *wound;
  view->n_layers = res->n_layers;
  view->sigma_r = res->sigma_r + (size_t)s * (size_t)res->n_layers;
  view->sigma_theta = res->sigma_theta + (size_t)s * (size_t)res->n_layers;
  view->core_pressure = res->core_pressure[s];
}

/* Records the roll's state as stage s and applies the defect rules to it. */
static rs_status record(rs_storage_result *res, const rs_storage_roll *roll,
                        const rs_reel_result *wound, const rs_defect_limits *lim, int s)
{
  const int N = roll->n;
  res->hours[s] = roll->hours;
  res->temperature[s] = roll->temperature;
  res->humidity[s] = roll->humidity;
  res->core_pressure[s] = -roll->sr[0];
  for (int j = 0; j < N; ++j) {
    res->sigma_r[(size_t)s * N + j] = roll->sr[j + 1];
    res->sigma_theta[(size_t)s * N + j] = roll->st[j];
  }
  res->n_stages = s + 1;
  rs_reel_result view;
  stage_view(res, wound, s, &view);
  return rs_defects_assess(&view, lim, &res->defects[s]);
}

rs_status rs_storage_run(const rs_problem *problem, const rs_reel_result *wound,
                         rs_storage_result **out)
{
  *out = NULL;
  if (!problem || !wound)
    return RS_ERROR(RS_ERR_INTERNAL, "rs_storage_run: no problem or no wound roll");
  const double t0 = rs_clock_wall();
  const rs_storage_spec *sp = &problem->storage;
  rs_storage_roll roll;
  rs_storage_creep *creep = NULL;
  rs_defect_limits lim;
  rs_defect_limits_from_problem(problem, &lim);
  rs_status st = rs_storage_roll_init(&roll, problem, wound);
  if (st != RS_OK) return st;
  rs_storage_result *res = result_new(sp->n_stages + 1, roll.n);
  if (!res) {
    rs_storage_roll_free(&roll);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory for %d storage stages of %d layers",
                    sp->n_stages, roll.n);
  }
  *out = res;
  st = record(res, &roll, wound, &lim, 0);
  if (st == RS_OK) st = rs_storage_creep_create(&roll, &creep);
  for (int i = 0; st == RS_OK && i < sp->n_stages; ++i) {
    const rs_storage_stage *stage = &sp->stage[i];
    st = rs_storage_change(&roll, stage->temperature, stage->humidity,
                           RS_ACCURACY_PER_RTOL * problem->numerics.rtol);
    if (st == RS_OK && creep && stage->hours > 0.0)
      st = rs_storage_creep_hold(creep, &roll, stage->hours);
    if (st != RS_OK) {
      rs_error_wrap("storage stage %d (%g h at %g C, %g %% RH)", i + 1, stage->hours,
                    stage->temperature, stage->humidity);
      break;
    }
    roll.hours += stage->hours;
    st = record(res, &roll, wound, &lim, i + 1);
  }
  res->elastic_solves = roll.solves;
  res->max_substeps = roll.max_substeps;
  res->wall_seconds = rs_clock_wall() - t0;
  rs_storage_creep_destroy(&creep);
  rs_storage_roll_free(&roll);
  return st;
}

/* v is the first value seen or below the best so far */
static int first_or_less(double v, double best, int have) { return !have || v < best; }

void rs_storage_worst_stages(const rs_storage_result *res, rs_storage_worst *w)
{
  double hoop = 0, buck = 0, pres = 0, slip = 0, core = 0;
  w->hoop = w->starring = w->pressure = w->slip = w->core = -1;
  for (int s = 0; res && s < res->n_stages; ++s) {
    const rs_defect_report *d = res->defects[s];
    if (!d) continue;
    if (d->hoop.verdict != RS_DEFECT_NOT_ASSESSED && first_or_less(d->hoop.min, hoop, w->hoop >= 0)) {
      hoop = d->hoop.min;
      w->hoop = s;
    }
    if (d->starring.verdict != RS_DEFECT_NOT_ASSESSED && d->starring.compressed > 0 &&
        first_or_less(d->starring.margin_min, buck, w->starring >= 0)) {
      buck = d->starring.margin_min;
      w->starring = s;
    }
    /* the greatest pressure and the core pressure are figures with or without a limit */
    if (res->n_layers > 0 && first_or_less(-d->pressure.max, -pres, w->pressure >= 0)) {
      pres = d->pressure.max;
      w->pressure = s;
    }
    if (d->slip.verdict != RS_DEFECT_NOT_ASSESSED &&
        first_or_less(d->slip.margin_min, slip, w->slip >= 0)) {
      slip = d->slip.margin_min;
      w->slip = s;
    }
    if (res->n_layers > 0 && first_or_less(-d->core.pressure, -core, w->core >= 0)) {
      core = d->core.pressure;
      w->core = s;
    }
  }
}
