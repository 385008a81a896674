/* The optimisation's history (<stem>-optimize.png): the objective at each evaluation,
 * the feasible runs apart from those that break a constraint or failed, the best marked.
 * The objective is a figure (/optimize/figures/<name>) or a varied key (its column of
 * /optimize/values, by /optimize/parameters). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/figures.h"
#include "plot/plot_internal.h"
#include "util/error.h"

/* The values of quantity `name` at each of the n evaluations (*y malloc'd, NULL when the
 * file has no such quantity). */
static rs_status read_quantity(plot_ctx *c, const char *name, double **y, size_t *n)
{
  char path[PLOT_PATH];
  *y = NULL;
  *n = 0;
  if (rs_reader_exists(c->rd, rsi_plot_at(path, "/optimize/figures/%s", name)))
    return rs_reader_read_1d(c->rd, path, y, n);
  if (!rs_reader_exists(c->rd, "/optimize/parameters") || !rs_reader_exists(c->rd, "/optimize/values"))
    return RS_OK;
  char **keys = NULL;
  size_t nk = 0, rows = 0, cols = 0;
  double *values = NULL;
  rs_status st = rs_reader_read_strings(c->rd, "/optimize/parameters", &keys, &nk);
  if (st == RS_OK) st = rs_reader_read_2d(c->rd, "/optimize/values", &values, &rows, &cols);
  for (size_t k = 0; st == RS_OK && k < nk && k < cols; ++k) {
    if (strcmp(keys[k], name) != 0) continue;
    *y = malloc((rows ? rows : 1) * sizeof **y);
    if (!*y) {
      st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
      break;
    }
    for (size_t i = 0; i < rows; ++i) (*y)[i] = values[i * cols + k];
    *n = rows;
    break;
  }
  rs_reader_free_strings(&keys, nk);
  free(values);
  return st;
}

/* ok[i] = 1 when evaluation i ran (status 0) and meets every constraint of the file's
 * attribute "constraints" ("NAME <= X" a line). */
static rs_status feasibility(plot_ctx *c, size_t n, int *ok)
{
  double *status = NULL;
  size_t ns = 0;
  rs_status st = read_quantity(c, "status", &status, &ns);
  for (size_t i = 0; i < n; ++i) ok[i] = st == RS_OK && (!status || (i < ns && status[i] == 0));
  free(status);
  char *cons = NULL;
  if (st != RS_OK || rs_reader_attr_string(c->rd, "/optimize", "constraints", &cons) != RS_OK) {
    rs_error_clear();
    return st;
  }
  for (char *line = strtok(cons, "\n"); st == RS_OK && line; line = strtok(NULL, "\n")) {
    char name[256], op[3];
    double bound;
    if (sscanf(line, "%255s %2s %lf", name, op, &bound) != 3) continue;
    double *q = NULL;
    size_t nq = 0;
    st = read_quantity(c, name, &q, &nq);
    for (size_t i = 0; q && i < n; ++i)
      if (!(i < nq && (op[0] == '<' ? q[i] <= bound : q[i] >= bound))) ok[i] = 0;
    free(q);
  }
  free(cons);
  return st;
}

rs_status rsi_plot_optimize_history(plot_ctx *c)
{
  char *objective = NULL, *sense = NULL;
  if (rs_reader_attr_string(c->rd, "/optimize", "objective", &objective) != RS_OK)
    return RS_ERROR(RS_ERR_INPUT, "'%s': /optimize has no attribute objective",
                    rs_reader_path(c->rd));
  if (rs_reader_attr_string(c->rd, "/optimize", "sense", &sense) != RS_OK) sense = NULL;
  rs_error_clear();
  double *y = NULL, best = NAN;
  size_t n = 0;
  rs_status st = read_quantity(c, objective, &y, &n);
  if (st == RS_OK && rs_reader_exists(c->rd, "/optimize/best"))
    st = rs_reader_read_scalar(c->rd, "/optimize/best", &best);
  char *out = st == RS_OK ? rsi_plot_path(c, "optimize") : NULL;
  if (st == RS_OK && !out) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) st = rs_gp_figure(&c->gp, out);
  free(out);
  double *x = malloc((n ? n : 1) * sizeof *x), *yf = malloc((n ? n : 1) * sizeof *yf);
  int *ok = malloc((n ? n : 1) * sizeof *ok);
  if (st == RS_OK && (!x || !yf || !ok)) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) st = feasibility(c, n, ok);
  if (st == RS_OK) {
    char head[512];
    snprintf(head, sizeof head, "optimisation history (%s): %s %s", c->stem,
             sense ? sense : "objective", objective);
    rsi_plot_title(c, head, "every evaluation; the best feasible one marked");
    rs_gp_printf(&c->gp, "set grid\nset xlabel 'evaluation'\nset ylabel ");
    rs_gp_string(&c->gp, objective);
    rs_gp_printf(&c->gp, "\nset key outside below horizontal\nset offsets 0.5, 0.5, 0, 0\n");
    for (size_t i = 0; i < n; ++i) x[i] = (double)(i + 1);
    char style[128];
    for (size_t i = 0; i < n; ++i) yf[i] = ok[i] ? y[i] : NAN;
    snprintf(style, sizeof style, "with points pointtype 7 linecolor rgb '%s'", rsi_plot_color(0));
    st = rsi_plot_curve(c, x, yf, n, style, "feasible", NULL);
    for (size_t i = 0; i < n; ++i) yf[i] = ok[i] ? NAN : y[i];
    snprintf(style, sizeof style, "with points pointtype 2 linecolor rgb '%s'", rsi_plot_color(1));
    if (st == RS_OK) st = rsi_plot_curve(c, x, yf, n, style, "infeasible or failed", NULL);
    size_t b = best >= 0 && best < (double)n ? (size_t)best : n;
    if (st == RS_OK && b < n) {
      snprintf(style, sizeof style, "with points pointtype 6 pointsize 3 linewidth 2 "
                                    "linecolor rgb '%s'", rsi_plot_color(3));
      st = rsi_plot_curve(c, &x[b], &y[b], 1, style, "best", NULL);
    }
    if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no evaluation of the objective");
    rs_gp_plot_end(&c->gp);
  }
  free(x);
  free(yf);
  free(ok);
  free(y);
  free(objective);
  free(sense);
  return st;
}
