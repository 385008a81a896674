/* The winding nip as a contact problem (seed paper, eqs. (12)-(22)): wound roll (upper
 * cylinder 1), sheet, drum or rider (lower cylinder 2), stick/slip friction on both faces
 * of the sheet, and the wound-on tension T0 from the wound-on condition (22).
 *
 * SIGN CONVENTIONS (docs/nip.md)
 *   x        along the sheet, in the direction of travel; the sheet enters at x = -a with
 *            tension Ti and leaves at x = +a with T0 (N/m).
 *   pressure p(x) >= 0, compression positive (the paper's sigma+- = h = -p).
 *   shear    tau+ = tau_xy(x, +h), tau- = tau_xy(x, -h) of the sheet (the paper's), Pa.
 *            The roll feels -tau+ in +x, the drum +tau-. Sheet equilibrium:
 *            N(x) = Ti - int_{-a}^{x} (tau+ - tau-) dx, N(a) = T0.
 *   slip     velocity of the sheet face relative to the cylinder surface, per unit speed:
 *            s+ = eps_sheet - eps_1 + xi1, s- = eps_sheet - eps_2 + xi2, with eps_sheet the
 *            sheet's strain from its unstressed state and eps_k the cylinder's from its state
 *            without the nip. Wound-on condition (22), read with these references
 *            (docs/nip.md): the wound sheet moves with the roll, so
 *            xi1 = eps1_mean - c11 T0 / (2h), eps1_mean = -C0_11 P / (2 pi R1^2) the mean
 *            circumferential strain of the roll surface (n = 0 mode). The paper's xi1 = 0
 *            holds for strains measured from the far-field (wound) states.
 *            In slip the friction on the cylinder (-tau+ resp. +tau-) has the sign of s and
 *            magnitude mu p; stick: s = 0 and |tau| <= mu p. Dissipation is >= 0.
 *   winder   M1/R1 = int tau+ + T0 = share * Ti with share = 1 (center: undriven rider,
 *            M2 = 0), 0 (surface: undriven roll, M1 = 0), torque_share (center-surface).
 *
 * DISCRETISATION: M nodes x_i = -a + i dx, dx = 2a/(M-1). Pressure piecewise linear (hat
 * functions, eq. (16)-(18)), zero at both ends. Shear piecewise CONSTANT on the M-1
 * elements and the stick/slip conditions at each element's upstream node (staggered): the
 * paper's literal collocation (hat shear, stick at the nodes) is singular (docs/nip.md).
 * Unknowns: M-2 pressures, 2(M-1) shears, delta0, eps0, xi2, T0 (3M). Equations:
 * indentation (12) at the nodes (M), stick (13)-(14) or slip (15) per element
 * (2(M-1)), sheet equilibrium and winder torque (20) (2).
 *
 * Thread safety: a handle is used by one thread at a time. No I/O. */
#ifndef RS_NIP_NIP_CONTACT_H
#define RS_NIP_NIP_CONTACT_H

#include "cylinder/cylinder.h"
#include "reelsim/material.h"
#include "nip/nip_seam.h"
#include "reelsim/nip.h"
#include "sheet/sheet.h"
#include "reelsim/status.h"


/* Deep copy into dst (whose arrays are reused or grown); free dst with rs_nip_solution_free. */
rs_status rs_nip_solution_copy(rs_nip_solution *dst, const rs_nip_solution *src);

typedef struct rs_nip_contact_config {
  rs_ortho drum;               /* constants of the lower cylinder (plane strain) */
  double drum_radius;          /* m */
  double drum_core_radius;     /* m, rigid core; 0 < core < radius */
  rs_sheet sheet;
  double mu_roll;              /* upper contact (sheet on roll), >= 0 */
  double mu_drum;              /* lower contact (sheet on drum), >= 0 */
  rs_winder_kind winder;
  double torque_share;         /* center-surface: M1/R1 = share * Ti, in [0, 1] */
  int nodes;                   /* M >= 4 */
  rs_series_opts series;       /* kernel series; terms = 0 and tol = 0: automatic, 1e-7 */
  int max_iterations;          /* active-set solves per half-width; 0: 4 M + 40 */
  double load_rtol;            /* |P(a)/P - 1| at the returned a; 0: 1e-9 */
} rs_nip_contact_config;


/* Checks the configuration (RS_ERR_INPUT naming the scene key: nip.friction.roll,
 * nip.friction.drum, nip.drum.radius / core_radius, nip.nodes, nip.torque_share). */
rs_status rs_nip_contact_create(const rs_nip_contact_config *cfg, rs_nip_contact **out);

/* The roll (upper cylinder) at this call: constants (plane strain), radius R, core R0.
 * Keeps the previous solution for a warm start; rebuilds the roll kernels only when
 * something changed. */
rs_status rs_nip_contact_set_roll(rs_nip_contact *nc, const rs_ortho *roll, double R, double R0);

/* Changes the friction coefficients (>= 0; RS_ERR_INPUT naming nip.friction.roll or
 * .drum otherwise), keeping the warm-start state: continuation in mu. */
rs_status rs_nip_contact_set_friction(rs_nip_contact *nc, double mu_roll, double mu_drum);

/* Forgets the warm-start state (the next solve starts cold). */
void rs_nip_contact_forget(rs_nip_contact *nc);

/* Solves the nip for a given half-width a (m) and incoming tension Ti (N/m); the load is
 * an output (eq. (21)). The stick/slip state: cold, from the solution of the friction
 * conditions as a linear complementarity problem (Lemke), confirmed by the active-set
 * iteration; warm, the iteration from the previous state, with the LCP as the fallback.
 * RS_ERR_SOLVER (with what was tried) if neither gives a consistent state, e.g. a Lemke
 * secondary ray where the width cannot carry the drum's traction. */
rs_status rs_nip_contact_solve_width(rs_nip_contact *nc, double a, double Ti, rs_nip_solution *out);

/* Solves the nip for a given load P (N/m): finds a with |P(a)/P - 1| <= load_rtol
 * (safeguarded secant on ln a; the first trial predicted from the last three solves, or
 * cold from Hertz in series with the sheet). RS_ERR_INPUT naming nip.load if no half-width
 * up to 0.2 min(R1, R2) carries P, or (surface winders) if mu_drum P <= (1 - share) Ti. */
rs_status rs_nip_contact_solve_load(rs_nip_contact *nc, double P, double Ti, rs_nip_solution *out);

/* ---- from a nip spec and the material ------------------------------------------------ */

/* The radial modulus the roll gets: the secant modulus of the stack law between p0 and
 * p0 + dp (Pa), (dp) / int_{p0}^{p0+dp} dP / E_r(P); E_r(p0) when dp = 0. */
double rs_radial_secant_modulus(const rs_radial_law *law, double p0, double dp);

/* The nip seam entry: an rs_nip handle for RS_NIP_CONTACT (used by rs_nip_create). */
rs_status rs_nip_contact_nip_create(const rs_nip_spec *spec, const rs_material *mat, rs_nip **out);

#endif
