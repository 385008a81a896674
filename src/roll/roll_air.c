/* Entrained air in the roll (docs/roll-model.md, "Entrained air"): the film under layer j
 * (node j) in series with the stack law at that node's pressure. Runs only when the roll
 * has films (rs_roll_params.air_film), after the stack law and its range check. */
#include "roll/roll_internal.h"

/* E_r at the nodes 0..k becomes t / (t / E_r + h_j p_a / (p_a + P_j)^2) */
void roll_air_modulus(rs_roll *roll, int k)
{
  const double *h = roll->p.air_film, pa = roll->p.air_pressure, t = roll->p.caliper;
  for (int j = 0; j <= k; ++j)
    roll->Er[j] = rs_air_series_modulus(roll->Er[j], t, h[j], roll->P_node[j], pa);
}
