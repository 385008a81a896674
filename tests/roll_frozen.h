/* The first lumping scheme, kept as a reference for the tests of the one the engine winds
 * (validation/test_roll.c, hard/test_hard.c) and for bench/bench_lumping.c: a block of m
 * layers integrated once with the modulus frozen before the block, every block layer's
 * sub-increment taken as the outermost one's (the whole block's load at its outer radius
 * s), the block's own nodes getting the share of the block's tension wound at or above
 * them. Error first order in m, ~60x the engine's predictor-corrector's
 * (docs/accuracy.md). For m = 1 it is the engine's Hakiel accretion, the same call. Built
 * on the engine's internals (roll_internal.h); not part of the library. */
#ifndef RS_TESTS_ROLL_FROZEN_H
#define RS_TESTS_ROLL_FROZEN_H

#include <math.h>
#include <stdlib.h>

#include "roll/roll_internal.h"

/* The block's increment at the nodes 0..k (dsr, dsh) from the integration just done:
 * e_j = y(r_j)/y(s) by the engine's one-layer decays, ds = -(total/s) e, ds + r ds' =
 * ds (1 + w); RS_ERR_SOLVER when one is not finite */
static rs_status roll_frozen_increment(rs_roll *roll, int k, int top, double total)
{
  double *dsr = roll->dsr, *dsh = roll->dsh;
  roll_segments seg;
  rsi_roll_decays_raw(roll->L, dsr, 0, top, &seg);
  for (int g = seg.count - 1; g >= 0; --g)
    for (int j = seg.b[g]; j < seg.b[g + 1]; ++j) dsr[j] = roll_decay_clear(dsr[j] * seg.s[g]);
  dsr[top] = 1.0;
  const double scale = -total / roll_node_radius(roll, top);
  for (int j = 0; j <= top; ++j) {
    dsr[j] *= scale;
    dsh[j] = dsr[j] * (1.0 + roll->w[j]);
  }
  if (roll->shift) { /* the outermost layer's outer face: traction free */
    dsr[k] = 0.0;
    dsh[k] = 0.0;
  }
  for (int j = 0; j <= k; ++j)
    if (!isfinite(dsr[j]) || !isfinite(dsh[j])) return RS_ERR_SOLVER;
  return RS_OK;
}

/* rs_roll_add_layers with the first scheme (valid m and tensions: the tests' own) */
static rs_status roll_add_layers_frozen(rs_roll *roll, int m, const double *T0)
{
  if (m == 1) return rs_roll_add_layers(roll, 1, T0);
  const int k_old = roll->n, k = k_old + m, shift = roll->shift, top = k - shift;
  const double t = roll->p.caliper;
  double total = 0.0;
  for (int i = 0; i < m; ++i) total += T0[i];
  /* a lumped block: no lazy deep part, w stored node by node, no drift profile */
  rsi_roll_lazy_configure(roll, m);
  roll->w_lazy = 0;
  rsi_roll_profile_configure(roll, 0);
  rsi_roll_lazy_flush(roll, 0);
  rs_status st = rsi_roll_air_nodes(roll, k_old, k);
  if (st == RS_OK) st = rsi_roll_set_modulus_stress(roll, top);
  if (st == RS_OK) st = rsi_roll_integrate(roll, top);
  if (st == RS_OK) st = roll_frozen_increment(roll, k, top, total);
  rsi_roll_start_release(roll, st);
  if (st) return st;
  roll->deep_lo = 0;
  roll->c_deep = roll->c2_deep = 0.0;
  rsi_roll_profile_drop(roll); /* the reference's nodes take the increment node by node */
  roll->core_sigma += roll->dsr[0];
  double above = 0.0; /* the tension wound at or above block layer b */
  for (int b = m - 1; b >= 0; --b) {
    const int j = k_old + 1 + b;
    /* with the load beneath a layer, a block layer's own tension is not on its outer face */
    const double share_above = total > 0.0 ? above / total : 0.0;
    above += T0[b];
    const double share_at = shift ? share_above : (total > 0.0 ? above / total : 0.0);
    roll->sigma_r[j - 1] = share_at * roll->dsr[j];
    roll->sigma_theta[j - 1] = T0[b] / t + share_above * roll->dsh[j];
  }
  for (int j = 1; j <= k_old; ++j) {
    roll->sigma_r[j - 1] += roll->dsr[j];
    roll->sigma_theta[j - 1] += roll->dsh[j];
  }
  if (shift) roll->hoop_stale = 1;
  roll->n = k;
  roll->stats.increments++;
  return rsi_roll_check_invariants(roll, 1) ? RS_ERR_INTERNAL : RS_OK;
}

#endif
