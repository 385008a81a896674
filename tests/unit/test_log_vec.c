/* rs_log_positive (src/util/log_vec.h), the branch-free ln x the roll engine forms ln g^2
 * with in one vectorised pass, against the C library's log():
 *   random_normals   a million x = m 2^e, m uniform in [1, 2), e uniform in [-1022, 1023]:
 *                    within 1.5 ulp of log() (measured 1.0; glibc's log is within ~0.52
 *                    ulp of the exact value)
 *   near_one         1 +- 2^-k (k = 1..52) and 1 +- i 2^-40: ln x is small there, and
 *                    the relative error is what counts: within 1.5 ulp of log()
 *   powers_and_ends  ln 1 = 0 exactly; 2^k (k = -1022..1023) within 1 ulp; the ends of
 *                    the range (DBL_MIN, DBL_MAX) and the neighbours of sqrt(1/2) and
 *                    sqrt(2), where the reduction's exponent changes, within 1.5 ulp
 *   loop_vectorised  an array of them in a plain loop gives what the calls one at a time
 *                    give, within 1 ulp (whether this loop vectorises depends on the
 *                    build's flags; the engine's own pass, compiled with roll_ode.c's,
 *                    is checked in test_roll_layer.lg2_range) */
#include <float.h>
#include <math.h>
#include <stdint.h>

#include "check.h"
#include "splitmix.h"
#include "util/log_vec.h"

/* |a - b| in units of the last place of b (b = log(x), nonzero) */
static double ulps(double a, double b)
{
  const double u = nextafter(fabs(b), INFINITY) - fabs(b);
  return fabs(a - b) / u;
}

static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static uint64_t rng(void) { return splitmix64(&rng_state); }

static void random_normals(void)
{
  double worst = 0.0, at = 1.0;
  for (long i = 0; i < 1000000; ++i) {
    const double m = 1.0 + (double)(rng() >> 11) * 0x1p-53;
    const int e = (int)(rng() % 2046) - 1022;
    const double x = ldexp(m, e);
    if (x == 1.0) continue; /* log(1) = 0: no ulp */
    const double d = ulps(rs_log_positive(x), log(x));
    if (d > worst) {
      worst = d;
      at = x;
    }
  }
  CHECK_LOG("worst ulp", worst);
  CHECK_LOG("at x", at);
  CHECK_LT(worst, 1.5);
}

static void near_one(void)
{
  double worst = 0.0;
  for (int k = 1; k <= 52; ++k) {
    const double h = ldexp(1.0, -k);
    worst = fmax(worst, ulps(rs_log_positive(1.0 + h), log(1.0 + h)));
    worst = fmax(worst, ulps(rs_log_positive(1.0 - h), log(1.0 - h)));
  }
  for (int i = 1; i <= 100000; ++i) {
    const double h = i * 0x1p-40;
    worst = fmax(worst, ulps(rs_log_positive(1.0 + h), log(1.0 + h)));
    worst = fmax(worst, ulps(rs_log_positive(1.0 - h), log(1.0 - h)));
  }
  CHECK_LOG("worst ulp", worst);
  CHECK_LT(worst, 1.5);
}

static void powers_and_ends(void)
{
  CHECK(rs_log_positive(1.0) == 0.0);
  double worst = 0.0;
  for (int k = -1022; k <= 1023; ++k)
    if (k != 0) worst = fmax(worst, ulps(rs_log_positive(ldexp(1.0, k)), log(ldexp(1.0, k))));
  CHECK_LOG("powers of two: worst ulp", worst);
  CHECK_LT(worst, 1.0 + 1e-12);
  const double s = sqrt(0.5), t = sqrt(2.0);
  const double xs[] = {DBL_MIN, nextafter(DBL_MIN, 1.0), DBL_MAX, nextafter(DBL_MAX, 0.0),
                       s, nextafter(s, 0.0), nextafter(s, 1.0), t, nextafter(t, 0.0),
                       nextafter(t, 2.0), 2.0 * s, 0.5 * t, 1e300 * s, 1e-300 * t};
  double ends = 0.0;
  for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i)
    ends = fmax(ends, ulps(rs_log_positive(xs[i]), log(xs[i])));
  CHECK_LOG("ends and reduction boundaries: worst ulp", ends);
  CHECK_LT(ends, 1.5);
}

static void loop_vectorised(void)
{
  enum { M = 4099 }; /* not a multiple of a vector's width: the loop's tail runs too */
  static double x[M], y[M];
  for (int i = 0; i < M; ++i) x[i] = exp(-700.0 + 1400.0 * i / (M - 1));
  for (int i = 0; i < M; ++i) y[i] = rs_log_positive(x[i]);
  double worst = 0.0;
  for (int i = 0; i < M; ++i) {
    volatile double xi = x[i]; /* one at a time: not the vectorised loop */
    const double b = rs_log_positive(xi);
    if (b != 0.0) worst = fmax(worst, ulps(y[i], b));
    else CHECK(y[i] == 0.0);
  }
  CHECK_LOG("worst ulp between the loop and single calls", worst);
  CHECK_LT(worst, 1.0 + 1e-12);
}

static const check_case cases[] = {{"random_normals", random_normals},
                                   {"near_one", near_one},
                                   {"powers_and_ends", powers_and_ends},
                                   {"loop_vectorised", loop_vectorised}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
