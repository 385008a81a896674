/* Lemke's method of the stick/slip LCP (src/nip/contact_lemke.c): its revised (product)
 * form against the dense tableau, and its answers against the definition of a solution.
 *
 * The problems have the nip's structure (contact_lcp.c): S elements, margins w+ = mu pbar -
 * q and w- = mu pbar + q linear in the slips u = (s+, s-), w = c + Mt u, Mt = [[W+, -W+],
 * [W-, -W-]], W+- = P -+ Q: Q a diagonally dominant tangential response with a positive
 * diagonal (its friction falls as the element slips forward), P a small pressure coupling,
 * c+- = mu pbar -+ q0 with q0 beyond the friction limit at some elements. */
#include "check.h"
#include "nip/contact_internal.h"
#include "splitmix.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct problem {
  int S, m;
  double *U, *c; /* the stored s+ columns (-Mt's first S columns, m x S) and c */
} problem;

static double uniform(uint64_t *s)
{
  return (double)(splitmix64(s) >> 11) * 0x1.0p-53;
}

static problem make(int S, uint64_t seed, double coupling)
{
  problem p = {S, 2 * S, NULL, NULL};
  p.U = malloc((size_t)p.m * S * sizeof *p.U);
  p.c = malloc((size_t)p.m * sizeof *p.c);
  uint64_t s = seed;
  for (int e = 0; e < S; ++e) {
    double mu = 0.2 + uniform(&s), q0 = (4 * uniform(&s) - 2) * mu;
    p.c[e] = mu - q0;
    p.c[S + e] = mu + q0;
    for (int j = 0; j < S; ++j) {
      double Q = (j == e ? 1.0 + uniform(&s) : (uniform(&s) - 0.5) / S);
      double P = coupling * (uniform(&s) - 0.5);
      p.U[(size_t)j * p.m + e] = -(P + Q);     /* -(W+) */
      p.U[(size_t)j * p.m + S + e] = -(P - Q); /* -(W-) */
    }
  }
  return p;
}

static void drop(problem *p)
{
  free(p->U);
  free(p->c);
}

/* The state is a solution of the LCP: the slips it implies (w = 0 where an element slips,
 * s = 0 where it sticks, solved by Gaussian elimination here) are >= 0 and every margin is
 * >= 0. Returns the largest violation, relative to the data's scale. */
static double violation(const problem *p, const signed char *state)
{
  const int S = p->S, m = p->m;
  int *act = malloc((size_t)S * sizeof *act), k = 0;
  for (int e = 0; e < S; ++e)
    if (state[e]) act[k++] = e;
  /* rows: w+_e = 0 (forward slip) or w-_e = 0 (backward); unknowns s_e = s+_e - s-_e */
  double *A = calloc((size_t)(k > 0 ? k : 1) * (k + 1), sizeof *A), *s = calloc((size_t)S, sizeof *s);
  for (int r = 0; r < k; ++r) {
    int e = act[r], row = state[e] > 0 ? e : S + e;
    for (int cidx = 0; cidx < k; ++cidx) A[(size_t)r * (k + 1) + cidx] = -p->U[(size_t)act[cidx] * m + row];
    A[(size_t)r * (k + 1) + k] = -p->c[row];
  }
  for (int col = 0; col < k; ++col) { /* partial pivoting */
    int piv = col;
    for (int r = col + 1; r < k; ++r)
      if (fabs(A[(size_t)r * (k + 1) + col]) > fabs(A[(size_t)piv * (k + 1) + col])) piv = r;
    for (int j = 0; j <= k; ++j) {
      double t = A[(size_t)col * (k + 1) + j];
      A[(size_t)col * (k + 1) + j] = A[(size_t)piv * (k + 1) + j];
      A[(size_t)piv * (k + 1) + j] = t;
    }
    for (int r = col + 1; r < k; ++r) {
      double f = A[(size_t)r * (k + 1) + col] / A[(size_t)col * (k + 1) + col];
      for (int j = col; j <= k; ++j) A[(size_t)r * (k + 1) + j] -= f * A[(size_t)col * (k + 1) + j];
    }
  }
  for (int r = k - 1; r >= 0; --r) {
    double t = A[(size_t)r * (k + 1) + k];
    for (int j = r + 1; j < k; ++j) t -= A[(size_t)r * (k + 1) + j] * s[act[j]];
    s[act[r]] = t / A[(size_t)r * (k + 1) + r];
  }
  double worst = 0, scale = 0;
  for (int i = 0; i < m; ++i) scale = fmax(scale, fabs(p->c[i]));
  for (int e = 0; e < S; ++e) worst = fmax(worst, -state[e] * s[e]); /* slip in its direction */
  for (int i = 0; i < m; ++i) {                                      /* margins */
    double w = p->c[i];
    for (int j = 0; j < S; ++j) w -= p->U[(size_t)j * m + i] * s[j];
    worst = fmax(worst, -w / scale);
  }
  free(act);
  free(A);
  free(s);
  return worst;
}

/* The revised form, the tableau (revised_max 0) and the tableau formed after a few pivots
 * give the same outcome, pivots, state and basic values, bit for bit. */
static void revised_equals_tableau(void)
{
  const int sizes[] = {3, 8, 31, 63};
  int solved = 0, switched = 0, longest = 0;
  for (size_t iz = 0; iz < sizeof sizes / sizeof *sizes; ++iz)
    for (uint64_t seed = 1; seed <= 6; ++seed) {
      const int S = sizes[iz], m = 2 * S;
      problem p = make(S, 1000 * seed + (uint64_t)S, seed % 3 == 0 ? 2.0 : 0.1);
      signed char *st0 = malloc((size_t)S), *st1 = malloc((size_t)S);
      double *x0 = malloc((size_t)m * sizeof *x0), *x1 = malloc((size_t)m * sizeof *x1);
      int piv0 = 0;
      memset(st0, 7, (size_t)S);
      int f0 = rs_nipc_lemke(m, S, p.U, p.c, 0, 20 * m, st0, x0, &piv0);
      CHECK(f0 >= 0);
      solved += f0 == 1;
      longest = piv0 > longest ? piv0 : longest;
      const int limits[] = {1, 3, S / 2, 2 * m, 20 * m + 5};
      for (size_t il = 0; il < sizeof limits / sizeof *limits; ++il) {
        int piv1 = 0;
        memset(st1, 7, (size_t)S);
        int f1 = rs_nipc_lemke(m, S, p.U, p.c, limits[il], 20 * m, st1, x1, &piv1);
        CHECK(f1 == f0);
        CHECK(piv1 == piv0);
        switched += piv1 > limits[il];
        if (f0 == 1 && f1 == 1) {
          CHECK(memcmp(st0, st1, (size_t)S) == 0);
          CHECK(memcmp(x0, x1, (size_t)m * sizeof *x0) == 0);
        }
      }
      free(st0);
      free(st1);
      free(x0);
      free(x1);
      drop(&p);
    }
  CHECK_LOG("problems solved (of 24)", solved);
  CHECK_LOG("runs that formed the tableau midway", switched);
  CHECK_LOG("longest pivot path", longest);
  CHECK(solved >= 12); /* the comparison covers solutions, and paths long enough to switch */
  CHECK(switched >= 24);
}

/* Every solution Lemke reports satisfies the LCP (slips in their direction, margins >= 0),
 * with both forms; on problems with a weak coupling (Q dominant: a solution exists) Lemke
 * finds one every time. */
static void solutions_satisfy_lcp(void)
{
  double worst = 0;
  int solved = 0;
  for (int S = 4; S <= 64; S *= 2)
    for (uint64_t seed = 1; seed <= 5; ++seed) {
      const int m = 2 * S;
      problem p = make(S, 77 * seed + (uint64_t)S, 0.05);
      signed char *st = malloc((size_t)S);
      for (int form = 0; form < 2; ++form) {
        int piv = 0;
        int f = rs_nipc_lemke(m, S, p.U, p.c, form ? m : 0, 20 * m, st, NULL, &piv);
        CHECK(f == 1);
        if (f == 1) {
          worst = fmax(worst, violation(&p, st));
          solved += form;
        }
      }
      free(st);
      drop(&p);
    }
  CHECK_LOG("problems solved (of 25)", solved);
  CHECK_LOG("largest violation of the LCP, relative", worst);
  CHECK_LT(worst, 1e-12);
}

static const check_case cases[] = {{"revised_equals_tableau", revised_equals_tableau},
                                   {"solutions_satisfy_lcp", solutions_satisfy_lcp}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
