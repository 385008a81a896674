/* Helpers shared by the roll-engine tests (validation/test_roll.c, hard/test_hard*.c,
 * unit/test_roll_state.c): parameters of a linear-law, Pfeiffer or Hakiel-quadratic roll, winding at a constant tension, and Altmann's closed
 * form for constant E_r. Needs check.h included first. */
#ifndef RS_TESTS_ROLL_HELPERS_H
#define RS_TESTS_ROLL_HELPERS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "roll/roll.h"

static inline rs_roll_params linear_params(double rc, double t, double Et, double Er, double Ec,
                                           int n)
{
  rs_roll_params p = {0};
  p.core_radius = rc;
  p.caliper = t;
  p.E_theta = Et;
  p.nu_rtheta = 0.0;
  p.core_stiffness = Ec;
  p.radial.law = RS_RADIAL_LINEAR;
  p.radial.E_r = Er;
  p.max_layers = n;
  p.rtol = 1e-10;
  p.atol = 1e-12;
  p.max_steps = 0;
  return p;
}

static inline rs_roll_params pfeiffer_params(double rc, double t, double Et, double K1, double K2,
                                             double Ec, int n)
{
  rs_roll_params p = linear_params(rc, t, Et, 1.0, Ec, n);
  p.radial.law = RS_RADIAL_PFEIFFER;
  p.radial.K1 = K1;
  p.radial.K2 = K2;
  CHECK(rs_radial_law_prepare(&p.radial) == RS_OK);
  return p;
}

/* E_r = C0 + C1 P + C2 P^2 (Hakiel's quadratic stack law) */
static inline rs_roll_params hakiel_params(double rc, double t, double Et, double C0, double C1,
                                           double C2, double Ec, int n)
{
  rs_roll_params p = linear_params(rc, t, Et, 1.0, Ec, n);
  p.radial.law = RS_RADIAL_HAKIEL;
  p.radial.n_coef = 3;
  p.radial.C[0] = C0;
  p.radial.C[1] = C1;
  p.radial.C[2] = C2;
  CHECK(rs_radial_law_prepare(&p.radial) == RS_OK);
  return p;
}

/* a roll of n layers wound per_step at a time at tension T0 by add (rs_roll_add_layers, or
 * the reference scheme of tests/roll_frozen.h) */
static inline rs_roll *wind_by(const rs_roll_params *p, int n, int per_step, double T0,
                               rs_status (*add)(rs_roll *, int, const double *))
{
  rs_roll *roll = NULL;
  rs_status st = rs_roll_create(p, &roll);
  CHECK(st == RS_OK);
  if (st) {
    fprintf(stderr, "%s\n", rs_error_message());
    return NULL;
  }
  double *T = malloc((size_t)per_step * sizeof(double));
  for (int i = 0; i < per_step; ++i) T[i] = T0;
  for (int done = 0; done < n;) {
    int m = n - done < per_step ? n - done : per_step;
    st = add(roll, m, T);
    CHECK(st == RS_OK);
    if (st) {
      fprintf(stderr, "%s at %s\n", rs_error_message(), rs_error_where());
      break;
    }
    done += m;
  }
  free(T);
  return roll;
}

static inline rs_roll *wind(const rs_roll_params *p, int n, int per_step, double T0)
{
  return wind_by(p, n, per_step, T0, rs_roll_add_layers);
}

/* Altmann (1968) closed form of one increment for constant g (Hakiel's ODE):
 *   ds(r) = -(T/s) [(r/s)^(g-1) + c (rc/s)^(2g) (r/s)^(-g-1)] / [1 + c (rc/s)^(2g)],
 *   c = (g - 1 - kc)/(g + 1 + kc),   kc = E_theta/E_c + nu - 1.
 * Evaluated through logarithms so g = 700 does not overflow. Returns ds and r ds'. */
static inline void altmann_increment(double g, double kc, double rc, double s, double T, double r,
                              double *ds, double *rds)
{
  double c = (g - 1.0 - kc) / (g + 1.0 + kc);
  double a = exp((g - 1.0) * log(r / s));                       /* (r/s)^(g-1) */
  double b = c * exp(2.0 * g * log(rc / s) - (g + 1.0) * log(r / s));
  double den = 1.0 + c * exp(2.0 * g * log(rc / s));
  *ds = -(T / s) * (a + b) / den;
  *rds = -(T / s) * ((g - 1.0) * a - (g + 1.0) * b) / den;
}

/* sigma_r, sigma_theta per layer and core pressure from the closed form, accumulated, with
 * layer k's load where `placement` puts it: on the roll beneath it (the increment on
 * [rc, s_{k-1}]; a layer's hoop stress is its mean over the turn) or at its own outer
 * radius s_k (Hakiel: layer k itself keeps T/t; hoop stress at the outer radius). */
static inline void altmann_roll(double g, double kc, double rc, double t, int n, double T,
                                double *sr, double *st, double *core_p,
                                rs_load_placement placement)
{
  const int shift = placement == RS_LOAD_BENEATH;
  double core = 0.0;
  for (int j = 0; j < n; ++j) {
    sr[j] = 0.0;
    st[j] = T / t;
  }
  for (int k = 1; k <= n; ++k) {
    const int top = k - shift; /* the node the layer loads */
    double s = rc + top * t, ds, rds;
    altmann_increment(g, kc, rc, s, T, rc, &ds, &rds);
    core += ds;
    double ds_below = ds; /* at the inner face of turn j */
    for (int j = 1; j <= top; ++j) {
      altmann_increment(g, kc, rc, s, T, rc + j * t, &ds, &rds);
      sr[j - 1] += ds;
      /* beneath: the turn's mean hoop stress, the exact integral of d(r ds)/dr over it */
      if (shift)
        st[j - 1] += ((rc + j * t) * ds - (rc + (j - 1) * t) * ds_below) / t;
      else if (j < k)
        st[j - 1] += ds + rds;
      ds_below = ds;
    }
  }
  *core_p = -core;
}

#endif
