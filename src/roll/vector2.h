/* CVODE's hot vector operations for the roll engine's 2-component state (w, ln y).
 * Private to src/roll. */
#ifndef REELSIM_ROLL_VECTOR2_H
#define REELSIM_ROLL_VECTOR2_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_nonlinearsolver.h>

/* Replaces, in the ops table of v (a serial vector of length 2), the operations CVODE's
 * BDF step calls most with straight-line 2-component versions. Vectors CVODE
 * clones from v inherit them. Returns 0, or -1 if v is not a serial vector of length 2. */
int rsi_roll_vector2_specialise(N_Vector v);

/* A nonlinear solver for CVODE's BDF corrector equations on a 2-component state whose
 * right-hand side is f(t, w, L) = (a(t) + p w + q w^2, b(t) + w) (the roll's Riccati pair:
 * p = -2, q = -1): each corrector equation solved exactly, a quadratic in w, from one
 * right-hand side a step, with no Jacobian, no linear solver and no convergence test
 * (CVODE then forms the correction's norm itself: roll_corrector.c checks that it does).
 * tmpl: a vector like the state. NULL if out of memory. Free with SUNNonlinSolFree, after
 * CVodeFree. */
SUNNonlinearSolver rsi_roll_newton2_create(SUNContext ctx, N_Vector tmpl, void *cvode_mem,
                                           double p, double q);
/* Attaches the solver to its CVODE. 0, or -1 if CVODE refuses. */
int rsi_roll_newton2_attach(SUNNonlinearSolver S);
/* The corrector equation's exact solution for such a right-hand side: from the residual
 * R = F(ycor) at the current correction, with w the state's first component there, the
 * further correction d that makes F zero (the root next to 0). 0, or 1 if there is no
 * real root (the step is too long for the equation). */
int rsi_roll_corrector_quadratic(double gamma, double p, double q, double w, const double R[2],
                                 double d[2]);

#endif
