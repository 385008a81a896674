/* The Pareto front of (time, error) points: see include/reelsim/study.h.
 *
 * A point is dominated when another is no worse in both coordinates and better in one.
 * The study has tens of runs, so the plain O(n^2) pairwise test is used: it needs no
 * memory and its correctness is obvious, ties and duplicates included. */
#include <math.h>

#include "reelsim/study.h"

/* Does a dominate b? (both finite) */
static int dominates(double ta, double ea, double tb, double eb)
{
  return ta <= tb && ea <= eb && (ta < tb || ea < eb);
}

int rs_pareto_front(int n, const double *time, const double *error, int *on_front)
{
  int count = 0;
  for (int i = 0; i < n; ++i) {
    int front = isfinite(time[i]) && isfinite(error[i]);
    for (int j = 0; front && j < n; ++j)
      if (j != i && isfinite(time[j]) && isfinite(error[j]) &&
          dominates(time[j], error[j], time[i], error[i]))
        front = 0;
    on_front[i] = front;
    count += front;
  }
  return count;
}

int rs_pareto_within(int n, const double *time, const double *error, const int *on_front,
                     int i, double time_rtol, double error_rtol)
{
  if (i < 0 || i >= n || !isfinite(time[i]) || !isfinite(error[i])) return 0;
  if (on_front[i]) return 1;
  /* dominated; is it dominated only by points within the noise? */
  const double t = time[i] * (1.0 - time_rtol), e = error[i] * (1.0 - error_rtol);
  for (int j = 0; j < n; ++j)
    if (j != i && on_front[j] && dominates(time[j], error[j], t, e)) return 0;
  return 1;
}
