/* The roll engine's 2-component CVODE machinery (src/roll/vector2.c) on its own: Newton
 * with the exact 2 x 2 Jacobian as CVODE's nonlinear solver, the straight-line vector
 * operations, on the engine's Riccati pair with a constant g,
 * whose solution is closed form:
 *     w' = g^2 - 1 - 2w - w^2,  L' = w;   u = 1 + w:  u' = g^2 - u^2,
 *     u = g tanh(g x + c),  c = atanh(u0/g),  L = ln(cosh(g x + c)/cosh c) - x. */
#include <math.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>

#include "check.h"
#include "roll/vector2.h"

typedef struct riccati {
  double g2;
} riccati;

static int rhs(sunrealtype x, N_Vector yv, N_Vector fv, void *user)
{
  (void)x;
  const riccati *p = user;
  const sunrealtype *y = N_VGetArrayPointer(yv);
  sunrealtype *f = N_VGetArrayPointer(fv);
  f[0] = p->g2 - 1.0 - 2.0 * y[0] - y[0] * y[0];
  f[1] = y[0];
  return 0;
}

static int jac2(double x, const double y[2], double J[2][2], void *user)
{
  (void)x;
  (void)user;
  J[0][0] = -(2.0 + 2.0 * y[0]);
  J[0][1] = 0.0;
  J[1][0] = 1.0;
  J[1][1] = 0.0;
  return 0;
}

typedef struct run {
  double w, L;
  long steps, nls_iters, jacobians, rhs, setups;
} run;

/* integrates from x = 0 (w = w0, L = 0) to x1 the way the roll engine sets CVODE up */
static run integrate_with(double g, double w0, double x1, double rtol, int setup_only)
{
  run out = {NAN, NAN, 0, 0, 0, 0, 0};
  riccati p = {g * g};
  SUNContext ctx = NULL;
  CHECK(SUNContext_Create(NULL, &ctx) == 0);
  N_Vector y = N_VNew_Serial(2, ctx);
  CHECK(y && rs_roll_vector2_specialise(y) == 0);
  N_VGetArrayPointer(y)[0] = w0;
  N_VGetArrayPointer(y)[1] = 0.0;
  void *cv = CVodeCreate(CV_BDF, ctx);
  CHECK(CVodeInit(cv, rhs, 0.0, y) == CV_SUCCESS);
  CHECK(CVodeSStolerances(cv, rtol, rtol * 1e-2) == CV_SUCCESS);
  CHECK(CVodeSetUserData(cv, &p) == CV_SUCCESS);
  SUNNonlinearSolver nls = rs_roll_newton2_create(ctx, y, cv, jac2, &p);
  if (setup_only)
    CHECK(nls && rs_roll_newton2_attach(nls) == 0);
  else /* the Newton solver alone, no linear solver beside it */
    CHECK(nls && CVodeSetNonlinearSolver(cv, nls) == CV_SUCCESS);
  CHECK(CVodeSetMaxNumSteps(cv, 100000) == CV_SUCCESS);
  sunrealtype t = 0.0;
  if (CVode(cv, x1, y, &t, CV_NORMAL) == CV_SUCCESS) {
    out.w = N_VGetArrayPointer(y)[0];
    out.L = N_VGetArrayPointer(y)[1];
  }
  CVodeGetNumSteps(cv, &out.steps);
  CVodeGetNumNonlinSolvIters(cv, &out.nls_iters);
  CVodeGetNumRhsEvals(cv, &out.rhs);
  out.jacobians = rs_roll_newton2_jacobians(nls);
  if (setup_only) CVodeGetNumLinSolvSetups(cv, &out.setups);
  CVodeFree(&cv);
  SUNNonlinSolFree(nls);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
  return out;
}

static run integrate(double g, double w0, double x1, double rtol)
{
  return integrate_with(g, w0, x1, rtol, 1);
}

/* (w, L) at x1 from w(0) = w0, L(0) = 0 at tolerance rtol against the closed form, to tol */
static void check_closed_form(double g, double w0, double x1, double rtol, double tol)
{
  const double c = atanh((1.0 + w0) / g);
  run r = integrate(g, w0, x1, rtol);
  CHECK_CLOSE(r.w, g * tanh(g * x1 + c) - 1.0, tol);
  CHECK_CLOSE(r.L, log(cosh(g * x1 + c) / cosh(c)) - x1, tol);
}

/* a mild case: w relaxes from 0 to g - 1 = 4 */
static void riccati_g5(void) { check_closed_form(5.0, 0.0, 1.0, 1e-10, 1e-8); }

/* stiff: g = 700 (the engine's hard case), w from 0 to 699 over a boundary layer of
 * width 1/(2g) in x, then constant */
static void riccati_g700(void) { check_closed_form(700.0, 0.0, 0.05, 1e-9, 1e-7); }

/* The counters CVODE reads from the solver are per solve (CVODE adds them up: a
 * cumulative count made its total grow quadratically), one exact Jacobian per Newton
 * iteration, and about one iteration per step on the stiff case (CVODE counts one
 * right-hand side per iteration): below 2 right-hand sides a step. (The accuracy checks
 * above do not see a wrong Jacobian: CVODE's convergence test still holds the error.) */
static void one_jacobian_per_iteration(void)
{
  run r = integrate(700.0, 0.0, 0.05, 1e-8);
  CHECK(r.steps > 10);
  CHECK(r.jacobians == r.nls_iters);
  CHECK_LT((double)r.rhs / r.steps, 2.0);
}

/* rs_roll_newton2_attach relies on how CVODE 6.4 drives a matrix-based linear solver that
 * forms nothing: CVODE itself decides when a "setup" is due (every 20 steps, on a large
 * change of gamma, after a failure), calls it through the nonlinear solver's lsetup, resets
 * its convergence-rate estimate there, and never calls the linear solve (the Newton
 * solver eliminates its own 2 x 2 systems; the do-nothing solve returns an unrecoverable
 * failure, so a call would stop the integration). Pinned here so that a SUNDIALS that stops
 * honouring it fails a test instead of silently costing a third more right-hand sides:
 *  - the integration succeeds and matches the closed form (the solve was never called);
 *  - CVODE asked for setups, and far fewer than one a step (it decides: 39 in 216 steps);
 *  - the same solver without the linear solver beside it (CVODE then resets the rate
 *    estimate at every step) needs more right-hand sides: measured 1.24 a step against
 *    1.11 on this problem (1.6 against 2.1 on the roll engine's); asserted 5 % more. */
static void setup_only_honoured(void)
{
  const double g = 700.0, x1 = 0.5, rtol = 1e-8, c = atanh(1.0 / g);
  run with = integrate_with(g, 0.0, x1, rtol, 1), without = integrate_with(g, 0.0, x1, rtol, 0);
  CHECK_LOG("steps, setup-only solver attached", with.steps);
  CHECK_LOG("setups CVODE asked for", with.setups);
  CHECK_LOG("rhs per step, attached", (double)with.rhs / with.steps);
  CHECK_LOG("rhs per step, Newton alone", (double)without.rhs / without.steps);
  CHECK_CLOSE(with.w, g * tanh(g * x1 + c) - 1.0, 1e-6);
  CHECK(with.setups > 0);
  CHECK(with.setups * 4 < with.steps);
  CHECK_LT(1.05 * with.rhs / with.steps, (double)without.rhs / without.steps);
}

static const check_case cases[] = {
    {"riccati_g5", riccati_g5},
    {"riccati_g700", riccati_g700},
    {"one_jacobian_per_iteration", one_jacobian_per_iteration},
    {"setup_only_honoured", setup_only_honoured},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
