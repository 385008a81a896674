/* The runs of a sweep: grid and Latin hypercube (plan.h). */
#include "sweep/app_error.h"
#include "sweep/plan.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

rs_status sweep_sample_parse(const char *arg, sweep_sample *s)
{
  s->kind = SWEEP_SAMPLE_GRID;
  s->runs = 0;
  if (arg && strcmp(arg, "grid") == 0) return RS_OK;
  if (arg && strncmp(arg, "lhs:", 4) == 0) {
    char *end;
    errno = 0;
    long r = strtol(arg + 4, &end, 10);
    if (!arg[4] || *end || errno == ERANGE)
      return APP_ERROR(RS_ERR_INPUT, "--sample %s: R is not a whole number", arg);
    if (r < 1 || r > SWEEP_MAX_RUNS)
      return APP_ERROR(RS_ERR_INPUT, "--sample %s: R must lie in [1, %d]", arg, SWEEP_MAX_RUNS);
    s->kind = SWEEP_SAMPLE_LHS;
    s->runs = (int)r;
    return RS_OK;
  }
  return APP_ERROR(RS_ERR_INPUT, "--sample %s: expected grid or lhs:R", arg ? arg : "");
}

void sweep_sample_name(const sweep_sample *s, char *buf, size_t size)
{
  if (s->kind == SWEEP_SAMPLE_LHS) snprintf(buf, size, "lhs:%d", s->runs);
  else snprintf(buf, size, "grid");
}

unsigned sweep_sample_vary_forms(const sweep_sample *s)
{
  return s->kind == SWEEP_SAMPLE_LHS ? SWEEP_VARY_GRID | SWEEP_VARY_RANGE | SWEEP_VARY_LIST
                                     : SWEEP_VARY_GRID | SWEEP_VARY_LIST;
}

/* splitmix64 (Steele, Lea & Flood 2014): a small, well-mixed generator; the same seed gives
 * the same stream on every machine. */
static uint64_t next(uint64_t *x)
{
  uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/* uniform in [0, 1) with 53 random bits */
static double uniform(uint64_t *x) { return (double)(next(x) >> 11) * 0x1.0p-53; }

rs_status sweep_plan_check_size(int n_keys, const sweep_vary *vary, const sweep_sample *s)
{
  if (s->kind == SWEEP_SAMPLE_LHS) return RS_OK; /* R was bounded when parsed */
  long long n = 1;
  for (int k = 0; k < n_keys; ++k) {
    n *= vary[k].n > 0 ? vary[k].n : 1;
    if (n > SWEEP_MAX_RUNS)
      return APP_ERROR(RS_ERR_INPUT, "--vary: the grid has more than %d runs", SWEEP_MAX_RUNS);
  }
  return RS_OK;
}

/* Every this many points a plan being made asks whether to stop (some milliseconds). */
enum { POLL_POINTS = 1 << 16 };

static rs_status stopped(long long done, long long n)
{
  return APP_ERROR(RS_ERR_INTERRUPTED, "stopped while making the plan (%lld of %lld points)", done, n);
}

static rs_status make_grid(sweep_plan *p, rs_reel_progress_fn stop)
{
  long long n = 1;
  for (int k = 0; k < p->n_keys; ++k) {
    n *= p->vary[k].n;
    if (n > SWEEP_MAX_RUNS)
      return APP_ERROR(RS_ERR_INPUT, "--vary: the grid has more than %d runs", SWEEP_MAX_RUNS);
  }
  p->n_runs = (int)n;
  p->points = malloc((size_t)n * (size_t)p->n_keys * sizeof *p->points);
  if (!p->points) return APP_ERROR(RS_ERR_MEMORY, "out of memory for %lld runs", n);
  for (long long i = 0; i < n; ++i) {
    if (stop && i % POLL_POINTS == 0 && stop(NULL, 0, 0)) return stopped(i, n);
    long long rest = i;
    for (int k = p->n_keys - 1; k >= 0; --k) {
      const sweep_vary *v = &p->vary[k];
      int j = (int)(rest % v->n);
      rest /= v->n;
      p->points[i * p->n_keys + k] = v->words ? (double)j : v->values[j];
    }
  }
  return RS_OK;
}

static rs_status make_lhs(sweep_plan *p, int r, rs_reel_progress_fn stop)
{
  p->n_runs = r;
  p->points = malloc((size_t)r * (size_t)p->n_keys * sizeof *p->points);
  int *perm = malloc((size_t)r * sizeof *perm);
  if (!p->points || !perm) {
    free(perm);
    return APP_ERROR(RS_ERR_MEMORY, "out of memory for %d runs", r);
  }
  uint64_t state = SWEEP_LHS_SEED;
  for (int k = 0; k < p->n_keys; ++k) {
    const sweep_vary *v = &p->vary[k];
    for (int j = 0; j < r; ++j) perm[j] = j;
    for (int j = r - 1; j > 0; --j) { /* Fisher-Yates */
      if (stop && j % POLL_POINTS == 0 && stop(NULL, 0, 0)) {
        free(perm);
        return stopped((long long)k * r, (long long)p->n_keys * r);
      }
      int m = (int)(next(&state) % (uint64_t)(j + 1)), t = perm[j];
      perm[j] = perm[m];
      perm[m] = t;
    }
    for (int i = 0; i < r; ++i) {
      if (stop && i % POLL_POINTS == 0 && stop(NULL, 0, 0)) {
        free(perm);
        return stopped((long long)k * r + i, (long long)p->n_keys * r);
      }
      int j = perm[i];
      double x;
      if (v->kind == SWEEP_LIST) {
        int item = (int)((long long)j * v->n / r);
        x = v->words ? (double)item : v->values[item];
      } else {
        x = v->lo + (v->hi - v->lo) * ((j + uniform(&state)) / r);
        if (x > v->hi) x = v->hi;
      }
      p->points[(size_t)i * (size_t)p->n_keys + (size_t)k] = x;
    }
  }
  free(perm);
  return RS_OK;
}

rs_status sweep_plan_make(int n_keys, const sweep_vary *vary, const sweep_sample *s,
                          sweep_plan *plan)
{
  return sweep_plan_make_stoppable(n_keys, vary, s, NULL, plan);
}

rs_status sweep_plan_make_stoppable(int n_keys, const sweep_vary *vary, const sweep_sample *s,
                                    rs_reel_progress_fn stop, sweep_plan *plan)
{
  memset(plan, 0, sizeof *plan);
  plan->n_keys = n_keys;
  plan->vary = vary;
  if (n_keys < 1) return APP_ERROR(RS_ERR_INPUT, "nothing to vary: give --vary KEY=LO:HI:N");
  rs_status st = s->kind == SWEEP_SAMPLE_LHS ? make_lhs(plan, s->runs, stop) : make_grid(plan, stop);
  if (st != RS_OK) sweep_plan_free(plan);
  return st;
}

void sweep_plan_free(sweep_plan *plan)
{
  free(plan->points);
  plan->points = NULL;
  plan->n_runs = 0;
}

rs_status sweep_plan_sets(const sweep_plan *plan, int i, int n_sets, const char *const *sets,
                          const char ***all, char **text)
{
  enum { ONE = SWEEP_KEY_MAX + 512 };
  *all = malloc(((size_t)n_sets + (size_t)plan->n_keys) * sizeof **all);
  *text = malloc((size_t)plan->n_keys * ONE);
  if (!*all || !*text) return APP_ERROR(RS_ERR_MEMORY, "out of memory");
  for (int j = 0; j < n_sets; ++j) (*all)[j] = sets[j];
  for (int k = 0; k < plan->n_keys; ++k) {
    char *t = *text + (size_t)k * ONE;
    rs_status st = sweep_vary_set_text(&plan->vary[k],
                                       plan->points[(size_t)i * (size_t)plan->n_keys + (size_t)k],
                                       t, ONE);
    if (st != RS_OK) return st;
    (*all)[n_sets + k] = t;
  }
  return RS_OK;
}
