/* The one unknown shared by the lanes: sum_i w_i max(0, a_i x + b_i) = total.
 */
#include "reel/lanes_share.h"

#include <math.h>
#include <stdlib.h>

#include "reelsim/status.h"
#include "util/error.h"

/* Insertion sort of the lanes by breakpoint z_i = -b_i / a_i, increasing (n <=
 * 256 lanes; ties keep the lanes' order, so the result does not depend on the
 * sort's stability). */
static void sort_by_breakpoint(int n, const double *a, const double *b,
                               int *order) {
  for (int i = 0; i < n; ++i) {
    int j = i;
    double zi = -b[i] / a[i];
    while (j > 0 && -b[order[j - 1]] / a[order[j - 1]] > zi) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = i;
  }
}

static rs_status check_inputs(int n, const double *w, const double *a,
                              const double *b, double total) {
  if (n < 1 || !w || !a || !b)
    return RS_ERROR(RS_ERR_INPUT, "lanes: %d lanes given", n);
  if (!(total > 0) || !isfinite(total))
    return RS_ERROR(RS_ERR_INPUT,
                    "lanes: the total to share is %g (must be positive)",
                    total);
  for (int i = 0; i < n; ++i)
    if (!(w[i] > 0) || !(a[i] > 0) || !isfinite(w[i]) || !isfinite(a[i]) ||
        !isfinite(b[i]))
      return RS_ERROR(RS_ERR_INPUT,
                      "lanes: lane %d has width %g, stiffness %g, offset %g", i,
                      w[i], a[i], b[i]);
  return RS_OK;
}

/* Walks the breakpoints upwards. On the segment above the j-th breakpoint the
 * active lanes are order[0..j] and the left side is A x + B with A = sum w a, B
 * = sum w b over them; the root lies on the first segment whose upper end
 * already reaches the total. */
rs_status rsi_lanes_share(int n, const double *w, const double *a,
                          const double *b, double total, int *order, double *x,
                          double *q) {
  rs_status st = check_inputs(n, w, a, b, total);
  if (st != RS_OK)
    return st;
  sort_by_breakpoint(n, a, b, order);
  double A = 0, B = 0, root = 0;
  for (int j = 0; j < n; ++j) {
    int i = order[j];
    A += w[i] * a[i];
    B += w[i] * b[i];
    if (j + 1 < n) {
      int up = order[j + 1];
      double z_up = -b[up] / a[up];
      if (A * z_up + B < total)
        continue;
    }
    root = (total - B) / A;
    break;
  }
  if (!isfinite(root))
    return RS_ERROR(RS_ERR_SOLVER,
                    "lanes: the shared unknown is not finite (%g)", root);
  *x = root;
  if (q)
    for (int i = 0; i < n; ++i)
      q[i] = fmax(0.0, a[i] * root + b[i]);
  return RS_OK;
}
