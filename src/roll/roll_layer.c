/* One layer's increment, built and committed in one pass over the nodes above a reused
 * start (the common case of a long roll: every increment but the references', load
 * beneath the layer). The same operations as rsi_roll_block_increment followed by rsi_roll_commit,
 * node for node, so the same numbers bit for bit; what they do in five passes over the
 * nodes (the decays' scaling, the shape's update, ds = -S e, the finiteness check, the
 * commit) is one here. An increment is checked before anything is written: the largest
 * decay of each segment bounds |ds| there, and where that bound is not finite (or c_deep
 * is not) the two-step path runs instead, with its node-by-node check and its report of
 * the lowest node that is not finite. */
#include <math.h>

#include "roll/roll_internal.h"
#include "util/vector_clones.h"

/* The increment of one layer of tension T0 (N/m) wound onto the roll, from the integration
 * just done, committed (rs_roll_add_layers' step for m = 1). */
RS_VECTOR_CLONES static rs_status roll_add_one_pass(rs_roll *roll, double T0)
{
  const int k_old = roll->n, k = k_old + 1, bottom = k_old + 1 - roll->shift;
  const int lo = roll->ref.start;
  /* the case of rsi_roll_block_increment's deep part read from the shape (lo = start > 0),
   * with the load beneath the layer, over a range the decays cut into segments */
  if (!roll->shift || lo < 1 || lo > roll->ref.shape_top || !(roll->ref.shape_e[lo] > 1e-280) ||
      bottom - lo < 256) {
    rsi_roll_block_increment(roll, k_old, 1, &T0, NULL);
    return rsi_roll_commit(roll, 1, &T0);
  }
  const double S = T0 / roll_node_radius(roll, bottom); /* the block's sum for m = 1 */
  double *restrict e = roll->dsr, *restrict se = roll->ref.shape_e, *restrict sr = roll->sigma_r;
  roll_segments seg;
  rsi_roll_decays_raw(roll->L, e, lo, bottom, &seg);
  const double e_lo = roll_decay_clear(e[lo] * seg.s[0]);
  double c2;
  const double c = rsi_roll_deep_scales(roll, lo, -S * e_lo / se[lo], &c2);
  int finite = isfinite(c) && isfinite(c2) && seg.count == 4 && roll_deep_bounded(roll, c, c2);
  for (int g = 0; finite && g < seg.count; ++g) finite = seg.M[g] * seg.s[g] * S < INFINITY;
  if (!finite) { /* the two-step path: its check names the node */
    rsi_roll_block_increment(roll, k_old, 1, &T0, NULL);
    return rsi_roll_commit(roll, 1, &T0);
  }
  roll->deep_lo = lo;
  roll->c_deep = c;
  roll->c2_deep = c2;
  rsi_roll_profile_commit(roll, lo, c);
  /* below the start: c times the shape, plus c2 times the shape's correction (the lazy
   * nodes in their common scales) */
  rsi_roll_commit_deep(roll, lo, c, c2, 0.0);
  /* the shape above the start follows this integration, in the reference's scale, unless
   * that scale would overflow (rsi_roll_block_increment) */
  const double scale = e_lo > 1e-280 ? se[lo] / e_lo : 0.0;
  const int follow = e_lo > 1e-280 && scale < 1e200;
  for (int g = 0; g < seg.count; ++g)
    rsi_roll_shape_segment(e, sr, follow ? se : NULL, seg.b[g], seg.b[g + 1], seg.s[g], -S, scale);
  if (follow)
    rsi_roll_shape_followed(roll, bottom, scale, &seg);
  else if (e_lo > 1e-280)
    rsi_roll_shape_cut(roll, lo);
  sr[bottom - 1] += -S; /* the layer beneath takes the load */
  sr[k - 1] = 0.0;      /* the new layer's outer face is free */
  roll->hoop_stale = 1; /* the hoop stresses follow from the radial ones when read */
  return RS_OK;
}

rs_status rsi_roll_add_one(rs_roll *roll, double T0)
{
  return roll_add_one_pass(roll, T0);
}
