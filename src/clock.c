/* See include/reelsim/clock.h. */
#include "reelsim/clock.h"

#include <time.h>

static double seconds(clockid_t id)
{
  struct timespec ts;
  if (clock_gettime(id, &ts) != 0) return 0.0;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double rs_clock_wall(void) { return seconds(CLOCK_MONOTONIC); }

double rs_clock_thread_cpu(void) { return seconds(CLOCK_THREAD_CPUTIME_ID); }
