/* The node passes that replace a loop node by node with one that vectorises (or with
 * running maxima side by side), each of which must give the loop's own numbers bit for
 * bit (docs/performance.md, "The million-layer film"): the roll of a case winds the same
 * however its passes are written.
 *   rebase_same_bits    the rebase's nodes (rsi_roll_rebase_nodes) against the node-by-node
 *                       loop with roll_exp_step (rsi_roll_rebase_nodes_exp, compiled as the
 *                       library's roll_reference.c is), where rsi_roll_rebase_small says every
 *                       exponent is within the Taylor sum's range; and that it says so
 *                       only then (an exponent of 0.03, of -0.03, a NaN: not)
 *   carry_same_bits     the same for the deeper level's carry (rsi_roll_carry_nodes)
 *   deep_maxima_order   the level's maxima (rsi_roll_deep_maxima) against one running
 *                       maximum node by node, with NaNs, nodes in tension, zeros
 *   gauge_pmax_order    the gauge's largest pressure (rs_reel_deformed_pmax) against fmax()
 *                       in order, with NaN pressures inside and last, a NaN core pressure */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/gauge.h"
#include "roll/roll_internal.h"
#include "splitmix.h"

enum { N = 1031 };

static double uniform(uint64_t *s, double a, double b)
{
  return a + (b - a) * (double)(splitmix64(s) >> 11) * 0x1.0p-53;
}

static int differ(const double *a, const double *b, int n)
{
  int d = 0;
  for (int j = 0; j < n; ++j) d += memcmp(&a[j], &b[j], sizeof a[j]) != 0;
  return d;
}

typedef struct nodes {
  double pw[N], pL[N], E[N], w[N], L[N], e[N], Eref[N];
} nodes;

static void fill(nodes *x, uint64_t *s)
{
  for (int j = 0; j < N; ++j) {
    x->pw[j] = uniform(s, -3.0, 3.0);
    x->pL[j] = uniform(s, -1.0, 1.0);
    x->E[j] = uniform(s, 1e6, 6e7);
    x->w[j] = uniform(s, -0.5, 2.0);
    x->L[j] = uniform(s, -40.0, 0.0);
    x->e[j] = exp(uniform(s, -30.0, 0.0));
    x->Eref[j] = uniform(s, 1e6, 6e7);
  }
}

static void rebase_same_bits(void)
{
  uint64_t s = 35;
  int bad = 0, cases = 0;
  for (int r = 0; r < 40; ++r) {
    static nodes a, b;
    fill(&a, &s);
    b = a;
    const double pLf = a.pL[N / 2];
    /* C so that |C (pL - pLf)| < 0.03 (|pL - pLf| < 2): the vector pass */
    const double C = uniform(&s, -0.0149, 0.0149);
    const int lo = r % 7, hi = N - r % 5;
    CHECK(rsi_roll_rebase_small(C, a.pL, pLf, lo, hi));
    rsi_roll_rebase_nodes(C, a.pw, a.pL, pLf, a.E, a.w, a.L, a.e, a.Eref, lo, hi);
    rsi_roll_rebase_nodes_exp(C, b.pw, b.pL, pLf, b.E, b.w, b.L, b.e, b.Eref, lo, hi);
    bad += differ(a.w, b.w, N) + differ(a.L, b.L, N) + differ(a.e, b.e, N) +
           differ(a.Eref, b.Eref, N);
    ++cases;
  }
  CHECK_LOG("rebases compared", cases);
  CHECK_LOG("values that differ between the two loops", bad);
  CHECK(bad == 0);
  /* one exponent at the range's edge, beyond it, or not a number: the loop node by node */
  static double pL[N];
  for (int j = 0; j < N; ++j) pL[j] = 0.5 * sin(j);
  CHECK(rsi_roll_rebase_small(0.05, pL, 0.0, 0, N));
  const double edge[] = {0.6, -0.6, 1.0, NAN};
  for (size_t i = 0; i < sizeof edge / sizeof edge[0]; ++i) {
    const double keep = pL[700];
    pL[700] = edge[i];
    CHECK(!rsi_roll_rebase_small(0.05, pL, 0.0, 0, N)); /* |0.05 x 0.6| = 0.03 */
    CHECK(rsi_roll_rebase_small(0.05, pL, 0.0, 0, 700)); /* the node outside the range */
    pL[700] = keep;
  }
}

static void carry_same_bits(void)
{
  uint64_t s = 36;
  int bad = 0;
  for (int r = 0; r < 40; ++r) {
    static nodes a, b;
    fill(&a, &s);
    b = a;
    const double A = uniform(&s, 0.9, 1.1), B = uniform(&s, -0.0299, 0.0299);
    const int lo = r % 3, hi = N - r % 11;
    CHECK(rsi_roll_rebase_small(B, a.pL, 0.0, lo, hi));
    rsi_roll_carry_nodes(A, B, a.pw, a.pL, a.w, a.L, a.e, lo, hi);
    rsi_roll_carry_nodes_exp(A, B, b.pw, b.pL, b.w, b.L, b.e, lo, hi);
    bad += differ(a.w, b.w, N) + differ(a.L, b.L, N) + differ(a.e, b.e, N);
  }
  CHECK_LOG("values that differ between the two loops", bad);
  CHECK(bad == 0);
}

static void deep_maxima_order(void)
{
  uint64_t s = 37;
  int bad = 0;
  static double pL[N], e[N], sr[N];
  for (int r = 0; r < 60; ++r) {
    for (int j = 0; j < N; ++j) {
      pL[j] = uniform(&s, -2.0, 2.0);
      e[j] = exp(uniform(&s, -20.0, 0.0));
      sr[j] = -uniform(&s, 0.0, 4e6);
    }
    if (r % 3 == 1) sr[r * 7 % N] = 1e3;           /* a node in tension */
    if (r % 4 == 2) pL[r * 13 % N] = NAN;          /* not a number */
    if (r % 5 == 3) e[r * 11 % N] = NAN;
    if (r % 6 == 4) pL[(r * 17) % N] = 7.0;        /* a largest that is one node's */
    const double core = -5e6, c = uniform(&s, -1e3, 0.0), c2 = uniform(&s, -10.0, 10.0);
    const int D = N - r;
    double m, q;
    rsi_roll_deep_maxima(pL, e, sr, core, c, c2, D, &m, &q);
    double m1 = 0.0, q1 = 0.0; /* node by node */
    for (int j = 0; j < D; ++j) {
      m1 = fabs(pL[j]) > m1 ? fabs(pL[j]) : m1;
      const double P = -((j == 0 ? core : sr[j - 1]) + e[j] * (c + c2 * pL[j]));
      const double x = P > 0.0 ? e[j] / P : INFINITY;
      q1 = x > q1 || x != x ? x : q1;
    }
    bad += memcmp(&m, &m1, sizeof m) != 0;
    bad += !(memcmp(&q, &q1, sizeof q) == 0 || (isnan(q) && isnan(q1)));
  }
  CHECK_LOG("maxima that differ from the running one", bad);
  CHECK(bad == 0);
}

static double pmax_in_order(double core, const double *sr, int n)
{
  double Pmax = core;
  for (int j = 0; j < n; ++j) {
    const double P = -sr[j];
    if (P > Pmax || isnan(Pmax)) Pmax = P;
  }
  return Pmax;
}

static void gauge_pmax_order(void)
{
  uint64_t s = 38;
  int bad = 0, nans = 0;
  static double sr[N];
  for (int r = 0; r < 80; ++r) {
    const int n = N - r;
    for (int j = 0; j < n; ++j) sr[j] = -uniform(&s, -1e3, 3e6);
    sr[n - 1] = 0.0;
    if (r % 4 == 1) sr[r % n] = NAN;       /* a pressure that is not a number: skipped */
    if (r % 4 == 2) sr[n - 1] = NAN;
    if (r == 13) /* none a number, nor the core's: NaN */
      for (int j = 0; j < n; ++j) sr[j] = NAN;
    if (r % 4 == 3) sr[(r * 29) % n] = -9e6; /* a largest inside */
    /* a core pressure that is not a number: the first pressure taken whatever it is */
    const double core = r % 8 == 5 ? NAN : uniform(&s, 0.0, 4e6);
    const double a = rs_reel_deformed_pmax(core, sr, n), b = pmax_in_order(core, sr, n);
    bad += !(memcmp(&a, &b, sizeof a) == 0 || (isnan(a) && isnan(b)));
    nans += isnan(b);
  }
  CHECK_LOG("largest pressures that differ from fmax in order", bad);
  CHECK(bad == 0);
  CHECK(nans == 1); /* the case with no number reached NaN, and it alone */
}

static const check_case cases[] = {
    {"rebase_same_bits", rebase_same_bits},
    {"carry_same_bits", carry_same_bits},
    {"deep_maxima_order", deep_maxima_order},
    {"gauge_pmax_order", gauge_pmax_order},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
