/* Which nonlinear solver CVODE's corrector equations get in the roll engine, and the check
 * at start that lets the engine use its exact corrector.
 *
 * The exact corrector (vector2.c) solves each BDF corrector equation in closed form and
 * never calls CVODE's convergence test. CVODE's error test needs the norm of the
 * correction, which the convergence test forms when it is called; when it is not, CVODE
 * forms it itself after the solve (in cvNls: `if (!cv_acnrmcur) cv_acnrm = N_VWrmsNorm(...)`,
 * a flag only CVodeSetNonlinearSolver clears and only the convergence test sets). That is
 * CVODE's private behaviour (6.4 to 7.5 alike), not its documented interface, so it is
 * checked once per process, before the first roll is made (rsi_roll_corrector_selftest): the
 * engine's equation with a constant g, whose solution is closed form,
 *     w' = g^2 - 1 - 2w - w^2,  L' = w,   u = 1 + w = g tanh(g x + c),  c = atanh(u0/g),
 *     L = ln(cosh(g x + c)/cosh c) - x,
 * integrated with the exact corrector at a loose tolerance. Were the norm left stale (say
 * 0), every step would pass the error test and grow tenfold, and the answer would miss
 * the closed form by orders of magnitude more than the tolerance. If the check fails, every
 * roll gets CVODE's own Newton iteration instead (SUNDIALS' Newton solver with the dense
 * 2 x 2 linear solver and the exact Jacobian): ~1.6 right-hand sides a step instead of
 * one, the results within the tolerance of the exact corrector's. */
#include <pthread.h>
#include <stdatomic.h>

#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "roll/roll_corrector.h"
#include "roll/roll_internal.h"
#include "roll/vector2.h"
#include "util/sundials_compat.h"

/* the self-test's equation: g = 5 from w = 0 to x = 1 at rtol 1e-5, held to 1e-3 relative
 * (the exact corrector's error there: ~1e-5; with the norm stale at 0: ~1) */
#define ST_G 5.0
#define ST_X1 1.0
#define ST_RTOL 1e-5
#define ST_TOL 1e-3

static int st_rhs(sunrealtype x, N_Vector yv, N_Vector fv, void *user)
{
  (void)x;
  (void)user;
  const sunrealtype *y = NV_DATA_S(yv);
  sunrealtype *f = NV_DATA_S(fv);
  f[0] = ST_G * ST_G - 1.0 - 2.0 * y[0] - y[0] * y[0];
  f[1] = y[0];
  return 0;
}

/* The test hook's sabotage (rsi_roll_corrector_selftest(1)): the solver's solve wrapped so that
 * after its first solve it calls CVODE's convergence test once with a zero update. CVODE
 * then records a correction norm of 0 as formed by the test and never forms it again:
 * the failure the self-test is there to catch. Per thread (a test runs it alone). */
typedef int (*nls_solve_fn)(SUNNonlinearSolver S, N_Vector y0, N_Vector ycor, N_Vector w,
                            sunrealtype tol, sunbooleantype call_setup, void *mem);
typedef struct sabotage {
  nls_solve_fn solve;
  SUNNonlinSolConvTestFn ctest;
  void *ctest_data;
  N_Vector zero;
  int done;
} sabotage;
static _Thread_local sabotage st_sab;

static int sab_set_ctest(SUNNonlinearSolver S, SUNNonlinSolConvTestFn f, void *data)
{
  (void)S;
  st_sab.ctest = f;
  st_sab.ctest_data = data;
  return SUN_NLS_SUCCESS;
}

static int sab_solve(SUNNonlinearSolver S, N_Vector y0, N_Vector ycor, N_Vector w, sunrealtype tol,
                     sunbooleantype call_setup, void *mem)
{
  int flag = st_sab.solve(S, y0, ycor, w, tol, call_setup, mem);
  if (flag == SUN_NLS_SUCCESS && !st_sab.done && st_sab.ctest) {
    st_sab.done = 1;
    N_VConst(0.0, st_sab.zero);
    (void)st_sab.ctest(S, ycor, st_sab.zero, tol, w, st_sab.ctest_data);
  }
  return flag;
}

int rsi_roll_corrector_selftest(int sabotage_it, double *error)
{
  double err = INFINITY;
  SUNContext ctx = NULL;
  N_Vector y = NULL;
  void *cv = NULL;
  SUNNonlinearSolver nls = NULL;
  int pass = 0;
  if (rs_sundials_context_create(&ctx) != 0) return 0;
  y = N_VNew_Serial(2, ctx);
  if (!y || rsi_roll_vector2_specialise(y) != 0) goto done;
  NV_DATA_S(y)[0] = 0.0;
  NV_DATA_S(y)[1] = 0.0;
  cv = CVodeCreate(CV_BDF, ctx);
  nls = cv ? rsi_roll_newton2_create(ctx, y, cv, -2.0, -1.0) : NULL;
  if (!nls || CVodeInit(cv, st_rhs, 0.0, y) != CV_SUCCESS ||
      CVodeSStolerances(cv, ST_RTOL, 1e-2 * ST_RTOL) != CV_SUCCESS)
    goto done;
  if (sabotage_it) {
    st_sab = (sabotage){.solve = nls->ops->solve, .zero = N_VClone(y)};
    if (!st_sab.zero) goto done;
    nls->ops->setctestfn = sab_set_ctest;
    nls->ops->solve = sab_solve;
  }
  if (rsi_roll_newton2_attach(nls) != 0) goto done;
  sunrealtype t = 0.0;
  if (CVodeSetMaxNumSteps(cv, 5000) == CV_SUCCESS && CVode(cv, ST_X1, y, &t, CV_NORMAL) == CV_SUCCESS) {
    const double c = atanh(1.0 / ST_G), u = ST_G * tanh(ST_G * ST_X1 + c);
    const double w = u - 1.0, L = log(cosh(ST_G * ST_X1 + c) / cosh(c)) - ST_X1;
    err = fmax(fabs(NV_DATA_S(y)[0] - w) / fabs(w), fabs(NV_DATA_S(y)[1] - L) / fabs(L));
    pass = err <= ST_TOL; /* (false for a NaN) */
  }
done:
  if (cv) CVodeFree(&cv);
  if (nls) SUNNonlinSolFree(nls);
  if (sabotage_it && st_sab.zero) N_VDestroy(st_sab.zero);
  st_sab = (sabotage){0};
  if (y) N_VDestroy(y);
  if (ctx) SUNContext_Free(&ctx);
  if (error) *error = err;
  return pass;
}

static pthread_once_t selftest_once = PTHREAD_ONCE_INIT;
static int selftest_passed;
static atomic_int newton_forced;

static void selftest_run(void) { selftest_passed = rsi_roll_corrector_selftest(0, NULL); }

int rsi_roll_corrector_exact_trusted(void)
{
  pthread_once(&selftest_once, selftest_run);
  return selftest_passed && !atomic_load(&newton_forced);
}

void rsi_roll_corrector_force_newton(int on) { atomic_store(&newton_forced, on != 0); }

/* CVODE's Jacobian function for the dense fallback: the increment ODE's exact Jacobian
 * (roll_ode.c), J = df/d(w, L) = [[-(2 + 2w), 0], [1, 0]] */
static int jac_dense(sunrealtype x, N_Vector y, N_Vector fy, SUNMatrix J, void *user, N_Vector t1,
                     N_Vector t2, N_Vector t3)
{
  (void)fy;
  (void)t1;
  (void)t2;
  (void)t3;
  (void)x;
  rs_roll *roll = user;
  ++roll->stats.jac_evals;
  SM_ELEMENT_D(J, 0, 0) = -(2.0 + 2.0 * NV_DATA_S(y)[0]);
  SM_ELEMENT_D(J, 0, 1) = 0.0;
  SM_ELEMENT_D(J, 1, 0) = 1.0;
  SM_ELEMENT_D(J, 1, 1) = 0.0;
  return 0;
}

int rsi_roll_corrector_attach(SUNContext ctx, void *cvode, N_Vector y, SUNNonlinearSolver *nls,
                              SUNLinearSolver *ls, SUNMatrix *A)
{
  *nls = NULL;
  *ls = NULL;
  *A = NULL;
  if (rsi_roll_corrector_exact_trusted()) {
    /* the corrector equations solved exactly (vector2.c): rsi_roll_rhs is
     * (g^2(x) - 1 - 2w - w^2, w), quadratic in w with g^2 independent of the state */
    *nls = rsi_roll_newton2_create(ctx, y, cvode, -2.0, -1.0);
    return *nls && rsi_roll_newton2_attach(*nls) == 0 ? 0 : -1;
  }
  /* CVODE's own Newton solver (made by CVodeInit) with a dense linear solver */
  *A = SUNDenseMatrix(2, 2, ctx);
  *ls = *A ? SUNLinSol_Dense(y, *A, ctx) : NULL;
  if (!*ls || CVodeSetLinearSolver(cvode, *ls, *A) != CV_SUCCESS ||
      CVodeSetJacFn(cvode, jac_dense) != CV_SUCCESS)
    return -1;
  return 0;
}
