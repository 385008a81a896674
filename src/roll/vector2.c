/* Straight-line versions of the serial N_Vector operations for vectors of length 2.
 *
 * Why: the roll engine's state has two components, so each of CVODE's vector operations
 * does two flops, and the serial implementation's generality (special cases of the
 * coefficients, loops, length checks) costs far more than the flops (docs/performance.md).
 * SUNDIALS lets a program supply its own vector operations through the N_Vector ops table;
 * these compute the same quantities as the serial ones (a x + b y is evaluated as written,
 * so where the serial code factors c (x + y) the last bit may differ). Everything else
 * stays SUNDIALS' own.
 * And the corrector equations: CVODE accepts any nonlinear solver that solves its
 * residual, and the roll's, quadratic in w, has a closed-form root (newton2_solve), where
 * SUNDIALS' Newton solver with a linear solver would iterate. */
#include <math.h>
#include <stdlib.h>

#include <cvode/cvode.h>

#include "util/sundials_compat.h"
#include "vector2.h"

#define D(v) NV_DATA_S(v)

/* z = a x + b y (z may be x or y) */
static void v2_linear_sum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z)
{
  const sunrealtype *xd = D(x), *yd = D(y);
  sunrealtype z0 = a * xd[0] + b * yd[0], z1 = a * xd[1] + b * yd[1];
  D(z)[0] = z0;
  D(z)[1] = z1;
}

/* z = c x */
static void v2_scale(sunrealtype c, N_Vector x, N_Vector z)
{
  sunrealtype z0 = c * D(x)[0], z1 = c * D(x)[1];
  D(z)[0] = z0;
  D(z)[1] = z1;
}

static void v2_const(sunrealtype c, N_Vector z)
{
  D(z)[0] = c;
  D(z)[1] = c;
}

static void v2_abs(N_Vector x, N_Vector z)
{
  sunrealtype z0 = fabs(D(x)[0]), z1 = fabs(D(x)[1]);
  D(z)[0] = z0;
  D(z)[1] = z1;
}

static void v2_inv(N_Vector x, N_Vector z)
{
  sunrealtype z0 = 1.0 / D(x)[0], z1 = 1.0 / D(x)[1];
  D(z)[0] = z0;
  D(z)[1] = z1;
}

static void v2_add_const(N_Vector x, sunrealtype b, N_Vector z)
{
  sunrealtype z0 = D(x)[0] + b, z1 = D(x)[1] + b;
  D(z)[0] = z0;
  D(z)[1] = z1;
}

static sunrealtype v2_min(N_Vector x)
{
  return fmin(D(x)[0], D(x)[1]);
}

/* sqrt(sum_i (x_i w_i)^2 / n), n = 2, summed in the serial code's order */
static sunrealtype v2_wrms_norm(N_Vector x, N_Vector w)
{
  sunrealtype p0 = D(x)[0] * D(w)[0], p1 = D(x)[1] * D(w)[1];
  sunrealtype sum = 0.0;
  sum += p0 * p0;
  sum += p1 * p1;
  return sqrt(sum / 2.0);
}

/* z = sum_i c_i X_i (z may be one of the X_i) */
static int v2_linear_combination(int nvec, sunrealtype *c, N_Vector *X, N_Vector z)
{
  sunrealtype z0 = 0.0, z1 = 0.0;
  for (int i = 0; i < nvec; ++i) {
    z0 += c[i] * D(X[i])[0];
    z1 += c[i] * D(X[i])[1];
  }
  D(z)[0] = z0;
  D(z)[1] = z1;
  return 0;
}

/* Z_j = a_j x + Y_j */
static int v2_scale_add_multi(int nvec, sunrealtype *a, N_Vector x, N_Vector *Y, N_Vector *Z)
{
  const sunrealtype x0 = D(x)[0], x1 = D(x)[1];
  for (int j = 0; j < nvec; ++j) {
    sunrealtype z0 = a[j] * x0 + D(Y[j])[0], z1 = a[j] * x1 + D(Y[j])[1];
    D(Z[j])[0] = z0;
    D(Z[j])[1] = z1;
  }
  return 0;
}

/* Z_i = c_i X_i (Z_i may be X_i): CVODE rescales its history array with it whenever the
 * step changes */
static int v2_scale_vector_array(int nvec, sunrealtype *c, N_Vector *X, N_Vector *Z)
{
  for (int i = 0; i < nvec; ++i) {
    sunrealtype z0 = c[i] * D(X[i])[0], z1 = c[i] * D(X[i])[1];
    D(Z[i])[0] = z0;
    D(Z[i])[1] = z1;
  }
  return 0;
}

int rsi_roll_vector2_specialise(N_Vector v)
{
  if (!v || N_VGetVectorID(v) != SUNDIALS_NVEC_SERIAL || NV_LENGTH_S(v) != 2) return -1;
  N_Vector_Ops o = v->ops;
  o->nvlinearsum = v2_linear_sum;
  o->nvscale = v2_scale;
  o->nvconst = v2_const;
  o->nvabs = v2_abs;
  o->nvinv = v2_inv;
  o->nvaddconst = v2_add_const;
  o->nvmin = v2_min;
  o->nvwrmsnorm = v2_wrms_norm;
  o->nvlinearcombination = v2_linear_combination;
  o->nvscaleaddmulti = v2_scale_add_multi;
  o->nvscalevectorarray = v2_scale_vector_array;
  return 0;
}

/* ---- The exact corrector for the 2 x 2 systems of CVODE's steps ---------------------- */

typedef struct newton2 {
  SUNNonlinSolSysFn sys; /* CVODE's residual F(ycor) */
  void *cvode;
  double p, q;           /* f = (a(t) + p w + q w^2, b(t) + w) */
  N_Vector res;
  int maxiters, curiter;
  long niters, nconvfails; /* in the last solve */
} newton2;

#define NEWTON2(S) ((newton2 *)(S)->content)

static SUNNonlinearSolver_Type newton2_type(SUNNonlinearSolver S)
{
  (void)S;
  return SUNNONLINEARSOLVER_ROOTFIND;
}

static int newton2_initialize(SUNNonlinearSolver S)
{
  NEWTON2(S)->niters = NEWTON2(S)->nconvfails = 0;
  return SUN_NLS_SUCCESS;
}

/* The corrector equation solved exactly for a right-hand side of the form
 *     f(t, w, L) = (a(t) + p w + q w^2,  b(t) + w)
 * (the roll's Riccati pair: p = -2, q = -1, a = g^2(t) - 1, b = 0). One residual R = F(ycor)
 * at the initial guess, whose f carries a(t) and b(t); a correction d from there gives
 *     F_w = R_w + B d_w + A d_w^2,   B = 1 - gamma (p + 2 q w),   A = -gamma q,
 *     F_L = R_L + d_L - gamma d_w,
 * so d_w is the root of the quadratic next to 0 (in the form without cancellation) and
 * d_L = gamma d_w - R_L: the BDF step's own solution, where Newton would take two
 * iterations and CVODE's convergence test to come within a tenth of the error estimate of
 * it. No real root (a step far too long for the equation): a recoverable failure, CVODE
 * retries with a shorter step. CVODE's convergence test is never called here, so CVODE
 * forms the correction's norm for its error test itself (cvNls: acnrmcur stays false). */
int rsi_roll_corrector_quadratic(double gamma, double p, double q, double w, const double R[2],
                                 double d[2])
{
  const double A = -gamma * q, B = 1.0 - gamma * (p + 2.0 * q * w);
  const double disc = B * B - 4.0 * A * R[0];
  const double den = B + copysign(sqrt(disc), B);
  if (!(disc >= 0.0) || !(den != 0.0) || !isfinite(den)) return 1;
  d[0] = -2.0 * R[0] / den;
  d[1] = gamma * d[0] - R[1];
  return 0;
}

/* Solves F(ycor) = ycor + rl1 zn1 - gamma f(t, ypred + ycor) = 0 for the corrector ycor
 * exactly (rsi_roll_corrector_quadratic): one residual at the initial guess, whose f carries
 * a(t) and b(t). gamma is all it needs from CVODE. CVODE's setup requests (call_setup) are
 * ignored: no Jacobian or matrix is formed. CVODE adds the counts to its own after every
 * solve: they are per solve. */
static int newton2_solve(SUNNonlinearSolver S, N_Vector y0, N_Vector ycor, N_Vector w,
                         sunrealtype tol, sunbooleantype call_setup, void *mem)
{
  (void)w;
  (void)tol;
  (void)call_setup;
  newton2 *c = NEWTON2(S);
  sunrealtype *yc = D(ycor);
  const sunrealtype *yp = D(y0), *r = D(c->res);
  c->niters = c->nconvfails = 0;
  c->curiter = 0;
  sunrealtype gamma;
  if (CVodeGetCurrentGamma(c->cvode, &gamma) != CV_SUCCESS) return SUN_NLS_MEM_NULL;
  int flag = c->sys(ycor, c->res, mem);
  if (flag != SUN_NLS_SUCCESS) return flag; /* CVODE's code: < 0 fatal, > 0 recoverable */
  double d[2];
  if (rsi_roll_corrector_quadratic(gamma, c->p, c->q, yp[0] + yc[0], r, d) != 0) {
    c->nconvfails = 1;
    return SUN_NLS_CONV_RECVR;
  }
  yc[0] += d[0];
  yc[1] += d[1];
  c->niters = 1;
  return SUN_NLS_SUCCESS;
}

static int newton2_set_sys(SUNNonlinearSolver S, SUNNonlinSolSysFn f)
{
  NEWTON2(S)->sys = f;
  return SUN_NLS_SUCCESS;
}

static int newton2_set_maxiter(SUNNonlinearSolver S, int maxiters)
{
  if (maxiters < 1) return SUN_NLS_ILL_INPUT;
  NEWTON2(S)->maxiters = maxiters;
  return SUN_NLS_SUCCESS;
}

static int newton2_num_iters(SUNNonlinearSolver S, long *n)
{
  *n = NEWTON2(S)->niters;
  return SUN_NLS_SUCCESS;
}

static int newton2_cur_iter(SUNNonlinearSolver S, int *m)
{
  *m = NEWTON2(S)->curiter;
  return SUN_NLS_SUCCESS;
}

static int newton2_num_conv_fails(SUNNonlinearSolver S, long *n)
{
  *n = NEWTON2(S)->nconvfails;
  return SUN_NLS_SUCCESS;
}

static int newton2_free(SUNNonlinearSolver S)
{
  if (!S) return SUN_NLS_SUCCESS;
  if (S->content) {
    N_VDestroy(NEWTON2(S)->res);
    free(S->content);
    S->content = NULL;
  }
  SUNNonlinSolFreeEmpty(S);
  return SUN_NLS_SUCCESS;
}

SUNNonlinearSolver rsi_roll_newton2_create(SUNContext ctx, N_Vector tmpl, void *cvode_mem,
                                           double p, double q)
{
  SUNNonlinearSolver S = SUNNonlinSolNewEmpty(ctx);
  if (!S) return NULL;
  newton2 *c = calloc(1, sizeof *c);
  S->content = c;
  if (c) c->res = N_VClone(tmpl);
  if (!c || !c->res) {
    newton2_free(S);
    return NULL;
  }
  c->cvode = cvode_mem;
  c->p = p;
  c->q = q;
  c->maxiters = 3; /* CVODE's default; it sets its own when the solver is attached */
  S->ops->gettype = newton2_type;
  S->ops->initialize = newton2_initialize;
  S->ops->solve = newton2_solve;
  S->ops->free = newton2_free;
  S->ops->setsysfn = newton2_set_sys;
  S->ops->setmaxiters = newton2_set_maxiter;
  S->ops->getnumiters = newton2_num_iters;
  S->ops->getcuriter = newton2_cur_iter;
  S->ops->getnumconvfails = newton2_num_conv_fails;
  return S;
}

int rsi_roll_newton2_attach(SUNNonlinearSolver S)
{
  return CVodeSetNonlinearSolver(NEWTON2(S)->cvode, S) == CV_SUCCESS ? 0 : -1;
}
