/* Straight-line versions of the serial N_Vector operations for vectors of length 2.
 *
 * Why: the roll engine's state has two components, so each of CVODE's vector operations
 * does two flops, and the serial implementation's generality (special cases of the
 * coefficients, loops, length checks) costs far more than the flops: callgrind measured
 * N_VLinearSum_Serial alone at ~130 instructions a call and a quarter of the engine's
 * instructions (docs/performance.md). SUNDIALS lets a program supply its own vector
 * operations through the N_Vector ops table; these compute the same quantities as the
 * serial ones (a x + b y is evaluated as written, so where the serial code factors
 * c (x + y) the last bit may differ). Everything else stays SUNDIALS' own.
 * The same for Newton's method on the 2 x 2 corrector equations: SUNDIALS' Newton solver,
 * the linear-solver interface and the dense LU spent more on their bookkeeping (when to
 * re-form the matrix, scaling for a stale one, loops and checks) than the six flops of a
 * 2 x 2 elimination; CVODE accepts any nonlinear solver that solves its residual. */
#include <math.h>
#include <stdlib.h>

#include <cvode/cvode.h>
#include <sunmatrix/sunmatrix_dense.h>

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
  return 0;
}

/* ---- Newton's method for the 2 x 2 systems of CVODE's steps ------------------------- */

typedef struct newton2 {
  SUNNonlinSolSysFn sys;          /* CVODE's residual F(ycor) */
  SUNNonlinSolLSetupFn lsetup;    /* CVODE's linear-solver setup: its convergence bookkeeping */
  SUNNonlinSolConvTestFn ctest;   /* CVODE's convergence test */
  void *ctest_data;
  void *cvode;
  rs_roll_jac2_fn jac;
  void *user;
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

/* Solves F(ycor) = ycor + rl1 zn1 - gamma f(t, ypred + ycor) = 0 for the corrector ycor,
 * F' = I - gamma J: two equations, so each iteration forms the exact Jacobian at the
 * current iterate and eliminates with partial pivoting (full Newton: no stale matrix to
 * decide about). Convergence is CVODE's own test (rate estimate, tolerance tq[4]). */
static int newton2_solve(SUNNonlinearSolver S, N_Vector y0, N_Vector ycor, N_Vector w,
                         sunrealtype tol, sunbooleantype call_setup, void *mem)
{
  newton2 *c = NEWTON2(S);
  sunrealtype t, gamma, rl1;
  N_Vector ypred, yn, fn, zn1;
  void *user_data;
  if (CVodeGetNonlinearSystemData(c->cvode, &t, &ypred, &yn, &fn, &gamma, &rl1, &zn1,
                                  &user_data) != CV_SUCCESS)
    return SUN_NLS_MEM_NULL;
  sunrealtype *yc = D(ycor), *r = D(c->res), *d = D(c->delta);
  const sunrealtype *yp = D(y0);
  int flag;
  /* CVODE adds these counts to its own after every solve: they are per solve */
  c->niters = c->nconvfails = 0;
  /* CVODE decides when a setup is due (every 20 steps, a large change of gamma, after a
   * failure) and resets its convergence-rate estimate there; the matrix it forms is not
   * used here, but the test below is CVODE's and depends on that estimate */
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
    free(S->content);
    S->content = NULL;
  }
  SUNNonlinSolFreeEmpty(S);
  return SUN_NLS_SUCCESS;
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
  }
  if (!c || !c->res || !c->delta) {
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

long rs_roll_newton2_jacobians(SUNNonlinearSolver S)
{
  return S && S->content ? NEWTON2(S)->njac : 0;
}
/* ---- the 2 x 2 direct solver --------------------------------------------------------- */

typedef struct linsol2 {
  int swap;          /* rows exchanged by the pivoting */
  double a, b, l, u; /* [[1, 0], [l, 1]] [[a, b], [0, u]] = P A */
} linsol2;

static SUNLinearSolver_Type ls2_type(SUNLinearSolver S)
{
  (void)S;
  return SUNLINEARSOLVER_DIRECT;
}

static SUNLinearSolver_ID ls2_id(SUNLinearSolver S)
{
  (void)S;
  return SUNLINEARSOLVER_CUSTOM;
}

static int ls2_setup(SUNLinearSolver S, SUNMatrix A)
{
  linsol2 *f = S->content;
  double a00 = SM_ELEMENT_D(A, 0, 0), a01 = SM_ELEMENT_D(A, 0, 1);
  double a10 = SM_ELEMENT_D(A, 1, 0), a11 = SM_ELEMENT_D(A, 1, 1);
  f->swap = fabs(a10) > fabs(a00);
  if (f->swap) {
    double t0 = a00, t1 = a01;
    a00 = a10, a01 = a11, a10 = t0, a11 = t1;
  }
  if (a00 == 0.0) return SUNLS_LUFACT_FAIL; /* singular: CVODE retries with a smaller step */
  f->a = a00;
  f->b = a01;
  f->l = a10 / a00;
  f->u = a11 - f->l * a01;
  return f->u == 0.0 ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
}

static int ls2_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, sunrealtype tol)
{
  (void)A;
  (void)tol;
  const linsol2 *f = S->content;
  double b0 = D(b)[0], b1 = D(b)[1];
  if (f->swap) {
    double t = b0;
    b0 = b1, b1 = t;
  }
  b1 -= f->l * b0;
  const double x1 = b1 / f->u;
  D(x)[0] = (b0 - f->b * x1) / f->a;
  D(x)[1] = x1;
  return SUNLS_SUCCESS;
}

static int ls2_free(SUNLinearSolver S)
{
  if (!S) return 0;
  free(S->content);
  S->content = NULL;
  SUNLinSolFreeEmpty(S);
  return 0;
}

SUNLinearSolver rs_roll_linsol2_create(SUNContext ctx)
{
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return NULL;
  S->content = calloc(1, sizeof(linsol2));
  if (!S->content) {
    SUNLinSolFreeEmpty(S);
    return NULL;
  }
  S->ops->gettype = ls2_type;
  S->ops->getid = ls2_id;
  S->ops->setup = ls2_setup;
  S->ops->solve = ls2_solve;
  S->ops->free = ls2_free;
  return S;
}
