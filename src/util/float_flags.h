/* Range checks of doubles as 64-bit words, for loops over arrays that must vectorise on
 * every x86-64, not only with AVX2: a loop that ORs the comparisons of its doubles into a
 * flag (the check of a pass's results, its slow path taken only when the flag is raised)
 * needs the comparison's mask as a 64-bit integer, which GCC forms in vector registers
 * with AVX2 but not with the baseline's SSE2 (no 64-bit integer compare there), and then
 * leaves the whole loop scalar. These read the bits instead: among the doubles of one
 * sign the order of the bit patterns is the order of the values (+0 lowest, then the
 * subnormals, the normals, +inf, and the NaNs above it), so "lo <= bits(x) < hi" is one
 * unsigned comparison, here written with a subtraction, an addition and an OR, which SSE2
 * vectorises. The flags are OR-ed over a loop; its top bit says whether any x was outside.
 * Private to the library. */
#ifndef REELSIM_UTIL_FLOAT_FLAGS_H
#define REELSIM_UTIL_FLOAT_FLAGS_H

#include <stdint.h>
#include <string.h>

/* the bits of x */
static inline uint64_t rs_double_bits(double x)
{
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  return u;
}

/* A word whose top bit is set unless lo <= u < hi (lo < hi, hi - lo <= 2^63): v = u - lo
 * (unsigned, wrapping) is below hi - lo exactly when u is inside; then v < 2^63 and
 * v + 2^63 - (hi - lo) < 2^63 too, and otherwise one of the two has its top bit set (the
 * second as long as v < 2^63 + hi - lo, beyond which v has it). */
static inline uint64_t rs_flag_word_outside(uint64_t u, uint64_t lo, uint64_t hi)
{
  const uint64_t v = u - lo;
  return v | (v + ((UINT64_C(1) << 63) - (hi - lo)));
}

/* the bits of |x| (the sign bit cleared) */
static inline uint64_t rs_abs_bits(double x) { return rs_double_bits(x) & ~(UINT64_C(1) << 63); }

/* raised unless x > 0 and x < +inf (the subnormals count as positive): from the least
 * positive subnormal's bits to +inf's */
static inline uint64_t rs_flag_not_positive_finite(double x)
{
  return rs_flag_word_outside(rs_double_bits(x), 1, UINT64_C(0x7ff0000000000000));
}

/* raised unless DBL_MIN <= x <= DBL_MAX (positive, normal, finite) */
static inline uint64_t rs_flag_not_positive_normal(double x)
{
  return rs_flag_word_outside(rs_double_bits(x), UINT64_C(0x0010000000000000),
                              UINT64_C(0x7ff0000000000000));
}

/* raised unless |x| < limit (a NaN raises it), limit_bits = rs_double_bits(limit) of a
 * positive limit */
static inline uint64_t rs_flag_not_below(double x, uint64_t limit_bits)
{
  return rs_flag_word_outside(rs_abs_bits(x), 0, limit_bits);
}

/* raised when +0 <= x <= +inf (x >= 0 as a comparison says it, but for -0, which it
 * also counts: callers whose x cannot be -0), not for a NaN */
static inline uint64_t rs_flag_not_below_zero(double x)
{
  return ~rs_flag_word_outside(rs_double_bits(x), 0, UINT64_C(0x7ff0000000000001));
}

/* whether a flag OR-ed over a loop was raised by any of its doubles */
static inline int rs_flag_raised(uint64_t flags) { return (int)(flags >> 63); }

#endif
