/* The range checks of src/util/float_flags.h, which the engine's and the stack law's
 * vectorised passes OR into their flags, against the comparisons they stand for:
 *   special_values   0, -0, the subnormals' ends, DBL_MIN, DBL_MAX, the infinities, NaNs
 *                    of both signs and payloads, the limits and their neighbours: every
 *                    flag's top bit equals the comparison's truth, value by value
 *   random_bits      a million random 64-bit patterns read as doubles (every class:
 *                    normals, subnormals, NaNs, both signs), and a million doubles within
 *                    a few ulps of the limits: the same
 *   or_over_a_loop   flags OR-ed over an array raise exactly when one element is outside
 *                    (one bad element placed at each position of a 37-element array) */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "splitmix.h"
#include "util/float_flags.h"

static uint64_t rng_state = 0x2545f4914f6cdd1du;
static uint64_t rng(void) { return splitmix64(&rng_state); }

static double from_bits(uint64_t u)
{
  double x;
  memcpy(&x, &u, sizeof x);
  return x;
}

/* the limits the callers use (roll_increment.c, roll_profile.c) */
static const double limits[] = {0.0299, 0.03};

/* the number of flags whose top bit disagrees with its comparison at x */
static int mismatches(double x)
{
  int bad = 0;
  bad += rs_flag_raised(rs_flag_not_positive_finite(x)) != !(x > 0.0 && x < INFINITY);
  bad += rs_flag_raised(rs_flag_not_positive_normal(x)) != !(x >= DBL_MIN && x <= DBL_MAX);
  for (size_t i = 0; i < sizeof limits / sizeof limits[0]; ++i)
    bad += rs_flag_raised(rs_flag_not_below(x, rs_double_bits(limits[i]))) !=
           !(fabs(x) < limits[i]);
  if (!(x == 0.0 && signbit(x))) /* the one value where bits and x >= 0 part: -0 */
    bad += rs_flag_raised(rs_flag_not_below_zero(x)) != (x >= 0.0);
  return bad;
}

static void special_values(void)
{
  const double xs[] = {0.0, -0.0, 0x1p-1074, -0x1p-1074, nextafter(DBL_MIN, 0.0),
                       -nextafter(DBL_MIN, 0.0), DBL_MIN, -DBL_MIN,
                       nextafter(DBL_MIN, 1.0), 1.0, -1.0, DBL_MAX, -DBL_MAX,
                       nextafter(DBL_MAX, 0.0), INFINITY, -INFINITY, NAN, -NAN,
                       from_bits(UINT64_C(0x7ff0000000000001)), from_bits(UINT64_C(0xfff0000000000001)),
                       from_bits(UINT64_C(0x7fffffffffffffff)), from_bits(UINT64_C(0xffffffffffffffff)),
                       0.0299, -0.0299, nextafter(0.0299, 0.0), nextafter(0.0299, 1.0),
                       -nextafter(0.0299, 0.0), 0.03, -0.03, nextafter(0.03, 0.0),
                       nextafter(0.03, 1.0), -nextafter(0.03, 1.0)};
  int bad = 0;
  for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i) {
    const int m = mismatches(xs[i]);
    if (m) CHECK_LOG("mismatch at", xs[i]);
    bad += m;
  }
  CHECK_LOG("values", (double)(sizeof xs / sizeof xs[0]));
  CHECK(bad == 0);
  /* -0: not below zero for the comparison, raised by the bits (documented) */
  CHECK(rs_flag_raised(rs_flag_not_below_zero(-0.0)) == 0);
  CHECK(rs_flag_raised(rs_flag_not_below_zero(0.0)) == 1);
}

static void random_bits(void)
{
  int bad = 0;
  for (long i = 0; i < 1000000; ++i) bad += mismatches(from_bits(rng()));
  CHECK_LOG("mismatches, random patterns", bad);
  CHECK(bad == 0);
  int near = 0;
  const double anchors[] = {DBL_MIN, DBL_MAX, 0x1p-1074, 0.0299, 0.03};
  for (long i = 0; i < 1000000; ++i) {
    const double a = anchors[rng() % 5];
    const int64_t step = (int64_t)(rng() % 9) - 4;
    double x = from_bits(rs_double_bits(a) + (uint64_t)step);
    if (rng() & 1) x = -x;
    near += mismatches(x);
  }
  CHECK_LOG("mismatches, within 4 ulps of the limits", near);
  CHECK(near == 0);
}

static void or_over_a_loop(void)
{
  enum { M = 37 };
  double x[M];
  int wrong = 0;
  for (int at = -1; at < M; ++at) {
    for (int i = 0; i < M; ++i) x[i] = 1.0 + i;
    if (at >= 0) x[at] = at % 3 == 0 ? 0.0 : at % 3 == 1 ? INFINITY : NAN;
    uint64_t f = 0;
    for (int i = 0; i < M; ++i) f |= rs_flag_not_positive_finite(x[i]);
    wrong += rs_flag_raised(f) != (at >= 0);
  }
  CHECK_LOG("wrong flags", wrong);
  CHECK(wrong == 0);
}

static const check_case cases[] = {{"special_values", special_values},
                                   {"random_bits", random_bits},
                                   {"or_over_a_loop", or_over_a_loop}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
