/* An exact ring-by-ring statics oracle for a linear orthotropic roll (a test oracle: no
 * code of the engine is used).
 *
 * Every turn is an annulus [s_{i-1}, s_i] of a cylindrically orthotropic, linear, plane
 * stress material (E_theta, E_r, nu: eps_theta = (sigma_theta - nu sigma_r)/E_theta). In
 * an annulus equilibrium sigma_theta = d(r sigma_r)/dr and compatibility give Lekhnitskii's
 * closed form
 *     sigma_r = a (r/R)^(g-1) + b (r/R)^(-g-1),   sigma_theta = g [a (r/R)^(g-1) - b (r/R)^(-g-1)],
 *     u = r (sigma_theta - nu sigma_r) / E_theta,  g^2 = E_theta / E_r,
 * so an annulus maps the state (sigma_r, u) at its inner face to that at its outer face by
 * one 2 x 2 solve (a, b from the inner face). Interfaces carry sigma_r and u continuously.
 * The core is a state at r_c: rigid (u = 0), elastic (u = r_c sigma_r / E_c) or a real
 * isotropic tube (an annulus of its own, g = 1, with a free bore), propagated the same way.
 *
 * Winding layer k: the body that carries its load is the core and turns 1..top, with
 * top = k - 1 when the layer presses on the roll beneath it (it joins at T0/t, a thin ring
 * pressing T0/s_{k-1}) or top = k when its load is put at its own outer radius (Hakiel).
 * The increment is the body's response to sigma_r(s_top) = -T0/s_top: one solution from
 * the core outwards, scaled. sigma_r of turn j is read at its outer radius s_j; its hoop
 * stress is the turn's mean (its tension / t) when the load goes beneath, and the value at
 * s_j in Hakiel's accounting, as the engine reports them. Cost O(N^2) annulus maps. */
#ifndef RS_TESTS_RING_STATICS_H
#define RS_TESTS_RING_STATICS_H

#include <math.h>
#include <stdlib.h>

typedef enum ring_core_kind { RING_CORE_RIGID, RING_CORE_ELASTIC, RING_CORE_TUBE } ring_core_kind;

typedef struct ring_roll {
  double rc, t;              /* core radius, caliper (m) */
  double E_theta, E_r, nu;   /* web (Pa) */
  ring_core_kind core;
  double E_c;                /* elastic core: u = r_c sigma_r / E_c */
  double bore, E_tube, nu_tube; /* tube core: inner radius, isotropic modulus and Poisson */
  int beneath;               /* 1: layer k loads s_{k-1}; 0: s_k (Hakiel) */
} ring_roll;

/* (sigma_r, u) at R_in -> at R_out through an annulus of ratio g, modulus E_theta, nu;
 * also sigma_theta at R_out */
static inline void ring_map(double g, double Et, double nu, double R_in, double R_out,
                            double *sr, double *u, double *st_out)
{
  const double st_in = Et * *u / R_in + nu * *sr;
  const double a = 0.5 * (*sr + st_in / g), b = 0.5 * (*sr - st_in / g);
  const double rho = R_out / R_in, up = pow(rho, g - 1.0), dn = pow(rho, -g - 1.0);
  const double s_r = a * up + b * dn, s_t = g * (a * up - b * dn);
  *sr = s_r;
  *u = R_out * (s_t - nu * s_r) / Et;
  *st_out = s_t;
}

/* Winds n layers at tension T[k-1] (N/m) and returns sigma_r, sigma_theta per layer (at
 * its outer radius) and the core pressure. Work arrays of n + 1. */
static inline void ring_wind(const ring_roll *R, int n, const double *T, double *sr, double *st,
                             double *core_p)
{
  const double g = sqrt(R->E_theta / R->E_r);
  double *nsr = malloc((size_t)(n + 1) * sizeof(double));
  double *nst = malloc((size_t)(n + 1) * sizeof(double));
  double core = 0.0;
  for (int j = 0; j < n; ++j) sr[j] = st[j] = 0.0;
  for (int k = 1; k <= n; ++k) {
    const int top = R->beneath ? k - 1 : k;
    /* one solution from the core: state at r_c */
    double s_r = 1.0, u = 0.0, s_t = 0.0;
    if (R->core == RING_CORE_ELASTIC) {
      u = R->rc / R->E_c;
    } else if (R->core == RING_CORE_TUBE) {
      s_r = 0.0; /* free bore */
      u = 1.0;
      ring_map(1.0, R->E_tube, R->nu_tube, R->bore, R->rc, &s_r, &u, &s_t);
    }
    nsr[0] = s_r;
    for (int i = 1; i <= top; ++i) {
      ring_map(g, R->E_theta, R->nu, R->rc + (i - 1) * R->t, R->rc + i * R->t, &s_r, &u, &s_t);
      nsr[i] = s_r;
      nst[i] = s_t;
    }
    const double scale = -T[k - 1] / (R->rc + top * R->t) / nsr[top];
    core += scale * nsr[0];
    for (int j = 1; j <= top; ++j) {
      sr[j - 1] += scale * nsr[j];
      if (j < k) /* beneath: the turn's mean, the exact integral [r sigma_r] / t of its hoop
                    stress; Hakiel: the value at its outer radius, as Hakiel accounts it */
        st[j - 1] += R->beneath ? scale * ((R->rc + j * R->t) * nsr[j] -
                                           (R->rc + (j - 1) * R->t) * nsr[j - 1]) / R->t
                                : scale * nst[j];
    }
    st[k - 1] += T[k - 1] / R->t; /* the new layer joins at T0/t */
  }
  *core_p = -core;
  free(nsr);
  free(nst);
}

#endif
