/* The stress history as a reel effect (effect.h): a stage is stored at the first increment
 * boundary at or after each multiple of `every` layers (record.history_every > 0), and the
 * final state always closes the history. The stage arrays are sized for the whole reel up
 * front (rows of N values), so a stage costs one copy. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reel/effect.h"

typedef struct history {
  int every;       /* layers between stages */
  long cap;        /* stages the arrays hold */
  long next_stage; /* layers at which the next stage is due */
} history;

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

/* Appends the roll's present state, outer radius R, as a stage of rows `stride` values long. */
static void history_store(rs_reel_result *res, const rs_roll *roll, int stride, double R)
{
  int n = rs_roll_layers(roll), s = res->n_stages++;
  double *sr = res->stage_sigma_r + (size_t)s * stride;
  double *st = res->stage_sigma_theta + (size_t)s * stride;
  memcpy(sr, rs_roll_sigma_r(roll), (size_t)n * sizeof(double));
  memcpy(st, rs_roll_sigma_theta(roll), (size_t)n * sizeof(double));
  for (int j = n; j < stride; ++j) sr[j] = st[j] = NAN;
  res->stage_layers[s] = n;
  res->stage_radius[s] = R;
}

static rs_status history_setup(rs_reel_effect *e, rs_reel_state *s, rs_roll_params *params)
{
  (void)params;
  history *h = calloc(1, sizeof *h);
  if (!h) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the stress history");
  e->content = h;
  h->every = s->pb->record.history_every;
  h->next_stage = h->every;
  return history_alloc(s->res, s->N, s->per_step, h->every, &h->cap);
}

/* A stage when the increment reached a multiple of `every`, at the reel's outer radius (the
 * films included with entrained air). */
static rs_status history_after(rs_reel_effect *e, const rs_reel_state *s)
{
  history *h = e->content;
  if (h->cap > 0 && s->first >= h->next_stage) {
    rs_reel_layer next = {.j = s->first};
    rs_reel_place(s, &next);
    history_store(s->res, s->roll, s->N, next.R);
    h->next_stage = (s->first / h->every + 1) * (long)h->every;
  }
  return RS_OK;
}

/* After a rewind to `layers`, drops the stages recorded beyond it. */
static void history_rewind(rs_reel_effect *e, const rs_reel_state *s, int layers)
{
  history *h = e->content;
  rs_reel_result *res = s->res;
  while (res->n_stages > 0 && res->stage_layers[res->n_stages - 1] > layers) res->n_stages--;
  h->next_stage = (layers / h->every + 1) * (long)h->every;
}

/* Closes the history with the final state and, when the run stopped early, packs the rows
 * to the n layers actually wound. */
static rs_status history_collect(rs_reel_effect *e, const rs_reel_state *s, rs_status st)
{
  const history *h = e->content;
  rs_reel_result *res = s->res;
  const int n = rs_roll_layers(s->roll), N = s->N;
  (void)st;
  if (h->cap == 0) return RS_OK;
  if (n > 0 && res->n_stages < h->cap &&
      (res->n_stages == 0 || res->stage_layers[res->n_stages - 1] != n))
    history_store(res, s->roll, N, rs_roll_outer_radius(s->roll));
  if (n < N)
    for (int k = 0; k < res->n_stages; ++k) {
      memmove(res->stage_sigma_r + (size_t)k * n, res->stage_sigma_r + (size_t)k * N,
              (size_t)n * sizeof(double));
      memmove(res->stage_sigma_theta + (size_t)k * n, res->stage_sigma_theta + (size_t)k * N,
              (size_t)n * sizeof(double));
    }
  return RS_OK;
}

static void history_destroy(rs_reel_effect *e)
{
  free(e->content); /* the stages are the result's */
  e->content = NULL;
}

const rs_reel_effect_ops rs_reel_history_effect = {
    .name = "history",
    .setup = history_setup,
    .after_increment = history_after,
    .rewind = history_rewind,
    .collect = history_collect,
    .destroy = history_destroy,
};
