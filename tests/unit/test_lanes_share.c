/* The lanes' shared unknown: sum_i w_i max(0, a_i x + b_i) = total, held
 * against hand solutions and an independent bisection. */
#include <stdlib.h>

#include "check.h"
#include "reel/lanes_share.h"

/* Uniform lanes, no offsets: x = total / (W a) exactly as arithmetic allows. */
static void uniform(void) {
  double w[4] = {0.3, 0.3, 0.3, 0.3}, a[4] = {2e6, 2e6, 2e6, 2e6},
         b[4] = {0, 0, 0, 0}, q[4];
  int order[4];
  double x = -1;
  CHECK(rsi_lanes_share(4, w, a, b, 240.0, order, &x, q) == RS_OK);
  CHECK_CLOSE(x, 240.0 / (1.2 * 2e6), 1e-15);
  for (int i = 0; i < 4; ++i)
    CHECK_CLOSE(q[i], 200.0, 1e-15);
}

/* Two lanes of 1 m, a = 1: q = (x + 5, x - 10). For total 9 only the first
 * carries: x = 4, q = (9, 0) (the second is slack). For total 25 both: 2x - 5 =
 * 25, x = 15, q = (20, 5). */
static void slack_by_hand(void) {
  double w[2] = {1, 1}, a[2] = {1, 1}, b[2] = {5, -10}, q[2];
  int order[2];
  double x;
  CHECK(rsi_lanes_share(2, w, a, b, 9.0, order, &x, q) == RS_OK);
  CHECK_CLOSE(x, 4.0, 1e-15);
  CHECK_CLOSE(q[0], 9.0, 1e-15);
  CHECK(q[1] == 0.0);
  CHECK(rsi_lanes_share(2, w, a, b, 25.0, order, &x, q) == RS_OK);
  CHECK_CLOSE(x, 15.0, 1e-15);
  CHECK_CLOSE(q[0], 20.0, 1e-15);
  CHECK_CLOSE(q[1], 5.0, 1e-15);
}

static double weighted(int n, const double *w, const double *a, const double *b,
                       double x) {
  double s = 0;
  for (int i = 0; i < n; ++i)
    s += w[i] * fmax(0.0, a[i] * x + b[i]);
  return s;
}

/* Random lanes (fixed seed): the total is met to round-off, and x agrees with a
 * bisection of the (nondecreasing) left side that knows nothing of the
 * breakpoints. */
static void against_bisection(void) {
  srand(12345);
  double worst_sum = 0, worst_x = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    int n = 1 + rand() % 40, order[40];
    double w[40], a[40], b[40], q[40], x;
    for (int i = 0; i < n; ++i) {
      w[i] = 0.01 + (double)rand() / RAND_MAX;
      a[i] = 1e5 * (0.5 + (double)rand() / RAND_MAX);
      b[i] = 400.0 * ((double)rand() / RAND_MAX - 0.5);
    }
    double total = 1.0 + 500.0 * (double)rand() / RAND_MAX;
    if (rsi_lanes_share(n, w, a, b, total, order, &x, q) != RS_OK) {
      CHECK(0);
      return;
    }
    double s = 0;
    for (int i = 0; i < n; ++i) {
      s += w[i] * q[i];
      if (q[i] < 0)
        CHECK(q[i] >= 0);
    }
    worst_sum = fmax(worst_sum, fabs(s - total) / total);
    double lo = -1.0, hi = 1.0;
    while (weighted(n, w, a, b, lo) > total)
      lo *= 2;
    while (weighted(n, w, a, b, hi) < total)
      hi *= 2;
    for (int it = 0; it < 200; ++it) {
      double mid = 0.5 * (lo + hi);
      if (weighted(n, w, a, b, mid) < total)
        lo = mid;
      else
        hi = mid;
    }
    worst_x = fmax(worst_x, fabs(x - 0.5 * (lo + hi)) / fmax(fabs(x), 1e-12));
  }
  printf("worst |sum - total| / total = %.17g, worst |x - bisection| / |x| = "
         "%.17g\n",
         worst_sum, worst_x);
  CHECK_LT(worst_sum, 1e-13);
  CHECK_LT(worst_x, 1e-9);
}

static void refuses_bad_input(void) {
  double w[2] = {1, 1}, a[2] = {1, 0}, b[2] = {0, 0}, x;
  int order[2];
  CHECK(rsi_lanes_share(2, w, a, b, 1.0, order, &x, NULL) == RS_ERR_INPUT);
  a[1] = 1;
  CHECK(rsi_lanes_share(2, w, a, b, 0.0, order, &x, NULL) == RS_ERR_INPUT);
  CHECK(rsi_lanes_share(0, w, a, b, 1.0, order, &x, NULL) == RS_ERR_INPUT);
  b[0] = NAN;
  CHECK(rsi_lanes_share(2, w, a, b, 1.0, order, &x, NULL) == RS_ERR_INPUT);
}

static const check_case cases[] = {{"uniform", uniform},
                                   {"slack_by_hand", slack_by_hand},
                                   {"against_bisection", against_bisection},
                                   {"refuses_bad_input", refuses_bad_input}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
