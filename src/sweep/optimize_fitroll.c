/* reelsim fit roll: scene keys fitted to a roll's measurements (sweep/fitroll.h).
 *
 * Residuals r_i = m(x_i; k) - y_i, the model's quantity at the data's points (fr_model) for
 * the key values k; minimised in the keys scaled to [0, 1] over their ranges by NLopt's
 * BOBYQA (bounded, derivative free: each evaluation is a whole reel), from the ranges'
 * middle. The intervals: the Jacobian in the keys' own units by central differences (a
 * step of 1e-3 of each range), its 2K reels wound at once (rs_reel_wind_many), then
 * rs_fit_intervals. */
#include <math.h>
#include <nlopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/fit.h"
#include "reelsim/scene.h"
#include "sweep/app_error.h"
#include "sweep/fitroll.h"

char **fr_sets_of(const fr_problem *p, const double *x, int *n)
{
  *n = p->n_sets + p->n_vars;
  size_t size = (size_t)(*n + 1) * sizeof(char *) + (size_t)p->n_vars * 200;
  for (int i = 0; i < p->n_sets; ++i) size += strlen(p->sets[i]) + 1;
  char **s = malloc(size);
  if (!s) return NULL;
  char *w = (char *)(s + *n + 1), *end = (char *)s + size;
  for (int i = 0; i < p->n_sets; ++i) {
    s[i] = w;
    w += snprintf(w, (size_t)(end - w), "%s", p->sets[i]) + 1;
  }
  for (int k = 0; k < p->n_vars; ++k) {
    s[p->n_sets + k] = w;
    if (sweep_vary_set_text(&p->vars[k], x[k], w, 200) != RS_OK) {
      free(s);
      return NULL;
    }
    w += strlen(w) + 1;
  }
  s[*n] = NULL;
  return s;
}

/* loads the scene at key values x: RS_OK and *sc, or the scene's error */
static rs_status load_at(const fr_problem *p, const double *x, rs_scene **sc)
{
  int n = 0;
  char **sets = fr_sets_of(p, x, &n);
  if (!sets) return APP_ERROR(RS_ERR_MEMORY, "fit roll: out of memory");
  rs_status st = rs_scene_load(p->scene, n, (const char *const *)sets, sc);
  free(sets);
  return st;
}

typedef struct fr_ctx {
  const fr_problem *p;
  fr_result *r;
  nlopt_opt opt;
  double *res;     /* [n] residuals of the last evaluation */
  double scale;    /* the data's RMS magnitude */
  rs_status first; /* the first evaluation's status */
} fr_ctx;

/* residuals of a wound result */
static double residuals(const fr_problem *p, const rs_reel_result *res, double *r)
{
  const fr_data *d = p->data;
  if (fr_model(d, res, r) != 0) return NAN;
  double s = 0.0;
  for (int i = 0; i < d->n; ++i) {
    r[i] -= d->y[i];
    s += r[i] * r[i];
  }
  return s;
}

static double objective(unsigned K, const double *u, double *grad, void *data)
{
  (void)grad;
  fr_ctx *c = data;
  const fr_problem *p = c->p;
  double x[RS_FIT_MAX_PARAMS];
  for (unsigned k = 0; k < K; ++k) x[k] = p->vars[k].lo + u[k] * (p->vars[k].hi - p->vars[k].lo);
  rs_scene *sc = NULL;
  rs_reel_result *res = NULL;
  rs_status st = load_at(p, x, &sc);
  if (!st) st = rs_scene_wind(sc, p->wind, &res);
  double ssr = st ? NAN : residuals(p, res, c->res);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
  if (c->r->evaluations++ == 0) c->first = st;
  if (st == RS_ERR_INTERRUPTED) {
    c->r->stopped = 1;
    nlopt_force_stop(c->opt);
  }
  app_error_clear();
  const double rms = sqrt(ssr / p->data->n);
  if (p->after) p->after(p->user, c->r->evaluations, x, rms);
  /* a reel that fails: far worse than any that winds (BOBYQA needs finite values) */
  return isfinite(ssr) ? ssr / (c->scale * c->scale) : 1e30;
}

/* the Jacobian at x by central differences, 2K reels at once; RS_OK or a reel's error */
static rs_status jacobian(const fr_problem *p, const double *x, double *J)
{
  const int K = p->n_vars, n = p->data->n;
  rs_scene *sc[2 * RS_FIT_MAX_PARAMS] = {0};
  rs_reel_job jobs[2 * RS_FIT_MAX_PARAMS];
  double h[RS_FIT_MAX_PARAMS], *r = malloc((size_t)2 * n * sizeof *r);
  rs_status st = r ? RS_OK : APP_ERROR(RS_ERR_MEMORY, "fit roll: out of memory");
  memset(jobs, 0, sizeof jobs);
  for (int k = 0; k < K && !st; ++k) {
    double xs[RS_FIT_MAX_PARAMS];
    h[k] = 1e-3 * (p->vars[k].hi - p->vars[k].lo);
    for (int s = 0; s < 2 && !st; ++s) {
      memcpy(xs, x, (size_t)K * sizeof *xs);
      xs[k] += s ? -h[k] : h[k];
      st = load_at(p, xs, &sc[2 * k + s]);
      if (!st) {
        jobs[2 * k + s].problem = rs_scene_problem(sc[2 * k + s]);
        if (p->wind) jobs[2 * k + s].opts = *p->wind;
      }
    }
  }
  if (!st) st = rs_reel_wind_many(2 * K, jobs, p->threads, NULL);
  for (int k = 0; k < K && !st; ++k) {
    for (int s = 0; s < 2 && !st; ++s) {
      if (jobs[2 * k + s].status)
        st = APP_ERROR(jobs[2 * k + s].status, "fit roll: the reel at %s %+g: %s", p->vars[k].key,
                      s ? -h[k] : h[k], jobs[2 * k + s].message);
      else if (!isfinite(residuals(p, jobs[2 * k + s].result, r + (size_t)s * n)))
        st = APP_ERROR(RS_ERR_SOLVER, "fit roll: the reel at %s %+g has no layers", p->vars[k].key,
                      s ? -h[k] : h[k]);
    }
    for (int i = 0; i < n && !st; ++i) J[(size_t)i * K + k] = (r[i] - r[n + i]) / (2 * h[k]);
  }
  for (int j = 0; j < 2 * K; ++j) {
    rs_reel_result_destroy(&jobs[j].result);
    rs_scene_destroy(&sc[j]);
  }
  free(r);
  return st;
}

rs_status fr_run(const fr_problem *p, fr_result *r)
{
  memset(r, 0, sizeof *r);
  const int K = p->n_vars, n = p->data->n;
  if (K < 1 || K > RS_FIT_MAX_PARAMS)
    return APP_ERROR(RS_ERR_INPUT, "fit roll: 1 to %d --vary keys (got %d)", RS_FIT_MAX_PARAMS, K);
  if (n < K + 1)
    return APP_ERROR(RS_ERR_INPUT,
                    "fit roll: %d measured points cannot determine %d keys with an error "
                    "estimate: at least %d are needed", n, K, K + 1);
  fr_ctx c = {.p = p, .r = r, .res = malloc((size_t)n * sizeof(double))};
  double *J = calloc((size_t)n * K, sizeof(double));
  if (!c.res || !J) {
    free(c.res);
    free(J);
    return APP_ERROR(RS_ERR_MEMORY, "fit roll: out of memory");
  }
  for (int i = 0; i < n; ++i) c.scale += p->data->y[i] * p->data->y[i];
  c.scale = c.scale > 0.0 ? sqrt(c.scale / n) : 1.0;
  double u[RS_FIT_MAX_PARAMS], lo[RS_FIT_MAX_PARAMS], hi[RS_FIT_MAX_PARAMS], f = 0.0;
  for (int k = 0; k < K; ++k) u[k] = 0.5, lo[k] = 0.0, hi[k] = 1.0;
  c.opt = nlopt_create(NLOPT_LN_BOBYQA, (unsigned)K);
  rs_status st = c.opt ? RS_OK : APP_ERROR(RS_ERR_MEMORY, "fit roll: cannot create the optimiser");
  if (!st) {
    nlopt_set_lower_bounds(c.opt, lo);
    nlopt_set_upper_bounds(c.opt, hi);
    nlopt_set_min_objective(c.opt, objective, &c);
    nlopt_set_xtol_rel(c.opt, 1e-6);
    nlopt_set_ftol_rel(c.opt, 1e-10);
    nlopt_set_maxeval(c.opt, 60 * K + 40);
    nlopt_result nr = nlopt_optimize(c.opt, u, &f);
    snprintf(r->nlopt, sizeof r->nlopt, "%s", nlopt_result_to_string(nr));
    nlopt_destroy(c.opt);
    if (c.first && !r->stopped)
      st = APP_ERROR(c.first, "fit roll: the reel at the ranges' middle does not wind");
  }
  for (int k = 0; k < K; ++k) {
    r->x[k] = p->vars[k].lo + u[k] * (p->vars[k].hi - p->vars[k].lo);
    r->half_width[k] = NAN;
  }
  if (!st && !r->stopped) { /* the residuals and the intervals at the optimum */
    rs_scene *sc = NULL;
    rs_reel_result *res = NULL;
    st = load_at(p, r->x, &sc);
    if (!st) st = rs_scene_wind(sc, p->wind, &res);
    const double ssr = st ? NAN : residuals(p, res, c.res);
    rs_reel_result_destroy(&res);
    rs_scene_destroy(&sc);
    if (!st) {
      r->rms = sqrt(ssr / n);
      for (int i = 0; i < n; ++i)
        if (i == 0 || fabs(c.res[i]) > fabs(r->worst_residual)) r->worst = i, r->worst_residual = c.res[i];
      st = jacobian(p, r->x, J);
      if (!st) {
        r->intervals_ok = rs_fit_intervals(n, K, J, ssr, r->half_width, NULL) == RS_OK;
        app_error_clear();
      }
    }
    if (st == RS_ERR_INTERRUPTED) r->stopped = 1, st = RS_OK;
  }
  free(c.res);
  free(J);
  return st;
}
