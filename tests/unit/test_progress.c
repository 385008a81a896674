/* The progress line's time estimate (src/cli/progress.c) against synthetic cost profiles,
 * not against a clock: samples (n, T(n)) of a known cumulative cost T, and the estimate
 * half-way compared with the exact time left T(N) - T(n). */
#include <math.h>

#include "check.h"
#include "cli/progress.h"

enum { N = 6000 };

/* cost per layer a + b n: T(n) = a n + b n (n + 1) / 2 (the sum over layers 1..n) */
static double T_linear_cost(double a, double b, int n) { return a * n + b * n * (n + 1.0) / 2.0; }

/* samples every `every` layers up to `upto`, with a relative wobble of +-noise */
static double estimate(double a, double b, int upto, int every, double noise)
{
  cli_eta e;
  cli_eta_init(&e, N);
  for (int n = every; n <= upto; n += every) {
    double wobble = 1.0 + noise * sin(12.9898 * n); /* deterministic, zero mean */
    cli_eta_add(&e, n, T_linear_cost(a, b, n) * wobble);
  }
  return cli_eta_left(&e);
}

/* Work growing with the layers wound (every increment from the core): c(n) = b n. Half-way
 * the time left is 3x the elapsed time; the plain extrapolation says 1x. */
static void growing_cost_half_way(void)
{
  const double b = 1e-7;
  double exact = T_linear_cost(0, b, N) - T_linear_cost(0, b, N / 2);
  double elapsed = T_linear_cost(0, b, N / 2);
  double left = estimate(0, b, N / 2, 10, 0.0);
  CHECK_LOG("exact time left / elapsed", exact / elapsed);
  CHECK_CLOSE(left, exact, 1e-3);
  /* the estimate the line used to give is 2x (and more) optimistic: this test can fail */
  CHECK_LT(elapsed * 2.0, exact);
}

/* A constant cost: the fit's b is 0 and the estimate is the plain extrapolation. */
static void constant_cost(void)
{
  const double a = 2e-4;
  double left = estimate(a, 0, 1500, 7, 0.0);
  CHECK_CLOSE(left, a * (N - 1498), 1e-9); /* the last sample is at n = 1498 */
}

/* A mixed profile with a 5 % wobble on every sample, early (a tenth of the way) and late:
 * within 10 % of the exact time left. */
static void noisy_mixed_cost(void)
{
  const double a = 1e-4, b = 2e-8;
  int stops[2] = {600, 4500};
  for (int i = 0; i < 2; ++i) {
    int n = stops[i];
    double exact = T_linear_cost(a, b, N) - T_linear_cost(a, b, n);
    double left = estimate(a, b, n, 3, 0.05);
    CHECK_CLOSE(left, exact, 0.10);
  }
}

/* No estimate from fewer than two samples; none negative at the end. */
static void edges(void)
{
  cli_eta e;
  cli_eta_init(&e, N);
  CHECK(cli_eta_left(&e) < 0.0);
  cli_eta_add(&e, 10, 0.01);
  cli_eta_add(&e, 10, 0.02); /* the same layer count again is not a new sample */
  CHECK(cli_eta_left(&e) < 0.0);
  cli_eta_add(&e, 20, 0.02);
  CHECK(cli_eta_left(&e) >= 0.0);
  double done = estimate(1e-4, 1e-8, N, 5, 0.0);
  CHECK_ABS(done, 0.0, 1e-12);
}

static const check_case cases[] = {
    {"growing_cost_half_way", growing_cost_half_way},
    {"constant_cost", constant_cost},
    {"noisy_mixed_cost", noisy_mixed_cost},
    {"edges", edges},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
