/* Entrained air in the roll (docs/roll-model.md, "Entrained air"): the film under layer j
 * (node j) in series with the stack law at that node's pressure. Runs only when the roll
 * has films (rs_roll_params.air_film), after the stack law and its range check. */
#include "roll/roll_internal.h"

/* E at the nodes [lo, hi) (pressures P) becomes t / (t / E + c), c = h_j p_a / (p_a + P_j)^2 (the law of
 * rs_air_series_modulus), written E - E (c E) / (t + c E): no branch, so the loop
 * vectorises (every node at every increment), and a node without a film (c = 0) keeps E_r
 * bit for bit. */
void roll_air_series(const rs_roll *roll, const double *restrict P, double *restrict E, int lo, int hi)
{
  const double *restrict h = roll->p.air_film;
  const double pa = roll->p.air_pressure, t = roll->p.caliper;
  for (int j = lo; j < hi; ++j) {
    const double p = P[j] > 0.0 ? P[j] : 0.0, q = pa + p;
    const double c = h[j] * pa / (q * q), e = E[j];
    E[j] = e - e * (c * e) / (t + c * e);
  }
}
