/* rs_reel_wind_many: a small pool of POSIX threads that takes the jobs in order.
 * Nothing in the winding path shares mutable state between reels (each rs_roll owns its
 * SUNDIALS context, the error record is thread-local), so a job needs no locking; only
 * the index of the next job is shared. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "reelsim/clock.h"
#include "reelsim/reel.h"
#include "util/error.h"

typedef struct pool {
  int n;
  rs_reel_job *jobs;
  atomic_int next;
} pool;

static void run_job(rs_reel_job *job)
{
  double t0 = rs_clock_wall(), c0 = rs_clock_thread_cpu();
  rs_error_clear();
  job->result = NULL;
  job->status = rs_reel_wind(job->problem, &job->opts, &job->result);
  snprintf(job->message, sizeof job->message, "%s", job->status ? rs_error_message() : "");
  snprintf(job->where, sizeof job->where, "%s", job->status ? rs_error_where() : "");
  job->wall_seconds = rs_clock_wall() - t0;
  job->cpu_seconds = rs_clock_thread_cpu() - c0;
}

static void *worker(void *arg)
{
  pool *p = arg;
  for (int i; (i = atomic_fetch_add(&p->next, 1)) < p->n;) run_job(&p->jobs[i]);
  return NULL;
}

rs_status rs_reel_wind_many(int n, rs_reel_job *jobs, int threads, int *used)
{
  if (used) *used = 0;
  if (n < 0 || (n > 0 && !jobs)) return RS_ERROR(RS_ERR_INTERNAL, "no jobs to wind");
  for (int i = 0; i < n; ++i)
    if (!jobs[i].problem) return RS_ERROR(RS_ERR_INTERNAL, "job %d has no problem", i + 1);
  if (threads <= 0) {
    long online = sysconf(_SC_NPROCESSORS_ONLN);
    threads = online > 0 ? (int)(online < 1024 ? online : 1024) : 1;
  }
  if (threads > n) threads = n;
  if (n == 0) return RS_OK;

  pool p = {.n = n, .jobs = jobs};
  atomic_init(&p.next, 0);
  pthread_t *tid = threads > 1 ? malloc((size_t)(threads - 1) * sizeof *tid) : NULL;
  int started = 0;
  /* A thread that cannot be started (or no memory for its id) only means fewer workers:
   * this one always works. */
  while (tid && started < threads - 1 && pthread_create(&tid[started], NULL, worker, &p) == 0)
    ++started;
  worker(&p);
  for (int t = 0; t < started; ++t) pthread_join(tid[t], NULL);
  free(tid);
  if (used) *used = started + 1;
  return RS_OK;
}
