/* CVODE's vector operations for the creep state, as plain loops the compiler vectorises.
 *
 * The creep state is N (1 + arms) values (42,000 on the 6054-layer reel with three terms a
 * direction) and the right-hand side costs about ten operations a value, so CVODE's own
 * vector kernels (norms, linear sums, Gram-Schmidt) are most of the work: the distribution's
 * serial kernels ran about 20 instructions a value each (callgrind). These do the same
 * arithmetic in loops over restrict pointers (SIMD with the project's flags). Same results
 * up to the order of summation in the norms and dot products. */
#include <math.h>

#include <nvector/nvector_serial.h>

#include "storage/creep_vector.h"

#define LEN(v) NV_LENGTH_S(v)
#define DAT(v) NV_DATA_S(v)

static void cv_linear_sum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z)
{
  const sunindextype n = LEN(x);
  const double *xd = DAT(x), *yd = DAT(y);
  double *zd = DAT(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
}

static void cv_scale(sunrealtype c, N_Vector x, N_Vector z)
{
  const sunindextype n = LEN(x);
  const double *xd = DAT(x);
  double *zd = DAT(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = c * xd[i];
}

static void cv_const(sunrealtype c, N_Vector z)
{
  const sunindextype n = LEN(z);
  double *restrict zd = DAT(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = c;
}

static void cv_prod(N_Vector x, N_Vector y, N_Vector z)
{
  const sunindextype n = LEN(x);
  const double *xd = DAT(x), *yd = DAT(y);
  double *zd = DAT(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] * yd[i];
}

static void cv_div(N_Vector x, N_Vector y, N_Vector z)
{
  const sunindextype n = LEN(x);
  const double *xd = DAT(x), *yd = DAT(y);
  double *zd = DAT(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] / yd[i];
}

static sunrealtype cv_wsqrsum(N_Vector x, N_Vector w)
{
  const sunindextype n = LEN(x);
  const double *restrict xd = DAT(x), *restrict wd = DAT(w);
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  sunindextype i = 0;
  for (; i + 4 <= n; i += 4) {
    const double a = xd[i] * wd[i], b = xd[i + 1] * wd[i + 1];
    const double c = xd[i + 2] * wd[i + 2], d = xd[i + 3] * wd[i + 3];
    s0 += a * a, s1 += b * b, s2 += c * c, s3 += d * d;
  }
  for (; i < n; ++i) s0 += (xd[i] * wd[i]) * (xd[i] * wd[i]);
  return (s0 + s1) + (s2 + s3);
}

static sunrealtype cv_wrmsnorm(N_Vector x, N_Vector w)
{
  return sqrt(cv_wsqrsum(x, w) / (double)LEN(x));
}

static sunrealtype cv_dot(N_Vector x, N_Vector y)
{
  const sunindextype n = LEN(x);
  const double *restrict xd = DAT(x), *restrict yd = DAT(y);
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  sunindextype i = 0;
  for (; i + 4 <= n; i += 4) {
    s0 += xd[i] * yd[i], s1 += xd[i + 1] * yd[i + 1];
    s2 += xd[i + 2] * yd[i + 2], s3 += xd[i + 3] * yd[i + 3];
  }
  for (; i < n; ++i) s0 += xd[i] * yd[i];
  return (s0 + s1) + (s2 + s3);
}

static int cv_dot_multi(int nv, N_Vector x, N_Vector *Y, sunrealtype *dots)
{
  for (int k = 0; k < nv; ++k) dots[k] = cv_dot(x, Y[k]);
  return 0;
}

/* z = sum_k c_k X_k */
static int cv_linear_combination(int nv, sunrealtype *c, N_Vector *X, N_Vector z)
{
  const sunindextype n = LEN(z);
  double *zd = DAT(z);
  const double *x0 = DAT(X[0]);
  const double c0 = c[0];
  for (sunindextype i = 0; i < n; ++i) zd[i] = c0 * x0[i];
  for (int k = 1; k < nv; ++k) {
    const double *xk = DAT(X[k]), ck = c[k];
    for (sunindextype i = 0; i < n; ++i) zd[i] += ck * xk[i];
  }
  return 0;
}

/* Z_k = a_k x + Y_k */
static int cv_scale_add_multi(int nv, sunrealtype *a, N_Vector x, N_Vector *Y, N_Vector *Z)
{
  const sunindextype n = LEN(x);
  const double *xd = DAT(x);
  for (int k = 0; k < nv; ++k) {
    const double *yd = DAT(Y[k]), ak = a[k];
    double *zd = DAT(Z[k]);
    for (sunindextype i = 0; i < n; ++i) zd[i] = ak * xd[i] + yd[i];
  }
  return 0;
}

void rs_creep_vector_specialise(N_Vector v)
{
  v->ops->nvlinearsum = cv_linear_sum;
  v->ops->nvscale = cv_scale;
  v->ops->nvconst = cv_const;
  v->ops->nvprod = cv_prod;
  v->ops->nvdiv = cv_div;
  v->ops->nvwrmsnorm = cv_wrmsnorm;
  v->ops->nvwsqrsumlocal = cv_wsqrsum;
  v->ops->nvdotprod = cv_dot;
  v->ops->nvdotprodlocal = cv_dot;
  v->ops->nvdotprodmulti = cv_dot_multi;
  v->ops->nvlinearcombination = cv_linear_combination;
  v->ops->nvscaleaddmulti = cv_scale_add_multi;
}
