/* Entrained air in the roll (docs/roll-model.md, "Entrained air"): the film under layer j
 * (node j) in series with the stack law at that node's pressure, and the nodes at their
 * real radii. Runs only when the roll has films (rs_roll_params.air_film), after the stack
 * law and its range check. */
#include <stdlib.h>

#include "roll/roll_internal.h"
#include "util/error.h"

/* E at the nodes [lo, hi) (pressures P) becomes t / (t / E + c), c = h_j p_a / (p_a + P_j)^2 (the law of
 * rs_air_series_modulus), written E - E (c E) / (t + c E): no branch, so the loop
 * vectorises (every node at every increment), and a node without a film (c = 0) keeps E_r
 * bit for bit.
 * With the nodes at their real radii (roll->air.geom) the stack is homogenised over the real
 * pitch p = t + h of each node's interval: the web carries the hoop force, so over the
 * pitch E_theta' = E_theta t / p, and the radial compliances add over it,
 * p / E_r' = t / E_r + c; the ODE's g^2 = E_theta' / E_r' = (E_theta / E) (t / p)^2 with E the
 * series modulus above, i.e. E_r' as the engine reads it is E (p / t)^2. The decay over one
 * layer, g Delta(ln r) = g p / r, then does not depend on p (g p = sqrt(E_theta t (t / E_r + c))):
 * the pitch enters through the radius only. */
void rsi_roll_air_series(const rs_roll *roll, const double *restrict P, double *restrict E, int lo, int hi)
{
  const double *restrict h = roll->p.air_film;
  const double pa = roll->p.air_pressure, t = roll->p.caliper;
  for (int j = lo; j < hi; ++j) {
    const double p = P[j] > 0.0 ? P[j] : 0.0, q = pa + p;
    const double c = h[j] * pa / (q * q), e = E[j];
    E[j] = e - e * (c * e) / (t + c * e);
  }
  if (roll->air.geom) {
    const double *restrict f = roll->air.pitch_sq;
    for (int j = lo; j < hi; ++j) E[j] *= f[j];
  }
}

/* The arrays of the real radii, when the roll has films and the load beneath each layer
 * (Hakiel's placement keeps r_c + j t: its hoop stresses are point values of the
 * homogenised stack, not the web's) */
rs_status rsi_roll_air_alloc(rs_roll *roll)
{
  const rs_roll_params *p = &roll->p;
  roll->air.kc0 = roll->kc;
  if (!p->air_film || !p->air_radius || !roll->shift) return RS_OK;
  const size_t cap = (size_t)p->max_layers;
  roll->air.node_r = malloc((cap + 1) * sizeof(double));
  roll->air.inv_pitch = malloc((cap + 1) * sizeof(double));
  roll->air.pitch_sq = malloc((cap + 1) * sizeof(double));
  if (!roll->air.node_r || !roll->air.inv_pitch || !roll->air.pitch_sq)
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate a roll of %d layers", p->max_layers);
  for (size_t j = 0; j <= cap; ++j) {
    roll->air.node_r[j] = p->core_radius + (double)j * p->caliper;
    roll->air.inv_pitch[j] = roll->inv_caliper;
    roll->air.pitch_sq[j] = 1.0;
  }
  return RS_OK;
}

void rsi_roll_air_free(rs_roll *roll)
{
  free(roll->air.node_r);
  free(roll->air.inv_pitch);
  free(roll->air.pitch_sq);
  roll->air.node_r = roll->air.inv_pitch = roll->air.pitch_sq = NULL;
}

/* The nodes k_old + 1..k an increment creates, at the radii the caller gave, from the first
 * with a film beneath it. The core condition r y'/y = kc at r_c comes from the hoop strain
 * u / r_c of the first turn: homogenised over its pitch p_0, E_theta and nu_rtheta both
 * scale by t / p_0, so kc + 1 = (E_theta / E_c + nu) t / p_0. */
rs_status rsi_roll_air_nodes(rs_roll *roll, int k_old, int k)
{
  if (!roll->air.node_r) return RS_OK;
  const double t = roll->p.caliper;
  for (int j = k_old + 1; j <= k; ++j) {
    if (!roll->air.geom && roll->p.air_film[j - 1] != 0.0) roll->air.geom = 1;
    if (!roll->air.geom) continue;
    const double r = roll->p.air_radius[j], p = r - roll->air.node_r[j - 1];
    if (!(p > 0.0) || !isfinite(r))
      return RS_ERROR(RS_ERR_INPUT, "entrained air: node %d at r = %g m is not above node %d at %g m",
                      j, r, j - 1, roll->air.node_r[j - 1]);
    roll->air.node_r[j] = r;
    roll->xnode[j] = log(r);
    roll->air.inv_pitch[j - 1] = 1.0 / p;
    roll->air.pitch_sq[j - 1] = (p / t) * (p / t);
    roll->air.inv_pitch[j] = roll->inv_caliper; /* until the node above it exists */
    roll->air.pitch_sq[j] = 1.0;
    if (j == 1) roll->kc = (roll->air.kc0 + 1.0) * (t / p) - 1.0;
  }
  return RS_OK;
}

/* The layer coordinate of radius r: j + (r - r_j) / p_j in the interval [r_j, r_{j+1}] that
 * holds r, found from the last one (CVODE's calls cluster); 1/p_j in *inv_pitch */
double rsi_roll_air_coord(rs_roll *roll, double r, double *inv_pitch)
{
  const double *R = roll->air.node_r;
  const int last = roll->ode.nodes_in_use - 1;
  int j = roll->air.geom_j < 0 ? 0 : roll->air.geom_j > last ? last : roll->air.geom_j;
  while (j > 0 && r < R[j]) --j;
  while (j < last && r >= R[j + 1]) ++j;
  roll->air.geom_j = j;
  *inv_pitch = roll->air.inv_pitch[j];
  return j + (r - R[j]) * roll->air.inv_pitch[j];
}
