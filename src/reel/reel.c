/* Winding a whole reel: grow the roll increment by increment; at each layer the recipes
 * give the web tension and nip load, the nip model (if the problem has one) gives the
 * wound-on tension T0, and the build-up engine winds it on. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reel/gauge.h"
#include "reel/nip_policy.h"
#include "reel/winder.h"
#include "reel/reel_air.h"
#include "reel/spin.h"
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

/* ---- stress history -------------------------------------------------------------------
 * A stage is stored at the first increment boundary at or after each multiple of
 * `every` layers, and the final state always closes the history. The stage arrays are
 * sized for the whole reel up front (rows of N values), so a stage costs one copy. */

/* Stress history allowed in memory: beyond this a user almost surely mistyped the
 * interval, and the HDF5 file (built in memory too) would need as much again. */
static const double history_max_bytes = 2147483648.0; /* 2 GiB */

/* How many stages a full run of N layers stores, per_step layers per increment. */
static long history_stages(int N, int per_step, int every)
{
  long count = 0, next = every, last = 0;
  for (long done = 0; done < N;) {
    done += N - done < per_step ? N - done : per_step;
    if (done >= next) {
      ++count;
      last = done;
      next = (done / every + 1) * (long)every;
    }
  }
  return count + (last != N);
}

static rs_status history_alloc(rs_reel_result *res, int N, int per_step, int every, long *cap)
{
  long S = history_stages(N, per_step, every);
  double bytes = (double)S * N * 2.0 * sizeof(double);
  *cap = 0;
  if (bytes > history_max_bytes) {
    /* at most N/e + 1 stages: the least interval whose bound fits */
    long max_stages = (long)(history_max_bytes / (2.0 * sizeof(double) * N));
    long least = max_stages > 1 ? N / (max_stages - 1) + 1 : N;
    return RS_ERROR(RS_ERR_INPUT,
                    "output.history_every = %d would store %ld stages of %d layers, %.2f GiB of "
                    "stress history (at most 2 GiB); use output.history_every >= %ld",
                    every, S, N, bytes / 1073741824.0, least);
  }
  size_t cells = (size_t)S * (size_t)N;
  res->stage_layers = malloc((size_t)S * sizeof(int));
  res->stage_radius = malloc((size_t)S * sizeof(double));
  res->stage_sigma_r = malloc(cells * sizeof(double));
  res->stage_sigma_theta = malloc(cells * sizeof(double));
  if (!res->stage_layers || !res->stage_radius || !res->stage_sigma_r || !res->stage_sigma_theta)
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the stress history (%ld stages of %d layers)",
                    S, N);
  *cap = S;
  return RS_OK;
}

/* Appends the roll's present state as a stage of rows `stride` values long. */
static void history_store(rs_reel_result *res, const rs_roll *roll, int stride)
{
  int n = rs_roll_layers(roll), s = res->n_stages++;
  double *sr = res->stage_sigma_r + (size_t)s * stride;
  double *st = res->stage_sigma_theta + (size_t)s * stride;
  memcpy(sr, rs_roll_sigma_r(roll), (size_t)n * sizeof(double));
  memcpy(st, rs_roll_sigma_theta(roll), (size_t)n * sizeof(double));
  for (int j = n; j < stride; ++j) sr[j] = st[j] = NAN;
  res->stage_layers[s] = n;
  res->stage_radius[s] = rs_roll_outer_radius(roll);
}

/* Closes the history with the final state and, when the run stopped early, packs the
 * rows to the n layers actually wound. */
static void history_finish(rs_reel_result *res, const rs_roll *roll, int N, long cap)
{
  int n = rs_roll_layers(roll);
  if (cap == 0) return;
  if (n > 0 && res->n_stages < cap &&
      (res->n_stages == 0 || res->stage_layers[res->n_stages - 1] != n))
    history_store(res, roll, N);
  if (n < N)
    for (int s = 0; s < res->n_stages; ++s) {
      memmove(res->stage_sigma_r + (size_t)s * n, res->stage_sigma_r + (size_t)s * N,
              (size_t)n * sizeof(double));
      memmove(res->stage_sigma_theta + (size_t)s * n, res->stage_sigma_theta + (size_t)s * N,
              (size_t)n * sizeof(double));
    }
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

/* Appends one kept nip solve to the result's record. */
static rs_status nip_record(rs_reel_result *res, int *cap, double r, double T0, double Ti,
                            const rs_nip_report *rep)
{
  if (res->n_nip == *cap) {
    int c = *cap ? 2 * *cap : 64;
    double **d[] = {&res->nip_radius, &res->nip_T0, &res->nip_Ti, &res->nip_a, &res->nip_solve_load};
    for (int i = 0; i < 5; ++i) {
      double *g = realloc(*d[i], (size_t)c * sizeof(double));
      if (!g) return RS_ERROR(RS_ERR_MEMORY, "cannot grow the nip record to %d solves", c);
      *d[i] = g;
    }
    int *it = realloc(res->nip_iterations, (size_t)c * sizeof(int));
    if (!it) return RS_ERROR(RS_ERR_MEMORY, "cannot grow the nip record to %d solves", c);
    res->nip_iterations = it;
    *cap = c;
  }
  int k = res->n_nip++;
  res->nip_radius[k] = r;
  res->nip_T0[k] = T0;
  res->nip_Ti[k] = Ti;
  res->nip_a[k] = rep->a;
  res->nip_solve_load[k] = rep->load;
  res->nip_iterations[k] = rep->iterations;
  return RS_OK;
}

/* After a rewind to `layers`, drops the history stages recorded beyond it. */
static void history_rewind(rs_reel_result *res, int layers, int every, long *next_stage)
{
  while (res->n_stages > 0 && res->stage_layers[res->n_stages - 1] > layers) res->n_stages--;
  if (every > 0) *next_stage = (layers / every + 1) * (long)every;
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

static int compare_doubles(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

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

rs_status rs_reel_wind(const rs_problem *pb, const rs_reel_options *opts, rs_reel_result **out)
{
  if (!out) return RS_ERROR(RS_ERR_INTERNAL, "rs_reel_wind: out is NULL");
  *out = NULL;
  if (!pb) return RS_ERROR(RS_ERR_INTERNAL, "rs_reel_wind: no problem");
  const double t_start = rs_clock_wall();
  const int N = pb->n_layers, per_step = pb->numerics.layers_per_step;
  if (N < 1) return RS_ERROR(RS_ERR_INPUT, "the problem winds no layers");
  if (per_step < 1)
    return RS_ERROR(RS_ERR_INPUT, "numerics.layers_per_step must be >= 1 (got %d)", per_step);
  const int every = pb->record.history_every;
  if (every < 0)
    return RS_ERROR(RS_ERR_INPUT, "output.history_every must be >= 0 (got %d)", every);

  rs_roll_params params;
  reel_params(pb, &params);
  rs_reel_result *res = reel_result_new(N);
  /* an increment never holds more than the roll's layers (layers_per_step may exceed N) */
  double *block = malloc((size_t)(per_step < N ? per_step : N) * sizeof(double));
  rs_roll *roll = NULL;
  rs_nip *nip = NULL;
  rs_status st = RS_OK;
  rs_cancel_scope cancel_scope = {0};
  reel_cancel cancel = {opts, 0, N};
  long hist_cap = 0, next_stage = every;
  /* the nip: its update policy, the state to rewind to, the profiles asked for
   * (declared before the first goto: `done` frees snap) */
  rs_nip_policy pol;
  rs_roll_state *snap = NULL;
  int nip_cap = 0, n_prof = 0, next_prof = 0;
  int spin_stop = 0; /* centrifugal load: a layer that cannot stay on the roll */
  /* entrained air: the films, and whether the roll reached its size before N layers */
  const int has_air = pb->air.on;
  rs_reel_air air = {0};
  int air_end = 0;
  rs_reel_gauge gauge = {0}; /* the wound radius: the roll's deformed radius as it grew */
  double prof_r[RS_MAX_PROFILES];
  if (!res || !block) {
    st = RS_ERROR(RS_ERR_MEMORY, "cannot allocate the results of %d layers", N);
    goto done;
  }
  res->core_radius = pb->core.radius;
  if (every > 0 && (st = history_alloc(res, N, per_step, every, &hist_cap))) goto done;
  if ((st = rs_reel_gauge_init(&gauge, N))) goto done;
  if (has_air) {
    if ((st = rs_reel_air_create(&air, N))) goto done;
    params.air_film = air.film;
    params.air_pressure = pb->air.pressure;
    params.air_radius = air.node;
  }
  if ((st = rs_roll_create(&params, &roll))) goto done;
  if ((st = rs_winder_nip_create(pb, &nip))) goto done;

  if (nip) {
    rs_nip_policy_init(&pol, &pb->nip, per_step, N);
    if (pb->nip.update == RS_NIP_UPDATE_ADAPTIVE && (st = rs_roll_state_create(&snap))) goto done;
    if (pb->nip.model == RS_NIP_CONTACT && pb->record.n_profiles > 0) {
      n_prof = pb->record.n_profiles;
      memcpy(prof_r, pb->record.nip_profiles_at, (size_t)n_prof * sizeof(double));
      qsort(prof_r, (size_t)n_prof, sizeof(double), compare_doubles);
      res->profiles = calloc((size_t)n_prof, sizeof *res->profiles);
      res->profile_radius = calloc((size_t)n_prof, sizeof(double));
      if (!res->profiles || !res->profile_radius) {
        st = RS_ERROR(RS_ERR_MEMORY, "cannot allocate %d nip profiles", n_prof);
        goto done;
      }
    }
  }

  rs_cancel_push(&cancel_scope, opts && opts->progress ? reel_cancel_poll : NULL, &cancel);
  for (int first = 0; first < N;) {
    int m = N - first < per_step ? N - first : per_step, solved = 0, force = 0;
    /* with air, the real outer radius (films compressed as the roll presses them now) */
    double R_air = has_air ? rs_reel_air_begin(&air, pb, roll, first) : 0.0;
    if (nip) {
      const double R = has_air ? R_air : rs_roll_outer_radius(roll);
      const int want_profile = next_prof < n_prof && R >= prof_r[next_prof];
      if (rs_nip_policy_due(&pol, first) || want_profile) {
        const int n = rs_roll_layers(roll);
        /* The web tension of the layer about to go on (its radius rs_roll_layer_radius(roll,
         * first) = R + caliper), the Ti that layer gets below: with Ti(R) the layer's T0 was
         * Ti(R + t) + (T0 - Ti)(R), off the nip's T0 by t dTi/dr, and where T0 -> 0 under a
         * taper (center-surface winder, mu_roll = 0: T0 = share Ti exactly) that made it
         * negative and stopped the run as "slack" (tests/hard/test_hard_nip.c). */
        rs_nip_state ns = {.roll_radius = R,
                           .core_radius = pb->core.radius,
                           .web_tension = rs_recipe_eval(&pb->tension, has_air ? R + pb->material.caliper
                                                                               : rs_roll_layer_radius(roll, first)),
                           .nip_load = rs_recipe_eval(&pb->nip.load, R),
                           .surface_modulus = rs_roll_surface_modulus(roll),
                           .surface_pressure = n > 0 ? -rs_roll_layer_sigma_r(roll, n - 1) : 0.0};
        double T0 = 0.0;
        res->nip_solves++;
        if ((st = rs_nip_wound_on_tension(nip, &ns, &T0))) {
          rs_error_wrap("nip model '%s' at roll radius %.6g m (layer %d of %d)", rs_nip_name(nip),
                        R, first + 1, N);
          if (st == RS_ERR_INPUT && n > 0) {
            /* the recipe turned impossible part-way (e.g. a tension the drum cannot carry
             * beyond some radius): the scene was sound at the start and the finished
             * layers stand, so this is the run failing there (exit 3, --keep-partial),
             * not a scene to reject (exit 2, nothing wound) */
            char why[1024];
            snprintf(why, sizeof why, "%s", rs_error_message());
            st = RS_ERROR(RS_ERR_SOLVER, "cannot wind past layer %d: %s", n, why);
          }
          goto done;
        }
        if (!(T0 >= 0.0) || !isfinite(T0)) {
          st = RS_ERROR(RS_ERR_SOLVER,
                        "wound-on tension %g N/m at roll radius %.6g m (layer %d of %d) is %s: the "
                        "web would go slack on the roll",
                        T0, R, first + 1, N, isfinite(T0) ? "negative" : "not finite");
          goto done;
        }
        if (!rs_nip_policy_offer(&pol, first, R, T0, ns.web_tension)) {
          /* the wound-on tension moved more than predicted: wind that stretch again */
          res->nip_rejected++;
          if ((st = rs_roll_restore(roll, snap))) goto done;
          first = pol.j2;
          history_rewind(res, first, every, &next_stage);
          rs_reel_gauge_rewind(&gauge, first);
          continue;
        }
        rs_nip_report rep;
        rs_nip_get_report(nip, &rep);
        if ((st = nip_record(res, &nip_cap, R, T0, ns.web_tension, &rep))) goto done;
        const rs_nip_solution *sol = want_profile ? rs_nip_last_solution(nip) : NULL;
        if (sol) {
          if ((st = rs_nip_solution_copy(&res->profiles[res->n_profiles], sol))) goto done;
          res->profile_radius[res->n_profiles++] = R;
        }
        while (want_profile && next_prof < n_prof && prof_r[next_prof] <= R) ++next_prof;
        if (snap && (st = rs_roll_save(roll, snap))) goto done;
        solved = 1;
      }
    }
    for (int b = 0; b < m; ++b) {
      int j = first + b;
      double r = has_air ? R_air + pb->material.caliper : rs_roll_layer_radius(roll, j);
      double Ti = rs_recipe_eval(&pb->tension, r), T0 = Ti;
      double load = nip ? rs_recipe_eval(&pb->nip.load, r) : 0.0, film = 0.0;
      if (has_air) {
        /* the film this layer brings; the layer nearest the roll's size is the last */
        film = rs_reel_air_film(pb, R_air, Ti, rs_recipe_eval(&pb->speed, r), load);
        /* a slack web (Ti = 0, no nip) floats on an unbounded film: past the roll's size
         * (a recipe at its end) that is the end, before it the run cannot go on */
        if (!isfinite(film) && rs_reel_air_stop(&air, pb, j, R_air, 0.0)) {
          m = b;
          air_end = 1;
          break;
        }
        if (!isfinite(film)) {
          st = RS_ERROR(RS_ERR_SOLVER,
                        "entrained air: the film under layer %d of %d (r = %.6g m, web tension "
                        "%g N/m) is not finite: a slack web floats on the air it carries",
                        j + 1, N, R_air, Ti);
          goto done;
        }
        if (rs_reel_air_stop(&air, pb, j, R_air, film)) {
          m = b;
          air_end = 1;
          break;
        }
      }
      /* the nip's part of T0, as solved or predicted at the radius the layer goes on at
       * (the roll's outer radius then, computed as rs_roll_outer_radius does, so that at a
       * solve the prediction is the solve's NIT bit for bit; r - caliper differs by an ulp,
       * which the slope of NIT turns into 1e-13 N/m) */
      if (nip) {
        double nit = rs_nip_policy_predict(&pol, has_air ? R_air : rs_roll_layer_radius(roll, j - 1));
        T0 = Ti + nit;
        /* T0 = 0 exactly (a taper to 0 on a center-surface winder with mu_roll = 0, where
         * T0 = share Ti; mu_roll = 0 on a surface winder) comes out of Ti + NIT with a
         * round-off of ~1e-13 N/m either way: below the nip's accuracy (load_rtol 1e-9) of
         * the tensions it is made of, it is 0, not a slack web (tests/hard/test_hard_nip.c) */
        if (T0 < 0.0 && T0 >= -1e-9 * (fabs(Ti) + fabs(pol.n1) + fabs(pol.n2))) T0 = 0.0;
        /* A negative PREDICTED T0 is not yet a slack web: the linear prediction of NIT
         * overshoots where NIT has a kink (a tension table's kink when T0 does not follow
         * Ti), and the adaptive check would only see it at the next solve. Solve here
         * instead; a solve's own T0 < 0 stops the run above. Terminates: the solve is due
         * at once, and after it layer `first` gets the solve's T0 (>= 0) or the policy
         * rewinds with a shorter interval. */
        if (!(T0 >= 0.0) && isfinite(T0) && b == 0 && !solved) {
          rs_nip_policy_solve_at(&pol, first);
          force = 1;
          break;
        }
      }
      if (!(T0 >= 0.0) || !isfinite(T0)) {
        st = RS_ERROR(RS_ERR_SOLVER,
                      "wound-on tension %g N/m at r = %.6g m (layer %d of %d) is %s: the web would "
                      "go slack on the roll",
                      T0, r, j + 1, N, isfinite(T0) ? "negative" : "not finite");
        goto done;
      }
      res->radius[j] = r;
      if (has_air) {
        rs_reel_air_wound(&air, j, R_air, film, pb->material.caliper);
        R_air += film + pb->material.caliper;
        res->radius[j] = R_air;
      }
      res->web_tension[j] = Ti;
      res->nip_load[j] = load;
      res->wound_on_tension[j] = T0;
      block[b] = T0;
      if (pb->centrifugal) {
        /* the hoop force the spinning layer needs for its own rotation is not pressed on
         * the roll beneath it (docs/roll-model.md, "Centrifugal load") */
        const double V = rs_recipe_eval(&pb->speed, r);
        const double spin = pb->material.density * pb->material.caliper * V * V;
        block[b] = T0 - spin;
        if (!(block[b] > 0.0)) {
          spin_stop = 1;
          st = RS_ERROR(RS_ERR_SOLVER,
                        "centrifugal load: at r = %.6g m (layer %d of %d) the wound-on tension "
                        "%g N/m is not above rho t V^2 = %g N/m (V = %g m/s): the web cannot "
                        "stay on the spinning roll", r, j + 1, N, T0, spin, V);
          goto done;
        }
      }
    }
    if (force) continue;
    if (m == 0) break; /* air: the roll reached its size */
    if ((st = rs_roll_add_layers(roll, m, block))) {
      rs_error_wrap("winding layers %d-%d of %d (r = %.6g m)", first + 1, first + m, N,
                    rs_roll_layer_radius(roll, first + m - 1));
      goto done;
    }
    first += m;
    if (hist_cap > 0 && first >= next_stage) {
      history_store(res, roll, N);
      if (has_air) res->stage_radius[res->n_stages - 1] = R_air;
      next_stage = (first / every + 1) * (long)every;
    }
    if ((st = rs_reel_gauge_record(&gauge, pb, first, rs_roll_core_pressure(roll), rs_roll_sigma_r(roll),
                                   has_air ? air.film : NULL, 0)))
      goto done;
    cancel.done = first;
    if (opts && opts->progress && opts->progress(opts->user, first, N)) {
      st = RS_ERROR(RS_ERR_INTERRUPTED, "interrupted after layer %d of %d", first, N);
      goto done;
    }
    if (air_end) break;
  }

done:
  rs_cancel_pop(&cancel_scope);
  if (res && roll) {
    reel_collect(roll, res, t_start);
    history_finish(res, roll, N, hist_cap);
  }
  else if (res) res->n_layers = 0;
  if (res && has_air && air.film && res->n_layers > 0) {
    rs_status ast = rs_reel_air_entrained(&air, res); /* the spin part's stack has them */
    if (st == RS_OK) st = ast;
  }
  if (res && pb->centrifugal && (st == RS_OK || spin_stop) && res->n_layers > 0 &&
      (!has_air || res->air_film_entrained)) {
    rs_status sst = rs_spin_wound(pb, res, 0);
    if (st == RS_OK) st = sst;
  }
  if (res && has_air && res->air_film_entrained) {
    rs_status ast = rs_reel_air_finish(&air, pb, res);
    if (st == RS_OK) st = ast;
    if (res->n_stages > 0 && res->stage_layers[res->n_stages - 1] == res->n_layers)
      res->stage_radius[res->n_stages - 1] = res->radius[res->n_layers - 1];
  }
  if (res && res->n_layers > 0 && gauge.layers) {
    rs_status gst = reel_gauges(pb, res, &gauge, has_air ? air.film : NULL);
    if (st == RS_OK) st = gst;
  }
  if (st == RS_OK) {
    for (int j = 0; j < res->n_layers; ++j)
      if (!isfinite(res->sigma_r[j]) || !isfinite(res->sigma_theta[j])) {
        st = RS_ERROR(RS_ERR_SOLVER, "non-finite stress in layer %d after winding", j + 1);
        break;
      }
    if (st == RS_OK && !isfinite(res->core_pressure))
      st = RS_ERROR(RS_ERR_SOLVER, "non-finite core pressure after winding");
  }
  free(block);
  rs_reel_gauge_free(&gauge);
  rs_reel_air_free(&air);
  rs_roll_state_destroy(&snap);
  rs_nip_destroy(&nip);
  rs_roll_destroy(&roll);
  *out = res;
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
