/* Winding a whole reel: set up the roll and the effects the problem has (the nip, entrained
 * air, the centrifugal load, the stress history, the wound radius), grow the roll increment
 * by increment (reel_step.c), finish the result. The phases and the effect interface:
 * effect.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reel/effect.h"
#include "reelsim/clock.h"
#include "reelsim/nip.h"
#include "nip/nip_contact.h"
#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "roll/roll.h"
#include "util/error.h"

void rs_reel_result_destroy(rs_reel_result **resp)
{
  if (!resp || !*resp) return;
  rs_reel_result *res = *resp;
  free(res->radius);
  free(res->wound_on_tension);
  free(res->web_tension);
  free(res->nip_load);
  free(res->sigma_r);
  free(res->sigma_theta);
  free(res->at_speed_sigma_r);
  free(res->at_speed_sigma_theta);
  free(res->air_film);
  free(res->air_film_entrained);
  free(res->stage_layers);
  free(res->stage_radius);
  free(res->stage_sigma_r);
  free(res->stage_sigma_theta);
  free(res->nip_radius);
  free(res->nip_T0);
  free(res->nip_Ti);
  free(res->nip_a);
  free(res->nip_solve_load);
  free(res->nip_iterations);
  for (int i = 0; res->profiles && i < res->n_profiles; ++i) rs_nip_solution_free(&res->profiles[i]);
  free(res->profiles);
  free(res->profile_radius);
  free(res->deformed_radius);
  free(res->wound_radius);
  free(res->wound_in_tension);
  rs_lanes_result_destroy(&res->lanes);
  free(res);
  *resp = NULL;
}

/* here beside rs_reel_result_destroy, which frees res->lanes (lanes.h fills it) */
void rs_lanes_result_destroy(rs_lanes_result **lrp)
{
  if (!lrp || !*lrp) return;
  rs_lanes_result *lr = *lrp;
  free(lr->x), free(lr->width), free(lr->caliper), free(lr->core_pressure);
  free(lr->outer_radius), free(lr->wound_on_tension), free(lr->web_tension), free(lr->slack);
  free(lr->strain), free(lr->nip_load), free(lr->sigma_r), free(lr->sigma_theta);
  free(lr->radius);
  free(lr);
  *lrp = NULL;
}

static rs_reel_result *reel_result_new(int n)
{
  rs_reel_result *res = calloc(1, sizeof *res);
  if (!res) return NULL;
  size_t sz = (size_t)(n > 0 ? n : 1) * sizeof(double);
  res->radius = malloc(sz);
  res->wound_on_tension = malloc(sz);
  res->web_tension = malloc(sz);
  res->nip_load = malloc(sz);
  res->sigma_r = malloc(sz);
  res->sigma_theta = malloc(sz);
  if (!res->radius || !res->wound_on_tension || !res->web_tension || !res->nip_load ||
      !res->sigma_r || !res->sigma_theta)
    rs_reel_result_destroy(&res);
  return res;
}

static void reel_params(const rs_problem *pb, rs_roll_params *p)
{
  memset(p, 0, sizeof *p);
  p->core_radius = pb->core.radius;
  p->core_stiffness = rs_core_stiffness(&pb->core);
  p->caliper = pb->material.caliper;
  p->E_theta = pb->material.E_theta;
  p->nu_rtheta = pb->material.nu_rtheta;
  p->radial = pb->material.radial;
  p->max_layers = pb->n_layers;
  p->rtol = pb->numerics.rtol;
  p->atol = pb->numerics.atol;
  p->max_steps = pb->numerics.max_steps;
  p->reuse = pb->numerics.reuse;
  p->placement = pb->numerics.load_placement;
  p->correction = pb->numerics.error_correction;
}

/* Copies the roll's state into the result (the layers finished so far). */
static void reel_collect(const rs_roll *roll, rs_reel_result *res, double t_start)
{
  int n = rs_roll_layers(roll);
  rs_roll_stats stats;
  res->n_layers = n;
  memcpy(res->sigma_r, rs_roll_sigma_r(roll), (size_t)n * sizeof(double));
  memcpy(res->sigma_theta, rs_roll_sigma_theta(roll), (size_t)n * sizeof(double));
  res->core_pressure = rs_roll_core_pressure(roll);
  rs_roll_get_stats(roll, &stats);
  res->increments = stats.increments;
  res->cvode_steps = stats.cvode_steps;
  res->rhs_evals = stats.rhs_evals;
  res->full_integrations = stats.full_integrations;
  res->wall_seconds = rs_clock_wall() - t_start;
}

/* ---- set up: the effects the problem has, in the loop's order ---------------------------
 * the history (its setup refuses an oversized history before anything else is allocated),
 * the air (it places the layers: the nip is solved at its radii, with its films), the nip,
 * the centrifugal load (on the T0 the nip gave), the wound radius (every reel; last: it
 * reads the result the others finished). A driver's own effects come first. */
static rs_status reel_effects(rs_reel_state *s, const rs_reel_effect *extra, int n_extra)
{
  const rs_problem *pb = s->pb;
  const rs_reel_effect_ops *ops[] = {
      pb->record.history_every > 0 ? &rs_reel_history_effect : NULL,
      pb->air.on ? &rs_reel_air_effect : NULL,
      pb->nip.model != RS_NIP_NONE ? &rs_reel_nip_effect : NULL,
      pb->centrifugal ? &rs_reel_spin_effect : NULL,
      &rs_reel_gauge_effect,
  };
  const int n_ops = (int)(sizeof ops / sizeof ops[0]);
  if (n_extra < 0 || n_extra + n_ops > RS_REEL_MAX_EFFECTS)
    return RS_ERROR(RS_ERR_INTERNAL, "the reel takes at most %d effects of a driver's (got %d)",
                    RS_REEL_MAX_EFFECTS - n_ops, n_extra);
  for (int k = 0; k < n_extra; ++k) s->effects[s->n_effects++] = extra[k];
  for (int k = 0; k < n_ops; ++k)
    if (ops[k]) s->effects[s->n_effects++] = (rs_reel_effect){ops[k], NULL};
  for (int k = 0; k < s->n_effects; ++k) {
    if (s->effects[k].ops->place && !s->placer) s->placer = &s->effects[k];
    if (s->effects[k].ops->web_tension && !s->web) s->web = &s->effects[k];
  }
  return RS_OK;
}

rs_status rs_reel_state_create(const rs_problem *pb, const rs_reel_effect *extra, int n_extra,
                               rs_reel_state **out)
{
  *out = NULL;
  const int N = pb->n_layers, per_step = pb->numerics.layers_per_step;
  if (N < 1) return RS_ERROR(RS_ERR_INPUT, "the problem winds no layers");
  if (per_step < 1)
    return RS_ERROR(RS_ERR_INPUT, "numerics.layers_per_step must be >= 1 (got %d)", per_step);
  if (pb->record.history_every < 0)
    return RS_ERROR(RS_ERR_INPUT, "output.history_every must be >= 0 (got %d)",
                    pb->record.history_every);
  rs_reel_state *s = calloc(1, sizeof *s);
  if (!s) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the reel");
  *out = s;
  s->pb = pb;
  s->N = N;
  s->per_step = per_step;
  s->t_start = rs_clock_wall();
  s->res = reel_result_new(N);
  /* an increment never holds more than the roll's layers (layers_per_step may exceed N) */
  s->block = malloc((size_t)(per_step < N ? per_step : N) * sizeof(double));
  if (!s->res || !s->block) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the results of %d layers", N);
  s->res->core_radius = pb->core.radius;
  rs_roll_params params;
  reel_params(pb, &params);
  rs_status st = reel_effects(s, extra, n_extra);
  for (int k = 0; !st && k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->setup) st = e->ops->setup(e, s, &params);
  }
  if (!st) st = rs_roll_create(&params, &s->roll);
  return st;
}

/* ---- finish ------------------------------------------------------------------------------ */

/* Merges an effect's status into the run's: the first failure stands. */
static rs_status reel_merge(rs_status st, rs_status more) { return st == RS_OK ? more : st; }

rs_status rs_reel_state_finish(rs_reel_state *s, rs_status st, rs_reel_result **out)
{
  rs_reel_result *res = s->res;
  *out = res;
  if (!res) return st;
  if (!s->roll) {
    res->n_layers = 0;
    s->res = NULL;
    return st;
  }
  reel_collect(s->roll, res, s->t_start);
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->collect) st = reel_merge(st, e->ops->collect(e, s, st));
  }
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->finish) st = reel_merge(st, e->ops->finish(e, s, st));
  }
  for (int j = 0; st == RS_OK && j < res->n_layers; ++j)
    if (!isfinite(res->sigma_r[j]) || !isfinite(res->sigma_theta[j]))
      st = RS_ERROR(RS_ERR_SOLVER, "non-finite stress in layer %d after winding", j + 1);
  if (st == RS_OK && !isfinite(res->core_pressure))
    st = RS_ERROR(RS_ERR_SOLVER, "non-finite core pressure after winding");
  s->res = NULL;
  return st;
}

void rs_reel_state_destroy(rs_reel_state **sp)
{
  if (!sp || !*sp) return;
  rs_reel_state *s = *sp;
  rs_roll_destroy(&s->roll);
  for (int k = s->n_effects - 1; k >= 0; --k)
    if (s->effects[k].ops->destroy) s->effects[k].ops->destroy(&s->effects[k]);
  free(s->block);
  rs_reel_result_destroy(&s->res);
  free(s);
  *sp = NULL;
}
