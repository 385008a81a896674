/* reelsim sweep's runs in one process: checked, then wound in batches over threads. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/clock.h"
#include "reelsim/scene.h"
#include "sweep/app_error.h"
#include "sweep/sweep.h"

/* Runs per batch and thread: the scenes and results of a batch are in memory together. */
enum { BATCH_PER_THREAD = 16 };

static rs_status load_run(const sweep_spec *spec, int i, rs_scene **scene)
{
  const char **all = NULL;
  char *text = NULL;
  rs_status st = sweep_plan_sets(spec->plan, i, spec->n_sets, spec->sets, &all, &text);
  if (st == RS_OK)
    st = rs_scene_load(spec->scene_path, spec->n_sets + spec->plan->n_keys, all, scene);
  if (st == RS_ERR_INPUT) {
    /* name the run by its values */
    char what[1024];
    size_t used = 0;
    what[0] = '\0';
    for (int k = 0; k < spec->plan->n_keys && used < sizeof what; ++k)
      used += (size_t)snprintf(what + used, sizeof what - used, "%s%s", k ? " " : "",
                               all[spec->n_sets + k]);
    app_error_wrap("run %d of %d (%s)", i + 1, spec->plan->n_runs, what);
  }
  free(all);
  free(text);
  return st;
}

/* FNV-1a (64 bits) of a resolved scene's text, continuing from h, without its comment
 * lines (the files and --sets it came from) and its `source:` lines (where a model was
 * found, which may differ between machines holding the same model). */
static uint64_t digest_scene(uint64_t h, const char *text)
{
  while (*text) {
    const char *end = strchr(text, '\n');
    size_t len = end ? (size_t)(end - text) + 1 : strlen(text);
    size_t lead = strspn(text, " ");
    if (text[lead] != '#' && strncmp(text + lead, "source:", 7) != 0)
      for (size_t k = 0; k < len; ++k) {
        h ^= (unsigned char)text[k];
        h *= 0x100000001b3ULL;
      }
    text += len;
  }
  return h;
}

rs_status sweep_check_runs(const sweep_spec *spec, uint64_t *digest)
{
  uint64_t h = 0xcbf29ce484222325ULL; /* FNV-1a's offset basis */
  for (int i = 0; i < spec->plan->n_runs; ++i) {
    if (spec->progress && spec->progress(NULL, 0, 0))
      return APP_ERROR(RS_ERR_INTERRUPTED, "stopped while checking run %d of %d", i + 1,
                      spec->plan->n_runs);
    rs_scene *scene = NULL;
    rs_status st = load_run(spec, i, &scene);
    if (st == RS_OK) h = digest_scene(h, rs_scene_resolved_text(scene));
    rs_scene_destroy(&scene);
    if (st != RS_OK) return st;
  }
  if (digest) *digest = h;
  return RS_OK;
}

rs_status sweep_result_alloc(sweep_result *r, int n, int profiles)
{
  memset(r, 0, sizeof *r);
  r->n_runs = n;
  r->figures = malloc((size_t)n * SWEEP_N_FIGURES * sizeof *r->figures);
  if (profiles) r->profiles = calloc((size_t)n, sizeof *r->profiles);
  if (!r->figures || (profiles && !r->profiles)) {
    sweep_result_free(r);
    return APP_ERROR(RS_ERR_MEMORY, "out of memory for %d runs", n);
  }
  for (size_t k = 0; k < (size_t)n * SWEEP_N_FIGURES; ++k) r->figures[k] = NAN;
  return RS_OK;
}

void sweep_result_free(sweep_result *r)
{
  for (int i = 0; r->profiles && i < r->n_runs; ++i) free((void *)r->profiles[i].radius);
  free(r->profiles);
  free(r->figures);
  memset(r, 0, sizeof *r);
}

/* The final profiles of a result in one block: radius, sigma_r, sigma_theta. */
static void keep_profile(const rs_reel_result *res, rs_output_profile *prof)
{
  memset(prof, 0, sizeof *prof);
  int nl = 0;
  const double *radius = rs_reel_result_radius(res, &nl);
  if (nl <= 0) return;
  size_t n = (size_t)nl;
  double *block = malloc(3 * n * sizeof *block);
  if (!block) return; /* the figures stand; the profile is left empty */
  memcpy(block, radius, n * sizeof *block);
  memcpy(block + n, rs_reel_result_sigma_r(res, NULL), n * sizeof *block);
  memcpy(block + 2 * n, rs_reel_result_sigma_theta(res, NULL), n * sizeof *block);
  *prof = (rs_output_profile){(int)n, block, block + n, block + 2 * n};
}

/* A failed run does not sink the sweep, but why it failed is said (on rank 0's stderr: a
 * worker rank sends it there), not only recorded as a status. */
void sweep_say_failed(int i, const char *why)
{
  fprintf(stderr, "reelsim: sweep: run %d failed: %s\n", i + 1, why && why[0] ? why : "(no message)");
}

void sweep_run_one(const sweep_spec *spec, int i, double fig[SWEEP_N_FIGURES],
                   rs_output_profile *prof, char *why, size_t why_size)
{
  double t0 = rs_clock_wall();
  rs_scene *scene = NULL;
  rs_reel_result *res = NULL;
  rs_status st = load_run(spec, i, &scene);
  if (st == RS_OK) {
    rs_reel_options opts = {spec->progress, NULL};
    st = rs_scene_wind(scene, &opts, &res);
  }
  double wall = rs_clock_wall() - t0;
  if (st != RS_OK) sweep_say_failed(i, app_error_message());
  if (why && why_size)
    snprintf(why, why_size, "%s", st == RS_OK ? "" : app_error_message()[0] ? app_error_message() : "(no message)");
  sweep_figures_compute(scene ? rs_scene_problem(scene) : NULL, res, st, wall, fig);
  if (prof) {
    if (st == RS_OK) keep_profile(res, prof);
    else memset(prof, 0, sizeof *prof);
  }
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&scene);
}

/* A batch of runs first..first+n-1 over the threads. */
static rs_status wind_batch(const sweep_spec *spec, int first, int n, sweep_result *out,
                            rs_scene **scenes, rs_reel_job *jobs)
{
  memset(jobs, 0, (size_t)n * sizeof *jobs);
  double t_load = rs_clock_wall();
  for (int j = 0; j < n; ++j) {
    rs_status st = load_run(spec, first + j, &scenes[j]);
    jobs[j].status = st;
    if (st == RS_OK) {
      jobs[j].problem = rs_scene_problem(scenes[j]);
      jobs[j].opts.progress = spec->progress;
    }
  }
  double load_each = (rs_clock_wall() - t_load) / n;
  /* rs_reel_wind_many winds every job it is given: the ones that did not load are left
   * out and keep their status */
  rs_reel_job *todo = malloc((size_t)n * sizeof *todo);
  int *where = malloc((size_t)n * sizeof *where), m = 0, used = 0;
  rs_status st = RS_OK;
  if (!todo || !where) st = APP_ERROR(RS_ERR_MEMORY, "out of memory");
  for (int j = 0; st == RS_OK && j < n; ++j)
    if (jobs[j].status == RS_OK) {
      where[m] = j;
      todo[m++] = jobs[j];
    }
  if (st == RS_OK && m > 0) st = rs_reel_wind_many(m, todo, spec->threads, &used);
  for (int q = 0; st == RS_OK && q < m; ++q) jobs[where[q]] = todo[q];
  if (used > out->threads) out->threads = used;
  for (int j = 0; st == RS_OK && j < n; ++j) {
    int i = first + j;
    double fig[SWEEP_N_FIGURES];
    if (jobs[j].status != RS_OK) sweep_say_failed(i, jobs[j].message);
    sweep_figures_compute(scenes[j] ? rs_scene_problem(scenes[j]) : NULL, jobs[j].result,
                          jobs[j].status, jobs[j].wall_seconds + load_each, fig);
    for (int f = 0; f < SWEEP_N_FIGURES; ++f) out->figures[(size_t)f * out->n_runs + i] = fig[f];
    if (out->profiles && jobs[j].status == RS_OK) keep_profile(jobs[j].result, &out->profiles[i]);
  }
  for (int j = 0; j < n; ++j) {
    rs_reel_result_destroy(&jobs[j].result);
    rs_scene_destroy(&scenes[j]);
  }
  free(todo);
  free(where);
  return st;
}

static int stopped(const sweep_spec *spec)
{
  return spec->progress && spec->progress(NULL, 0, 0);
}

rs_status sweep_wind_threads(const sweep_spec *spec, sweep_result *out)
{
  int n = spec->plan->n_runs;
  rs_status st = sweep_result_alloc(out, n, spec->profiles);
  if (st != RS_OK) return st;
  int threads = spec->threads > 0 ? spec->threads : 64;
  int batch = threads * BATCH_PER_THREAD;
  if (batch > n) batch = n;
  rs_scene **scenes = calloc((size_t)batch, sizeof *scenes);
  rs_reel_job *jobs = calloc((size_t)batch, sizeof *jobs);
  if (!scenes || !jobs) st = APP_ERROR(RS_ERR_MEMORY, "out of memory");
  for (int first = 0; st == RS_OK && first < n; first += batch) {
    if (stopped(spec)) {
      out->stopped = 1;
      break;
    }
    st = wind_batch(spec, first, first + batch <= n ? batch : n - first, out, scenes, jobs);
  }
  if (stopped(spec)) out->stopped = 1;
  free(scenes);
  free(jobs);
  for (int i = 0; i < n; ++i) out->failed += out->figures[(size_t)SWEEP_FIG_STATUS * n + i] != 0;
  return st;
}
