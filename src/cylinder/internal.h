/* Private parts of the cylinder module (cylinder/cylinder.h). */
#ifndef RS_CYLINDER_INTERNAL_H
#define RS_CYLINDER_INTERNAL_H

#include "cylinder/cylinder.h"

#include <math.h>

#define RS_PI 3.14159265358979323846

/* Constants divided by A_ref = max(A_rr, A_tt): all mode algebra is done with these. */
typedef struct rs_cyl_nd {
  double rr, rt, tt, g;
} rs_cyl_nd;

/* Per-mode data in the scaled form used by the series. With C(n) in m/Pa,
 *   C(n) = (R / A_ref) * F(n) / n    (n >= 1),   C(0) = (R / A_ref) * F(0),
 * so F(n) -> F_inf (the half-plane, O(1)) as n -> infinity. */
typedef struct rs_cyl_mode {
  double F[2][2];
} rs_cyl_mode;

struct rs_cylinder {
  rs_ortho c;
  double R, R0;
  double A_ref;
  rs_cyl_nd nd;
  double rho0;           /* R0 / R */
  /* large-n expansion F(n) = e[0] + e[1]/n + e[2]/n^2 + O(1/n^3) (entry-wise) */
  double Fexp[3][2][2];
  rs_cyl_mode *cache;    /* modes 0..ncache-1 */
  long ncache, capcache;
};

/* ortho.c: RS_ERR_INPUT unless the constants are finite and positive definite. */
rs_status rs_cyl_check_ortho(const rs_ortho *c);

/* modes.c: F(n) of mode n >= 0 from the boundary-value problem. */
rs_status rs_cyl_mode_solve(const rs_cyl_nd *nd, double rho0, long n, double F[2][2]);

/* modes.c: the algebraic (core-free) part F_alg(eps), eps = 1/n, analytic in eps;
 * eps = 0 is the half-plane. */
rs_status rs_cyl_mode_algebraic(const rs_cyl_nd *nd, double eps, double F[2][2]);

/* modes.c: displacement (U, V) in units of R/A_ref at rho = r/R (L = ln rho,
 * L0 = ln(rho0/rho), both to full relative accuracy) for the mode load (P, Q). */
rs_status rs_cyl_mode_eval(const rs_cyl_nd *nd, double rho0, long n, double P, double Q,
                           double rho, double L, double L0, double *U, double *V);

/* sums.c: closed-form sums over n >= 1 of a_n cos(n t)/n^k and a_n sin(n t)/n^k, k = 0,1,2,
 * where a_n are the cosine coefficients (on the circle) of a basis function f of
 * half-width w (radians) centred at 0: f(theta) = a_0 + sum a_n cos(n theta).
 * out[0..2] = cos sums k = 0,1,2; out[3..5] = sin sums. Returns 0, or -1 when the sin
 * k = 0 sum is infinite (t on a jump of f). t is reduced to [-pi, pi). */
int rs_cyl_closed_sums(rs_basis basis, double w, double t, double out[6]);

/* sums.c: the same, only the cos sums (mask bit 1: out[0..2]) and/or the sin sums (bit 2:
 * out[3..5]); the others are left untouched. */
int rs_cyl_closed_sums_part(rs_basis basis, double w, double t, unsigned mask, double out[6]);

/* sums.c: the same (mask as above) at nk offsets on a grid of half cells, t_i = h2[i] c/2
 * with c the cell (c = w for a hat, 2 w for a box), none within w of +-pi: the boundary
 * values of the pieces, shared by neighbouring offsets, are evaluated once (a third of the
 * work for a hat, half for a box). out[i] as rs_cyl_closed_sums_part's; the sin k = 0 sum
 * on a jump of f is infinite as there (its return value, here not reported). */
rs_status rs_cyl_closed_sums_grid(rs_basis basis, double w, int nk, const long *h2,
                                  unsigned mask, double (*out)[6]);

/* t reduced to [-pi, pi] as remainder(t, 2 pi) does, which leaves |t| < pi as it is */
static inline double rs_cyl_wrap(double t)
{
  return fabs(t) < RS_PI ? t : remainder(t, 2 * RS_PI);
}

/* sums.c: Fourier cosine coefficient a_n (n >= 0) of the basis on the circle. */
double rs_cyl_basis_coef(rs_basis basis, double w, long n);

/* a_n for n >= 1 from s = sin(n y), y = w/2 for a hat, w for a box (what kernels.c advances
 * by rotation): hat (w/pi) (sin(n w/2) / (n w/2))^2, box 2 sin(n w) / (pi n) */
static inline double rs_cyl_basis_coef_sin(rs_basis basis, double w, long n, double s)
{
  if (basis == RS_BASIS_HAT) {
    double sc = s / (0.5 * (double)n * w);
    return w / RS_PI * sc * sc;
  }
  return 2.0 / (RS_PI * (double)n) * s;
}

/* cylinder.c: makes sure the cache holds modes 0..nmax. */
rs_status rs_cyl_cache_reserve(rs_cylinder *cyl, long nmax);

#endif
