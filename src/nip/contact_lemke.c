/* Lemke's complementary pivoting (Lemke 1965; Cottle, Pang & Stone 1992, "The linear
 * complementarity problem", sec. 4.4) for the stick/slip LCP of contact_lcp.c, in two
 * forms with the same arithmetic.
 *
 * The tableau: rows i = 0..m-1 read w_i - sum_j Mt_ij u_j - t = c_i. Variables: w_i
 * (i < m), s+_j (m + j), s-_j (m + S + j), t (vt = 2 m). Stored columns: w (m), s+ (S), t,
 * the right-hand side; the column of s-_j is minus that of s+_j in any basis (row
 * operations keep the linear relation), so it is not stored. A pivot on row r divides the
 * row by the entering column's entry d_r and takes d_i times it from every other row i:
 * for any column x, x_r <- x_r / d_r, x_i <- x_i - d_i x_r.
 *
 * The revised form applies those operations to a column only when it is needed: the
 * entering column (its original column through the pivots so far, each pivot kept as its
 * row and entering column, the product form of the basis inverse) and the right-hand side.
 * Pivot k then costs O(k m) instead of the tableau's O(m (m + S)): on the contact reel's
 * cold start (m = 252, 123 pivots) about a sixth of the multiplications. Every number is
 * the one the tableau holds (the same operations on each column in the same order; only
 * zeros may differ in sign, which no test of the method reads), so the pivots and the
 * solution are the tableau's. Past `revised_max` pivots (a long path, where O(k m) a pivot
 * would exceed the tableau's) the tableau is formed from the revised state and carries on.
 * Ties go to the artificial variable, then the smallest index; the pivot count is capped. */
#include "nip/contact_internal.h"
#include "util/vector_clones.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The problem: the stored s+ columns U (m x S, column-major) and the right-hand side c of
 * the starting tableau (w basic). */
typedef struct lemke_problem {
  int m, S, vt;
  const double *U, *c;
} lemke_problem;

/* stored column of variable v (the s+ column for s-) and the sign of its true column */
static int stored_col(const lemke_problem *p, int v)
{
  return v == p->vt ? p->m + p->S : v < p->m + p->S ? v : v - p->S;
}
static double col_sign(const lemke_problem *p, int v)
{
  return v >= p->m + p->S && v < p->vt ? -1.0 : 1.0;
}

/* The ratio test for an entering column d (signed): the row where d is positive whose
 * right-hand side x bounds it first (x stays >= 0); ties: the row of t first (ends), then
 * the smallest index. -1: none (a secondary ray). */
static int ratio_test(const lemke_problem *p, const double *d, const double *x, const int *basis)
{
  int r = -1;
  double best = INFINITY;
  for (int i = 0; i < p->m; ++i) {
    double col = d[i];
    if (!(col > 1e-12)) continue;
    double ratio = fmax(x[i], 0.0) / col, tie = 1e-12 * fmax(1.0, best);
    if (r < 0 || ratio < best - tie || (ratio <= best + tie && basis[i] == p->vt)) {
      best = ratio;
      r = i;
    }
  }
  return r;
}

/* The stick/slip state of a solution: slip forward (1) or backward (-1) where s+ or s- is
 * basic and positive, stick (0) elsewhere */
static void solution_state(const lemke_problem *p, const int *basis, const double *x, signed char *state)
{
  const int m = p->m, S = p->S;
  memset(state, 0, (size_t)S);
  for (int i = 0; i < m; ++i) {
    int v = basis[i];
    if (v < m || v == p->vt) continue; /* w or t */
    if (!(x[i] > 0)) continue;
    int j = v - m; /* u index: s+ for j < S, s- otherwise */
    state[j < S ? j : j - S] = j < S ? 1 : -1;
  }
}

/* ---- the tableau ---- */

typedef struct lemke_tableau {
  double *T; /* m rows of W (padded to a multiple of 4: see row_update) */
  int W, ct, cr;
} lemke_tableau;

#define TT(tb, i, j) ((tb)->T[(size_t)(i) * (tb)->W + (j)])

/* x -= f y over a padded row (n a multiple of 4: -O2 vectorises it) */
RS_VECTOR_CLONES static void row_update(int n, double *restrict x, double f,
                                        const double *restrict y)
{
  n &= ~3;
  for (int j = 0; j < n; ++j) x[j] -= f * y[j];
}

/* Pivots on (r, enter); returns the variable that left the basis */
static int tableau_pivot(const lemke_problem *p, lemke_tableau *tb, int *basis, int r, int enter)
{
  const int ce = stored_col(p, enter), W = tb->W;
  const double se = col_sign(p, enter);
  double pv = se * TT(tb, r, ce);
  for (int j = 0; j < W; ++j) TT(tb, r, j) /= pv;
  for (int i = 0; i < p->m; ++i) {
    if (i == r) continue;
    double f = se * TT(tb, i, ce);
    if (f == 0) continue;
    row_update(W, tb->T + (size_t)i * W, f, tb->T + (size_t)r * W);
  }
  int leaving = basis[r];
  basis[r] = enter;
  return leaving;
}

/* the signed column of v and the right-hand side out of the tableau */
static void tableau_column(const lemke_problem *p, const lemke_tableau *tb, int v, double *d, double *x)
{
  const int cn = stored_col(p, v);
  const double sn = col_sign(p, v);
  for (int i = 0; i < p->m; ++i) {
    d[i] = sn * TT(tb, i, cn);
    x[i] = TT(tb, i, tb->cr);
  }
}

/* Lemke's pivoting on the tableau from the pivot (r, enter) on: 1 at a solution, 0 on a
 * secondary ray or past the pivot cap (*pivots > cap) */
static int tableau_lemke(const lemke_problem *p, lemke_tableau *tb, int *basis, int r, int enter,
                         int cap, int *pivots, double *d, double *x)
{
  for (;;) {
    int leaving = tableau_pivot(p, tb, basis, r, enter);
    if (++*pivots > cap) return 0;
    if (leaving == p->vt) break;
    /* the complement of the leaving variable enters */
    enter = leaving < p->m ? leaving + p->m : leaving - p->m;
    tableau_column(p, tb, enter, d, x);
    if ((r = ratio_test(p, d, x, basis)) < 0) return 0;
  }
  tableau_column(p, tb, p->vt, d, x); /* x: the right-hand side */
  return 1;
}

#undef TT

/* ---- the revised (product) form ---- */

typedef struct lemke_revised {
  double *eta; /* the signed entering column of each pivot so far, m each */
  int *erow;   /* its pivot row */
  int n;
} lemke_revised;

/* y -= e yr (a multiple of 4 first: -O2 vectorises it) */
RS_VECTOR_CLONES static void eta_update(int m, double *restrict y, double yr, const double *restrict e)
{
  int m4 = m & ~3;
  for (int i = 0; i < m4; ++i) y[i] -= e[i] * yr;
  for (int i = m4; i < m; ++i) y[i] -= e[i] * yr;
}

/* y <- the stored column c of the tableau now (c: w, then s+, then t): its starting column
 * through the pivots so far */
static void revised_column(const lemke_problem *p, const lemke_revised *rv, int c, double *y)
{
  const int m = p->m;
  if (c < m) {
    memset(y, 0, (size_t)m * sizeof *y);
    y[c] = 1;
  } else if (c < m + p->S) {
    memcpy(y, p->U + (size_t)(c - m) * m, (size_t)m * sizeof *y);
  } else {
    for (int i = 0; i < m; ++i) y[i] = -1;
  }
  for (int k = 0; k < rv->n; ++k) {
    const double *e = rv->eta + (size_t)k * m;
    const int r = rv->erow[k];
    if (y[r] == 0) continue; /* the row operations leave y as it is */
    const double yr = y[r] / e[r];
    eta_update(m, y, yr, e);
    y[r] = yr;
  }
}

/* Pivots on (r, enter) with its signed column d: the right-hand side x updated, the pivot
 * kept; returns the variable that left the basis */
static int revised_pivot(const lemke_problem *p, lemke_revised *rv, int *basis, double *x, int r,
                         int enter, const double *d)
{
  const int m = p->m;
  const double xr = x[r] / d[r];
  for (int i = 0; i < m; ++i) {
    if (i == r || d[i] == 0) continue;
    x[i] -= d[i] * xr;
  }
  x[r] = xr;
  memcpy(rv->eta + (size_t)rv->n * m, d, (size_t)m * sizeof *d);
  rv->erow[rv->n++] = r;
  int leaving = basis[r];
  basis[r] = enter;
  return leaving;
}

/* The tableau of the revised state: every stored column through the pivots so far */
static int tableau_from_revised(const lemke_problem *p, const lemke_revised *rv, const double *x,
                                lemke_tableau *tb, double *y)
{
  const int m = p->m;
  tb->W = (m + p->S + 2 + 3) & ~3;
  tb->ct = m + p->S;
  tb->cr = m + p->S + 1;
  tb->T = calloc((size_t)m * tb->W, sizeof *tb->T);
  if (!tb->T) return 0;
  for (int c = 0; c <= tb->ct; ++c) {
    revised_column(p, rv, c, y);
    for (int i = 0; i < m; ++i) tb->T[(size_t)i * tb->W + c] = y[i];
  }
  for (int i = 0; i < m; ++i) tb->T[(size_t)i * tb->W + tb->cr] = x[i];
  return 1;
}

int rs_nipc_lemke(int m, int S, const double *U, const double *c, int revised_max, int cap,
                  signed char *state_out, double *x_out, int *pivots)
{
  const lemke_problem p = {.m = m, .S = S, .vt = 2 * m, .U = U, .c = c};
  if (revised_max > cap + 1) revised_max = cap + 1;
  if (revised_max < 0) revised_max = 0;
  lemke_revised rv = {0};
  lemke_tableau tb = {0};
  int *basis = malloc((size_t)m * sizeof *basis);
  double *x = malloc((size_t)m * sizeof *x), *d = malloc((size_t)m * sizeof *d);
  rv.eta = malloc(((size_t)revised_max + 1) * m * sizeof *rv.eta);
  rv.erow = malloc(((size_t)revised_max + 1) * sizeof *rv.erow);
  int found = -1;
  *pivots = 0;
  if (!basis || !x || !d || !rv.eta || !rv.erow) goto done;
  for (int i = 0; i < m; ++i) basis[i] = i;
  memcpy(x, c, (size_t)m * sizeof *x);
  int r = 0; /* start: c >= 0 is the full-stick solution */
  for (int i = 1; i < m; ++i)
    if (x[i] < x[r]) r = i;
  found = 1;
  if (x[r] >= 0) goto done;
  int enter = p.vt;
  for (int i = 0; i < m; ++i) d[i] = -1; /* t's column */
  for (;;) {
    if (rv.n >= revised_max) { /* a long path: the tableau from here on */
      found = tableau_from_revised(&p, &rv, x, &tb, d)
                  ? tableau_lemke(&p, &tb, basis, r, enter, cap, pivots, d, x)
                  : -1;
      break;
    }
    int leaving = revised_pivot(&p, &rv, basis, x, r, enter, d);
    if (++*pivots > cap) {
      found = 0;
      break;
    }
    if (leaving == p.vt) break;
    enter = leaving < m ? leaving + m : leaving - m;
    revised_column(&p, &rv, stored_col(&p, enter), d);
    const double se = col_sign(&p, enter);
    if (se < 0)
      for (int i = 0; i < m; ++i) d[i] = -d[i];
    if ((r = ratio_test(&p, d, x, basis)) < 0) {
      found = 0;
      break;
    }
  }
done:
  if (found == 1) {
    solution_state(&p, basis, x, state_out);
    if (x_out) memcpy(x_out, x, (size_t)m * sizeof *x);
  }
  free(tb.T);
  free(rv.eta);
  free(rv.erow);
  free(basis);
  free(x);
  free(d);
  return found;
}
