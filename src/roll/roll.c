/* The roll build-up engine: Hakiel-type accretion (Hakiel 1987, Tappi J. 70(5)),
 * each increment integrated with SUNDIALS CVODE in a scale-free form.
 *
 * One increment winds layers onto the roll [r_c, s]. Its stress change ds(r) solves
 *     r^2 ds'' + 3 r ds' - (g^2 - 1) ds = 0,     g^2(r) = E_theta / E_r(P(r)),
 * with r_c ds'(r_c) = kc ds(r_c), kc = E_theta/E_c + nu_rtheta - 1 (0 = E_theta/E_c for a
 * rigid core), and ds(s) = -T/s. The core condition is homogeneous, so ds = A y(r) with
 * y(r_c) = 1. Instead of y, which grows like (r/r_c)^(g-1) and overflows for g ~ 700,
 * CVODE integrates the bounded pair, in x = ln r,
 *     w = r y'/y = dy/dx / y :   dw/dx = g^2 - 1 - 2 w - w^2,    w(r_c) = kc   (Riccati)
 *     L = ln y               :   dL/dx = w,                       L(r_c) = 0
 * and ds(r_j) = -(T/s) exp(L(r_j) - L(s)) <= T/s in magnitude, r ds' = w ds. The stable
 * equilibrium of the Riccati equation is w = g - 1 (rate -2g in x), so w stays between kc
 * and g - 1: nothing can overflow. The equation is stiff where g is large: BDF. In x = ln r
 * a roll of constant g has w constant and L linear, so CVODE's steps are set by how g
 * varies, not by the 1/r^q derivatives of ln r (3x fewer steps than integrating in r).
 *
 * Where a layer's load goes (rs_load_placement): by default the new layer k joins at hoop
 * stress T0/t and presses on the roll beneath it, so its increment lives on [r_c, s_{k-1}]
 * with ds(s_{k-1}) = -T0/s_{k-1} and its own outer face is traction free; Hakiel's original
 * condition puts ds(s_k) = -T0/s_k at its outer radius. In the engine the two differ only
 * in the node a layer loads (k - shift) and in whether that node's layer takes the load in
 * its hoop stress (docs/roll-model.md).
 *
 * E_r is frozen at the pressures before the increment (Hakiel). The pressures live at the
 * nodes r_0 = r_c (core) and r_j = s_j (outer radius of layer j); between nodes ln g^2 is a
 * C^1 cubic Hermite (centred slopes). A continuous, once-differentiable g keeps BDF at high
 * order instead of shrinking its steps at every layer boundary (fewer steps than linear
 * interpolation: docs/performance.md), g^2 stays positive, and a constant E_r gives a constant g.
 *
 * A lumped increment of m layers (numerics.layers_per_step) is the sum of its m single-layer
 * increments, all read off one integration: y comes from the core, so layer i's load can be
 * put at its own radius s_i exactly (ds_i = -(T_i/s_i) y/y(s_i)). What one integration cannot
 * give is each layer's own modulus (Hakiel: the pressures just before that layer), so it is
 * a predictor-corrector: integrate with the modulus frozen before the block, take from those
 * sub-increments the mean pressure each node would have carried before each of the layers
 * that reach it, integrate again with the modulus there. Error first order in m - 1, ~60x
 * below that of a block integrated once with its whole load at its outer radius (the
 * tests' reference, tests/roll_frozen.h; docs/accuracy.md). For m = 1 it is exact Hakiel
 * accretion.
 *
 * An increment need not be integrated from the core: below the newest layers the modulus
 * barely changes, so it keeps the deep part of the last integration from the core and
 * integrates from a start node up, the error this adds held to RS_ACCURACY_PER_RTOL x rtol x
 * T0/s (rsi_roll_reuse_start; numerics.reuse; docs/roll-model.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "roll/roll_internal.h"
#include "util/error.h"
#include "util/sundials_compat.h"

void rs_roll_destroy(rs_roll **rollp)
{
  if (!rollp || !*rollp) return;
  rs_roll *roll = *rollp;
  rsi_roll_ode_free(roll);
  rsi_roll_reference_free(roll);
  rsi_roll_profile_free(roll);
  rsi_roll_lazy_free(roll);
  rsi_roll_air_free(roll);
  double *arrays[] = {roll->sigma_r, roll->sigma_theta, roll->w,   roll->L,
                      roll->xnode,   roll->P_mean, roll->dsr,
                      roll->dsh,     roll->scratch.u,   roll->scratch.d, roll->scratch.q,
                      roll->scratch.c, roll->scratch.a, roll->scratch.b};
  for (size_t i = 0; i < sizeof arrays / sizeof *arrays; ++i) free(arrays[i]);
  free(roll->wstep);
  free(roll);
  *rollp = NULL;
}

static rs_status roll_check_params(const rs_roll_params *p)
{
  if (!(p->core_radius > 0.0) || !isfinite(p->core_radius))
    return RS_ERROR(RS_ERR_INPUT, "core radius must be > 0 m (got %g)", p->core_radius);
  if (!(p->caliper > 0.0) || !isfinite(p->caliper))
    return RS_ERROR(RS_ERR_INPUT, "caliper must be > 0 m (got %g)", p->caliper);
  if (!(p->E_theta > 0.0) || !isfinite(p->E_theta))
    return RS_ERROR(RS_ERR_INPUT, "E_theta must be > 0 Pa (got %g)", p->E_theta);
  if (!(p->core_stiffness > 0.0))
    return RS_ERROR(RS_ERR_INPUT, "core stiffness must be > 0 Pa (got %g)", p->core_stiffness);
  if (!(p->nu_rtheta > -1.0 && p->nu_rtheta < 1.0))
    return RS_ERROR(RS_ERR_INPUT, "nu_rtheta must lie in (-1, 1) (got %g)", p->nu_rtheta);
  if (p->max_layers < 1)
    return RS_ERROR(RS_ERR_INPUT, "the roll needs room for at least one layer (got %d)",
                    p->max_layers);
  if (!(p->rtol > 0.0 && p->rtol < 1.0))
    return RS_ERROR(RS_ERR_INPUT, "rtol must lie in (0, 1) (got %g)", p->rtol);
  if (p->reuse != RS_REUSE_ON && p->reuse != RS_REUSE_OFF && p->reuse != RS_REUSE_FIRST_ORDER)
    return RS_ERROR(RS_ERR_INPUT, "unknown reuse setting %d", (int)p->reuse);
  if (p->placement != RS_LOAD_BENEATH && p->placement != RS_LOAD_HAKIEL)
    return RS_ERROR(RS_ERR_INPUT, "unknown load placement %d", (int)p->placement);
  if (p->correction != RS_CORRECTION_ON && p->correction != RS_CORRECTION_OFF)
    return RS_ERROR(RS_ERR_INPUT, "unknown error correction setting %d", (int)p->correction);
  return RS_OK;
}

/* The roll's own arrays for params->max_layers layers (nodes 0..cap) and its components',
 * zeroed; 0 when one could not be allocated */
static int roll_alloc_arrays(rs_roll *roll, size_t cap)
{
  double **const node_arrays[] = {&roll->w,   &roll->L,   &roll->xnode,
                                  &roll->P_mean, &roll->dsr, &roll->dsh,    &roll->scratch.u,
                                  &roll->scratch.d, &roll->scratch.q, &roll->scratch.c,
                                  &roll->scratch.a, &roll->scratch.b};
  double **const layer_arrays[] = {&roll->sigma_r, &roll->sigma_theta};
  int ok = rsi_roll_calloc(node_arrays, sizeof node_arrays / sizeof *node_arrays, cap + 1);
  ok &= rsi_roll_calloc(layer_arrays, 2, cap);
  ok &= rsi_roll_ode_alloc(roll, cap);
  ok &= rsi_roll_reference_alloc(roll, cap);
  ok &= rsi_roll_profile_alloc(roll, cap);
  ok &= rsi_roll_lazy_alloc(roll, cap);
  return ok;
}

rs_status rs_roll_create(const rs_roll_params *params, rs_roll **out)
{
  *out = NULL;
  rs_status st = roll_check_params(params);
  if (st) return st;
  rs_roll *roll = calloc(1, sizeof *roll);
  if (!roll) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the roll");
  roll->p = *params;
  if (roll->p.atol <= 0.0) roll->p.atol = roll->p.rtol;
  if (roll->p.max_steps <= 0) roll->p.max_steps = 100000;
  roll->shift = params->placement == RS_LOAD_BENEATH;
  roll->inv_caliper = 1.0 / params->caliper;
  roll->kc = (isinf(params->core_stiffness) ? 0.0 : params->E_theta / params->core_stiffness) +
             params->nu_rtheta - 1.0;
  const size_t cap = (size_t)params->max_layers;
  if (!roll_alloc_arrays(roll, cap)) {
    rs_roll_destroy(&roll);
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate a roll of %d layers", params->max_layers);
  }
  for (size_t j = 0; j <= cap; ++j) roll->xnode[j] = log(params->core_radius + j * params->caliper);
  if ((st = rsi_roll_air_alloc(roll))) {
    rs_roll_destroy(&roll);
    return st;
  }
  if (rsi_roll_ode_create(roll) != 0) {
    st = RS_ERROR(RS_ERR_INTERNAL, "cannot set up CVODE for the roll: %s",
                  roll->ode.cvode_msg[0] ? roll->ode.cvode_msg : "allocation failed");
    rs_roll_destroy(&roll);
    return st;
  }
  *out = roll;
  return RS_OK;
}

rs_status rs_roll_add_layers(rs_roll *roll, int m, const double *T0)
{
  if (m < 1) return RS_ERROR(RS_ERR_INPUT, "an increment winds at least one layer (got %d)", m);
  if (roll->n + m > roll->p.max_layers)
    return RS_ERROR(RS_ERR_INPUT, "the roll holds %d layers; cannot wind %d more onto %d",
                    roll->p.max_layers, m, roll->n);
  for (int i = 0; i < m; ++i)
    if (!(T0[i] >= 0.0) || !isfinite(T0[i]))
      return RS_ERROR(RS_ERR_INPUT, "wound-on tension of layer %d must be finite and >= 0 (got %g N/m)",
                      roll->n + i + 1, T0[i]);
  const int k_old = roll->n, k = roll->n + m;
  const int top = k - roll->shift; /* the highest node the increment loads */
  /* a lumped block's corrector reads the pressures at every node: no lazy deep part */
  rsi_roll_lazy_configure(roll, m);
  /* a block, or Hakiel's hoop stresses, read w at every node: w stored node by node */
  roll->w_lazy = m == 1 && roll->shift;
  /* the deep part corrected for the drift (roll_profile.c): one layer and its load beneath */
  rsi_roll_profile_configure(roll, roll->lazy.ok && roll->shift && roll->p.reuse == RS_REUSE_ON);
  if (m > 1) rsi_roll_lazy_flush(roll, 0);

  /* with entrained air, the new nodes at their real radii (roll_air.c) */
  rs_status st = rsi_roll_air_nodes(roll, k_old, k);
  if (st) return st;
  /* the predictor: the modulus frozen at the pressures before the increment (Hakiel) */
  st = rsi_roll_set_modulus_stress(roll, top);
  if (st == RS_OK) st = rsi_roll_integrate(roll, top);
  if (st) {
    rsi_roll_start_release(roll, st);
    return st;
  }

  if (m == 1) { /* rsi_roll_block_increment and rsi_roll_commit, fused where it can */
    st = rsi_roll_add_one(roll, T0[0]);
  } else {
    rsi_roll_block_increment(roll, k_old, m, T0, roll->P_mean);
    /* the corrector: each node's modulus at the mean pressure the m single-layer
     * increments would have seen there (the pressure before each, averaged over those
     * that reach the node), from the predictor's sub-increments; integrate again */
    rsi_roll_gather_pressure(roll, top, roll->P_mean);
    st = rsi_roll_set_modulus(roll, top);
    if (st == RS_OK) st = rsi_roll_integrate(roll, top);
    if (st) {
      rsi_roll_start_release(roll, st);
      return st;
    }
    rsi_roll_block_increment(roll, k_old, m, T0, NULL);
    st = rsi_roll_commit(roll, m, T0);
  }
  rsi_roll_start_release(roll, st);
  if (st) return st;
  roll->n = k;
  roll->stats.increments++;
#ifdef RS_ROLL_CHECKS
  /* the state's invariants (roll_check.c): the O(1) ones at every increment; those over
   * the nodes (O(n) each) at every increment up to 512 layers, then at powers of two and
   * every 2048th, beyond 32,768 layers at every n/16th (rounded to a power of two): sixteen
   * a doubling, so that they cost O(n) in all, a bounded share of a winding of any length */
  const int n_now = roll->n;
  int every = 2048;
  while (every < n_now / 16) every *= 2;
  const int full = n_now <= 512 || (n_now & (n_now - 1)) == 0 || n_now % every == 0;
  const char *why = rsi_roll_check_invariants(roll, full);
  if (why)
    return RS_ERROR(RS_ERR_INTERNAL, "the roll's state broke an invariant at layer %d: %s",
                    roll->n, why);
#endif
  return RS_OK;
}

/* ---- queries --------------------------------------------------------------------------- */

int rs_roll_layers(const rs_roll *roll) { return roll->n; }
double rs_roll_layer_radius(const rs_roll *roll, int j)
{
  return roll->air.geom && j + 1 <= roll->n ? roll->air.node_r[j + 1] : roll->p.core_radius + (j + 1) * roll->p.caliper;
}
double rs_roll_outer_radius(const rs_roll *roll)
{
  return roll_node_radius(roll, roll->n);
}
/* the stresses in full: the lazy deep part applied (roll_lazy.c; logically const) */
const double *rs_roll_sigma_r(const rs_roll *roll)
{
  return roll->lazy.top > 0 ? rsi_roll_lazy_view_r((rs_roll *)roll) : roll->sigma_r;
}
double rs_roll_layer_sigma_r(const rs_roll *roll, int j)
{
  return j >= 0 && j < roll->n ? rsi_roll_lazy_sigma(roll, j + 1) : NAN;
}
const double *rs_roll_sigma_theta(const rs_roll *roll)
{
  rs_roll *r = (rs_roll *)roll; /* caches of the state: logically const */
  if (roll->hoop_stale) { /* the turns' equilibrium, from the radial stresses in full */
    if (roll->air.geom)
      rsi_roll_hoop_from_equilibrium_at(r->sigma_theta, rs_roll_sigma_r(roll), rsi_roll_lazy_sigma(roll, 0),
                                    roll->air.node_r, roll->p.caliper, roll->n);
    else
      rsi_roll_hoop_from_equilibrium(r->sigma_theta, rs_roll_sigma_r(roll), rsi_roll_lazy_sigma(roll, 0),
                                 roll->p.core_radius, roll->p.caliper, roll->n);
    r->hoop_stale = 0; /* until the next increment */
    return roll->sigma_theta;
  }
  return roll->lazy.top > 0 && !roll->shift ? rsi_roll_lazy_view_theta(r) : roll->sigma_theta;
}
double rs_roll_core_pressure(const rs_roll *roll) { return -rsi_roll_lazy_sigma(roll, 0); }
double rs_roll_surface_modulus(const rs_roll *roll)
{
  const int node = roll->n - roll->shift; /* the outermost loaded interface */
  double P = node >= 0 && roll->n > 0 ? -rsi_roll_lazy_sigma(roll, node) : 0.0;
  const double E = rs_radial_modulus(&roll->p.radial, P);
  /* entrained air: the film at that interface in series (roll_air.c) */
  return roll->p.air_film && node >= 0 ? rs_air_series_modulus(E, roll->p.caliper, roll->p.air_film[node], P,
                                                                 roll->p.air_pressure)
                                       : E;
}

void rs_roll_get_stats(const rs_roll *roll, rs_roll_stats *stats)
{
  *stats = roll->stats;
}
