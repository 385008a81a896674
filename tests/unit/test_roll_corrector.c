/* The roll engine's exact corrector and its safeguard (src/roll/roll_corrector.c): the
 * self-test that checks, once per process, CVODE's private behaviour the exact corrector
 * relies on (CVODE forms the correction's norm for its error test itself when its
 * convergence test is not called), that it catches that behaviour broken, and the
 * fallback it then takes (CVODE's own Newton iteration with a dense linear solver) giving
 * the exact corrector's stresses to within the integration tolerance. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "roll/roll_corrector.h"
#include "roll/roll_internal.h"
#include "roll_helpers.h"

/* The self-test passes with this SUNDIALS: its error far inside the 1e-3 it allows, and
 * rolls get the exact corrector (no Jacobian formed) */
static void selftest_passes(void)
{
  double err = NAN;
  CHECK(rsi_roll_corrector_selftest(0, &err) == 1);
  CHECK_LOG("self-test relative error", err);
  CHECK_LT(err, 1e-4);
  CHECK(rsi_roll_corrector_exact_trusted() == 1);
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, 20);
  rs_roll *roll = wind(&p, 20, 1, 500.0);
  if (!roll) return;
  rs_roll_stats s;
  rs_roll_get_stats(roll, &s);
  CHECK(roll->ode.NLS != NULL && roll->ode.fallback_LS == NULL);
  CHECK(s.jac_evals == 0);
  rs_roll_destroy(&roll);
}

/* With CVODE's correction norm left stale at 0 (the test hook's sabotage: every step
 * passes the error test and grows) the self-test misses the closed form by far more than
 * it allows, and says so */
static void selftest_catches_stale_norm(void)
{
  double err = 0.0;
  CHECK(rsi_roll_corrector_selftest(1, &err) == 0);
  CHECK_LOG("self-test relative error, sabotaged", err);
  CHECK_LT(1e-2, err);
  /* and the sabotage leaves nothing behind: the next self-test passes */
  CHECK(rsi_roll_corrector_selftest(0, &err) == 1);
}

/* max |a - b| / max |b| over n values */
static double max_rel(const double *a, const double *b, int n)
{
  double d = 0.0, s = 0.0;
  for (int i = 0; i < n; ++i) {
    d = fmax(d, fabs(a[i] - b[i]));
    s = fmax(s, fabs(b[i]));
  }
  return d / s;
}

/* One roll wound with the exact corrector and with the fallback (forced through the test
 * hook): the same stresses to within the integration tolerance, rtol = 1e-6, relative to
 * the largest stress (measured 2e-8 in sigma_r, 7e-8 and 1.4e-7 in sigma_theta), the
 * fallback forming Jacobians and the exact corrector none */
static void agree(const rs_roll_params *p, int n, int per_step, double tol)
{
  rs_roll *exact = wind(p, n, per_step, 500.0);
  rsi_roll_corrector_force_newton(1);
  rs_roll *newton = wind(p, n, per_step, 500.0);
  rsi_roll_corrector_force_newton(0);
  if (!exact || !newton) goto done;
  CHECK(exact->ode.NLS != NULL);
  CHECK(newton->ode.NLS == NULL && newton->ode.fallback_LS != NULL && newton->ode.fallback_A != NULL);
  rs_roll_stats se, sn;
  rs_roll_get_stats(exact, &se);
  rs_roll_get_stats(newton, &sn);
  CHECK_LOG("CVODE steps, exact corrector", se.cvode_steps);
  CHECK_LOG("CVODE steps, Newton fallback", sn.cvode_steps);
  CHECK_LOG("rhs per step, exact", (double)se.rhs_evals / se.cvode_steps);
  CHECK_LOG("rhs per step, Newton", (double)sn.rhs_evals / sn.cvode_steps);
  CHECK(se.jac_evals == 0 && sn.jac_evals > 0);
  CHECK(rs_roll_layers(newton) == n);
  const double dr = max_rel(rs_roll_sigma_r(newton), rs_roll_sigma_r(exact), n);
  const double dt = max_rel(rs_roll_sigma_theta(newton), rs_roll_sigma_theta(exact), n);
  CHECK_LOG("sigma_r, max |Newton - exact| / max |exact|", dr);
  CHECK_LOG("sigma_theta, max |Newton - exact| / max |exact|", dt);
  CHECK_LT(dr, tol);
  CHECK_LT(dt, tol);
  CHECK_CLOSE(rs_roll_core_pressure(newton), rs_roll_core_pressure(exact), tol);
done:
  rs_roll_destroy(&exact);
  rs_roll_destroy(&newton);
}

/* newsprint (Pfeiffer law), layer by layer */
static void fallback_agrees(void)
{
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, 600);
  p.rtol = 1e-6;
  p.atol = 0.0;
  agree(&p, 600, 1, 1e-6);
}

/* the same with lumped increments of 8 layers (the predictor-corrector's two
 * integrations an increment) */
static void fallback_agrees_lumped(void)
{
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, 600);
  p.rtol = 1e-6;
  p.atol = 0.0;
  agree(&p, 600, 8, 1e-6);
}

/* the same on a short roll, both ways, where valgrind can watch the fallback's solvers made
 * and freed */
static void fallback_small(void)
{
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, 40);
  p.rtol = 1e-6;
  p.atol = 0.0;
  agree(&p, 40, 1, 1e-6);
  agree(&p, 40, 4, 1e-6);
}

static const check_case cases[] = {
    {"selftest_passes", selftest_passes},
    {"selftest_catches_stale_norm", selftest_catches_stale_norm},
    {"fallback_small", fallback_small},
    {"fallback_agrees", fallback_agrees},
    {"fallback_agrees_lumped", fallback_agrees_lumped},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
