/* Sharing a total across the lanes of the width (issue: lanes across the
 * width).
 *
 * Both couplings between the lanes have one form: lane i carries
 *     q_i(x) = max(0, a_i x + b_i)        (a_i > 0, per unit width)
 * of a quantity whose width-weighted total is held by the machine,
 *     sum_i w_i q_i(x) = Q,
 * and x is the one unknown shared by every lane:
 *   - the web's tension on a center winder: x = e, the mean machine-direction
 * strain, a_i = E_theta,i t_i, b_i = a_i (R_i / Rbar - 1) + (f_i - 1) Tbar, Q =
 * Tbar W;
 *   - a rigid lay-on roller's load: x = the roller's approach s, a_i = k_i the
 * lane's contact stiffness, b_i = k_i (R_i - max R), Q = Nbar W. The left side
 * is continuous, piecewise linear and nondecreasing in x, so for Q > 0 the root
 * is one x, found exactly on the segment between two breakpoints z_i = -b_i /
 * a_i. */
#ifndef RS_REEL_LANES_SHARE_H
#define RS_REEL_LANES_SHARE_H

#include "reelsim/status.h"

/* Solves sum_i w_i max(0, a_i x + b_i) = total for x (n >= 1 lanes, w_i > 0,
 * a_i > 0, total > 0, every input finite), writing x and each lane's share q_i
 * = max(0, a_i x + b_i) (q may be NULL). order is scratch of n ints. The
 * shares' weighted sum equals total to round-off; lanes whose breakpoint lies
 * at or above x get exactly 0. */
rs_status rsi_lanes_share(int n, const double *w, const double *a,
                          const double *b, double total, int *order, double *x,
                          double *q);

#endif
