/* Lanes across the width (internal to src/reel/; the model: docs/lanes.md).
 *
 * A problem with lanes (pb->lanes.count > 0) is wound by rs_lanes_wind instead of the one
 * roll of rs_reel_wind: one rs_reel_state per lane on the shared core, each with its own
 * problem (its caliper) and the lanes' coupling as its tension phase (effect.h: the web
 * tension and nip load its loop and its nip read, set before each layer), all stepped one
 * layer at a time with the coupling solved between the layers:
 *   R_i   lane i's deformed outer radius on its current state (lanes_radius.h)
 *   e     the web's mean strain: sum w_i max(0, E_theta t_i (e + R_i/Rbar - 1)
 *                                            + (f_i - 1) Tbar) = Tbar W  (rsi_lanes_share)
 *   N_i   the nip load: uniform (Nbar), or a rigid roller: sum w_i max(0, k_i (s + R_i - max R))
 *         = Nbar W, k_i the lane's surface modulus (rs_roll_surface_modulus)
 * The lanes are stepped in parallel (POSIX threads, a barrier per layer). */
#ifndef RS_REEL_LANES_H
#define RS_REEL_LANES_H

#include "reel/lanes_radius.h"
#include "reelsim/reel.h"

/* As rs_reel_wind, for pb->lanes.count > 0: *out holds the width-weighted mean roll and,
 * in (*out)->lanes, every lane's record. */
rs_status rs_lanes_wind(const rs_problem *pb, const rs_reel_options *opts, rs_reel_result **out);

/* One lane while the reel winds (lanes.c, lanes_collect.c). */
typedef struct rs_lane {
  rs_problem pb;            /* the lane's problem */
  struct rs_reel_state *s;  /* its winding state */
  rs_lane_radius radius;    /* its deformed outer radius, layer by layer */
  double R;                 /* m, its deformed outer radius now */
  double T, load;           /* N/m, its web tension and nip load for the next layer (its
                               tension phase, lanes.c) */
  rs_status st;             /* its step's status, the message copied from its thread */
  char msg[1024];
  rs_reel_result *res;      /* after finish */
} rs_lane;

/* Fills res->lanes and the width means from the lanes' finished results (lanes_collect.c);
 * lr: the per-layer records the driver kept (web tension, slack, strain, nip load). */
rs_status rs_lanes_collect(const rs_problem *pb, rs_lane *lane, rs_lanes_result *lr,
                           rs_reel_result **out);
/* The per-layer records of n lanes and N layers (NULL arrays where not kept). */
rs_lanes_result *rs_lanes_result_new(int n, int N, int with_nip);

#endif
