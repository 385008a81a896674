/* CVODE's hot vector operations for the roll engine's 2-component state (w, ln y).
 * Private to src/roll. */
#ifndef REELSIM_ROLL_VECTOR2_H
#define REELSIM_ROLL_VECTOR2_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
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
 * a 2 x 2 system cost more than the system). Attach with CVodeSetNonlinearSolver and no
 * linear solver. tmpl: a vector like the state. NULL if out of memory. Free with
 * SUNNonlinSolFree. */
SUNNonlinearSolver rs_roll_newton2_create(SUNContext ctx, N_Vector tmpl, void *cvode_mem,
                                          rs_roll_jac2_fn jac, void *user);
/* Jacobians formed so far (one per Newton iteration) */
long rs_roll_newton2_jacobians(SUNNonlinearSolver S);

/* A direct linear solver for CVODE's 2 x 2 Newton matrix (a SUNDenseMatrix that CVODE
 * fills with I - gamma J): Gaussian elimination with partial pivoting. The roll engine
 * attaches it beside rs_roll_newton2 only so that CVODE's setup decisions (when a setup
 * is due, the convergence-rate reset there) stay CVODE's own; the Newton iterations do not
 * call its solve. NULL if out of memory. Free with SUNLinSolFree. */
SUNLinearSolver rs_roll_linsol2_create(SUNContext ctx);

#endif
