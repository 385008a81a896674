/* A stack test's file in (its loading branch), the fitted model and its picture out. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/gnuplot.h"
#include "reelsim/fit.h"
#include "util/atomic_file.h"
#include "util/error.h"

/* the header's columns: which index holds strain, pressure, cycle (-1: absent) */
static rs_status read_header(const char *path, int lineno, char *line, int *ci)
{
  ci[0] = ci[1] = ci[2] = -1;
  int k = 0;
  for (char *save = NULL, *tok = strtok_r(line, ",\r\n", &save); tok;
       tok = strtok_r(NULL, ",\r\n", &save), ++k) {
    while (*tok == ' ' || *tok == '\t') ++tok;
    size_t len = strlen(tok);
    while (len && (tok[len - 1] == ' ' || tok[len - 1] == '\t')) tok[--len] = 0;
    const char *names[] = {"strain", "pressure", "cycle"};
    for (int c = 0; c < 3; ++c)
      if (strcmp(tok, names[c]) == 0) ci[c] = k;
  }
  if (ci[0] < 0 || ci[1] < 0)
    return RS_ERROR(RS_ERR_INPUT,
                    "%s:%d: the header must name the columns `strain` and `pressure` (Pa), "
                    "optionally `cycle`", path, lineno);
  return RS_OK;
}

typedef struct rows {
  int n, cap;
  double *P, *eps, *cyc;
} rows;

static rs_status rows_push(rows *r, double P, double e, double c)
{
  if (r->n == r->cap) {
    int cap = r->cap ? 2 * r->cap : 64;
    double *a = realloc(r->P, cap * sizeof(double)), *b = a ? realloc(r->eps, cap * sizeof(double)) : NULL;
    if (a) r->P = a;
    if (b) r->eps = b;
    double *d = b ? realloc(r->cyc, cap * sizeof(double)) : NULL;
    if (!d) return RS_ERROR(RS_ERR_MEMORY, "stack test: out of memory (%d rows)", cap);
    r->cyc = d;
    r->cap = cap;
  }
  r->P[r->n] = P;
  r->eps[r->n] = e;
  r->cyc[r->n++] = c;
  return RS_OK;
}

static rs_status read_rows(const char *path, FILE *f, int lineno, const int *ci, rows *r)
{
  char line[4096];
  while (fgets(line, sizeof line, f)) {
    ++lineno;
    char *s = line;
    while (*s == ' ' || *s == '\t') ++s;
    if (*s == '#' || *s == '\n' || *s == '\r' || *s == 0) continue;
    double v[3] = {NAN, NAN, 0.0};
    int k = 0;
    for (char *p = s;; ++k) {
      char *end;
      errno = 0;
      const double x = strtod(p, &end);
      for (int c = 0; c < 3; ++c)
        if (ci[c] == k) {
          if (end == p || errno == ERANGE || !isfinite(x))
            return RS_ERROR(RS_ERR_INPUT, "%s:%d: column %d is not a number", path, lineno, k + 1);
          v[c] = x;
        }
      p = strchr(end, ',');
      if (!p) break;
      ++p;
    }
    if (isnan(v[0]) || isnan(v[1]))
      return RS_ERROR(RS_ERR_INPUT, "%s:%d: the row has fewer columns than the header", path, lineno);
    if (v[0] < 0.0 || v[1] < 0.0)
      return RS_ERROR(RS_ERR_INPUT,
                      "%s:%d: strain %g and pressure %g Pa must be >= 0 (compression positive)",
                      path, lineno, v[0], v[1]);
    rs_status st = rows_push(r, v[1], v[0], v[2]);
    if (st) return st;
  }
  return RS_OK;
}

rs_status rs_fit_stack_read(const char *path, int cycle, double **P, double **eps, int *n)
{
  *P = *eps = NULL;
  *n = 0;
  FILE *f = fopen(path, "r");
  if (!f) return RS_ERROR(RS_ERR_INPUT, "%s: cannot open the stack test: %s", path, strerror(errno));
  char line[4096];
  int ci[3];
  rows r = {0};
  int lineno = 0, got = 0;
  while (!got && fgets(line, sizeof line, f)) { /* the header: the first line not a comment */
    ++lineno;
    got = line[0] != '#' && line[strspn(line, " \t\r\n")] != 0;
  }
  rs_status st = got ? read_header(path, lineno, line, ci)
                     : RS_ERROR(RS_ERR_INPUT, "%s: the file is empty", path);
  if (!st) st = read_rows(path, f, lineno, ci, &r);
  fclose(f);
  if (!st && r.n == 0) st = RS_ERROR(RS_ERR_INPUT, "%s: no data rows", path);
  int first = 0, last = r.n; /* the cycle's rows [first, last) */
  if (!st && ci[2] >= 0) {
    double want = cycle >= 0 ? cycle : r.cyc[r.n - 1];
    while (first < r.n && r.cyc[first] != want) ++first;
    if (first == r.n)
      st = RS_ERROR(RS_ERR_INPUT, "%s: no rows of cycle %d (--cycle)", path, cycle);
    last = first;
    while (last < r.n && r.cyc[last] == want) ++last;
  } else if (!st && cycle >= 0)
    st = RS_ERROR(RS_ERR_INPUT, "%s: --cycle %d given but the file has no `cycle` column", path, cycle);
  if (!st) { /* the loading branch: up to the cycle's peak pressure */
    int peak = first;
    for (int i = first; i < last; ++i)
      if (r.P[i] > r.P[peak]) peak = i;
    *n = peak - first + 1;
    *P = malloc((size_t)*n * sizeof(double));
    *eps = malloc((size_t)*n * sizeof(double));
    if (!*P || !*eps) {
      free(*P);
      free(*eps);
      *P = *eps = NULL;
      *n = 0;
      st = RS_ERROR(RS_ERR_MEMORY, "stack test: out of memory");
    } else {
      memcpy(*P, r.P + first, (size_t)*n * sizeof(double));
      memcpy(*eps, r.eps + first, (size_t)*n * sizeof(double));
    }
  }
  free(r.P);
  free(r.eps);
  free(r.cyc);
  return st;
}

/* the `radial:` line of the fitted law */
static int radial_yaml(char *buf, size_t sz, const rs_radial_law *L)
{
  int k = 0;
  switch (L->law) {
  case RS_RADIAL_LINEAR: return snprintf(buf, sz, "radial: {law: linear, E_r: %.10g}\n", L->E_r);
  case RS_RADIAL_PFEIFFER:
    return snprintf(buf, sz, "radial: {law: pfeiffer, K1: %.10g, K2: %.10g}\n", L->K1, L->K2);
  case RS_RADIAL_HAKIEL:
    k = snprintf(buf, sz, "radial: {law: hakiel, C: [");
    for (int i = 0; i < L->n_coef; ++i)
      k += snprintf(buf + k, sz - (size_t)k, "%s%.10g", i ? ", " : "", L->C[i]);
    return k + snprintf(buf + k, sz - (size_t)k, "]}\n");
  case RS_RADIAL_TABLE:
    k = snprintf(buf, sz, "radial: {law: table, points: [");
    for (int i = 0; i < L->n_points; ++i)
      k += snprintf(buf + k, sz - (size_t)k, "%s[%.10g, %.10g]", i ? ", " : "", L->P[i], L->E[i]);
    return k + snprintf(buf + k, sz - (size_t)k, "]}\n");
  }
  return 0;
}

rs_status rs_fit_stack_write_model(const char *path, const rs_fit_stack_result *fit,
                                   const char *source, const char *base_text)
{
  size_t cap = 16384 + (base_text ? strlen(base_text) : 0);
  char *buf = malloc(cap);
  if (!buf) return RS_ERROR(RS_ERR_MEMORY, "fit: out of memory");
  size_t k = (size_t)snprintf(buf, cap,
                              "# The radial stack law fitted by `reelsim fit stack` to %s\n"
                              "# (%d points, %.4g .. %.4g Pa, RMS strain residual %.3g).\n",
                              source, fit->n_points, fit->P_min, fit->P_max, fit->rms);
  for (int i = 0; i < fit->n_params; ++i)
    k += (size_t)snprintf(buf + k, cap - k, "#   %-10s %.6g +- %.3g (95 %%)\n", fit->name[i],
                          fit->value[i], fit->half_width[i]);
  if (base_text) { /* the base model's lines, its radial: replaced */
    const char *s = base_text;
    while (*s) {
      const char *e = strchr(s, '\n');
      size_t len = e ? (size_t)(e - s + 1) : strlen(s);
      if (strncmp(s, "radial:", 7) == 0) {
        k += (size_t)radial_yaml(buf + k, cap - k, &fit->radial);
        /* a block-style radial: its indented lines go with it */
        s += len;
        while (*s == ' ' || *s == '\t') {
          const char *e2 = strchr(s, '\n');
          s += e2 ? (size_t)(e2 - s + 1) : strlen(s);
        }
        continue;
      }
      if (strncmp(s, "name:", 5) == 0) {
        k += (size_t)snprintf(buf + k, cap - k, "name: fitted\n");
        s += len;
        continue;
      }
      memcpy(buf + k, s, len);
      k += len;
      s += len;
    }
    if (!strstr(base_text, "\nradial:") && strncmp(base_text, "radial:", 7) != 0)
      k += (size_t)radial_yaml(buf + k, cap - k, &fit->radial);
  } else
    k += (size_t)radial_yaml(buf + k, cap - k, &fit->radial);
  rs_status st = rs_atomic_file_write(path, buf, k);
  free(buf);
  return st;
}

rs_status rs_fit_stack_plot(const char *path, int n, const double *P, const double *eps,
                            const rs_fit_stack_result *fit, const char *title)
{
  enum { M = 200 };
  double mp[M], me[M], *res = malloc((size_t)n * sizeof(double)), *pk = malloc((size_t)n * sizeof(double));
  if (!res || !pk) {
    free(res);
    free(pk);
    return RS_ERROR(RS_ERR_MEMORY, "fit: out of memory");
  }
  for (int i = 0; i < M; ++i) {
    mp[i] = fit->P_max * i / (M - 1) * 1e-3;
    me[i] = rs_radial_strain(&fit->radial, fit->P_max * i / (M - 1));
  }
  for (int i = 0; i < n; ++i) {
    pk[i] = P[i] * 1e-3;
    res[i] = (rs_radial_strain(&fit->radial, P[i]) - eps[i]) * 1e3;
  }
  rs_gp gp;
  char *d1 = NULL, *d2 = NULL;
  rs_status st = rs_gp_begin(&gp, 1000, 760);
  const double *c1[] = {pk, eps, res}, *c2[] = {mp, me};
  if (!st) st = rs_gp_data(&gp, 3, c1, (size_t)n, &d1, NULL);
  if (!st) st = rs_gp_data(&gp, 2, c2, M, &d2, NULL);
  if (!st) st = rs_gp_figure(&gp, path);
  if (!st) {
    rs_gp_printf(&gp, "set multiplot layout 2,1 title ");
    rs_gp_string(&gp, title);
    rs_gp_printf(&gp, "\nset size 1,0.68\nset origin 0,0.30\nset grid\nset key left top\n"
                      "set ylabel 'stack strain (compression positive)'\nset format x ''\n");
    rs_gp_plot_item(&gp);
    rs_gp_string(&gp, d1);
    rs_gp_printf(&gp, " using 1:2 with points pt 7 ps 0.8 lc rgb '#1f77b4' title 'stack test'");
    rs_gp_plot_item(&gp);
    rs_gp_string(&gp, d2);
    rs_gp_printf(&gp, " using 1:2 with lines lw 2 lc rgb '#d62728' title ");
    char t[160];
    snprintf(t, sizeof t, "fitted %s law (RMS residual %.2g)",
             fit->radial.law == RS_RADIAL_PFEIFFER ? "Pfeiffer" : fit->radial.law == RS_RADIAL_HAKIEL ? "Hakiel"
             : fit->radial.law == RS_RADIAL_TABLE ? "table" : "linear", fit->rms);
    rs_gp_string(&gp, t);
    rs_gp_plot_end(&gp);
    rs_gp_printf(&gp, "set size 1,0.30\nset origin 0,0\nset format x '%%g'\nset xlabel 'pressure (kPa)'\n"
                      "set ylabel 'residual (1e-3)'\nunset key\n");
    rs_gp_plot_item(&gp);
    rs_gp_string(&gp, d1);
    rs_gp_printf(&gp, " using 1:3 with impulses lw 2 lc rgb '#1f77b4'");
    rs_gp_plot_end(&gp);
    rs_gp_printf(&gp, "unset multiplot\n");
    st = rs_gp_run(&gp, NULL);
  }
  free(d1);
  free(d2);
  rs_gp_end(&gp);
  free(res);
  free(pk);
  return st;
}
