/* Winding recipes over roll radius r in [r0, r1] (r0 core, r1 final radius). */
#include <math.h>

#include "util/bracket.h"

#include "reelsim/recipe.h"
#include "util/error.h"

/* constant   start
 * linear     start + (end - start) (r - r0) / (r1 - r0)
 * hyperbolic start (1 - k (1 - r0/r))            (the usual "taper" of winding practice)
 * torque     start r0 / r                        (constant drive torque M = start r0)
 * table      piecewise linear through (r_i, v_i), end values held outside.
 * Every law holds its end values outside [r0, r1]: the layer count is rounded, so the last
 * layer can sit up to half a caliper beyond the final radius, and a taper that ends at 0
 * must not turn negative there. A linear taper is a convex blend of its ends, so it is
 * exactly `end` at r1 and never below min(start, end) in between (no rounding below 0). */
double rs_recipe_eval(const rs_recipe *rc, double r)
{
  int ranged = rc->r1 > rc->r0;
  if (ranged && rc->law != RS_RECIPE_TABLE) {
    if (r > rc->r1) r = rc->r1;
    if (r < rc->r0) r = rc->r0;
  }
  switch (rc->law) {
  case RS_RECIPE_CONSTANT: return rc->start;
  case RS_RECIPE_LINEAR: {
    if (!ranged) return rc->start;
    double s = (r - rc->r0) / (rc->r1 - rc->r0);
    return (1.0 - s) * rc->start + s * rc->end;
  }
  case RS_RECIPE_HYPERBOLIC:
    if (ranged && r == rc->r1 && !isnan(rc->end)) return rc->end;
    return rc->start * (1.0 - rc->k * (1.0 - rc->r0 / r));
  case RS_RECIPE_TORQUE: return rc->start * rc->r0 / r;
  case RS_RECIPE_TABLE: {
    int n = rc->n_points;
    if (n == 1 || r <= rc->r[0]) return rc->value[0];
    if (r >= rc->r[n - 1]) return rc->value[n - 1];
    int lo = rs_bracket(rc->r, n, r), hi = lo + 1;
    double s = (r - rc->r[lo]) / (rc->r[hi] - rc->r[lo]);
    return rc->value[lo] + s * (rc->value[hi] - rc->value[lo]);
  }
  }
  return NAN;
}

double rs_recipe_min(const rs_recipe *rc)
{
  if (rc->law == RS_RECIPE_TABLE) {
    double m = INFINITY;
    for (int i = 0; i < rc->n_points; ++i) m = fmin(m, rc->value[i]);
    return m;
  }
  /* every other law is monotone in r: its extremes sit at the ends */
  return fmin(rs_recipe_eval(rc, rc->r0), rs_recipe_eval(rc, rc->r1));
}

rs_status rs_recipe_prepare(rs_recipe *rc, double r0, double r1)
{
  rc->r0 = r0;
  rc->r1 = r1;
  switch (rc->law) {
  case RS_RECIPE_CONSTANT:
  case RS_RECIPE_TORQUE:
  case RS_RECIPE_LINEAR:
    if (!isfinite(rc->start) || (rc->law == RS_RECIPE_LINEAR && !isfinite(rc->end)))
      return RS_ERROR(RS_ERR_INPUT, "%s recipe needs finite start%s", rs_recipe_law_name(rc->law),
                      rc->law == RS_RECIPE_LINEAR ? " and end" : "");
    return RS_OK;
  case RS_RECIPE_HYPERBOLIC:
    /* given the end value, k follows from end = start (1 - k (1 - r0/r1)) */
    if (isnan(rc->k)) {
      if (!isfinite(rc->end) || rc->start == 0.0 || r1 <= r0)
        return RS_ERROR(RS_ERR_INPUT, "hyperbolic recipe needs start and either end or k");
      rc->k = (1.0 - rc->end / rc->start) / (1.0 - r0 / r1);
      return RS_OK; /* the given end stays exact (eval returns it at r1) */
    }
    rc->end = NAN;
    rc->end = rs_recipe_eval(rc, r1);
    return RS_OK;
  case RS_RECIPE_TABLE:
    if (rc->n_points < 1 || rc->n_points > RS_TABLE_MAX)
      return RS_ERROR(RS_ERR_INPUT, "table recipe needs 1 to %d [r, value] points (got %d)",
                      RS_TABLE_MAX, rc->n_points);
    for (int i = 1; i < rc->n_points; ++i)
      if (!(rc->r[i] > rc->r[i - 1]))
        return RS_ERROR(RS_ERR_INPUT,
                        "table must be sorted by strictly increasing radius "
                        "(table[%d] r = %g after %g)",
                        i, rc->r[i], rc->r[i - 1]);
    return RS_OK;
  }
  return RS_ERROR(RS_ERR_INPUT, "unknown recipe law %d", (int)rc->law);
}

const char *rs_recipe_law_name(rs_recipe_kind law)
{
  switch (law) {
  case RS_RECIPE_CONSTANT: return "constant";
  case RS_RECIPE_LINEAR: return "linear";
  case RS_RECIPE_HYPERBOLIC: return "hyperbolic";
  case RS_RECIPE_TORQUE: return "torque";
  case RS_RECIPE_TABLE: return "table";
  }
  return "unknown";
}
