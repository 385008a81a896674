/* Straight-line versions of the serial N_Vector operations for vectors of length 2.
 *
 * Why: the roll engine's state has two components, so each of CVODE's vector operations
 * does two flops, and the serial implementation's generality (special cases of the
 * coefficients, loops, length checks) costs far more than the flops (docs/performance.md).
 * SUNDIALS lets a program supply its own vector
 * operations through the N_Vector ops table; these compute the same quantities as the
 * serial ones (a x + b y is evaluated as written, so where the serial code factors
 * c (x + y) the last bit may differ). Everything else stays SUNDIALS' own.
 * The same for Newton's method on the 2 x 2 corrector equations: SUNDIALS' Newton solver,
 * the linear-solver interface and the dense LU spent more on their bookkeeping (scaling
 * for a stale matrix, copies, loops and checks) than the six flops of a 2 x 2
 * elimination; CVODE accepts any nonlinear solver that solves its residual. */
#include <math.h>
#include <stdlib.h>

#include <cvode/cvode.h>
#include <sunmatrix/sunmatrix_dense.h>

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

int rs_roll_vector2_specialise(N_Vector v)
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

/* ---- Newton's method for the 2 x 2 systems of CVODE's steps ------------------------- */

typedef struct newton2 {
  SUNNonlinSolSysFn sys;          /* CVODE's residual F(ycor) */
  SUNNonlinSolLSetupFn lsetup;    /* CVODE's linear-solver setup: its convergence bookkeeping */
  SUNNonlinSolConvTestFn ctest;   /* CVODE's convergence test */
  void *ctest_data;
  void *cvode;
  SUNLinearSolver setup_only; /* attached beside it, with a matrix it never forms: */
  SUNMatrix unused;           /* see rs_roll_newton2_attach */
  rs_roll_jac2_fn jac;
  void *user;
  int quadratic;              /* f = (a(t) + p w + q w^2, b(t) + w): the exact corrector */
  double p, q;
  N_Vector res, delta;
  int maxiters, curiter;
  long niters, nconvfails; /* in the last solve */
  long njac;               /* in all solves */
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
int rs_roll_corrector_quadratic(double gamma, double p, double q, double w, const double R[2],
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

static int newton2_solve_exact(newton2 *c, const sunrealtype *yp, sunrealtype *yc,
                               const sunrealtype *r, double gamma, void *mem, N_Vector ycor)
{
  c->curiter = 0;
  int flag = c->sys(ycor, c->res, mem);
  if (flag != SUN_NLS_SUCCESS) return flag;
  double d[2];
  if (rs_roll_corrector_quadratic(gamma, c->p, c->q, yp[0] + yc[0], r, d) != 0) {
    c->nconvfails = 1;
    return SUN_NLS_CONV_RECVR;
  }
  yc[0] += d[0];
  yc[1] += d[1];
  c->niters = 1;
  return SUN_NLS_SUCCESS;
}

/* Solves F(ycor) = ycor + rl1 zn1 - gamma f(t, ypred + ycor) = 0 for the corrector ycor,
 * F' = I - gamma J: two equations, so each iteration forms the exact Jacobian at the
 * current iterate and eliminates with partial pivoting (full Newton: no stale matrix to
 * decide about). Convergence is CVODE's own test (rate estimate, tolerance tq[4]). */
static int newton2_solve(SUNNonlinearSolver S, N_Vector y0, N_Vector ycor, N_Vector w,
                         sunrealtype tol, sunbooleantype call_setup, void *mem)
{
  newton2 *c = NEWTON2(S);
  sunrealtype *yc = D(ycor), *r = D(c->res), *d = D(c->delta);
  const sunrealtype *yp = D(y0);
  int flag;
  /* CVODE adds these counts to its own after every solve: they are per solve */
  c->niters = c->nconvfails = 0;
  if (c->quadratic) { /* gamma is all it needs from CVODE (one getter, not nine) */
    sunrealtype gamma;
    if (CVodeGetCurrentGamma(c->cvode, &gamma) != CV_SUCCESS) return SUN_NLS_MEM_NULL;
    return newton2_solve_exact(c, yp, yc, r, gamma, mem, ycor);
  }
  sunrealtype t, gamma, rl1;
  N_Vector ypred, yn, fn, zn1;
  void *user_data;
  if (CVodeGetNonlinearSystemData(c->cvode, &t, &ypred, &yn, &fn, &gamma, &rl1, &zn1,
                                  &user_data) != CV_SUCCESS)
    return SUN_NLS_MEM_NULL;
  /* CVODE decides when a setup is due (every 20 steps, a large change of gamma, after a
   * failure) and resets its convergence-rate estimate there (the setup itself forms
   * nothing: rs_roll_newton2_attach); the test below is CVODE's and uses that estimate.
   * The exact corrector (above) calls no convergence test, so nothing reads that
   * estimate: it skips the setup (a third of the steps asked for one: 1.5 % of the
   * reel's instructions, the same steps and results; docs/performance.md). CVODE's
   * record of the last setup (its step and gamma) then stays where it was, so it asks
   * for one at every step after the 20th: the request is ignored alike, and the Newton
   * path, which honours it, resets that record at its first setup */
  if (call_setup && c->lsetup) {
    sunbooleantype jcur;
    flag = c->lsetup(SUNFALSE, &jcur, mem);
    if (flag != SUN_NLS_SUCCESS) return flag;
  }
  for (c->curiter = 0;;) {
    flag = c->sys(ycor, c->res, mem);
    if (flag != SUN_NLS_SUCCESS) break; /* CVODE's code: < 0 fatal, > 0 recoverable */
    const double y[2] = {yp[0] + yc[0], yp[1] + yc[1]};
    double J[2][2];
    c->njac++;
    if (c->jac(t, y, J, c->user) != 0) {
      flag = SUN_NLS_CONV_RECVR;
      break;
    }
    /* (I - gamma J) d = -res */
    double a00 = 1.0 - gamma * J[0][0], a01 = -gamma * J[0][1];
    double a10 = -gamma * J[1][0], a11 = 1.0 - gamma * J[1][1];
    double b0 = -r[0], b1 = -r[1];
    if (fabs(a10) > fabs(a00)) {
      double t0 = a00, t1 = a01, tb = b0;
      a00 = a10, a01 = a11, b0 = b1;
      a10 = t0, a11 = t1, b1 = tb;
    }
    const double l = a00 != 0.0 ? a10 / a00 : 0.0, u = a11 - l * a01;
    if (a00 == 0.0 || u == 0.0) { /* singular: CVODE retries with a smaller step */
      flag = SUN_NLS_CONV_RECVR;
      break;
    }
    d[1] = (b1 - l * b0) / u;
    d[0] = (b0 - a01 * d[1]) / a00;
    yc[0] += d[0];
    yc[1] += d[1];
    c->niters++;
    flag = c->ctest(S, ycor, c->delta, tol, w, c->ctest_data);
    if (flag != SUN_NLS_CONTINUE) break;
    if (++c->curiter >= c->maxiters) {
      flag = SUN_NLS_CONV_RECVR;
      break;
    }
  }
  if (flag == SUN_NLS_CONV_RECVR) c->nconvfails++;
  return flag;
}

static int newton2_set_sys(SUNNonlinearSolver S, SUNNonlinSolSysFn f)
{
  NEWTON2(S)->sys = f;
  return SUN_NLS_SUCCESS;
}

static int newton2_set_lsetup(SUNNonlinearSolver S, SUNNonlinSolLSetupFn f)
{
  NEWTON2(S)->lsetup = f;
  return SUN_NLS_SUCCESS;
}

static int newton2_set_ctest(SUNNonlinearSolver S, SUNNonlinSolConvTestFn f, void *data)
{
  NEWTON2(S)->ctest = f;
  NEWTON2(S)->ctest_data = data;
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
    N_VDestroy(NEWTON2(S)->delta);
    if (NEWTON2(S)->setup_only) SUNLinSolFreeEmpty(NEWTON2(S)->setup_only);
    if (NEWTON2(S)->unused) SUNMatDestroy(NEWTON2(S)->unused);
    free(S->content);
    S->content = NULL;
  }
  SUNNonlinSolFreeEmpty(S);
  return SUN_NLS_SUCCESS;
}

/* The linear solver attached beside the Newton solver: it has nothing to set up and is
 * never asked to solve (newton2_solve eliminates its own 2 x 2 systems). */
static SUNLinearSolver_Type setup_only_type(SUNLinearSolver S)
{
  (void)S;
  return SUNLINEARSOLVER_DIRECT;
}

/* CVODE's linear-system function for it: the matrix is never read, so nothing is formed */
static int setup_only_system(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix A,
                             sunbooleantype jok, sunbooleantype *jcur, sunrealtype gamma,
                             void *user, N_Vector t1, N_Vector t2, N_Vector t3)
{
  (void)t; (void)y; (void)fy; (void)A; (void)jok; (void)gamma; (void)user;
  (void)t1; (void)t2; (void)t3;
  *jcur = SUNTRUE;
  return 0;
}

static int setup_only_setup(SUNLinearSolver S, SUNMatrix A)
{
  (void)S;
  (void)A;
  return SUNLS_SUCCESS;
}

static int setup_only_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, sunrealtype tol)
{
  (void)S; (void)A; (void)x; (void)b; (void)tol;
  return SUNLS_PACKAGE_FAIL_UNREC; /* not called: a call would be a wiring error */
}

static SUNLinearSolver setup_only_create(SUNContext ctx)
{
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return NULL;
  S->ops->gettype = setup_only_type;
  S->ops->setup = setup_only_setup;
  S->ops->solve = setup_only_solve;
  return S;
}

SUNNonlinearSolver rs_roll_newton2_create(SUNContext ctx, N_Vector tmpl, void *cvode_mem,
                                          rs_roll_jac2_fn jac, void *user)
{
  SUNNonlinearSolver S = SUNNonlinSolNewEmpty(ctx);
  if (!S) return NULL;
  newton2 *c = calloc(1, sizeof *c);
  S->content = c;
  if (c) {
    c->res = N_VClone(tmpl);
    c->delta = N_VClone(tmpl);
    c->setup_only = setup_only_create(ctx);
    c->unused = SUNDenseMatrix(2, 2, ctx);
  }
  if (!c || !c->res || !c->delta || !c->setup_only || !c->unused) {
    newton2_free(S);
    return NULL;
  }
  c->cvode = cvode_mem;
  c->jac = jac;
  c->user = user;
  c->maxiters = 3; /* CVODE's default; it sets its own when the solver is attached */
  S->ops->gettype = newton2_type;
  S->ops->initialize = newton2_initialize;
  S->ops->solve = newton2_solve;
  S->ops->free = newton2_free;
  S->ops->setsysfn = newton2_set_sys;
  S->ops->setlsetupfn = newton2_set_lsetup;
  S->ops->setctestfn = newton2_set_ctest;
  S->ops->setmaxiters = newton2_set_maxiter;
  S->ops->getnumiters = newton2_num_iters;
  S->ops->getcuriter = newton2_cur_iter;
  S->ops->getnumconvfails = newton2_num_conv_fails;
  return S;
}

int rs_roll_newton2_attach(SUNNonlinearSolver S)
{
  newton2 *c = NEWTON2(S);
  if (CVodeSetNonlinearSolver(c->cvode, S) != CV_SUCCESS ||
      CVodeSetLinearSolver(c->cvode, c->setup_only, c->unused) != CV_SUCCESS)
    return -1;
  return CVodeSetLinSysFn(c->cvode, setup_only_system) == CV_SUCCESS ? 0 : -1;
}

void rs_roll_newton2_set_quadratic(SUNNonlinearSolver S, double p, double q)
{
  newton2 *c = NEWTON2(S);
  c->quadratic = 1;
  c->p = p;
  c->q = q;
}

long rs_roll_newton2_jacobians(SUNNonlinearSolver S)
{
  return S && S->content ? NEWTON2(S)->njac : 0;
}
