/* Orthotropic cylinder on a rigid core: the elastic half of the nip contact solver.
 *
 * A linear, cylindrically orthotropic cylinder (outer radius R, rigid core radius R0,
 * zero displacement at R0) loaded on r = R by a radial pressure p(theta) and a tangential
 * traction q(theta). Constitutive law and equilibrium are eqs. (1)-(5) of the seed paper
 * (docs/cylinder.md re-derives the mode solutions; the paper's eqs. (6)-(8) are damaged):
 *
 *   sigma_r     = A_rr dv_r/dr + A_rt (v_r + dv_t/dtheta)/r
 *   sigma_theta = A_rt dv_r/dr + A_tt (v_r + dv_t/dtheta)/r
 *   tau_rtheta  = G_rt (dv_r/dtheta / r + dv_t/dr - v_t/r)
 *
 * CONVENTIONS (used everywhere in this header)
 *   p      pressure on r = R, compression positive: sigma_r(R) = -p.
 *   q      tangential traction on r = R acting on the cylinder in +theta:  tau_rtheta(R) = q.
 *   w      radial surface displacement, positive INWARD (w = -v_r(R)): "approach", > 0
 *          under a compressive pressure.
 *   u      tangential surface displacement v_theta(R), positive in +theta.
 *   eps    circumferential surface strain eps_theta = (v_r + dv_theta/dtheta)/R at r = R
 *          (tension positive).
 *   x      arc length R*theta on the surface, increasing with theta.
 *
 * Mode pairing (n >= 1): the load p = P cos(n theta), q = Q sin(n theta) produces
 *   w(theta) = (C11 P + C12 Q) cos(n theta),   u(theta) = (C21 P + C22 Q) sin(n theta).
 * The other pairing follows by rotating theta by pi/(2n): p = P sin, q = Q cos gives
 *   w = (C11 P - C12 Q) sin,   u = (-C21 P + C22 Q) cos.
 * n = 0: p = P and q = Q uniform; w = C11 P (C12 = C21 = 0), u = C22 Q (torsion).
 * C is symmetric (Betti) and C11, C22 > 0.
 *
 * Influence kernels (eq. (19)): for a basis function f of amplitude 1 (Pa) centred at
 * x_j and an evaluation point x_i, x_i - x_j = d*dx + shift:
 *   pu  = w   per unit pressure      (even in the offset)
 *   pe  = eps per unit pressure      (even; it contains a local part -c p(x_i))
 *   qu  = w   per unit shear         (odd)
 *   qe  = eps per unit shear         (odd; Hilbert-transform (1/x) kernel)
 * Units: pu, qu in m/Pa; pe, qe in 1/Pa.
 *
 * Thread safety: a cylinder caches per-mode compliances and grows the cache on demand, so
 * functions that take a non-const rs_cylinder * must not run concurrently on one handle.
 * No I/O anywhere in this module. */
#ifndef RS_CYLINDER_CYLINDER_H
#define RS_CYLINDER_CYLINDER_H

#include "reelsim/status.h"


/* Orthotropic constants of eq. (2), Pa. Positive definite: A_rr, A_tt, G_rt > 0 and
 * A_rr A_tt > A_rt^2. */
typedef struct rs_ortho {
  double A_rr, A_rt, A_tt, G_rt;
} rs_ortho;

/* Engineering constants. Poisson convention: nu_ij = -eps_j / eps_i under uniaxial stress
 * in direction i, so that nu_ij / E_i = nu_ji / E_j. E_z, nu_rz, nu_tz (theta-z) are used
 * only in plane strain (eps_z = 0, the long nip line contact). */
typedef struct rs_ortho_engineering {
  double E_r, E_t, E_z;       /* Pa */
  double nu_rt, nu_rz, nu_tz; /* see the convention above */
  double G_rt;                /* Pa */
} rs_ortho_engineering;

/* Plane stress: [A] = inverse of the 2x2 compliance [[1/E_r, -nu_rt/E_r], [., 1/E_t]].
 * Plane strain: [A] = top-left 2x2 block of the inverse of the 3x3 (r, t, z) compliance.
 * RS_ERR_INPUT if a modulus is not positive or the compliance is not positive definite. */
rs_status rs_ortho_from_engineering(const rs_ortho_engineering *e, int plane_strain,
                                    rs_ortho *out);
/* Isotropic: plane strain A_rr = A_tt = E(1-nu)/((1+nu)(1-2nu)), A_rt = E nu/((1+nu)(1-2nu));
 * plane stress A_rr = A_tt = E/(1-nu^2), A_rt = nu E/(1-nu^2); G = E/(2(1+nu)). */
rs_status rs_ortho_isotropic(double E, double nu, int plane_strain, rs_ortho *out);

/* Half-plane limit of the mode compliance, H = lim_{n->inf} n C(n) / R (1/Pa): the surface
 * response of the orthotropic half-plane to p = P cos(kx), q = Q sin(kx) is
 * w = (H11 P + H12 Q) cos(kx) / k, u = (H21 P + H22 Q) sin(kx) / k. For isotropic plane
 * strain H11 = H22 = 2/E*, E* = E/(1-nu^2), and H12 = H21 = -(1-2nu)(1+nu)/E. The
 * effective (Hertz) plane-strain modulus of an orthotropic body is E* = 2/H11. */
rs_status rs_ortho_halfplane(const rs_ortho *c, double H[2][2]);

typedef struct rs_cylinder rs_cylinder;

/* 0 < R0 < R; R0/R in [1e-3, 0.999] (the tested range is 0.01 .. 0.99). */
rs_status rs_cylinder_create(const rs_ortho *c, double R, double R0, rs_cylinder **out);
void rs_cylinder_destroy(rs_cylinder **cyl); /* accepts NULL and *cyl == NULL */
double rs_cylinder_radius(const rs_cylinder *cyl);
double rs_cylinder_core_radius(const rs_cylinder *cyl);
const rs_ortho *rs_cylinder_constants(const rs_cylinder *cyl);

/* Fills the per-mode cache for n = 0..nmax (otherwise done on demand). */
rs_status rs_cylinder_prepare(rs_cylinder *cyl, long nmax);

/* Surface compliance C (m/Pa) of mode n >= 0 (pairing above). Computed from scratch
 * (no cache), so it may take a const handle. */
rs_status rs_cylinder_mode_compliance(const rs_cylinder *cyl, long n, double C[2][2]);

/* The mode solution inside the cylinder for the mode load p = P cos(n theta),
 * q = Q sin(n theta) (n = 0: uniform P and Q): v_r(r, theta) = U cos(n theta),
 * v_theta(r, theta) = V sin(n theta) (n = 0: v_r = U, v_theta = V), U and V in m.
 * Valid for any r > 0 (the analytic continuation beyond [R0, R]). */
rs_status rs_cylinder_mode_field(const rs_cylinder *cyl, long n, double P, double Q, double r,
                                 double *U, double *V);

/* ---- influence kernels -------------------------------------------------------------- */

typedef enum rs_basis {
  RS_BASIS_HAT, /* piecewise linear hat of half-width dx (eq. (18)), centred on a node */
  RS_BASIS_BOX  /* piecewise constant, width dx, centred on an element midpoint */
} rs_basis;

enum { /* which kernels to compute (bit mask) */
  RS_KERNEL_PU = 1,
  RS_KERNEL_PE = 2,
  RS_KERNEL_QU = 4,
  RS_KERNEL_QE = 8,
  RS_KERNEL_ALL = 15
};

/* Series truncation. terms > 0: exactly modes n = 0..terms. terms <= 0: terms is chosen
 * by doubling from 64 until the last doubling changed every requested kernel by less than
 * tol/4 times that kernel's max |value| (tol <= 0: 1e-6), up to max_terms (<= 0: 2^22);
 * RS_ERR_SOLVER if that is not enough. accelerate != 0 subtracts the large-n expansion
 * e0 + e1/n + e2/n^2 of each mode's multiplier and adds its sum back in closed form
 * (docs/cylinder.md); the result is the same series, it converges much faster. */
typedef struct rs_series_opts {
  long terms;
  double tol;
  long max_terms;
  int accelerate;
} rs_series_opts;

/* Kernel values for offsets x_eval - x_centre = d*dx + shift, d = -(M-1)..(M-1), stored
 * at index d + M - 1 (2M-1 values each). For the matrix of eq. (19):
 *   A_ij = pu[i - j + M - 1].
 * Typical use: hat pressure at nodes evaluated at nodes: shift = 0; box shear on elements
 * (centre x_j + dx/2) evaluated at nodes x_i: shift = -dx/2; at element midpoints: 0.
 * Zero-initialise before first use; arrays are reused when large enough;
 * rs_kernels_free releases them. Unrequested kernels are left untouched. */
typedef struct rs_kernels {
  int M;
  int capacity;     /* allocated 2M-1 */
  rs_basis basis;
  double dx, shift; /* m */
  long terms;       /* modes n = 0..terms were summed */
  double *pu, *pe, *qu, *qe;
} rs_kernels;

void rs_kernels_free(rs_kernels *k);
static inline int rs_kernel_index(int M, int d) { return d + M - 1; }

/* RS_ERR_INPUT for M < 2, dx <= 0, dx/R > pi/4 (box: dx/R > pi/2), or a requested qe
 * evaluated exactly on a box edge (log-singular there: a box shear's strain is infinite
 * at its edges). */
rs_status rs_cylinder_kernels(rs_cylinder *cyl, rs_basis basis, double dx, double shift, int M,
                              unsigned what, const rs_series_opts *opts, rs_kernels *out);

/* The nip's two shear kernels at the same offsets in one sweep over the modes: the box's qu
 * into box_qu and the hat's qe into hat_qe, each bit for bit what rs_cylinder_kernels gives
 * (RS_BASIS_BOX, RS_KERNEL_QU; RS_BASIS_HAT, RS_KERNEL_QE) with the same opts; for a given
 * number of terms (opts->terms > 0), else the two calls. */
rs_status rs_cylinder_kernels_shear(rs_cylinder *cyl, double dx, double shift, int M,
                                    const rs_series_opts *opts, rs_kernels *box_qu, rs_kernels *hat_qe);

/* The kernels `from` (any basis, shift) carried to the cell dx as the half-plane's scale
 * (kernels.c): pu lam-scaled less (H11/pi) dx ln lam, qu lam-scaled, pe, qe as they are,
 * lam = dx / from->dx; exact on the half-plane, the curvature's O(ln lam a / R) off on the
 * cylinder. The nip uses it for a much stiffer body (contact.c). */
rs_status rs_kernels_rescale(const rs_kernels *from, double dx, double H11, rs_kernels *to);

/* ---- frictionless normal contact of two cylinders (no sheet) -------------------------- */

typedef struct rs_contact_result {
  int M;
  int capacity;
  double a;       /* m, half-width */
  double dx;      /* m, 2a/(M-1) */
  double P;       /* N/m, load per unit length, trapezoid rule of p (exact for hats) */
  double delta0;  /* m, approach of the core centres */
  double eps0;    /* m, shift of the nip centre (eq. (12)); 0 for a symmetric contact */
  long terms;     /* series terms used */
  double *x;      /* node positions -a + i dx, i = 0..M-1 */
  double *p;      /* nodal pressures, compression positive (paper's h_j = -p_j);
                     p[0] = p[M-1] = 0 */
} rs_contact_result;

void rs_contact_result_free(rs_contact_result *r);

/* Given a, solve eq. (12) with v+ - v- = 0 and no shear:
 *   w1(x_i) + w2(x_i) = delta0 - (x_i^2 - 2 eps0 x_i) / (2 R*),  1/R* = 1/R1 + 1/R2,
 * at all M nodes for p_2..p_{M-1}, delta0, eps0 (LAPACKE_dgesv). M >= 3. */
rs_status rs_contact_frictionless(rs_cylinder *c1, rs_cylinder *c2, double a, int M,
                                  const rs_series_opts *opts, rs_contact_result *out);

/* Given the load P > 0 (N/m), find a with P(a) = P to relative accuracy rtol (<= 0: 1e-10)
 * by bracketing and Brent's method on the monotone P(a), a <= a_max (<= 0:
 * 0.2 min(R1, R2)). RS_ERR_INPUT if P needs a > a_max; RS_ERR_SOLVER if the root finder
 * fails within its iteration bound. */
rs_status rs_contact_frictionless_load(rs_cylinder *c1, rs_cylinder *c2, double P, int M,
                                       const rs_series_opts *opts, double a_max, double rtol,
                                       rs_contact_result *out);

#endif
