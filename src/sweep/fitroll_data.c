/* reelsim fit roll's data: the measured points in, the model's matching quantity out
 * (sweep/fitroll.h). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sweep/fitroll.h"

static const char *x_names[] = {"length", "radius"};
static const char *y_names[] = {"diameter", "pressure", "wound_in_tension"};
const char *fr_x_name(fr_x x) { return x_names[x]; }
const char *fr_y_name(fr_y y) { return y_names[y]; }

void fr_data_free(fr_data *d)
{
  free(d->x);
  free(d->y);
  d->x = d->y = NULL;
  d->n = 0;
}

static int name_index(const char *s, size_t len, const char *const *names, int n)
{
  for (int i = 0; i < n; ++i)
    if (strlen(names[i]) == len && strncmp(s, names[i], len) == 0) return i;
  return -1;
}

/* "a,b" -> the two names' indices */
static int read_header(char *line, fr_data *d)
{
  char *comma = strchr(line, ',');
  if (!comma) return -1;
  char *a = line, *b = comma + 1;
  while (*a == ' ') ++a;
  size_t la = (size_t)(comma - a);
  while (la && a[la - 1] == ' ') --la;
  while (*b == ' ') ++b;
  size_t lb = strcspn(b, " \r\n,");
  int xi = name_index(a, la, x_names, 2), yi = name_index(b, lb, y_names, 3);
  if (xi < 0 || yi < 0) return -1;
  d->xkind = (fr_x)xi;
  d->ykind = (fr_y)yi;
  return 0;
}

int fr_data_read(const char *path, fr_data *d, char *err, size_t size)
{
  memset(d, 0, sizeof *d);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(err, size, "%s: cannot open the measured data: %s", path, strerror(errno));
    return -1;
  }
  char line[4096];
  int lineno = 0, header = 0, cap = 0, bad = 0;
  while (!bad && fgets(line, sizeof line, f)) {
    ++lineno;
    const char *s = line + strspn(line, " \t");
    if (*s == '#' || *s == '\n' || *s == '\r' || *s == 0) continue;
    if (!header) {
      if (read_header(line, d) != 0) {
        snprintf(err, size, "%s:%d: the header must name two columns: `length` or `radius`, then "
                 "`diameter`, `pressure` or `wound_in_tension`", path, lineno);
        bad = 1;
      }
      header = 1;
      continue;
    }
    char *e1, *e2;
    errno = 0;
    double x = strtod(s, &e1), y = NAN;
    if (e1 != s && *e1 == ',') y = strtod(e1 + 1, &e2);
    if (e1 == s || *e1 != ',' || e2 == e1 + 1 || errno || !isfinite(x) || !isfinite(y) || x < 0) {
      snprintf(err, size, "%s:%d: two numbers, %s and %s, >= 0 and finite", path, lineno,
               x_names[d->xkind], y_names[d->ykind]);
      bad = 1;
      break;
    }
    if (d->n == cap) {
      cap = cap ? 2 * cap : 64;
      double *a = realloc(d->x, (size_t)cap * sizeof *a), *b = a ? realloc(d->y, (size_t)cap * sizeof *b) : NULL;
      if (a) d->x = a;
      if (!b) {
        snprintf(err, size, "%s: out of memory", path);
        bad = 1;
        break;
      }
      d->y = b;
    }
    d->x[d->n] = x;
    d->y[d->n++] = y;
  }
  fclose(f);
  if (!bad && d->n == 0) {
    snprintf(err, size, "%s: no measured points", path);
    bad = 1;
  }
  if (bad) fr_data_free(d);
  return bad ? -1 : 0;
}

/* y at x on the piecewise-linear curve (xs, ys), xs increasing; end values held outside */
static double interp(const double *xs, const double *ys, int n, double x)
{
  if (x <= xs[0]) return ys[0];
  if (x >= xs[n - 1]) return ys[n - 1];
  int lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (xs[mid] <= x) lo = mid;
    else hi = mid;
  }
  const double w = (x - xs[lo]) / (xs[hi] - xs[lo]);
  return ys[lo] + w * (ys[hi] - ys[lo]);
}

int fr_model(const fr_data *d, const rs_reel_result *res, double *out)
{
  const int n = rs_reel_result_n_layers(res);
  const double *radius = rs_reel_result_radius(res, NULL), *sigma_r = rs_reel_result_sigma_r(res, NULL);
  const double *deformed = rs_reel_result_deformed_radius(res, NULL);
  const double *wound = rs_reel_result_wound_radius(res, NULL);
  const double *wit = rs_reel_result_wound_in_tension(res, NULL);
  if (n < 1 || !deformed || !wound || !wit) return -1;
  double *xs = malloc((size_t)n * sizeof *xs), *ys = malloc((size_t)n * sizeof *ys);
  if (!xs || !ys) {
    free(xs);
    free(ys);
    return -1;
  }
  double L = 0.0, inner = rs_reel_result_core_radius(res);
  for (int j = 0; j < n; ++j) {
    L += 3.14159265358979323846 * (inner + radius[j]);
    inner = radius[j];
    xs[j] = d->xkind == FR_LENGTH ? L : deformed[j];
    ys[j] = d->ykind == FR_PRESSURE ? 0.0 - sigma_r[j]
          : d->ykind == FR_WIT ? wit[j]
          : 2.0 * (d->xkind == FR_LENGTH ? wound[j] : deformed[j]);
  }
  for (int i = 0; i < d->n; ++i) out[i] = interp(xs, ys, n, d->x[i]);
  free(xs);
  free(ys);
  return 0;
}
