/* The centrifugal load of a spinning roll (docs/roll-model.md, "Centrifugal load"). */
#ifndef REELSIM_REEL_SPIN_H
#define REELSIM_REEL_SPIN_H

#include "reelsim/problem.h"
#include "reelsim/reel.h"
#include "reelsim/status.h"

/* The stresses of turns 1..n (faces s[0] = r_c < s[1] < ... < s[n]) under the body force
 * c[j] r (c = rho omega^2, Pa/m^2, per turn j = 0..n-1), each turn an orthotropic annulus
 * with its radial modulus E_r[j]; the core u(r_c) = r_c E_c_inv sr_0, the outer face free.
 * dsr[0..n] are the face radial stresses (dsr[n] = 0), dst[0..n-1] each turn's mean hoop
 * stress. work: 2 (n + 1) doubles. */
rs_status rs_spin_field(int n, const double *s, const double *E_r, double E_theta, double nu,
                        double E_c_inv, const double *c, double *dsr, double *dst, double *work);

/* The spin part of a wound roll (res's rest-state stresses from loads T0 - rho t V^2, the
 * moduli frozen at that state): fills res->at_speed_* (the roll at the last layer's speed)
 * and turns res->sigma_r/sigma_theta/core_pressure into the roll at rest. `updates`: how
 * many times the slowing down of the roll as it grows is applied (0: the default). */
rs_status rs_spin_wound(const rs_problem *pb, rs_reel_result *res, int updates);

#endif
