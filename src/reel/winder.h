/* A winder with several nips (docs/nip.md, "Two-drum winders"): the nip the reel asks for
 * the wound-on tension, and the loads of a two-drum winder's nips from its statics.
 *
 * The reel sees one rs_nip whatever the winder: for the problem's one nip (no list, no
 * saturation) it is that nip's own model, so such a problem winds bit for bit as it did;
 * otherwise a "nip set" owns one model per nip, gives each its load at the roll's radius
 * and returns T0 = Ti + sum_k min(NIT_k, S) (S = material.nit_saturation). */
#ifndef RS_REEL_WINDER_H
#define RS_REEL_WINDER_H

#include "reelsim/nip.h"
#include "reelsim/problem.h"

/* g, m/s^2 (standard gravity) */
#define RS_GRAVITY 9.80665

/* The wound roll's weight per unit width (N/m) at outer radius R on a core of radius r_c:
 *     W' = rho g pi (R^2 - r_c^2)
 * rho the web's density (material.density); the core's own weight is not included. */
double rs_winder_roll_weight(double density, double R, double r_c);

/* Statics of a roll of radius R on two drums of radii Rf, Rr whose centres lie at the same
 * height a distance c apart, pressed down by a vertical load V (N/m: its weight and the
 * rider's load). The contact normals point from each drum's centre to the roll's; with
 * equal drums they make theta with the vertical, sin theta = (c/2)/(R + R_d), and
 *     N_front = N_rear = V / (2 cos theta).
 * In general the two force balances give N_f n_f + N_r n_r = (0, V). The tangential
 * (friction) forces at the nips are left out of the balance. RS_ERR_INPUT (naming the
 * numbers) when the roll cannot rest on both drums: it falls between them
 * (R + Rf + R + Rr <= c) or its centre is not between theirs. *angle_deg (may be NULL)
 * gets the front normal's angle from the vertical. */
rs_status rs_winder_drum_loads(double R, double Rf, double Rr, double c, double V,
                               double *N_front, double *N_rear, double *angle_deg);

/* Each nip's load (N/m) at roll radius R: a front or rear drum's from the statics of a
 * two-drum winder (weight of the roll on core radius r_c and every rider's load), every
 * other nip's from its own load recipe. load[] has w->n_nips entries; *total their sum. */
rs_status rs_winder_nip_loads(const rs_winder_spec *w, double density, double R, double r_c,
                              double *load, double *total);

/* The nip the reel asks for T0 (NULL for a problem without a nip). */
rs_status rs_winder_nip_create(const rs_problem *pb, rs_nip **out);

#endif
