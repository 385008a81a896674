/* ln x without branches or calls, so that a loop over an array of them vectorises.
 *
 * x = 2^k m with m in [sqrt(1/2), sqrt(2)) (the exponent read from the bits), and
 *     ln m = 2 atanh(s) = 2 s (1 + s^2/3 + s^4/5 + ...),   s = (m - 1)/(m + 1), |s| < 0.1716,
 * summed to s^23 (the first term left out, 2 s^25/25, is below 1e-19 of ln m), so
 *     ln x = k ln 2 + f - s (f - R),   f = m - 1,  R = 2 s^2 (1/3 + s^2/5 + ...) ... written
 * as f - (f^2/2 - s (f^2/2 + R)) to keep the large part f exact (the scheme of fdlibm's
 * e_log.c, here with a plain series instead of its minimax polynomial). k ln 2 is split
 * into a high part exact for |k| < 2^11 and a low part. Within ~1 ulp of the correctly
 * rounded value for every positive normal x (tests/unit/test_log_vec.c measures it against
 * libm); not for 0, subnormals, infinities or NaN (the callers' moduli are positive,
 * finite and far from the subnormal range). Private to the library. */
#ifndef REELSIM_UTIL_LOG_VEC_H
#define REELSIM_UTIL_LOG_VEC_H

#include <stdint.h>
#include <string.h>

static inline double rs_log_positive(double x)
{
  /* the bits of sqrt(1/2): x / 2^k lands in [sqrt(1/2), sqrt(2)) */
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  const uint64_t top = (u - UINT64_C(0x3fe6a09e667f3bcd)) >> 52; /* k mod 4096 */
  const uint64_t k = (top ^ 0x800) - 0x800;                       /* k, two's complement */
  const uint64_t um = u - (k << 52);                               /* the bits of m */
  double m;
  memcpy(&m, &um, sizeof m);
  /* k as a double without an integer conversion (none that vectorises before AVX-512):
   * the bits of 1.5 2^52 + k, less 1.5 2^52 */
  const uint64_t kb = UINT64_C(0x4338000000000000) + k;
  double kd;
  memcpy(&kd, &kb, sizeof kd);
  kd -= 6755399441055744.0;
  const double f = m - 1.0, s = f / (2.0 + f), z = s * s;
  const double R = z * (2.0 / 3 + z * (2.0 / 5 + z * (2.0 / 7 + z * (2.0 / 9 + z * (2.0 / 11 +
                   z * (2.0 / 13 + z * (2.0 / 15 + z * (2.0 / 17 + z * (2.0 / 19 + z * (2.0 / 21 +
                   z * (2.0 / 23)))))))))));
  const double hf2 = 0.5 * f * f;
  const double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  return kd * ln2_hi - ((hf2 - (s * (hf2 + R) + kd * ln2_lo)) - f);
}

#endif
