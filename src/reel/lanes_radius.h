/* A lane's deformed outer radius, layer by layer at O(1) amortised cost (internal to
 * src/reel/; docs/lanes.md, "The lanes' radii").
 *
 * The contract (docs/lanes.md): before layer k goes on, lane i's outer radius is
 *     R(k) = r_c + u_c + k t - sum_{j<k} c_j,   c_j = t (eps(P_j) + eps(P_{j+1})) / 2
 * (less, with entrained air, the film under each layer compressed by the pressure at its
 * node, h_j(P_j): c_j then counts -h_j(P_j) too),
 * u_c = -r_c P_c / E_c the core's displacement, P_j the pressure at node j (node 0 the
 * core's face, node k the free surface), eps(P) the stack law's strain from zero
 * (rs_reel_deformed_radius, the full-stack sum: O(k)). Summing it at every layer costs
 * O(N^2) a reel. Here the full sum is taken only at layers spaced geometrically (k_r, then
 * k_r + h, h = max(1, floor(RS_LANE_RADIUS_STEP k_r))); in between
 *     R(k) = r_c + u_c(k) + k t - D(k) - sum_{j0 <= j < k} c_j(k)
 * with the top of the stack, layers j0 = k_r - h - RS_LANE_RADIUS_MARGIN .. k - 1 (every
 * layer wound since the full sum and those just below), summed exactly from the roll's
 * current pressures (rs_roll_layer_sigma_r: O(1) a node, the lazy deep part untouched),
 * the core's displacement exact, and the deep part D (the compression of the layers below
 * j0) carried layer by layer: a layer's stress increment beneath it is proportional to
 * its T0 to first order (a slack lane, T0 = 0, adds none) and, over an interval, a function
 * of the depth below it, so layer m compresses the layers below j0 (m - k_r deeper than
 * the top at k_r) as the layer before k_r compressed those below j0 - (m - k_r), per unit
 * T0 (a full sum is also taken one layer before each interval, D_{k-1}):
 *     D(k) = D(k_r) + sum_{k_r <= m < k} T0_m [D_{k_r}(j) - D_{k_r - 1}(j)] / T0_{k_r - 1},
 *     j = j0 - (m - k_r),   D_k(j) the compression of layers 0..j-1 at k layers.
 * (The depth a layer's increment reaches is hundreds of layers on a stiff web: g ~ 17 on
 * newsprint, the increment falling like exp(-(g + 1) d t / R) with the depth d.)
 * Work: about N / RS_LANE_RADIUS_STEP nodes in the full sums and h + margin a layer in the
 * tops, RS_LANE_RADIUS_STEP N^2 / 2 + 66 N nodes a reel in all where the full sum at every
 * layer took N^2 / 2 (6054 layers: 0.7 million nodes against 18 million). Error: the deep
 * part's curvature in k over one interval (checked against the full-stack sum at every
 * layer in test_lanes_radius). */
#ifndef RS_REEL_LANES_RADIUS_H
#define RS_REEL_LANES_RADIUS_H

#include "reel/gauge.h"
#include "reelsim/problem.h"
#include "reelsim/status.h"
#include "roll/roll.h"

/* the relative interval between full sums, and the layers below the last full sum's top
 * that are summed exactly with those wound since */
#define RS_LANE_RADIUS_STEP 0.01
#define RS_LANE_RADIUS_MARGIN 16

typedef struct rs_lane_radius {
  int k_r;             /* layers at the interval's start (a full sum; -1: none yet) */
  int k_p;             /* layers at the last full sum (-1: none yet) */
  int next;            /* layers at the next full sum */
  int j0;              /* the deep part: layers 0..j0-1 */
  double deep;         /* m, its compression now (at k_r, then carried) */
  double rate;         /* 1 / T0 of the layer before k_r (0: none, or it was slack) */
  double *prefix, *prev; /* [N + 1] m, the compression of layers 0..j-1 at the last full
                            sum and at the one before */
  double *scratch;     /* [N] m, a full sum's deformed radii */
  rs_reel_strain *eps; /* eps(P) for the top's sums */
  long full_sums;      /* full-stack sums taken */
  long full_nodes;     /* layers summed in them */
  long top_layers;     /* layers summed in the tops */
} rs_lane_radius;

rs_status rs_lane_radius_init(rs_lane_radius *g, int N);
void rs_lane_radius_free(rs_lane_radius *g);
/* *R (m): the roll's deformed outer radius now (rs_roll_layers(roll) layers, the lane's
 * problem pb; film: its entrained films, each compressed by the pressure at its node as
 * rs_reel_deformed_radius has it, or NULL).
 * T0: the wound-on tensions of its layers 0..k-1. Called once per layer, the layers
 * increasing by one (a roll that went back is summed in full). */
rs_status rs_lane_radius_update(rs_lane_radius *g, const rs_problem *pb, const rs_roll *roll,
                                const double *film, const double *T0, double *R);

#endif
