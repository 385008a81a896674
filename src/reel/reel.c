/* Winding a whole reel: grow the roll increment by increment; at each layer the recipes
 * give the web tension and nip load, the effects the problem has (the nip, entrained air,
 * the centrifugal load, the stress history) act through their ops, and the build-up engine
 * winds the layers on. The phases and the effect interface: effect.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reel/effect.h"
#include "util/cancel.h"
#include "reelsim/clock.h"
#include "reelsim/nip.h"
#include "reelsim/nip_contact.h"
#include "reelsim/reel.h"
#include "reelsim/roll.h"

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
  free(res);
  *resp = NULL;
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

/* What gauges read, from the finished roll: the deformed radii (now and as each layer went
 * on) and the wound-in tension (src/reel/gauge.c) */
static rs_status reel_gauges(const rs_problem *pb, rs_reel_result *res, rs_reel_gauge *g,
                             const double *film)
{
  const int n = res->n_layers;
  res->deformed_radius = malloc((size_t)n * sizeof(double));
  res->wound_radius = malloc((size_t)n * sizeof(double));
  res->wound_in_tension = malloc((size_t)n * sizeof(double));
  if (!res->deformed_radius || !res->wound_radius || !res->wound_in_tension)
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the gauges' radii (%d layers)", n);
  rs_status st = rs_reel_deformed_radius(pb, res->core_pressure, res->sigma_r, film, n,
                                         res->deformed_radius);
  if (!st) st = rs_reel_gauge_record(g, pb, n, res->core_pressure, res->sigma_r, film, 1);
  if (st) return st;
  rs_reel_gauge_finish(g, pb, n, res->wound_radius);
  rs_reel_wound_in_tension(pb, res->sigma_theta, n, res->wound_in_tension);
  return RS_OK;
}

/* ---- set up: the effects the problem has, in the loop's order ---------------------------
 * the history (its setup refuses an oversized history before anything else is allocated),
 * the air (it places the layers: the nip is solved at its radii, with its films), the nip,
 * the centrifugal load (on the T0 the nip gave). A driver's own effects come first. */
static rs_status reel_effects(rs_reel_state *s, const rs_reel_effect *extra, int n_extra)
{
  const rs_problem *pb = s->pb;
  const rs_reel_effect_ops *ops[] = {
      pb->record.history_every > 0 ? &rs_reel_history_effect : NULL,
      pb->air.on ? &rs_reel_air_effect : NULL,
      pb->nip.model != RS_NIP_NONE ? &rs_reel_nip_effect : NULL,
      pb->centrifugal ? &rs_reel_spin_effect : NULL,
  };
  const int n_ops = (int)(sizeof ops / sizeof ops[0]);
  if (n_extra < 0 || n_extra + n_ops > RS_REEL_MAX_EFFECTS)
    return RS_ERROR(RS_ERR_INTERNAL, "the reel takes at most %d effects of a driver's (got %d)",
                    RS_REEL_MAX_EFFECTS - n_ops, n_extra);
  for (int k = 0; k < n_extra; ++k) s->effects[s->n_effects++] = extra[k];
  for (int k = 0; k < n_ops; ++k)
    if (ops[k]) s->effects[s->n_effects++] = (rs_reel_effect){ops[k], NULL};
  for (int k = 0; k < s->n_effects; ++k)
    if (s->effects[k].ops->place && !s->placer) s->placer = &s->effects[k];
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
  if (!st) st = rs_reel_gauge_init(&s->gauge, N);
  if (!st) st = rs_roll_create(&params, &s->roll);
  return st;
}

/* ---- per increment ----------------------------------------------------------------------- */

/* One layer: where it goes on, the recipes' tension and load, the effects' T0 (they may end
 * the increment before it or ask to plan it again), the check, what the roll carries, the
 * records. */
static rs_status reel_layer(rs_reel_state *s, rs_reel_step *step, int b)
{
  const rs_problem *pb = s->pb;
  rs_reel_result *res = s->res;
  rs_reel_layer L = {.j = step->first + b, .b = b};
  rs_status st;
  rs_reel_place(s, &L);
  L.Ti = L.T0 = rs_recipe_eval(&pb->tension, L.r);
  L.load = pb->nip.model != RS_NIP_NONE ? rs_recipe_eval(&pb->nip.load, L.r) : 0.0;
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->tension && ((st = e->ops->tension(e, s, step, &L)) || step->m == b || step->again))
      return st;
  }
  if (!(L.T0 >= 0.0) || !isfinite(L.T0))
    return RS_ERROR(RS_ERR_SOLVER,
                    "wound-on tension %g N/m at r = %.6g m (layer %d of %d) is %s: the web would "
                    "go slack on the roll",
                    L.T0, L.r, L.j + 1, s->N, isfinite(L.T0) ? "negative" : "not finite");
  L.radius = L.r;
  L.carried = L.T0;
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->wound && (st = e->ops->wound(e, s, &L))) return st;
  }
  res->radius[L.j] = L.radius;
  res->web_tension[L.j] = L.Ti;
  res->nip_load[L.j] = L.load;
  res->wound_on_tension[L.j] = L.T0;
  s->block[b] = L.carried;
  return RS_OK;
}

/* The roll went back to `layers` (an adaptive nip's check failed): every effect drops what
 * it recorded beyond. */
static void reel_rewind(rs_reel_state *s, int layers)
{
  s->first = layers;
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->rewind) e->ops->rewind(e, s, layers);
  }
  rs_reel_gauge_rewind(&s->gauge, layers);
}

/* After the roll's increment: the effects' records, then the wound radius. */
static rs_status reel_records(rs_reel_state *s)
{
  rs_status st;
  for (int k = 0; k < s->n_effects; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->after_increment && (st = e->ops->after_increment(e, s))) return st;
  }
  return rs_reel_gauge_record(&s->gauge, s->pb, s->first, rs_roll_core_pressure(s->roll),
                              rs_roll_sigma_r(s->roll), s->film, 0);
}

rs_status rs_reel_state_step(rs_reel_state *s)
{
  const int left = s->N - s->first;
  rs_reel_step step = {.first = s->first, .m = left < s->per_step ? left : s->per_step, .rewind = -1};
  rs_status st = RS_OK;
  for (int k = 0; k < s->n_effects && !st && step.rewind < 0; ++k) {
    rs_reel_effect *e = &s->effects[k];
    if (e->ops->begin) st = e->ops->begin(e, s, &step);
  }
  if (st) return st;
  if (step.rewind >= 0) {
    reel_rewind(s, step.rewind);
    return RS_OK;
  }
  for (int b = 0; b < step.m && !step.again; ++b)
    if ((st = reel_layer(s, &step, b))) return st;
  if (step.again) return RS_OK;
  if (step.m == 0) { /* the roll reached its size */
    s->done = 1;
    return RS_OK;
  }
  if ((st = rs_roll_add_layers(s->roll, step.m, s->block)))
    return rs_error_wrap("winding layers %d-%d of %d (r = %.6g m)", s->first + 1, s->first + step.m,
                         s->N, rs_roll_layer_radius(s->roll, s->first + step.m - 1));
  s->first += step.m;
  s->done = step.end || s->first >= s->N;
  return reel_records(s);
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
  if (res->n_layers > 0 && s->gauge.layers)
    st = reel_merge(st, reel_gauges(s->pb, res, &s->gauge, s->film));
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
  rs_reel_gauge_free(&s->gauge);
  free(s->block);
  rs_reel_result_destroy(&s->res);
  free(s);
  *sp = NULL;
}

/* ---- the driver -------------------------------------------------------------------------- */

/* The progress callback asked from inside long steps too (util/cancel.h): a nip solve with
 * many series terms or nodes stops within RS_CANCEL_INTERVAL of a Ctrl-C, not at its end. */
typedef struct reel_cancel {
  const rs_reel_options *opts;
  int done, N;
} reel_cancel;

static int reel_cancel_poll(void *user)
{
  const reel_cancel *c = user;
  return c->opts->progress(c->opts->user, c->done, c->N);
}

/* set up; increments until the reel is finished, the progress after each that wound layers;
 * finish */
rs_status rs_reel_wind(const rs_problem *pb, const rs_reel_options *opts, rs_reel_result **out)
{
  if (!out) return RS_ERROR(RS_ERR_INTERNAL, "rs_reel_wind: out is NULL");
  *out = NULL;
  if (!pb) return RS_ERROR(RS_ERR_INTERNAL, "rs_reel_wind: no problem");
  rs_reel_state *s = NULL;
  rs_status st = rs_reel_state_create(pb, NULL, 0, &s);
  if (!s) return st;
  rs_cancel_scope scope = {0};
  reel_cancel cancel = {opts, 0, s->N};
  rs_cancel_push(&scope, opts && opts->progress ? reel_cancel_poll : NULL, &cancel);
  while (st == RS_OK && !s->done) {
    const int before = s->first;
    if ((st = rs_reel_state_step(s)) || s->first <= before) continue;
    cancel.done = s->first;
    if (opts && opts->progress && opts->progress(opts->user, s->first, s->N))
      st = RS_ERROR(RS_ERR_INTERRUPTED, "interrupted after layer %d of %d", s->first, s->N);
  }
  rs_cancel_pop(&scope);
  st = rs_reel_state_finish(s, st, out);
  rs_reel_state_destroy(&s);
  return st;
}

void rs_reel_summarize(const rs_reel_result *res, rs_reel_summary *sum)
{
  memset(sum, 0, sizeof *sum);
  int n = res->n_layers;
  sum->layers = n;
  sum->core_pressure = res->core_pressure;
  if (n == 0) return;
  sum->final_radius = res->radius[n - 1];
  sum->peak_pressure = -INFINITY;
  sum->min_hoop = INFINITY;
  sum->wot_min = INFINITY;
  sum->wot_max = -INFINITY;
  for (int j = 0; j < n; ++j) {
    if (-res->sigma_r[j] > sum->peak_pressure) {
      sum->peak_pressure = -res->sigma_r[j];
      sum->peak_pressure_radius = res->radius[j];
    }
    if (res->sigma_theta[j] < sum->min_hoop) {
      sum->min_hoop = res->sigma_theta[j];
      sum->min_hoop_radius = res->radius[j];
    }
    sum->wot_min = fmin(sum->wot_min, res->wound_on_tension[j]);
    sum->wot_max = fmax(sum->wot_max, res->wound_on_tension[j]);
  }
  /* the core carries a pressure too; report it as the peak if it is the largest */
  if (res->core_pressure > sum->peak_pressure) {
    sum->peak_pressure = res->core_pressure;
    sum->peak_pressure_radius = res->core_radius;
  }
}
