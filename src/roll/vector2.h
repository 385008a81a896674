/* CVODE's hot vector operations for the roll engine's 2-component state (w, ln y).
 * Private to src/roll. */
#ifndef REELSIM_ROLL_VECTOR2_H
#define REELSIM_ROLL_VECTOR2_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_nonlinearsolver.h>

/* Replaces, in the ops table of v (a serial vector of length 2), the operations CVODE's
 * BDF/Newton step calls most with straight-line 2-component versions. Vectors CVODE
 * clones from v inherit them. Returns 0, or -1 if v is not a serial vector of length 2. */
int rs_roll_vector2_specialise(N_Vector v);

/* The Jacobian J = df/dy of a 2-component right-hand side at (t, y); 0 on success. */
typedef int (*rs_roll_jac2_fn)(double t, const double y[2], double J[2][2], void *user);

/* A nonlinear solver for CVODE's BDF corrector equations on a 2-component state: Newton's
 * method with the exact Jacobian (jac) at every iterate and a 2 x 2 pivoted elimination,
 * in place of SUNDIALS' Newton solver with a linear-solver module (whose bookkeeping for
 * a 2 x 2 system cost more than the system). tmpl: a vector like the state. NULL if out
 * of memory. Free with SUNNonlinSolFree, after CVodeFree. */
SUNNonlinearSolver rs_roll_newton2_create(SUNContext ctx, N_Vector tmpl, void *cvode_mem,
                                          rs_roll_jac2_fn jac, void *user);
/* Attaches the solver to its CVODE, with a linear solver beside it that forms nothing and
 * solves nothing (and a 2 x 2 matrix it never fills): CVODE keeps its own setup decisions
 * (a setup every 20 steps, after a large change of gamma or a failure) and resets its
 * convergence-rate estimate at each, which its convergence test needs. Without a
 * matrix-based linear solver CVODE resets the estimate at every step, and the corrector
 * takes two iterations where one does. 0, or -1 if CVODE refuses. */
int rs_roll_newton2_attach(SUNNonlinearSolver S);
/* Declares the right-hand side to be f(t, w, L) = (a(t) + p w + q w^2, b(t) + w): the
 * solver then solves each corrector equation exactly (a quadratic in w, one right-hand
 * side a step) instead of by Newton's method, forms no Jacobian, and skips the setups
 * CVODE asks for (they reset the convergence-rate estimate, which only Newton's
 * convergence test reads; CVodeGetNumLinSolvSetups stays 0). */
void rs_roll_newton2_set_quadratic(SUNNonlinearSolver S, double p, double q);
/* The corrector equation's exact solution for such a right-hand side: from the residual
 * R = F(ycor) at the current correction, with w the state's first component there, the
 * further correction d that makes F zero (the root next to 0). 0, or 1 if there is no
 * real root (the step is too long for the equation). */
int rs_roll_corrector_quadratic(double gamma, double p, double q, double w, const double R[2],
                                double d[2]);
/* Jacobians formed so far (one per Newton iteration) */
long rs_roll_newton2_jacobians(SUNNonlinearSolver S);

#endif
