/* When the reel asks the nip for the wound-on tension (internal to src/reel/).
 *
 * The nip is the expensive part of a reel with the contact model. The policy decides at
 * each increment whether to solve the nip, and what T0 the layers get in between:
 *   every k  solve at the first layer and then every k layers;
 *   adaptive solve where T0 changes, with a stated tolerance (T0_rtol, relative).
 * Between solves, the nip-induced tension NIT = T0 - Ti is extrapolated linearly in the
 * roll radius from the last two solves and added to the recipe's exact Ti(r): a tension
 * table's kinks cost nothing, a friction nip under a constant load is predicted exactly.
 *
 * Adaptive error control: each solve is also a check of the prediction that wound the
 * layers since the previous one. The prediction error of a linear extrapolation grows
 * with the distance, so the error found at the solve bounds it over the whole interval;
 * if it exceeds the tolerance the reel rewinds to the previous solve (roll state saved
 * there) and retries with a shorter interval, like an ODE step rejection. The interval
 * then grows or shrinks by 0.8 sqrt(tol / error), at most doubling. The last increment is
 * always solved: its solve checks the reel's last interval, which no later one would. */
#ifndef RS_REEL_NIP_POLICY_H
#define RS_REEL_NIP_POLICY_H

#include "nip/nip_seam.h"

typedef struct rs_nip_policy {
  rs_nip_update_kind kind;
  int every;         /* every: layers between solves */
  double rtol;       /* adaptive: tolerance on T0, relative */
  int min_step;      /* layers per increment: solves happen at increment starts */
  int max_step;      /* adaptive: longest interval, layers */
  int have;          /* accepted solves so far (0, 1, 2+) */
  double r1, n1;     /* the older accepted solve: roll radius (m) and NIT (N/m) */
  double r2, n2;     /* the latest accepted solve */
  int j2;            /* layers on the roll at the latest accepted solve */
  int step;          /* current interval, layers */
  int next;          /* layer count at which the next solve is due */
  int last;          /* adaptive: the last increment's first layer, a solve always due */
  long rejected;     /* adaptive: predictions rejected (rewinds) */
} rs_nip_policy;

void rs_nip_policy_init(rs_nip_policy *p, const rs_nip_spec *spec, int layers_per_step,
                        int n_layers);

/* Is a solve due with `layers` on the roll? */
int rs_nip_policy_due(const rs_nip_policy *p, int layers);

/* Makes a solve due with `layers` on the roll, whatever the interval says (a prediction
 * that cannot be used there, e.g. one that gives a negative T0). */
void rs_nip_policy_solve_at(rs_nip_policy *p, int layers);

/* The predicted NIT (N/m) at roll radius r from the accepted solves (hold with one). */
double rs_nip_policy_predict(const rs_nip_policy *p, double r);

/* A solve at `layers` on the roll, roll radius r, gave T0 with web tension Ti. Returns 1 if
 * it is accepted (the interval's prediction held, or there was nothing to check) and
 * records it; 0 if the prediction failed: the caller rewinds to p->j2 layers and carries
 * on (the policy has already shortened its interval). */
int rs_nip_policy_offer(rs_nip_policy *p, int layers, double r, double T0, double Ti);

#endif
