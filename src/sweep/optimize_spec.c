/* What an optimisation is asked: the figures it may name, constraints as text, and the
 * target pressure profile of the inverse problem (its file and its misfit). */
#include "sweep/optimize.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *opt_figure_name(int f)
{
  return f == OPT_MISFIT ? "misfit" : sweep_figures[f].name;
}

int opt_figure_index(const char *name)
{
  if (name && strcmp(name, "misfit") == 0) return OPT_MISFIT;
  return sweep_figure_find(name);
}

void opt_figure_list(char *buf, size_t size)
{
  sweep_figure_names(buf, size);
  size_t used = strlen(buf);
  if (used < size) snprintf(buf + used, size - used, ", misfit");
}

int opt_figure_recorded(const opt_problem *p, const opt_history *h, int f)
{
  if (f == OPT_MISFIT) return p->target != NULL;
  return (f >= 0 && f < SWEEP_N_WIND_FIGURES) || (f >= 0 && f < SWEEP_N_FIGURES && h->recorded[f]);
}

int opt_quantity_index(const char *name, int n_vars, const opt_var *vars)
{
  int f = opt_figure_index(name);
  if (f >= 0) return f;
  for (int k = 0; name && k < n_vars; ++k)
    if (strcmp(vars[k].key, name) == 0) return OPT_N_FIGURES + k;
  return -1;
}

/* A whole number string (surrounding spaces allowed), finite. */
static int parse_number(const char *s, double *v)
{
  char *end;
  errno = 0;
  *v = strtod(s, &end);
  if (end == s || errno == ERANGE || !isfinite(*v)) return -1;
  while (isspace((unsigned char)*end)) ++end;
  return *end ? -1 : 0;
}

int opt_constraint_parse(const char *text, int n_vars, const opt_var *vars, opt_constraint *c,
                         char *why, size_t size)
{
  memset(c, 0, sizeof *c);
  snprintf(c->text, sizeof c->text, "%s", text);
  const char *le = strstr(text, "<="), *ge = strstr(text, ">=");
  if (!le == !ge) {
    snprintf(why, size, "a constraint is FIGURE<=X or FIGURE>=X");
    return -1;
  }
  const char *op = le ? le : ge;
  char name[128];
  const char *a = text, *b = op;
  while (a < b && isspace((unsigned char)*a)) ++a;
  while (b > a && isspace((unsigned char)b[-1])) --b;
  if (b == a || (size_t)(b - a) >= sizeof name) {
    snprintf(why, size, "no figure before '%s'", le ? "<=" : ">=");
    return -1;
  }
  memcpy(name, a, (size_t)(b - a));
  name[b - a] = '\0';
  c->quantity = opt_quantity_index(name, n_vars, vars);
  if (c->quantity < 0) {
    snprintf(why, size, "unknown figure '%s'", name);
    return -1;
  }
  c->ge = ge != NULL;
  if (parse_number(op + 2, &c->bound) != 0) {
    snprintf(why, size, "'%s' is not a number", op + 2);
    return -1;
  }
  return 0;
}

void opt_target_free(opt_target *t)
{
  free(t->radius);
  free(t->pressure);
  memset(t, 0, sizeof *t);
}

/* "a, b" (comma, spaces or tab between): two finite numbers and nothing else. */
static int two_numbers(char *line, double *a, double *b)
{
  char *end;
  errno = 0;
  *a = strtod(line, &end);
  if (end == line || errno || !isfinite(*a)) return -1;
  char *p = end;
  while (*p == ' ' || *p == '\t') ++p;
  if (*p == ',' || *p == ';') ++p;
  *b = strtod(p, &end);
  if (end == p || errno || !isfinite(*b)) return -1;
  while (isspace((unsigned char)*end)) ++end;
  return *end ? -1 : 0;
}

int opt_target_read(const char *path, opt_target *t, char *err, size_t size)
{
  memset(t, 0, sizeof *t);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(err, size, "%s: cannot read: %s", path, strerror(errno));
    return -1;
  }
  char line[512];
  int lineno = 0, cap = 0, rc = 0, first = 1;
  while (fgets(line, sizeof line, f)) {
    ++lineno;
    size_t len = strlen(line);
    if (len == sizeof line - 1 && line[len - 1] != '\n') {
      snprintf(err, size, "%s:%d: line too long", path, lineno);
      rc = -1;
      break;
    }
    char *s = line;
    while (isspace((unsigned char)*s)) ++s;
    if (!*s || *s == '#') continue;
    double r, p;
    if (two_numbers(s, &r, &p) != 0) {
      if (first && t->n == 0 && (isalpha((unsigned char)*s) || *s == '"')) { /* a header */
        first = 0;
        continue;
      }
      snprintf(err, size, "%s:%d: expected 'radius,pressure' (m, Pa), got '%.*s'", path, lineno,
               (int)strcspn(s, "\r\n"), s);
      rc = -1;
      break;
    }
    first = 0;
    if (r <= 0) {
      snprintf(err, size, "%s:%d: the radius must be positive (got %g)", path, lineno, r);
      rc = -1;
      break;
    }
    if (t->n == cap) {
      cap = cap ? 2 * cap : 32;
      double *nr = realloc(t->radius, (size_t)cap * sizeof *nr);
      if (nr) t->radius = nr;
      double *np = realloc(t->pressure, (size_t)cap * sizeof *np);
      if (np) t->pressure = np;
      if (!nr || !np) {
        snprintf(err, size, "%s: out of memory", path);
        rc = -1;
        break;
      }
    }
    t->radius[t->n] = r;
    t->pressure[t->n] = p;
    ++t->n;
  }
  if (rc == 0 && ferror(f)) {
    snprintf(err, size, "%s: read error", path);
    rc = -1;
  }
  fclose(f);
  if (rc == 0 && t->n == 0) {
    snprintf(err, size, "%s:%d: no (radius, pressure) pairs", path, lineno);
    rc = -1;
  }
  if (rc != 0) opt_target_free(t);
  return rc;
}

/* The final pressure at radius r: linear between the points (core radius, core pressure),
 * (radius[i], -sigma_r[i]); the end values outside. The radii increase. */
static double pressure_at(const rs_reel_result *res, double r)
{
  int n = 0;
  const double *radius = rs_reel_result_radius(res, &n), *sigma_r = rs_reel_result_sigma_r(res, NULL);
  double r0 = rs_reel_result_core_radius(res), p0 = rs_reel_result_core_pressure(res);
  if (r <= r0) return p0;
  if (r >= radius[n - 1]) return -sigma_r[n - 1];
  int lo = -1, hi = n - 1; /* radius[lo] < r <= radius[hi]; lo = -1 is the core */
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (radius[mid] < r) lo = mid;
    else hi = mid;
  }
  double ra = lo < 0 ? r0 : radius[lo], pa = lo < 0 ? p0 : -sigma_r[lo];
  double rb = radius[hi], pb = -sigma_r[hi];
  return rb > ra ? pa + (pb - pa) * (r - ra) / (rb - ra) : pb;
}

double opt_target_misfit(const opt_target *t, const rs_reel_result *res)
{
  if (!t || t->n == 0 || rs_reel_result_n_layers(res) < 1) return NAN;
  double sum = 0;
  for (int i = 0; i < t->n; ++i) {
    double d = pressure_at(res, t->radius[i]) - t->pressure[i];
    sum += d * d;
  }
  return sqrt(sum / t->n);
}
