/* Fourier mode solutions of the orthotropic cylinder on a rigid core (seed paper eqs. (1)-(5),
 * re-derived in docs/cylinder.md) and the per-mode surface compliance.
 *
 * Mode n >= 2: v_r = U(r) cos(n theta), v_theta = V(r) sin(n theta) with U, V ~ r^lambda,
 *   A_rr G lambda^4 - mu_n lambda^2 + A_tt G (n^2 - 1)^2 = 0                          (7)
 *   mu_n = (A_rr + A_tt) G + n^2 (A_rr A_tt - A_rt^2 - 2 A_rt G).
 * Roots come in +-pairs: two "growing" (Re > 0) l1, l3 and two decaying -l1, -l3, real or a
 * complex-conjugate pair. Everything below uses only the symmetric functions
 *   s = l1 + l3, p = l1 l3, d2 = (l1 - l3)^2   (real in both cases),
 * scaled by n (ell = lambda/n), and the basis of each pair is
 *   avg = (F(l1) + F(l3))/2,   dd = (F(l1) - F(l3))/(l1 - l3),  F(l) = w(l) rho^l,
 * which is real, stays independent through a double root (dd -> rho^l ln rho), and is O(1):
 * growing functions are normalised at r = R (rho = r/R), decaying ones at r = R0
 * ((R0/r)^l). n = 1 has the double root 0 (rigid translation and a log solution), n = 0
 * decouples into a radial and a torsion problem. */
#include "cylinder/internal.h"
#include "util/error.h"

#include <math.h>
#include <string.h>

typedef struct poly { double c[4]; } poly; /* c0 + c1 ell + c2 ell^2 + c3 ell^3 */

static poly poly_lin(double c0, double c1) { return (poly){{c0, c1, 0, 0}}; }
/* (a0 + a1 ell) b + sc c, b of degree <= 2 (the families' product, written out: two
 * families for every mode of every new roll) */
static poly lin_mul_add(double a0, double a1, const poly *b, const poly *c, double sc)
{
  poly r;
  r.c[0] = a0 * b->c[0] + sc * c->c[0];
  r.c[1] = a0 * b->c[1] + a1 * b->c[0] + sc * c->c[1];
  r.c[2] = a0 * b->c[2] + a1 * b->c[1] + sc * c->c[2];
  r.c[3] = a1 * b->c[2] + sc * c->c[3];
  return r;
}
static double poly_val(poly a, double x)
{
  return ((a.c[3] * x + a.c[2]) * x + a.c[1]) * x + a.c[0];
}

/* The four polynomial vectors of one root family: displacement (wU, wV) and traction
 * times r / A_ref (tR, tT), as functions of ell; sign = +1 for the growing r^(n ell),
 * -1 for the decaying (R0/r)^(n ell). eps = 1/n. Growing: (wU, wV) is the null vector of
 * the second row of the mode matrix; decaying: of the first row (docs/cylinder.md):
 * neither vanishes for Re ell > 0. */
typedef struct family { poly wU, wV, tR, tT; } family;

static family make_family(const rs_cyl_nd *m, double eps, int sign)
{
  family f;
  if (sign > 0) {
    f.wU = (poly){{-m->g * eps * eps - m->tt, 0, m->g, 0}};
    f.wV = poly_lin((m->g + m->tt) * eps, m->g + m->rt);
  } else {
    f.wU = poly_lin((m->g + m->tt) * eps, m->g + m->rt);
    f.wV = (poly){{-m->tt * eps * eps - m->g, 0, m->rr, 0}};
  }
  double sg = sign;
  /* sigma_r r/A = A_rr r U' + A_rt (U + n V);  tau r/A = G (r V' - V - n U)  (all / n^3 after
   * the n^2 scaling of w), with r d/dr = +-n ell on the two families */
  f.tR = lin_mul_add(m->rt * eps, sg * m->rr, &f.wU, &f.wV, m->rt);
  f.tT = lin_mul_add(-m->g * eps, sg * m->g, &f.wV, &f.wU, -m->g);
  return f;
}

/* Symmetric functions of the scaled roots of (7) for eps = 1/n (eps = 0: half-plane),
 * written so that no difference of large terms is formed: with q = sqrt(A_rr A_tt),
 *   mu -+ sqrt(kappa) = G (sqrt A_rr +- sqrt A_tt)^2 + n^2 (q +- A_rt)(q -+ A_rt -+ 2G). */
typedef struct roots { double s, p, d2; } roots;

static roots scaled_roots(const rs_cyl_nd *m, double eps)
{
  double q = sqrt(m->rr * m->tt), srr = sqrt(m->rr), stt = sqrt(m->tt);
  double e2 = eps * eps;
  double plus = m->g * (stt - srr) * (stt - srr) * e2 + (q - m->rt) * (q + m->rt + 2 * m->g);
  double minus = m->g * (srr + stt) * (srr + stt) * e2 + (q + m->rt) * (q - m->rt - 2 * m->g);
  roots r;
  r.s = sqrt(plus / (m->rr * m->g));
  r.p = sqrt(m->tt / m->rr) * (1 - e2);
  r.d2 = minus / (m->rr * m->g);
  return r;
}

/* A(X) = (e^{l1 X} + e^{l3 X})/2 and E(X) = (e^{l1 X} - e^{l3 X})/(l1 - l3). */
static void exp_pair(const roots *r, double X, double *A, double *E)
{
  if (X == 0) {
    *A = 1;
    *E = 0;
    return;
  }
  if (r->d2 >= 0) {
    double d = sqrt(r->d2);
    double l1 = 0.5 * (r->s + d);
    double l3 = r->p / l1; /* no cancellation */
    double e1 = exp(l1 * X), e3 = exp(l3 * X);
    *A = 0.5 * (e1 + e3);
    double y = 0.5 * d * X;
    if (fabs(y) > 0.25) {
      *E = (e1 - e3) / d;
    } else {
      double y2 = y * y; /* sinh(y)/y */
      double sh = 1 + y2 / 6 * (1 + y2 / 20 * (1 + y2 / 42 * (1 + y2 / 72 * (1 + y2 / 110))));
      *E = exp(0.5 * r->s * X) * X * sh;
    }
  } else {
    double b = sqrt(-r->d2);
    double y = 0.5 * b * X, ex = exp(0.5 * r->s * X);
    *A = ex * cos(y);
    *E = ex * X * (fabs(y) > 1e-4 ? sin(y) / y : 1 - y * y / 6);
  }
}

/* avg and dd of one polynomial over the root pair at X. */
static void pair_values(const roots *r, poly P, double A, double E, double *avg, double *dd)
{
  double s = r->s, p = r->p;
  double m1 = 0.5 * s, m2 = 0.5 * (s * s - 2 * p), m3 = 0.5 * s * (s * s - 3 * p);
  double Pm = P.c[0] + P.c[1] * m1 + P.c[2] * m2 + P.c[3] * m3;
  double Pd = P.c[1] + P.c[2] * s + P.c[3] * (s * s - p);
  *avg = Pm * A + 0.25 * r->d2 * Pd * E;
  *dd = Pm * E + Pd * A;
}

/* The basis of mode n: 4 functions (columns), rows U, V, sigma_r r/(A nf), tau r/(A nf)
 * with nf = n (n >= 2) or 1, in units where U_phys = (R/A_ref) U. */
typedef struct mode_basis {
  long n;
  double rho0, nf;
  int kind; /* 0, 1, 2 */
  roots rt;
  family grow, dec;
  double lam, k1, k0; /* n = 1: lambda_11, (G+A_rt)/(G+A_tt); n = 0: sqrt(A_tt/A_rr) */
  rs_cyl_nd m;
} mode_basis;

static rs_status basis_init(const rs_cyl_nd *m, double rho0, long n, mode_basis *b)
{
  memset(b, 0, sizeof *b);
  b->n = n;
  b->rho0 = rho0;
  b->m = *m;
  if (n < 0) return RS_ERROR(RS_ERR_INPUT, "mode number n = %ld < 0", n);
  if (n == 0) {
    b->kind = 0;
    b->nf = 1;
    b->k0 = sqrt(m->tt / m->rr);
  } else if (n == 1) {
    b->kind = 1;
    b->nf = 1;
    double mu1 = m->rr * m->tt - m->rt * m->rt + m->g * (m->rr + m->tt - 2 * m->rt);
    b->lam = sqrt(mu1 / (m->rr * m->g));
    b->k1 = (m->g + m->rt) / (m->g + m->tt);
    b->grow = make_family(m, 1.0, +1);
    b->dec = make_family(m, 1.0, -1);
  } else {
    b->kind = 2;
    b->nf = (double)n;
    double eps = 1.0 / (double)n;
    b->rt = scaled_roots(m, eps);
    b->grow = make_family(m, eps, +1);
    b->dec = make_family(m, eps, -1);
  }
  return RS_OK;
}

/* Values of the 4 basis functions at rho = r/R: out[row][col], rows U, V, Tr, Tt (the
 * first `rows` of them; the others are left 0). L = ln(r/R), L0 = ln(R0/r) are passed in
 * because n L is needed to full relative accuracy for n up to 1e5 (callers form them with
 * log1p). n >= 2: AE, when given, holds exp_pair's A, E at the one nonzero of n L, n L0
 * (the two ends of the cylinder share it: X = n ln(R0/R) for both families). */
static void basis_eval_rows(const mode_basis *b, double rho, double L, double L0, int rows,
                            const double *AE, double out[4][4])
{
  const rs_cyl_nd *m = &b->m;
  memset(out, 0, 16 * sizeof(double));
  if (b->kind == 0) {
    double k = b->k0, eg = exp(k * L), ed = exp(k * L0);
    out[0][0] = eg;
    out[0][1] = ed;
    out[2][0] = (m->rr * k + m->rt) * eg;
    out[2][1] = (m->rt - m->rr * k) * ed;
    out[1][2] = rho;
    out[1][3] = b->rho0 / rho;
    out[3][3] = -2 * m->g * b->rho0 / rho;
    return;
  }
  if (b->kind == 1) {
    double l = b->lam, eg = exp(l * L), ed = exp(l * L0);
    const family *g = &b->grow, *d = &b->dec;
    out[0][0] = poly_val(g->wU, l) * eg;
    out[1][0] = poly_val(g->wV, l) * eg;
    out[2][0] = poly_val(g->tR, l) * eg;
    out[3][0] = poly_val(g->tT, l) * eg;
    out[0][1] = poly_val(d->wU, l) * ed;
    out[1][1] = poly_val(d->wV, l) * ed;
    out[2][1] = poly_val(d->tR, l) * ed;
    out[3][1] = poly_val(d->tT, l) * ed;
    out[0][2] = 1; /* rigid translation: U = 1, V = -1, no stress */
    out[1][2] = -1;
    out[0][3] = L; /* log solution: U = ln rho, V = -ln rho - k1 */
    out[1][3] = -L - b->k1;
    out[2][3] = m->rr - m->rt * b->k1;
    out[3][3] = m->g * (b->k1 - 1);
    return;
  }
  double nn = (double)b->n;
  const family *fam[2] = {&b->grow, &b->dec};
  double X[2] = {nn * L, nn * L0};
  for (int f = 0; f < 2; ++f) {
    double A, E;
    if (AE && X[f] != 0) {
      A = AE[0];
      E = AE[1];
    } else {
      exp_pair(&b->rt, X[f], &A, &E);
    }
    const poly *P[4] = {&fam[f]->wU, &fam[f]->wV, &fam[f]->tR, &fam[f]->tT};
    for (int row = 0; row < rows; ++row)
      pair_values(&b->rt, *P[row], A, E, &out[row][2 * f], &out[row][2 * f + 1]);
  }
}

static void basis_eval(const mode_basis *b, double rho, double L, double L0, double out[4][4])
{
  basis_eval_rows(b, rho, L, L0, 4, NULL, out);
}

/* Gaussian elimination with partial pivoting on a row-equilibrated n x n system (n <= 4)
 * with nrhs right-hand sides, in place. Inlined where n and nrhs are constants, so that
 * its loops are unrolled (a call per mode of every new roll: the nip's mode cache). */
static inline rs_status small_solve(int n, double A[4][4], int nrhs, double B[4][2])
{
  for (int i = 0; i < n; ++i) {
    double mx = 0;
#pragma GCC unroll 4
    for (int j = 0; j < n; ++j) {
      double v = fabs(A[i][j]);
      mx = v > mx ? v : mx; /* fmax without the call: mx starts at 0, a NaN entry leaves it */
    }
    if (!(mx > 0) || !isfinite(mx)) return RS_ERROR(RS_ERR_SOLVER, "mode system row %d is %g", i, mx);
#pragma GCC unroll 4
    for (int j = 0; j < n; ++j) A[i][j] /= mx;
#pragma GCC unroll 2
    for (int k = 0; k < nrhs; ++k) B[i][k] /= mx;
  }
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int i = c + 1; i < n; ++i)
      if (fabs(A[i][c]) > fabs(A[piv][c])) piv = i;
    if (!(fabs(A[piv][c]) > 1e-300)) return RS_ERROR(RS_ERR_SOLVER, "singular mode system");
    if (piv != c) {
#pragma GCC unroll 4
      for (int j = 0; j < n; ++j) {
        double t = A[c][j]; A[c][j] = A[piv][j]; A[piv][j] = t;
      }
#pragma GCC unroll 2
      for (int k = 0; k < nrhs; ++k) {
        double t = B[c][k]; B[c][k] = B[piv][k]; B[piv][k] = t;
      }
    }
    for (int i = c + 1; i < n; ++i) {
      double f = A[i][c] / A[c][c];
      if (f == 0) continue;
      for (int j = c; j < n; ++j) A[i][j] -= f * A[c][j];
#pragma GCC unroll 2
      for (int k = 0; k < nrhs; ++k) B[i][k] -= f * B[c][k];
    }
  }
#pragma GCC unroll 2
  for (int k = 0; k < nrhs; ++k)
    for (int i = n - 1; i >= 0; --i) {
      double s = B[i][k];
      for (int j = i + 1; j < n; ++j) s -= A[i][j] * B[j][k];
      B[i][k] = s / A[i][i];
    }
  return RS_OK;
}

/* Coefficients of the unit loads (P = 1: column 0, Q = 1: column 1):
 * U(R0) = V(R0) = 0, nf * (Tr, Tt)(R) = (-P, Q). at1: the basis at r = R (rho 1). */
static rs_status mode_coefficients(const mode_basis *b, double coef[4][2], double at1[4][4])
{
  double at0[4][4], A[4][4];
  double l0 = log(b->rho0), AE[2], *ae = NULL;
  if (b->kind == 2) { /* both ends' nonzero X is n l0: its exponentials once */
    exp_pair(&b->rt, (double)b->n * l0, &AE[0], &AE[1]);
    ae = AE;
  }
  basis_eval_rows(b, b->rho0, l0, 0.0, 2, ae, at0); /* only U, V at the core */
  basis_eval_rows(b, 1.0, 0.0, l0, 4, ae, at1);
  for (int j = 0; j < 4; ++j) {
    A[0][j] = at0[0][j];
    A[1][j] = at0[1][j];
    A[2][j] = at1[2][j];
    A[3][j] = at1[3][j];
  }
  memset(coef, 0, 8 * sizeof(double));
  coef[2][0] = -1.0 / b->nf;
  coef[3][1] = 1.0 / b->nf;
  rs_status st = small_solve(4, A, 2, coef);
  if (st) return rs_error_wrap("mode n = %ld", b->n);
  return RS_OK;
}

rs_status rs_cyl_mode_solve(const rs_cyl_nd *nd, double rho0, long n, double F[2][2])
{
  mode_basis b;
  double coef[4][2], at1[4][4];
  rs_status st = basis_init(nd, rho0, n, &b);
  if (st) return st;
  if (b.kind == 2) {
    /* The core couples to the surface through (R0/R)^(n l), l the slower growing root
     * (scaled): below 2^-64 of the rest the mode is the algebraic one to round-off (the
     * 4 x 4 system is block triangular up to such entries), a 2 x 2 system (a thick
     * roll's higher modes: the nip's mode cache of each new roll) */
    double lmin = b.rt.d2 >= 0 ? b.rt.p / (0.5 * (b.rt.s + sqrt(b.rt.d2))) : 0.5 * b.rt.s;
    if ((double)n * lmin * -log(rho0) > 45.0) return rs_cyl_mode_algebraic(nd, 1.0 / (double)n, F);
  }
  st = mode_coefficients(&b, coef, at1); /* the surface values come with them */
  if (st) return st;
  double nf = (n >= 1) ? (double)n : 1.0;
  for (int k = 0; k < 2; ++k) {
    double U = 0, V = 0;
    for (int j = 0; j < 4; ++j) {
      U += at1[0][j] * coef[j][k];
      V += at1[1][j] * coef[j][k];
    }
    F[0][k] = -U * nf; /* w = -v_r */
    F[1][k] = V * nf;
  }
  if (n == 0) F[0][1] = F[1][0] = 0; /* decoupled exactly */
  return RS_OK;
}

rs_status rs_cyl_mode_eval(const rs_cyl_nd *nd, double rho0, long n, double P, double Q,
                           double rho, double L, double L0, double *U, double *V)
{
  mode_basis b;
  double coef[4][2], at[4][4], at1[4][4];
  if (!(rho > 0)) return RS_ERROR(RS_ERR_INPUT, "r must be positive");
  rs_status st = basis_init(nd, rho0, n, &b);
  if (st) return st;
  st = mode_coefficients(&b, coef, at1);
  if (st) return st;
  basis_eval(&b, rho, L, L0, at);
  double u = 0, v = 0;
  for (int j = 0; j < 4; ++j) {
    double c = P * coef[j][0] + Q * coef[j][1];
    u += at[0][j] * c;
    v += at[1][j] * c;
  }
  *U = u;
  *V = v;
  return RS_OK;
}

/* Only the growing pair at r = R: what is left of mode 1/eps when the core is infinitely
 * far (exponentially small terms rho0^(2n) dropped); analytic in eps. */
rs_status rs_cyl_mode_algebraic(const rs_cyl_nd *nd, double eps, double F[2][2])
{
  roots r = scaled_roots(nd, eps);
  family f = make_family(nd, eps, +1);
  double W[2][2], T[4][4] = {{0}}, B[4][2] = {{-1, 0}, {0, 1}};
  pair_values(&r, f.wU, 1, 0, &W[0][0], &W[0][1]);
  pair_values(&r, f.wV, 1, 0, &W[1][0], &W[1][1]);
  pair_values(&r, f.tR, 1, 0, &T[0][0], &T[0][1]);
  pair_values(&r, f.tT, 1, 0, &T[1][0], &T[1][1]);
  rs_status st = small_solve(2, T, 2, B);
  if (st) return rs_error_wrap("half-plane limit");
  for (int k = 0; k < 2; ++k) {
    F[0][k] = -(W[0][0] * B[0][k] + W[0][1] * B[1][k]);
    F[1][k] = W[1][0] * B[0][k] + W[1][1] * B[1][k];
  }
  return RS_OK;
}
