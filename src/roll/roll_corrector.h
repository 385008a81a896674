/* How CVODE solves the roll engine's corrector equations (roll_corrector.c). Private to
 * src/roll and its tests. */
#ifndef REELSIM_ROLL_CORRECTOR_H
#define REELSIM_ROLL_CORRECTOR_H

#include <cvode/cvode.h>

/* Attaches to cvode (its user data the roll) the exact corrector (*nls, vector2.c) when the
 * self-test trusts it, else CVODE's own Newton iteration with a dense linear solver (*ls,
 * *A; *nls NULL). The caller stores and frees them (roll_ode.c). 0, or -1 if CVODE refuses
 * or memory runs out (what was made is in *nls, *ls, *A). */
int rsi_roll_corrector_attach(SUNContext ctx, void *cvode, N_Vector y, SUNNonlinearSolver *nls,
                              SUNLinearSolver *ls, SUNMatrix *A);
/* Whether the exact corrector may be used: its self-test, run once per process on first
 * call (thread-safe), passed, and no test forced the fallback */
int rsi_roll_corrector_exact_trusted(void);
/* The self-test itself (every call runs it): 1 if the exact corrector meets the closed
 * form of its test equation to 1e-3 (relative; *error, if error is not NULL: the larger
 * of the two components' relative errors, infinite if CVODE failed). sabotage != 0 (tests
 * only) breaks what it checks (CVODE's correction norm left stale at 0): it must then
 * return 0. */
int rsi_roll_corrector_selftest(int sabotage, double *error);
/* Test hook: on != 0 makes rolls created from now on use the fallback, as if the
 * self-test had failed; 0 undoes it */
void rsi_roll_corrector_force_newton(int on);

#endif
