/* The rebase's and the carry's passes over nodes (rsi_roll_reference_rebase and
 * rsi_roll_reference_carry, roll_reference.c, which own what they write and hand it over as
 * arrays): (w, L) += C (p_w, p_L), e *= exp(...), in loops that vectorise where every exponent
 * is within the Taylor sum's range, and node by node with roll_exp_step where one is not
 * (the same bits where both apply: test_roll_passes). Compiled as roll_reference.c is
 * (CMakeLists.txt: fused multiply-adds where the build has FMA). */
#include <stdint.h>

#include "roll/roll_internal.h"
#include "util/float_flags.h"
#include "util/vector_clones.h"

/* 1 when |s (pL_j - p0)| < 0.03 at every node of [lo, hi) (none NaN): roll_exp_step of
 * each is its Taylor sum (roll_exp_small), which a loop then takes without a branch. A
 * pass over p_L alone, that vectorises (the flag from the bits: util/float_flags.h) */
RS_VECTOR_CLONES static int roll_rebase_small(double s, const double *restrict pL, double p0,
                                              int lo, int hi)
{
  uint64_t wide = 0;
  const uint64_t limit = rs_double_bits(0.03);
  for (int j = lo; j < hi; ++j) wide |= rs_flag_not_below(s * (pL[j] - p0), limit);
  return !rs_flag_raised(wide);
}

/* The rebase's nodes [lo, hi) (rsi_roll_reference_rebase) and the carry's
 * (rsi_roll_reference_carry): exp by its Taylor sum alone with small != 0, where
 * roll_rebase_small holds (roll_exp_step's own choice there: the same bits), in a loop
 * over arrays passed as such that then vectorises; else roll_exp_step node by node */
static inline void roll_rebase_loop(double C, const double *restrict pw,
                                    const double *restrict pL, double pLf,
                                    const double *restrict E, double *restrict w,
                                    double *restrict L, double *restrict e,
                                    double *restrict Eref, int lo, int hi, int small)
{
  for (int j = lo; j < hi; ++j) {
    const double a = C * (pL[j] - pLf);
    w[j] += C * pw[j];
    L[j] += C * pL[j];
    e[j] *= small ? roll_exp_small(a) : roll_exp_step(a);
    Eref[j] = E[j];
  }
}

static inline void roll_carry_loop(double A, double B, const double *restrict pw,
                                   const double *restrict pL, double *restrict w,
                                   double *restrict L, double *restrict e, int lo, int hi,
                                   int small)
{
  for (int j = lo; j < hi; ++j) {
    w[j] += B * pw[j];
    L[j] += B * pL[j];
    e[j] *= A * (small ? roll_exp_small(B * pL[j]) : roll_exp_step(B * pL[j]));
  }
}

RS_VECTOR_CLONES static void roll_rebase_pass(double C, const double *restrict pw,
                                              const double *restrict pL, double pLf,
                                              const double *restrict E, double *restrict w,
                                              double *restrict L, double *restrict e,
                                              double *restrict Eref, int lo, int hi)
{
  roll_rebase_loop(C, pw, pL, pLf, E, w, L, e, Eref, lo, hi, 1);
}

RS_VECTOR_CLONES static void roll_carry_pass(double A, double B, const double *restrict pw,
                                             const double *restrict pL, double *restrict w,
                                             double *restrict L, double *restrict e, int lo,
                                             int hi)
{
  roll_carry_loop(A, B, pw, pL, w, L, e, lo, hi, 1);
}

int rsi_roll_rebase_small(double s, const double *pL, double p0, int lo, int hi)
{
  return roll_rebase_small(s, pL, p0, lo, hi);
}

void rsi_roll_rebase_nodes(double C, const double *pw, const double *pL, double pLf,
                           const double *E, double *w, double *L, double *e, double *Eref,
                           int lo, int hi)
{
  roll_rebase_pass(C, pw, pL, pLf, E, w, L, e, Eref, lo, hi);
}

void rsi_roll_carry_nodes(double A, double B, const double *pw, const double *pL, double *w,
                          double *L, double *e, int lo, int hi)
{
  roll_carry_pass(A, B, pw, pL, w, L, e, lo, hi);
}

void rsi_roll_rebase_nodes_exp(double C, const double *pw, const double *pL, double pLf,
                               const double *E, double *w, double *L, double *e, double *Eref,
                               int lo, int hi)
{
  roll_rebase_loop(C, pw, pL, pLf, E, w, L, e, Eref, lo, hi, 0);
}

void rsi_roll_carry_nodes_exp(double A, double B, const double *pw, const double *pL, double *w,
                              double *L, double *e, int lo, int hi)
{
  roll_carry_loop(A, B, pw, pL, w, L, e, lo, hi, 0);
}
