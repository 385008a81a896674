/* Locating a value in a sorted table (internal). */
#ifndef RS_UTIL_BRACKET_H
#define RS_UTIL_BRACKET_H

/* Index lo with xs[lo] <= x < xs[lo + 1], for xs strictly increasing, n >= 2 and
 * xs[0] < x < xs[n - 1] (callers hold the end values outside the table themselves). */
static inline int rs_bracket(const double *xs, int n, double x)
{
  int lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (xs[mid] <= x) lo = mid; else hi = mid;
  }
  return lo;
}

#endif
