/* Frictionless normal contact of two orthotropic cylinders, no sheet: the indentation
 * equation (12) of the seed paper with v+ - v- = 0 and zero shear, hat pressures (16)-(18)
 * and the load from eq. (21). */
#include "cylinder/internal.h"
#include "util/error.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void rs_contact_result_free(rs_contact_result *r)
{
  if (!r) return;
  free(r->x);
  free(r->p);
  memset(r, 0, sizeof *r);
}

static rs_status result_reserve(rs_contact_result *r, int M)
{
  if (r->capacity >= M && r->x && r->p) return RS_OK;
  free(r->x);
  free(r->p);
  r->x = calloc((size_t)M, sizeof(double));
  r->p = calloc((size_t)M, sizeof(double));
  if (!r->x || !r->p) {
    rs_contact_result_free(r);
    return RS_ERROR(RS_ERR_MEMORY, "contact result of %d nodes", M);
  }
  r->capacity = M;
  return RS_OK;
}

/* Unknowns p_2..p_{M-1} (interior nodes), delta0, eps0; one equation per node:
 *   sum_j (K1 + K2)_{ij} p_j - delta0 - eps0 x_i / R* = -x_i^2 / (2 R*).
 * (w positive inward, so w1 + w2 = delta0 - (x^2 - 2 eps0 x)/(2R*) is eq. (12) with
 * v_k = -w_k.) */
rs_status rs_contact_frictionless(rs_cylinder *c1, rs_cylinder *c2, double a, int M,
                                  const rs_series_opts *opts, rs_contact_result *out)
{
  if (!c1 || !c2 || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (M < 3 || M > 20000) return RS_ERROR(RS_ERR_INPUT, "M = %d out of range [3, 20000]", M);
  if (!(a > 0) || !isfinite(a)) return RS_ERROR(RS_ERR_INPUT, "half-width a = %g", a);
  double Rs = 1.0 / (1.0 / c1->R + 1.0 / c2->R);
  double dx = 2 * a / (M - 1);
  rs_kernels k1 = {0}, k2 = {0};
  double *A = NULL, *b = NULL;
  lapack_int *ipiv = NULL;
  rs_status st = rs_cylinder_kernels(c1, RS_BASIS_HAT, dx, 0.0, M, RS_KERNEL_PU, opts, &k1);
  if (st) goto fail_wrap;
  st = rs_cylinder_kernels(c2, RS_BASIS_HAT, dx, 0.0, M, RS_KERNEL_PU, opts, &k2);
  if (st) goto fail_wrap;
  st = result_reserve(out, M);
  if (st) goto done;
  A = malloc((size_t)M * M * sizeof *A);
  b = malloc((size_t)M * sizeof *b);
  ipiv = malloc((size_t)M * sizeof *ipiv);
  if (!A || !b || !ipiv) {
    st = RS_ERROR(RS_ERR_MEMORY, "contact system of %d", M);
    goto done;
  }
  for (int i = 0; i < M; ++i) {
    double xi = -a + i * dx;
    out->x[i] = xi;
    for (int j = 1; j < M - 1; ++j) {
      int d = rs_kernel_index(M, i - j);
      A[(size_t)i * M + (j - 1)] = k1.pu[d] + k2.pu[d];
    }
    A[(size_t)i * M + (M - 2)] = -1.0;
    A[(size_t)i * M + (M - 1)] = -xi / Rs;
    b[i] = -xi * xi / (2 * Rs);
  }
  /* The columns differ by orders of magnitude (m/Pa, 1, m/m): scale them to O(1) so the
   * pivoting sees comparable numbers; undone below. */
  double sc[3] = {fabs(k1.pu[M - 1] + k2.pu[M - 1]), 1.0, a / Rs};
  for (int i = 0; i < M; ++i) {
    for (int j = 0; j < M - 2; ++j) A[(size_t)i * M + j] /= sc[0];
    A[(size_t)i * M + (M - 1)] /= sc[2];
    b[i] /= a;
  }
  lapack_int info = LAPACKE_dgesv(LAPACK_ROW_MAJOR, (lapack_int)M, 1, A, (lapack_int)M, ipiv, b, 1);
  if (info != 0) {
    st = RS_ERROR(RS_ERR_SOLVER, "contact system singular (dgesv info %d)", (int)info);
    goto done;
  }
  /* the solution is (p_j sc0, delta0, eps0 sc2) / a */
  double P = 0;
  out->p[0] = out->p[M - 1] = 0;
  for (int j = 1; j < M - 1; ++j) {
    out->p[j] = b[j - 1] / sc[0] * a;
    P += out->p[j] * dx;
  }
  out->delta0 = b[M - 2] * a;
  out->eps0 = b[M - 1] / sc[2] * a;
  out->M = M;
  out->a = a;
  out->dx = dx;
  out->P = P;
  out->terms = k1.terms > k2.terms ? k1.terms : k2.terms;
  if (!isfinite(P)) st = RS_ERROR(RS_ERR_SOLVER, "non-finite load for a = %g", a);
  goto done;
fail_wrap:
  rs_error_wrap("contact kernels for a = %g m, M = %d", a, M);
done:
  rs_kernels_free(&k1);
  rs_kernels_free(&k2);
  free(A);
  free(b);
  free(ipiv);
  return st;
}

/* P(a) is monotone (about a^2, Hertz): Brent's method on f(a) = ln P(a) - ln P, which is
 * nearly linear in ln a, after a bracket found by doubling/halving from the Hertz guess
 * a^2 = 4 P R* / (pi E*), E* from the half-plane limits of both bodies. */

/* One evaluation of f(a) = ln P(a) - ln P: the bodies, the grid and the wanted load. */
typedef struct load_search {
  rs_cylinder *c1, *c2;
  int M;
  const rs_series_opts *opts;
  double P, lnP;
  rs_contact_result *out;
} load_search;

static rs_status load_eval(const load_search *ls, double a, double *f)
{
  rs_status st = rs_contact_frictionless(ls->c1, ls->c2, a, ls->M, ls->opts, ls->out);
  if (st) return rs_error_wrap("load %g N/m", ls->P);
  if (!(ls->out->P > 0))
    return RS_ERROR(RS_ERR_SOLVER, "P(a = %g) = %g <= 0", a, ls->out->P);
  *f = log(ls->out->P) - ls->lnP;
  return RS_OK;
}

/* The Hertz half-width a^2 = 4 P R* / (pi E*), 1/E* = (H1 + H2)/2 from the half-plane
 * compliances of both bodies; at most a_max / 2. */
static rs_status hertz_guess(rs_cylinder *c1, rs_cylinder *c2, double P, double a_max, double *a)
{
  double H1[2][2], H2[2][2];
  rs_status st = rs_ortho_halfplane(&c1->c, H1);
  if (st) return st;
  st = rs_ortho_halfplane(&c2->c, H2);
  if (st) return st;
  double Estar = 2.0 / (H1[0][0] + H2[0][0]);
  double Rs = 1.0 / (1.0 / c1->R + 1.0 / c2->R);
  *a = fmin(sqrt(4 * P * Rs / (RS_PI * Estar)), 0.5 * a_max);
  return RS_OK;
}

/* [lo, hi] with f(lo) <= 0 <= f(hi), by halving from a (too wide) or doubling up to a_max
 * (too narrow). */
static rs_status bracket_load(const load_search *ls, double a, double a_max, double *lo,
                              double *hi, double *flo, double *fhi)
{
  rs_status st = load_eval(ls, a, flo);
  if (st) return st;
  *lo = *hi = a;
  *fhi = *flo;
  int it = 0;
  while (*flo > 0 && it++ < 60) { /* too wide: shrink */
    *hi = *lo;
    *fhi = *flo;
    *lo *= 0.5;
    if ((st = load_eval(ls, *lo, flo))) return st;
  }
  while (*fhi < 0 && it++ < 60) { /* too narrow: widen, up to a_max */
    if (*hi >= a_max)
      return RS_ERROR(RS_ERR_INPUT, "load %g N/m needs a contact half-width beyond a_max = %g m "
                      "(P(a_max) = %g N/m)", ls->P, a_max, ls->out->P);
    *lo = *hi;
    *flo = *fhi;
    *hi = fmin(2 * *hi, a_max);
    if ((st = load_eval(ls, *hi, fhi))) return st;
  }
  if (!(*flo <= 0 && *fhi >= 0))
    return RS_ERROR(RS_ERR_SOLVER, "could not bracket P = %g N/m", ls->P);
  return RS_OK;
}

/* Brent (1973) on [lo, hi] in the variable ln a, to rtol in ln a; the result is left in
 * ls->out, solved at the root found. */
static rs_status brent_ln_a(const load_search *ls, double lo, double hi, double flo, double fhi,
                            double rtol)
{
  double xa = log(lo), xb = log(hi), fa = flo, fb = fhi, xc = xa, fc = fa, dd = xb - xa, e = dd;
  rs_status st;
  for (int iter = 0; iter < 100; ++iter) {
    if ((fb > 0) == (fc > 0)) {
      xc = xa;
      fc = fa;
      dd = e = xb - xa;
    }
    if (fabs(fc) < fabs(fb)) {
      xa = xb; xb = xc; xc = xa;
      fa = fb; fb = fc; fc = fa;
    }
    double tol = 0.5 * rtol, xm = 0.5 * (xc - xb);
    if (fabs(xm) <= tol || fb == 0) {
      double af;
      return load_eval(ls, exp(xb), &af);
    }
    if (fabs(e) >= tol && fabs(fa) > fabs(fb)) {
      double s = fb / fa, p, q;
      if (xa == xc) {
        p = 2 * xm * s;
        q = 1 - s;
      } else {
        double qq = fa / fc, r = fb / fc;
        p = s * (2 * xm * qq * (qq - r) - (xb - xa) * (r - 1));
        q = (qq - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) q = -q; else p = -p;
      if (2 * p < fmin(3 * xm * q - fabs(tol * q), fabs(e * q))) {
        e = dd;
        dd = p / q;
      } else {
        dd = xm;
        e = dd;
      }
    } else {
      dd = xm;
      e = dd;
    }
    xa = xb;
    fa = fb;
    xb += fabs(dd) > tol ? dd : copysign(tol, xm);
    if ((st = load_eval(ls, exp(xb), &fb))) return st;
  }
  return RS_ERROR(RS_ERR_SOLVER, "Brent did not converge for P = %g N/m in 100 iterations", ls->P);
}

rs_status rs_contact_frictionless_load(rs_cylinder *c1, rs_cylinder *c2, double P, int M,
                                       const rs_series_opts *opts, double a_max, double rtol,
                                       rs_contact_result *out)
{
  if (!c1 || !c2 || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!(P > 0) || !isfinite(P)) return RS_ERROR(RS_ERR_INPUT, "load P = %g N/m must be positive", P);
  if (rtol <= 0) rtol = 1e-10;
  if (a_max <= 0) a_max = 0.2 * fmin(c1->R, c2->R);
  double a, lo, hi, flo, fhi;
  rs_status st = hertz_guess(c1, c2, P, a_max, &a);
  if (st) return st;
  const load_search ls = {c1, c2, M, opts, P, log(P), out};
  if ((st = bracket_load(&ls, a, a_max, &lo, &hi, &flo, &fhi))) return st;
  return brent_ln_a(&ls, lo, hi, flo, fhi, rtol);
}
