/* The roll engine's 2-component CVODE machinery (src/roll/vector2.c) on its own: the
 * corrector solved exactly for a right-hand side quadratic in w, the straight-line vector
 * operations, against CVODE's own Newton iteration (a dense linear solver and the exact
 * Jacobian: the engine's fallback, roll_corrector.c), on the engine's Riccati pair with a
 * constant g,
 * whose solution is closed form:
 *     w' = g^2 - 1 - 2w - w^2,  L' = w;   u = 1 + w:  u' = g^2 - u^2,
 *     u = g tanh(g x + c),  c = atanh(u0/g),  L = ln(cosh(g x + c)/cosh c) - x. */
#include <math.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>

#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "check.h"
#include "roll/vector2.h"
#include "util/sundials_compat.h"

/* w' = g2 - 1 + p w + q w^2, L' = w: the engine's pair (p = -2, q = -1), or with q = +1
 * the tangent, whose implicit steps can have no solution */
typedef struct riccati {
  double g2, p, q;
} riccati;

static int rhs(sunrealtype x, N_Vector yv, N_Vector fv, void *user)
{
  (void)x;
  const riccati *p = user;
  const sunrealtype *y = N_VGetArrayPointer(yv);
  sunrealtype *f = N_VGetArrayPointer(fv);
  f[0] = p->g2 - 1.0 + p->p * y[0] + p->q * y[0] * y[0];
  f[1] = y[0];
  return 0;
}

/* the Jacobian for CVODE's own Newton iteration */
static int jac_dense(sunrealtype x, N_Vector y, N_Vector fy, SUNMatrix J, void *user, N_Vector t1,
                     N_Vector t2, N_Vector t3)
{
  (void)x; (void)fy; (void)t1; (void)t2; (void)t3;
  const riccati *p = user;
  SM_ELEMENT_D(J, 0, 0) = p->p + 2.0 * p->q * N_VGetArrayPointer(y)[0];
  SM_ELEMENT_D(J, 0, 1) = 0.0;
  SM_ELEMENT_D(J, 1, 0) = 1.0;
  SM_ELEMENT_D(J, 1, 1) = 0.0;
  return 0;
}

typedef struct run {
  double w, L;
  long steps, nls_iters, rhs, setups, conv_fails;
} run;

enum { NEWTON = 1, EXACT = 2 }; /* how the solver is set up */

/* integrates from x = 0 (w = w0, L = 0) to x1 the way the roll engine sets CVODE up (mode
 * EXACT), or with CVODE's own Newton iteration (NEWTON: its fallback); h0 > 0: the first
 * step */
static run integrate_eq(riccati p, double w0, double x1, double rtol, int mode, double h0)
{
  run out = {NAN, NAN, 0, 0, 0, 0, 0};
  SUNContext ctx = NULL;
  CHECK(rs_sundials_context_create(&ctx) == 0);
  N_Vector y = N_VNew_Serial(2, ctx);
  CHECK(y && rsi_roll_vector2_specialise(y) == 0);
  N_VGetArrayPointer(y)[0] = w0;
  N_VGetArrayPointer(y)[1] = 0.0;
  void *cv = CVodeCreate(CV_BDF, ctx);
  CHECK(CVodeInit(cv, rhs, 0.0, y) == CV_SUCCESS);
  CHECK(CVodeSStolerances(cv, rtol, rtol * 1e-2) == CV_SUCCESS);
  CHECK(CVodeSetUserData(cv, &p) == CV_SUCCESS);
  SUNNonlinearSolver nls = NULL;
  SUNMatrix A = NULL;
  SUNLinearSolver LS = NULL;
  if (mode == EXACT) {
    nls = rsi_roll_newton2_create(ctx, y, cv, p.p, p.q);
    CHECK(nls && rsi_roll_newton2_attach(nls) == 0);
  } else {
    A = SUNDenseMatrix(2, 2, ctx);
    LS = A ? SUNLinSol_Dense(y, A, ctx) : NULL;
    CHECK(LS && CVodeSetLinearSolver(cv, LS, A) == CV_SUCCESS);
    CHECK(CVodeSetJacFn(cv, jac_dense) == CV_SUCCESS);
  }
  if (h0 > 0.0) CHECK(CVodeSetInitStep(cv, h0) == CV_SUCCESS);
  CHECK(CVodeSetMaxNumSteps(cv, 100000) == CV_SUCCESS);
  sunrealtype t = 0.0;
  if (CVode(cv, x1, y, &t, CV_NORMAL) == CV_SUCCESS) {
    out.w = N_VGetArrayPointer(y)[0];
    out.L = N_VGetArrayPointer(y)[1];
  }
  CVodeGetNumSteps(cv, &out.steps);
  CVodeGetNumNonlinSolvIters(cv, &out.nls_iters);
  CVodeGetNumRhsEvals(cv, &out.rhs);
  CVodeGetNumNonlinSolvConvFails(cv, &out.conv_fails);
  CVodeGetNumLinSolvSetups(cv, &out.setups);
  CVodeFree(&cv);
  if (nls) SUNNonlinSolFree(nls);
  if (LS) SUNLinSolFree(LS);
  if (A) SUNMatDestroy(A);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
  return out;
}

static run integrate_with(double g, double w0, double x1, double rtol, int mode, double h0)
{
  return integrate_eq((riccati){g * g, -2.0, -1.0}, w0, x1, rtol, mode, h0);
}

/* (w, L) at x1 from w(0) = w0, L(0) = 0 at tolerance rtol against the closed form, to tol */
static void check_closed_form(double g, double w0, double x1, double rtol, double tol, int mode)
{
  const double c = atanh((1.0 + w0) / g);
  run r = integrate_with(g, w0, x1, rtol, mode, 0.0);
  CHECK_CLOSE(r.w, g * tanh(g * x1 + c) - 1.0, tol);
  CHECK_CLOSE(r.L, log(cosh(g * x1 + c) / cosh(c)) - x1, tol);
}

/* The exact corrector on a mild case (w relaxes from 0 to g - 1 = 4) and a stiff one (g =
 * 700, the engine's hard case: w from 0 to 699 over a boundary layer of width 1/(2g) in x),
 * at a tight and a loose tolerance, where a wrong root
 * or an error test fed a stale norm would show (CVODE forms the correction's norm itself
 * when its convergence test is not called) */
static void exact_riccati_g5(void)
{
  check_closed_form(5.0, 0.0, 1.0, 1e-10, 1e-8, EXACT);
  check_closed_form(5.0, 0.0, 1.0, 1e-5, 1e-3, EXACT);
}
static void exact_riccati_g700(void)
{
  check_closed_form(700.0, 0.0, 0.05, 1e-9, 1e-7, EXACT);
  check_closed_form(700.0, 0.0, 0.05, 1e-5, 1e-3, EXACT);
}

/* Exact: one right-hand side per solve (CVODE counts one iteration per solve), no
 * linear-solver setup; the results those of CVODE's own Newton iteration to within the
 * tolerance (Newton stops within a tenth of the error estimate of the exact root) */
static void exact_one_rhs_per_step(void)
{
  run e = integrate_with(700.0, 0.0, 0.05, 1e-8, EXACT, 0.0);
  run n = integrate_with(700.0, 0.0, 0.05, 1e-8, NEWTON, 0.0);
  CHECK_LOG("steps, exact", e.steps);
  CHECK_LOG("steps, Newton", n.steps);
  CHECK_LOG("rhs per step, exact", (double)e.rhs / e.steps);
  CHECK_LOG("rhs per step, Newton", (double)n.rhs / n.steps);
  CHECK(e.steps > 10);
  /* and no linear-solver setup (there is no linear solver) */
  CHECK_LOG("linear-solver setups, exact", e.setups);
  CHECK_LOG("linear-solver setups, Newton", n.setups);
  CHECK(e.setups == 0 && n.setups > 0);
  CHECK(e.nls_iters >= e.steps && e.nls_iters <= e.steps + e.conv_fails + 20);
  CHECK_LT((double)e.rhs / e.steps, 1.35);
  CHECK_LT((double)e.rhs / e.steps, (double)n.rhs / n.steps);
  CHECK_CLOSE(e.w, n.w, 1e-6);
  CHECK_CLOSE(e.L, n.L, 1e-6);
}

/* The corrector's root against the residual formed from its definition: for random gamma,
 * predictor, history term c and (p, q) of both signs, F(d) = d + c - gamma f(ypred + d)
 * with f = (a + p w + q w^2, b + w) is zero at the correction returned, to rounding of the
 * terms; where the quadratic has no real root it says so (and that happens) */
static void corrector_solves_residual(void)
{
  unsigned long long s = 12345;
  int solved = 0, refused = 0;
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    double u[8];
    for (int k = 0; k < 8; ++k) { /* xorshift: uniform in [0, 1) */
      s ^= s << 13, s ^= s >> 7, s ^= s << 17;
      u[k] = (double)(s >> 11) / 9007199254740992.0;
    }
    const double gamma = pow(10.0, -4.0 + 4.0 * u[0]), p = -4.0 + 8.0 * u[1];
    const double q = u[2] < 0.5 ? -1.0 : 0.5, a = pow(10.0, 6.0 * u[3]), b = u[4] - 0.5;
    const double yp[2] = {-1.0 + 100.0 * u[5], 10.0 * u[6]}, c[2] = {50.0 * (u[7] - 0.5), 1.0};
    /* F at d = 0, then at the root */
    double f0 = a + p * yp[0] + q * yp[0] * yp[0], f1 = b + yp[0];
    const double R[2] = {c[0] - gamma * f0, c[1] - gamma * f1};
    double d[2];
    if (rsi_roll_corrector_quadratic(gamma, p, q, yp[0], R, d) != 0) {
      ++refused;
      continue;
    }
    ++solved;
    const double w = yp[0] + d[0];
    f0 = a + p * w + q * w * w;
    f1 = b + w;
    const double F0 = d[0] + c[0] - gamma * f0, F1 = d[1] + c[1] - gamma * f1;
    /* rounding scale: the largest term each residual sums */
    const double s0 = fabs(d[0]) + fabs(c[0]) + gamma * (fabs(a) + fabs(p * w) + fabs(q * w * w));
    const double s1 = fabs(d[1]) + fabs(c[1]) + gamma * (fabs(b) + fabs(w));
    worst = fmax(worst, fmax(fabs(F0) / s0, fabs(F1) / s1));
  }
  CHECK_LOG("roots found", solved);
  CHECK_LOG("no real root", refused);
  CHECK_LOG("worst residual / its terms", worst);
  CHECK(solved > 10000 && refused > 0);
  CHECK_LT(worst, 1e-13);
}

/* w' = 1 + w^2 from w(0) = 0: w = tan x, L = -ln cos x. A first step of 0.6: backward
 * Euler's w1 = h (1 + w1^2) has no real root for h > 1/2, so the solver reports a
 * recoverable failure, CVODE shortens the step, and the integration meets the closed form
 * (also the exact corrector with q = +1, the other sign) */
static void exact_no_root_recovers(void)
{
  const double x1 = 1.2;
  run r = integrate_eq((riccati){2.0, 0.0, 1.0}, 0.0, x1, 1e-9, EXACT, 0.6);
  CHECK_LOG("corrector failures", r.conv_fails);
  CHECK(r.conv_fails > 0);
  CHECK_CLOSE(r.w, tan(x1), 1e-6);
  CHECK_CLOSE(r.L, -log(cos(x1)), 1e-6);
}

static const check_case cases[] = {
    {"corrector_solves_residual", corrector_solves_residual},
    {"exact_riccati_g5", exact_riccati_g5},
    {"exact_riccati_g700", exact_riccati_g700},
    {"exact_one_rhs_per_step", exact_one_rhs_per_step},
    {"exact_no_root_recovers", exact_no_root_recovers},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
