/* The search of reelsim optimize (docs/optimize.md). The varied values are scaled to
 * x in [0, 1]^K over their LO:HI. A Latin hypercube of n_start points is wound first; from
 * its best feasible point (else the least infeasible) NLopt's COBYLA (Powell 1994: linear
 * approximations of the objective and constraints on a simplex, a trust region shrinking
 * to xtol) looks for the optimum under the inequality constraints. COBYLA sees a scaled
 * objective and constraints: f = -+ q / |q_start| and c = (q - X) / |X| (or X - q), <= 0
 * when met. A run that fails or is refused is not a crash for NLopt: it gets an objective
 * worse than any seen and every constraint violated by one unit. The answer is the best
 * feasible evaluation of all, whichever phase found it. */
#include "sweep/optimize.h"

#include <math.h>
#include <nlopt.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/clock.h"
#include "reelsim/output.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"
#include "sweep/app_error.h"

void opt_settings_default(opt_settings *s)
{
  s->n_start = 0;
  s->maxeval = 0;
  s->xtol_rel = 1e-4;
  s->xtol_abs = 1e-5;
  s->ftol_rel = 1e-9;
  s->seed = 20261124u;
}

void opt_history_free(opt_history *h)
{
  free(h->values);
  free(h->figures);
  free(h->phase);
  memset(h, 0, sizeof *h);
  h->best = -1;
}

const char *opt_result_text(const opt_history *h)
{
  if (h->n <= h->n_start) return "not run";
  const char *s = nlopt_result_to_string((nlopt_result)h->nlopt_result);
  return s ? s : "unknown";
}

double opt_quantity(const opt_problem *p, const opt_history *h, int i, int q)
{
  (void)p;
  if (q < OPT_N_FIGURES) return h->figures[(size_t)i * OPT_N_FIGURES + (size_t)q];
  return h->values[(size_t)i * (size_t)h->n_vars + (size_t)(q - OPT_N_FIGURES)];
}

/* Constraint j's violation at evaluation i: > 0 when not met (in the quantity's units). */
static double violation(const opt_problem *p, const opt_history *h, int i, int j)
{
  const opt_constraint *c = &p->cons[j];
  double q = opt_quantity(p, h, i, c->quantity);
  if (!isfinite(q)) return INFINITY;
  return c->ge ? c->bound - q : q - c->bound;
}

static int ran(const opt_history *h, int i)
{
  const double *f = h->figures + (size_t)i * OPT_N_FIGURES;
  return f[OPT_STATUS] == 0;
}

int opt_feasible(const opt_problem *p, const opt_history *h, int i)
{
  if (!ran(h, i)) return 0;
  if (!isfinite(opt_quantity(p, h, i, p->objective))) return 0;
  for (int j = 0; j < p->n_cons; ++j)
    if (!(violation(p, h, i, j) <= 0)) return 0;
  return 1;
}

/* Objective with the better one smaller. */
static double signed_objective(const opt_problem *p, const opt_history *h, int i)
{
  double q = opt_quantity(p, h, i, p->objective);
  return p->maximize ? -q : q;
}

char **opt_sets_of(const opt_problem *p, const opt_history *h, int i, int *n)
{
  int total = p->n_sets + p->n_vars;
  size_t bytes = (size_t)(total + 1) * sizeof(char *);
  for (int k = 0; k < p->n_vars; ++k) bytes += strlen(p->vars[k].key) + 32;
  char **sets = malloc(bytes);
  if (!sets) return NULL;
  char *s = (char *)(sets + total + 1);
  for (int k = 0; k < p->n_sets; ++k) sets[k] = (char *)p->sets[k];
  for (int k = 0; k < p->n_vars; ++k) {
    size_t room = strlen(p->vars[k].key) + 32;
    double v = h->values[(size_t)i * (size_t)p->n_vars + (size_t)k];
    char num[32];
    snprintf(s, room, "%s=%s", p->vars[k].key, rs_output_shortest(num, v)); /* 133.6 */
    sets[p->n_sets + k] = s;
    s += room;
  }
  sets[total] = NULL;
  *n = total;
  return sets;
}

double opt_resolution(const opt_var *v)
{
  double span = v->hi - v->lo;
  if (!(span > 0) || !isfinite(span)) return 0;
  return pow(10.0, floor(log10(span)) - 3);
}

/* Value k at scaled x, rounded to the key's resolution (opt_resolution): the text a scene
 * would hold ("133.6"), read back, and kept within [LO, HI]. */
static double value_at(const opt_var *var, double x)
{
  double t = x < 0 ? 0 : x > 1 ? 1 : x;
  double v = var->lo + t * (var->hi - var->lo), step = opt_resolution(var);
  if (step > 0) {
    int decimals = step < 1 ? (int)lround(-log10(step)) : 0;
    char text[64];
    snprintf(text, sizeof text, "%.*f", decimals, round(v / step) * step);
    v = strtod(text, NULL);
  }
  return v < var->lo ? var->lo : v > var->hi ? var->hi : v;
}

/* The evaluation at scaled point x: an earlier one at the same (rounded) values, else a
 * new one, wound, with its values and figures appended. Returns its index, or -1 when out
 * of memory. */
static int evaluate(const opt_problem *p, opt_history *h, const double *x, int phase)
{
  double vx[64];
  int K = p->n_vars < 64 ? p->n_vars : 64;
  for (int k = 0; k < K; ++k) vx[k] = value_at(&p->vars[k], x[k]);
  for (int i = 0; K == p->n_vars && i < h->n; ++i) /* a run is not spent twice on one recipe */
    if (memcmp(h->values + (size_t)i * (size_t)K, vx, (size_t)K * sizeof *vx) == 0) return i;
  if (h->n == h->cap) {
    int cap = h->cap ? 2 * h->cap : 64;
    double *v = realloc(h->values, (size_t)cap * (size_t)(p->n_vars ? p->n_vars : 1) * sizeof *v);
    if (v) h->values = v;
    double *f = realloc(h->figures, (size_t)cap * OPT_N_FIGURES * sizeof *f);
    if (f) h->figures = f;
    int *ph = realloc(h->phase, (size_t)cap * sizeof *ph);
    if (ph) h->phase = ph;
    if (!v || !f || !ph) return -1;
    h->cap = cap;
  }
  int i = h->n++;
  double *v = h->values + (size_t)i * (size_t)p->n_vars;
  double *f = h->figures + (size_t)i * OPT_N_FIGURES;
  h->phase[i] = phase;
  for (int k = 0; k < p->n_vars; ++k) v[k] = k < K ? vx[k] : value_at(&p->vars[k], x[k]);
  for (int j = 0; j < OPT_N_FIGURES; ++j) f[j] = NAN;
  int n_sets;
  char **sets = opt_sets_of(p, h, i, &n_sets);
  if (!sets) return -1;
  double t0 = rs_clock_wall();
  rs_scene *scene = NULL;
  rs_reel_result *res = NULL;
  rs_status st = rs_scene_load(p->scene, n_sets, (const char *const *)sets, &scene);
  free(sets);
  if (st == RS_OK) {
    for (int j = 0; j < SWEEP_N_FIGURES; ++j)
      h->recorded[j] |= !sweep_figure_lacks(rs_scene_problem(scene), j);
    st = rs_scene_wind(scene, p->wind, &res);
  }
  if (st == RS_ERR_INTERRUPTED) h->stopped = 1;
  double wall = rs_clock_wall() - t0;
  sweep_figures_compute(scene ? rs_scene_problem(scene) : NULL, res, st, wall, f);
  f[OPT_MISFIT] = st == RS_OK ? opt_target_misfit(p->target, res) : NAN;
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&scene);
  app_error_clear();
  return i;
}

/* A small, reproducible generator (xorshift64*) for the hypercube's permutations. */
static unsigned long long next_random(unsigned long long *s)
{
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return *s * 2685821657736338717ull;
}

typedef struct search {
  const opt_problem *p;
  opt_history *h;
  nlopt_opt opt;
  double fscale;      /* |objective| at the start point (1 if 0) */
  double *cscale;     /* per constraint: |X| (or the spread of the start's values) */
  int last;           /* the evaluation at the x NLopt asked last */
  int failed;         /* out of memory */
} search;

/* The evaluation at x: NLopt calls the objective, then each constraint, at the same x. */
static int at(search *s, const double *x)
{
  const opt_problem *p = s->p;
  opt_history *h = s->h;
  if (s->last >= 0) {
    const double *v = h->values + (size_t)s->last * (size_t)p->n_vars;
    int same = 1;
    for (int k = 0; k < p->n_vars && same; ++k) same = v[k] == value_at(&p->vars[k], x[k]);
    if (same) return s->last;
  }
  int before = h->n;
  s->last = evaluate(p, h, x, 1);
  if (s->last >= 0 && h->n == before) return s->last; /* an earlier run at these values */
  if (s->last < 0) {
    s->failed = 1;
    nlopt_force_stop(s->opt);
  } else if (h->stopped || (p->after && p->after(p->user, h))) {
    h->stopped = 1;
    nlopt_force_stop(s->opt);
  }
  return s->last;
}

static double worst_objective(const search *s)
{
  double worst = -INFINITY;
  for (int i = 0; i < s->h->n; ++i)
    if (ran(s->h, i) && isfinite(opt_quantity(s->p, s->h, i, s->p->objective)))
      worst = fmax(worst, signed_objective(s->p, s->h, i));
  return worst;
}

static double objective_fn(unsigned n, const double *x, double *grad, void *data)
{
  (void)n;
  (void)grad; /* COBYLA asks for none */
  search *s = data;
  int i = at(s, x);
  if (i < 0) return 0;
  double q = opt_quantity(s->p, s->h, i, s->p->objective);
  if (!ran(s->h, i) || !isfinite(q)) {
    double w = worst_objective(s);
    return (isfinite(w) ? w / s->fscale : 0) + 1;
  }
  return signed_objective(s->p, s->h, i) / s->fscale;
}

typedef struct cons_data {
  search *s;
  int j;
} cons_data;

static double constraint_fn(unsigned n, const double *x, double *grad, void *data)
{
  (void)n;
  (void)grad;
  cons_data *c = data;
  int i = at(c->s, x);
  if (i < 0) return 0;
  double v = violation(c->s->p, c->s->h, i, c->j);
  if (!ran(c->s->h, i) || !isfinite(v)) return 1;
  return v / c->s->cscale[c->j];
}

/* The best feasible evaluation (smallest signed objective), or -1. */
static int best_feasible(const opt_problem *p, const opt_history *h)
{
  int best = -1;
  for (int i = 0; i < h->n; ++i)
    if (opt_feasible(p, h, i) && (best < 0 || signed_objective(p, h, i) < signed_objective(p, h, best)))
      best = i;
  return best;
}

/* The least infeasible run (sum of violations relative to the bounds), or -1. */
static int least_infeasible(const opt_problem *p, const opt_history *h)
{
  int best = -1;
  double least = INFINITY;
  for (int i = 0; i < h->n; ++i) {
    if (!ran(h, i)) continue;
    double sum = 0;
    for (int j = 0; j < p->n_cons; ++j) {
      double v = violation(p, h, i, j);
      sum += v > 0 ? v / fmax(fabs(p->cons[j].bound), 1e-300) : 0;
    }
    if (sum < least) least = sum, best = i;
  }
  return best;
}

static int start_phase(const opt_problem *p, opt_history *h, int n0)
{
  int K = p->n_vars;
  int *perm = malloc((size_t)K * (size_t)n0 * sizeof *perm);
  double *x = malloc((size_t)K * sizeof *x);
  if (!perm || !x) {
    free(perm);
    free(x);
    return -1;
  }
  unsigned long long seed = p->settings.seed ? p->settings.seed : 1;
  for (int k = 0; k < K; ++k) {
    int *pk = perm + (size_t)k * (size_t)n0;
    for (int i = 0; i < n0; ++i) pk[i] = i;
    for (int i = n0 - 1; i > 0; --i) { /* Fisher-Yates */
      int j = (int)(next_random(&seed) % (unsigned long long)(i + 1));
      int t = pk[i];
      pk[i] = pk[j];
      pk[j] = t;
    }
  }
  int rc = 0;
  for (int i = 0; i < n0 && rc == 0; ++i) {
    for (int k = 0; k < K; ++k) x[k] = (perm[(size_t)k * (size_t)n0 + (size_t)i] + 0.5) / n0;
    if (evaluate(p, h, x, 0) < 0) rc = -1;
    else if (h->stopped || (p->after && p->after(p->user, h))) {
      h->stopped = 1;
      break;
    }
  }
  free(perm);
  free(x);
  return rc;
}

/* COBYLA's scales: the objective's magnitude at the start point (1 if 0), each
 * constraint's |X| (when X = 0, the spread of the start's values, else 1). */
static void search_scales(search *s, int from)
{
  const opt_problem *p = s->p;
  const opt_history *h = s->h;
  double q0 = fabs(opt_quantity(p, h, from, p->objective));
  s->fscale = q0 > 0 && isfinite(q0) ? q0 : 1;
  for (int j = 0; j < p->n_cons; ++j) {
    double X = fabs(p->cons[j].bound);
    if (X == 0) { /* the spread of the start's values, else 1 */
      for (int i = 0; i < h->n; ++i) {
        double q = opt_quantity(p, h, i, p->cons[j].quantity);
        if (ran(h, i) && isfinite(q)) X = fmax(X, fabs(q));
      }
    }
    s->cscale[j] = X > 0 ? X : 1;
  }
}

/* NLopt's bounds ([0, 1] per scaled key), objective, constraints, tolerances and budget;
 * > 0 when NLopt took them all. */
static nlopt_result search_settings(search *s, cons_data *cd, double *lo, double *hi, int n0,
                                    int maxeval)
{
  const opt_problem *p = s->p;
  for (int k = 0; k < p->n_vars; ++k) {
    lo[k] = 0;
    hi[k] = 1;
  }
  nlopt_result r = nlopt_set_lower_bounds(s->opt, lo);
  if (r > 0) r = nlopt_set_upper_bounds(s->opt, hi);
  if (r > 0) r = nlopt_set_min_objective(s->opt, objective_fn, s);
  for (int j = 0; j < p->n_cons && r > 0; ++j) {
    cd[j] = (cons_data){s, j};
    r = nlopt_add_inequality_constraint(s->opt, constraint_fn, &cd[j], 1e-9);
  }
  if (r > 0) r = nlopt_set_xtol_rel(s->opt, p->settings.xtol_rel);
  if (r > 0) r = nlopt_set_xtol_abs1(s->opt, p->settings.xtol_abs);
  if (r > 0) r = nlopt_set_ftol_rel(s->opt, p->settings.ftol_rel);
  if (r > 0) r = nlopt_set_maxeval(s->opt, maxeval);
  /* the first simplex: one hypercube cell wide, so COBYLA starts at the start's scale */
  if (r > 0) r = nlopt_set_initial_step1(s->opt, fmin(0.25, 1.0 / n0));
  return r;
}

/* COBYLA from evaluation `from` (its values scaled to [0, 1]). Returns 0, or -1 with the
 * reason in why (out of memory, NLopt refused its settings). */
static int cobyla_phase(const opt_problem *p, opt_history *h, int from, int n0, int maxeval,
                        char *why, size_t size)
{
  const int K = p->n_vars;
  search s = {.p = p, .h = h, .last = -1};
  s.cscale = malloc((size_t)(p->n_cons ? p->n_cons : 1) * sizeof *s.cscale);
  double *x = malloc((size_t)K * sizeof *x), *lo = calloc((size_t)K, sizeof *lo),
         *hi = malloc((size_t)K * sizeof *hi);
  cons_data *cd = malloc((size_t)(p->n_cons ? p->n_cons : 1) * sizeof *cd);
  s.opt = nlopt_create(NLOPT_LN_COBYLA, (unsigned)K);
  int rc = 0;
  if (!s.cscale || !x || !lo || !hi || !cd || !s.opt) {
    snprintf(why, size, "out of memory");
    rc = -1;
    goto done;
  }
  search_scales(&s, from);
  for (int k = 0; k < K; ++k) {
    double span = p->vars[k].hi - p->vars[k].lo;
    x[k] = span > 0 ? (h->values[(size_t)from * (size_t)K + (size_t)k] - p->vars[k].lo) / span : 0;
  }
  nlopt_result r = search_settings(&s, cd, lo, hi, n0, maxeval);
  if (r <= 0) {
    snprintf(why, size, "NLopt refused the settings (%s)", nlopt_result_to_string(r));
    rc = -1;
    goto done;
  }
  double fmin_found;
  h->nlopt_result = (int)nlopt_optimize(s.opt, x, &fmin_found);
  if (s.failed) {
    snprintf(why, size, "out of memory");
    rc = -1;
  }
done:
  nlopt_destroy(s.opt);
  free(s.cscale);
  free(x);
  free(lo);
  free(hi);
  free(cd);
  return rc;
}

int opt_run(const opt_problem *p, opt_history *h, char *why, size_t size)
{
  memset(h, 0, sizeof *h);
  h->best = -1;
  h->n_vars = p->n_vars;
  int K = p->n_vars;
  int n0 = p->settings.n_start > 0 ? p->settings.n_start : 4 * K + 4;
  int maxeval = p->settings.maxeval > 0 ? p->settings.maxeval : 30 * K + 30;
  if (start_phase(p, h, n0) != 0) {
    snprintf(why, size, "out of memory");
    return -1;
  }
  h->n_start = h->n;
  int from = best_feasible(p, h);
  if (from < 0) from = least_infeasible(p, h);
  int rc = 0;
  if (from >= 0 && !h->stopped) /* else nothing ran: nowhere to start from */
    rc = cobyla_phase(p, h, from, n0, maxeval, why, size);
  h->best = best_feasible(p, h);
  return rc;
}
