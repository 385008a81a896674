/* The base layer's clocks (reelsim/clock.h): the wall clock never goes back and counts a
 * sleep at least as long as it was (POSIX: nanosleep sleeps no less than asked); the
 * thread's CPU clock counts work and not sleep. Only lower bounds on time (a loaded
 * machine makes any interval longer), and an upper bound on CPU time while asleep. */
#include <time.h>

#include "check.h"
#include "reelsim/clock.h"

static void wall_monotonic(void)
{
  double prev = rs_clock_wall(), worst = 0.0;
  CHECK(prev > 0.0);
  for (int i = 0; i < 100000; ++i) {
    double t = rs_clock_wall();
    if (t - prev < worst) worst = t - prev;
    prev = t;
  }
  CHECK_ABS(worst, 0.0, 0.0); /* never negative */
  double t0 = rs_clock_wall();
  struct timespec ts = {0, 50 * 1000 * 1000};
  while (nanosleep(&ts, &ts) != 0) {}
  double slept = rs_clock_wall() - t0;
  CHECK_LOG("wall seconds over a 50 ms sleep", slept);
  CHECK(slept >= 0.05 * (1 - 1e-9));
}

static void thread_cpu(void)
{
  double c0 = rs_clock_thread_cpu();
  struct timespec ts = {0, 50 * 1000 * 1000};
  while (nanosleep(&ts, &ts) != 0) {}
  double asleep = rs_clock_thread_cpu() - c0;
  CHECK_LOG("CPU seconds over a 50 ms sleep", asleep);
  CHECK(asleep >= 0.0);
  CHECK_LT(asleep, 0.025);
  /* 20 ms of work, given up after 10 s of wall time if the clock does not count it */
  c0 = rs_clock_thread_cpu();
  double w0 = rs_clock_wall();
  volatile double x = 0.0;
  while (rs_clock_thread_cpu() - c0 < 0.02 && rs_clock_wall() - w0 < 10.0) x += 1.0;
  double busy = rs_clock_thread_cpu() - c0;
  CHECK_LOG("CPU seconds of a busy loop", busy);
  CHECK(busy >= 0.02);
  CHECK(x > 0.0);
}

static const check_case cases[] = {
    {"wall_monotonic", wall_monotonic},
    {"thread_cpu", thread_cpu},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
