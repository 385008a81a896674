/* Winding a whole reel: grow the roll increment by increment; at each layer the recipes
 * give the web tension and nip load, the nip model (if the scene has one) gives the
 * wound-on tension T0, and the build-up engine winds it on. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "reelsim/nip.h"
#include "reelsim/reel.h"
#include "reelsim/roll.h"

static double reel_now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

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

static void reel_params(const rs_scene *sc, rs_roll_params *p)
{
  memset(p, 0, sizeof *p);
  p->core_radius = sc->core.radius;
  p->core_stiffness = rs_core_stiffness(&sc->core);
  p->caliper = sc->material.caliper;
  p->E_theta = sc->material.E_theta;
  p->nu_rtheta = sc->material.nu_rtheta;
  p->radial = sc->material.radial;
  p->max_layers = sc->n_layers;
  p->rtol = sc->numerics.rtol;
  p->atol = sc->numerics.atol;
  p->max_steps = sc->numerics.max_steps;
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
  res->wall_seconds = reel_now() - t_start;
}

rs_status rs_reel_wind(const rs_scene *sc, const rs_reel_options *opts, rs_reel_result **out)
{
  *out = NULL;
  const double t_start = reel_now();
  const int N = sc->n_layers, per_step = sc->numerics.layers_per_step;
  if (N < 1) return RS_ERROR(RS_ERR_INPUT, "the scene winds no layers");
  if (per_step < 1)
    return RS_ERROR(RS_ERR_INPUT, "numerics.layers_per_step must be >= 1 (got %d)", per_step);

  rs_roll_params params;
  reel_params(sc, &params);
  rs_reel_result *res = reel_result_new(N);
  /* an increment never holds more than the roll's layers (layers_per_step may exceed N) */
  double *block = malloc((size_t)(per_step < N ? per_step : N) * sizeof(double));
  rs_roll *roll = NULL;
  rs_nip *nip = NULL;
  rs_status st = RS_OK;
  if (!res || !block) {
    st = RS_ERROR(RS_ERR_MEMORY, "cannot allocate the results of %d layers", N);
    goto done;
  }
  res->core_radius = sc->core.radius;
  if ((st = rs_roll_create(&params, &roll))) goto done;
  if ((st = rs_nip_create(&sc->nip, &sc->material, &nip))) goto done;

  for (int first = 0; first < N;) {
    int m = N - first < per_step ? N - first : per_step;
    for (int b = 0; b < m; ++b) {
      int j = first + b;
      double r = rs_roll_layer_radius(roll, j);
      double Ti = rs_recipe_eval(&sc->tension, r), T0 = Ti;
      double load = nip ? rs_recipe_eval(&sc->nip.load, r) : 0.0;
      if (nip) {
        rs_nip_state ns = {.roll_radius = rs_roll_outer_radius(roll),
                           .core_radius = sc->core.radius,
                           .web_tension = Ti,
                           .nip_load = load,
                           .surface_modulus = rs_roll_surface_modulus(roll),
                           .surface_pressure = rs_roll_layers(roll) > 0
                                                   ? -rs_roll_sigma_r(roll)[rs_roll_layers(roll) - 1]
                                                   : 0.0};
        if ((st = rs_nip_wound_on_tension(nip, &ns, &T0))) {
          rs_error_wrap("nip model '%s' at roll radius %.6g m (layer %d of %d)", rs_nip_name(nip),
                        ns.roll_radius, j + 1, N);
          goto done;
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
      res->web_tension[j] = Ti;
      res->nip_load[j] = load;
      res->wound_on_tension[j] = T0;
      block[b] = T0;
    }
    if ((st = rs_roll_add_layers(roll, m, block))) {
      rs_error_wrap("winding layers %d-%d of %d (r = %.6g m)", first + 1, first + m, N,
                    rs_roll_layer_radius(roll, first + m - 1));
      goto done;
    }
    first += m;
    if (opts && opts->progress && opts->progress(opts->user, first, N)) {
      st = RS_ERROR(RS_ERR_INTERRUPTED, "interrupted after layer %d of %d", first, N);
      goto done;
    }
  }

done:
  if (res && roll) reel_collect(roll, res, t_start);
  else if (res) res->n_layers = 0;
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
