/* CVODE's hot vector operations for the roll engine's 2-component state (w, ln y).
 * Private to src/roll. */
#ifndef REELSIM_ROLL_VECTOR2_H
#define REELSIM_ROLL_VECTOR2_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>

/* Replaces, in the ops table of v (a serial vector of length 2), the operations CVODE's
 * BDF/Newton step calls most with straight-line 2-component versions. Vectors CVODE
 * clones from v inherit them. Returns 0, or -1 if v is not a serial vector of length 2. */
int rs_roll_vector2_specialise(N_Vector v);

/* A direct linear solver for CVODE's 2 x 2 Newton matrix (a SUNDenseMatrix that CVODE
 * fills with I - gamma J): Gaussian elimination with partial pivoting, in place of the
 * dense solver's general loops. NULL if out of memory. Free with SUNLinSolFree. */
SUNLinearSolver rs_roll_linsol2_create(SUNContext ctx);

#endif
