/* The shortest decimal form of a double that reads back as the same double (base layer,
 * internal): "0.07622" where %.17g prints "0.07622000000000001". For CSV files, which a
 * person reads as well as a program. */
#ifndef RS_UTIL_SHORTEST_H
#define RS_UTIL_SHORTEST_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { RS_SHORTEST_SIZE = 32 };

/* v as %.Ng with the least N (1 .. 17) that strtod returns to v exactly, widened so that
 * a whole number below 1e15 keeps its digits ("150", not "1.5e+02"); NaN and the
 * infinities as printf writes them. Returns buf. */
static inline const char *rs_shortest(char buf[RS_SHORTEST_SIZE], double v)
{
  int prec = 1;
  for (; prec <= 17; ++prec) {
    snprintf(buf, RS_SHORTEST_SIZE, "%.*g", prec, v);
    if (prec == 17 || v != v || strtod(buf, NULL) == v) break;
  }
  const char *e = strchr(buf, 'e');
  if (e) {
    int exp10 = atoi(e + 1);
    if (exp10 >= prec && exp10 < 15) snprintf(buf, RS_SHORTEST_SIZE, "%.*g", exp10 + 1, v);
  }
  return buf;
}

#endif
