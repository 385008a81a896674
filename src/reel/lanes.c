/* Lanes across the width: the driver (lanes.h; the model and its sources: docs/lanes.md).
 *
 * Per layer k, every lane at k layers:
 *   1. each lane's deformed outer radius R_i (worker threads; lanes_radius.c: the top of the
 *      stack summed on its current state, the deep part carried from full-stack sums taken
 *      at geometrically spaced layers);
 *   2. (thread 0) Tbar = the tension recipe at the lanes' mean radius; the shared strain e
 *      from sum w_i max(0, E_theta t_i (e + R_i/Rbar - 1) + (f_i - 1) Tbar) = Tbar W; T_i;
 *      slack where T_i = 0; the nip load N_i (uniform Nbar or the roller's split);
 *   3. each lane winds layer k at web tension T_i and nip load N_i (worker threads).
 * Two barriers per layer. The nip with lanes is solved every nip.update_every layers (an
 * adaptive policy's rewinds would put the lanes at different layers: with lanes `adaptive`
 * runs as every 1). With entrained air the sheet ends, for every lane, before the first
 * layer that would end one lane's reel at the roll's size (rs_reel_air_ends). */
#include "reel/lanes.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "reel/effect.h"
#include "reel/lanes_share.h"
#include "reelsim/recipe.h"
#include "roll/roll.h"
#include "reel/result_internal.h"
#include "util/error.h"

typedef struct lanes_run {
  const rs_problem *pb;
  const rs_reel_options *opts;
  int n, N, threads;
  rs_lane *lane;
  double W;                       /* m, the width */
  double *w, *a, *b, *q, *T, *load, *k;
  int *order;
  int drum;                       /* a drum drives the roll (lanes_drum_driven) */
  rs_lanes_result *lr;
  pthread_barrier_t bar;
  pthread_mutex_t gate;           /* the workers wait here until the thread count is known */
  pthread_cond_t open;
  int ready;
  int layer;                      /* the layer the lanes wind next */
  int stop;                       /* thread 0: every thread leaves after the barrier */
  rs_status st;                   /* thread 0: the run's status */
  char msg[1200];
} lanes_run;

/* The lanes' coupling as the lane's tension phase (effect.h): the loop and the nip take
 * the lane's web tension T_i and nip load N_i from it, set by lanes_couple before each
 * layer (the same for every radius asked: the layer's). */
static double lane_web_tension(const rs_reel_effect *e, const rs_reel_state *s, double r)
{
  (void)s, (void)r;
  return ((const rs_lane *)e->content)->T;
}

static double lane_nip_load(const rs_reel_effect *e, const rs_reel_state *s, double r)
{
  (void)s, (void)r;
  return ((const rs_lane *)e->content)->load;
}

static const rs_reel_effect_ops lane_coupling = {
    .name = "lanes",
    .web_tension = lane_web_tension,
    .nip_load = lane_nip_load,
};

/* lane i's problem: the caliper its factor times material.caliper, no lanes, the nip solved
 * every nip.update_every layers (adaptive: every layer) */
static void lane_problem(const rs_problem *pb, int i, rs_problem *lp)
{
  *lp = *pb;
  lp->lanes.count = 0;
  lp->material.caliper = pb->material.caliper * pb->lanes.caliper[i];
  if (lp->nip.model != RS_NIP_NONE && lp->nip.update == RS_NIP_UPDATE_ADAPTIVE) {
    lp->nip.update = RS_NIP_UPDATE_EVERY;
    lp->nip.update_every = 1;
  }
}

/* the lane's deformed outer radius on its current state (lanes_radius.c: r_c with nothing
 * wound) */
static rs_status lane_radius(rs_lane *L)
{
  return rs_lane_radius_update(&L->radius, &L->pb, L->s->roll, L->s->film,
                               L->s->res->wound_on_tension, &L->R);
}

/* one layer on the lane: steps until a layer is wound (a step may only plan the nip again) */
static rs_status lane_wind_layer(rs_lane *L)
{
  const int before = L->s->first;
  rs_status st = RS_OK;
  for (int tries = 0; !st && !L->s->done && L->s->first == before; ++tries) {
    if (tries == 8)
      return RS_ERROR(RS_ERR_INTERNAL, "lane stepped %d times without winding layer %d", tries,
                      before + 1);
    st = rs_reel_state_step(L->s);
  }
  return st;
}

/* Thread t's lanes: t, t + threads, ... (wind the layer when `wind`), then their radii */
static void lanes_work(lanes_run *r, int t, int wind)
{
  for (int i = t; i < r->n; i += r->threads) {
    rs_lane *L = &r->lane[i];
    if (L->st) continue;
    rs_error_clear();
    if (wind) L->st = lane_wind_layer(L);
    if (!L->st) L->st = lane_radius(L);
    if (L->st) snprintf(L->msg, sizeof L->msg, "%s", rs_error_message());
  }
}

/* The nip loads of layer k: Nbar everywhere, or the rigid roller's split */
static rs_status lanes_nip(lanes_run *r, double Nbar, int k)
{
  const int n = r->n;
  double Rmax = -INFINITY, s;
  if (r->pb->lanes.nip == RS_LANES_NIP_UNIFORM || !(Nbar > 0.0)) {
    for (int i = 0; i < n; ++i) r->load[i] = Nbar > 0.0 ? Nbar : 0.0;
    return RS_OK;
  }
  for (int i = 0; i < n; ++i) Rmax = fmax(Rmax, r->lane[i].R);
  for (int i = 0; i < n; ++i) {
    r->k[i] = rs_roll_surface_modulus(r->lane[i].s->roll);
    r->a[i] = r->k[i];
    r->b[i] = r->k[i] * (r->lane[i].R - Rmax);
  }
  rs_status st = rsi_lanes_share(n, r->w, r->a, r->b, Nbar * r->W, r->order, &s, r->load);
  if (st) return rs_error_wrap("the roller's load split at layer %d", k + 1);
  return RS_OK;
}

/* Whether a drum drives the roll at its surface (docs/lanes.md, "Surface and two-drum
 * winders"): a surface or two-drum winder, or the one nip's drum driven (surface or
 * center-surface) */
static int lanes_drum_driven(const rs_problem *pb)
{
  if (pb->winder.type == RS_WINDER_TYPE_SURFACE || pb->winder.type == RS_WINDER_TYPE_TWO_DRUM)
    return 1;
  return pb->nip.model != RS_NIP_NONE &&
         (pb->nip.winder == RS_WINDER_SURFACE || pb->nip.winder == RS_WINDER_CENTER_SURFACE);
}

/* The lanes' web tensions T_i (r->T) and the shared strain *e, a_i = E_theta t_i, g_i the
 * tension profile's factor:
 *   center winder: sum w_i max(0, a_i (e + R_i/Rbar - 1) + (g_i - 1) Tbar) = Tbar W (the
 *     tension controller holds the mean of the web entering the roll);
 *   drum-driven: the web reaches the drum at the strain e its upstream tension sets, flat,
 *     sum w_i max(0, a_i e + (g_i - 1) Tbar) = Tbar W; the drum turns the roll so that the
 *     lanes it touches, the largest radius R_d = max R_i, take the web up at the drum's
 *     speed, so lane i takes it up at R_i/R_d of it and, the web's flow conserved (v/(1 + e)
 *     the same along it), T_i = max(0, a_i (e + R_i/R_d - 1) + (g_i - 1) Tbar).
 * Tbar <= 0: every lane slack. Records the misfit of the sum the machine holds. */
static rs_status lanes_web(lanes_run *r, double Tbar, double Rbar, double *e)
{
  const rs_problem *pb = r->pb;
  const int n = r->n, drum = r->drum;
  double Rd = -INFINITY, sum = 0.0;
  for (int i = 0; i < n; ++i) Rd = fmax(Rd, r->lane[i].R);
  for (int i = 0; i < n; ++i) {
    const rs_lane *L = &r->lane[i];
    r->a[i] = L->pb.material.E_theta * L->pb.material.caliper;
    r->b[i] = drum ? (pb->lanes.tension[i] - 1.0) * Tbar
                   : r->a[i] * (L->R / Rbar - 1.0) + (pb->lanes.tension[i] - 1.0) * Tbar;
  }
  *e = 0.0;
  if (!(Tbar > 0.0)) {
    for (int i = 0; i < n; ++i) r->T[i] = 0.0;
    return RS_OK;
  }
  rs_status st = rsi_lanes_share(n, r->w, r->a, r->b, Tbar * r->W, r->order, e, r->T);
  if (st) return st;
  for (int i = 0; i < n; ++i) sum += r->w[i] * r->T[i];
  r->lr->Tbar_W_misfit = fmax(r->lr->Tbar_W_misfit, fabs(sum - Tbar * r->W) / (Tbar * r->W));
  if (drum)
    for (int i = 0; i < n; ++i)
      r->T[i] = fmax(0.0, r->a[i] * (*e + (r->lane[i].R / Rd - 1.0)) + r->b[i]);
  return RS_OK;
}

/* Layer k's web tensions, slack flags and nip loads, set into the lanes' problems */
static rs_status lanes_couple(lanes_run *r, int k)
{
  const rs_problem *pb = r->pb;
  const int n = r->n;
  double Rbar = 0.0, rnom = 0.0, rbeneath = 0.0, e = 0.0;
  for (int i = 0; i < n; ++i) {
    Rbar += r->w[i] * r->lane[i].R;
    rnom += r->w[i] * rs_roll_layer_radius(r->lane[i].s->roll, k);
    rbeneath += r->w[i] * rs_roll_layer_radius(r->lane[i].s->roll, k - 1);
  }
  Rbar /= r->W;
  rnom /= r->W;
  rbeneath /= r->W;
  const double Tbar = rs_recipe_eval(&pb->tension, rnom);
  rs_status st = lanes_web(r, Tbar, Rbar, &e);
  if (st) return rs_error_wrap("the web's tension across the lanes at layer %d", k + 1);
  const double Nbar = pb->nip.model != RS_NIP_NONE ? rs_recipe_eval(&pb->nip.load, rbeneath) : 0.0;
  if ((st = lanes_nip(r, Nbar, k))) return st;
  r->lr->strain[k] = e;
  for (int i = 0; i < n; ++i) {
    rs_lane *L = &r->lane[i];
    L->T = r->T[i];
    L->load = r->load[i];
    r->lr->web_tension[(size_t)k * n + i] = r->T[i];
    r->lr->slack[(size_t)k * n + i] = !(r->T[i] > 0.0);
    if (r->lr->nip_load) r->lr->nip_load[(size_t)k * n + i] = r->load[i];
  }
  return RS_OK;
}

/* Thread 0 between the barriers: a lane's failure, the progress, the next layer's coupling */
static void lanes_between(lanes_run *r)
{
  for (int i = 0; i < r->n; ++i)
    if (r->lane[i].st) {
      r->st = r->lane[i].st;
      snprintf(r->msg, sizeof r->msg, "lane %d (x = %.6g m): %s", i + 1, r->pb->lanes.x[i],
               r->lane[i].msg);
      r->stop = 1;
      return;
    }
  const int k = r->layer;
  if (k > 0 && r->opts && r->opts->progress && r->opts->progress(r->opts->user, k, r->N)) {
    r->st = RS_ERR_INTERRUPTED;
    snprintf(r->msg, sizeof r->msg, "interrupted after layer %d of %d", k, r->N);
    r->stop = 1;
    return;
  }
  if (k >= r->N || r->lane[0].s->done) {
    r->stop = 1;
    return;
  }
  rs_error_clear();
  if ((r->st = lanes_couple(r, k))) {
    snprintf(r->msg, sizeof r->msg, "%s", rs_error_message());
    r->stop = 1;
    return;
  }
  /* entrained air: the sheet ends where the first lane (the highest) reaches the roll's
   * size, before any lane winds the layer, so that every lane has the same layers */
  for (int i = 0; r->pb->air.on && i < r->n; ++i) {
    const rs_lane *L = &r->lane[i];
    if (rs_reel_air_ends(L->s, L->T, r->pb->nip.model != RS_NIP_NONE ? L->load : 0.0)) {
      r->stop = 1;
      return;
    }
  }
}

typedef struct worker_arg {
  lanes_run *r;
  int t;
} worker_arg;

static void *lanes_worker(void *arg)
{
  worker_arg *wa = arg;
  lanes_run *r = wa->r;
  for (int wind = 0; !r->stop; wind = 1) {
    lanes_work(r, wa->t, wind);
    pthread_barrier_wait(&r->bar);
    if (wa->t == 0) {
      if (wind) r->layer++;
      lanes_between(r);
    }
    pthread_barrier_wait(&r->bar);
    if (r->stop) break;
  }
  return NULL;
}

/* the lanes' states and the run's scratch */
static rs_status lanes_setup(lanes_run *r)
{
  const rs_problem *pb = r->pb;
  const int n = r->n;
  r->lane = calloc((size_t)n, sizeof *r->lane);
  double **d[] = {&r->w, &r->a, &r->b, &r->q, &r->T, &r->load, &r->k};
  for (size_t j = 0; j < sizeof d / sizeof d[0]; ++j) *d[j] = calloc((size_t)n, sizeof(double));
  r->order = calloc((size_t)n, sizeof(int));
  r->lr = rs_lanes_result_new(n, r->N, pb->nip.model != RS_NIP_NONE);
  if (!r->lane || !r->w || !r->a || !r->b || !r->q || !r->T || !r->load || !r->k || !r->order ||
      !r->lr)
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate %d lanes", n);
  for (int i = 0; i < n; ++i) {
    r->w[i] = pb->lanes.width[i];
    r->W += r->w[i];
  }
  for (int i = 0; i < n; ++i) {
    rs_lane *L = &r->lane[i];
    lane_problem(pb, i, &L->pb);
    if (rs_lane_radius_init(&L->radius, r->N)) return rs_error_wrap("lane %d", i + 1);
    const rs_reel_effect coupling = {&lane_coupling, L};
    rs_status st = rs_reel_state_create(&L->pb, &coupling, 1, &L->s);
    if (st) return rs_error_wrap("lane %d (x = %.6g m)", i + 1, pb->lanes.x[i]);
  }
  return RS_OK;
}

static int lanes_threads(int n)
{
  long online = sysconf(_SC_NPROCESSORS_ONLN);
  const char *env = getenv("REELSIM_LANES_THREADS");
  if (env && atoi(env) > 0) online = atoi(env);
  int t = online > 0 ? (int)(online < 256 ? online : 256) : 1;
  return t < n ? t : n;
}

/* the threads: thread 0 is this one; a thread that cannot be started means fewer threads.
 * The workers wait at the gate until the count is known (the barrier's and the lanes'
 * stride). */
static void *lanes_gate(void *arg)
{
  worker_arg *wa = arg;
  lanes_run *r = wa->r;
  pthread_mutex_lock(&r->gate);
  while (!r->ready) pthread_cond_wait(&r->open, &r->gate);
  pthread_mutex_unlock(&r->gate);
  return lanes_worker(arg);
}

static rs_status lanes_run_threads(lanes_run *r)
{
  const int want = lanes_threads(r->n);
  pthread_t tid[256];
  worker_arg args[256];
  int started = 0;
  pthread_mutex_init(&r->gate, NULL);
  pthread_cond_init(&r->open, NULL);
  while (started < want - 1) {
    args[started + 1] = (worker_arg){r, started + 1};
    if (pthread_create(&tid[started], NULL, lanes_gate, &args[started + 1])) break;
    ++started;
  }
  r->threads = started + 1;
  rs_status st = RS_OK;
  if (pthread_barrier_init(&r->bar, NULL, (unsigned)r->threads)) {
    st = RS_ERROR(RS_ERR_MEMORY, "cannot set up the lanes' barrier");
    r->stop = 1; /* the started workers only pass the gate and leave */
  }
  pthread_mutex_lock(&r->gate);
  r->ready = 1;
  pthread_cond_broadcast(&r->open);
  pthread_mutex_unlock(&r->gate);
  args[0] = (worker_arg){r, 0};
  if (!st) lanes_worker(&args[0]);
  for (int t = 0; t < started; ++t) pthread_join(tid[t], NULL);
  if (!st) pthread_barrier_destroy(&r->bar);
  pthread_cond_destroy(&r->open);
  pthread_mutex_destroy(&r->gate);
  r->lr->threads = r->threads;
  return st;
}

static void lanes_free(lanes_run *r)
{
  for (int i = 0; r->lane && i < r->n; ++i) {
    rs_reel_state_destroy(&r->lane[i].s);
    rs_reel_result_destroy(&r->lane[i].res);
    rs_lane_radius_free(&r->lane[i].radius);
  }
  free(r->lane);
  free(r->w), free(r->a), free(r->b), free(r->q), free(r->T), free(r->load), free(r->k);
  free(r->order);
  rs_lanes_result_destroy(&r->lr);
}

rs_status rs_lanes_wind(const rs_problem *pb, const rs_reel_options *opts, rs_reel_result **out)
{
  *out = NULL;
  lanes_run r = {.pb = pb, .opts = opts, .n = pb->lanes.count, .N = pb->n_layers,
                 .drum = lanes_drum_driven(pb)};
  if (r.n < 1 || r.n > RS_LANES_MAX)
    return RS_ERROR(RS_ERR_INPUT, "lanes: %d lanes (1 to %d)", r.n, RS_LANES_MAX);
  if (pb->numerics.layers_per_step != 1)
    return RS_ERROR(RS_ERR_INPUT, "lanes wind one layer per increment");
  rs_status st = lanes_setup(&r);
  if (!st) st = lanes_run_threads(&r);
  if (!st && r.st) {
    rs_error_clear();
    st = RS_ERROR(r.st, "%s", r.msg);
  }
  for (int i = 0; r.lane && i < r.n; ++i)
    if (r.lane[i].s) {
      rs_status li = rs_reel_state_finish(r.lane[i].s, st, &r.lane[i].res);
      if (!st && li) st = rs_error_wrap("lane %d (x = %.6g m)", i + 1, pb->lanes.x[i]);
    }
  if (r.lane && r.lr) {
    rs_status cs = rs_lanes_collect(pb, r.lane, r.lr, out);
    r.lr = NULL;
    if (!st) st = cs;
  }
  lanes_free(&r);
  return st;
}
