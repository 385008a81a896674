/* Creep of a wound roll over one storage stage: the state (face stresses, arm stresses),
 * its right-hand side (one O(N) elastic solve, creep_bvp.c) and CVODE (docs/storage.md).
 *
 * The state: sigma_r at the faces 0..n-1 (face 0 is the core's, face n is free), then the
 * arm stresses q_i of every Prony term with a nonzero fraction, per turn, radial terms
 * first. Right-hand side, per turn j:
 *     E_r,j = E_r(P_j), P_j = -R_j            (the stack's tangent modulus, glassy)
 *     c_r,j = sum_i q^r_i,j / (tau_i E_r,j),   c_theta,j = sum_i q^theta_i,j / (tau_i E_theta)
 *     d sigma/dt from the elastic problem with those eigenstrain rates (rs_creep_bvp)
 *     dq_i/dt = w_i (dS/dt + sum_k q_k / tau_k) - q_i / tau_i     (S = R_j or H_j)
 * (E da/dt = dS/dt + sum_k q_k/tau_k is the turn's direct strain rate times its modulus).
 *
 * The Jacobian couples every turn to every other through the elastic problem: dense, so
 * never formed. CVODE's Newton iterations use GMRES (SPGMR) on Jacobian-vector products by
 * differences, preconditioned by the arms' own relaxation, P = I - gamma diag(-1/tau_i) on
 * the arm stresses and I on the face stresses: a turn held at fixed strain relaxes exactly
 * so, and the elastic coupling only moves the rates by O(1) factors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include "storage/creep.h"
#include "util/sundials_compat.h"
#include "storage/creep_vector.h"
#include "util/error.h"

struct rs_creep {
  rs_creep_params p;
  int n;
  int n_arm;                       /* arms in the state: radial then hoop */
  int arm_term[2 * RS_CREEP_MAX_TERMS];
  int arm_radial[2 * RS_CREEP_MAX_TERMS]; /* 1: a radial arm, 0: hoop */
  double arm_w[2 * RS_CREEP_MAX_TERMS], arm_rate[2 * RS_CREEP_MAX_TERMS]; /* w_i, 1/tau_i */
  long ny;
  double *q;                       /* [n_arm n] the arm stresses between holds */
  double *R_last, *H_last;         /* [n] the turn stresses at the last hold's end */
  double *F_last;                  /* [n] the face stresses at the last hold's end */
  int warm;                        /* CVODE holds the last hold's end: a hold that starts
                                      from it unchanged continues the integration */
  double t_end;                    /* h, CVODE's time at the last hold's end */
  double *P, *Er, *Sr, *St, *cr, *ct, *work; /* [n] right-hand side work */
  SUNContext ctx;
  void *cvode;
  N_Vector y, atol;
  SUNLinearSolver LS;
  char msg[RS_SUNDIALS_MSG_LEN];
  rs_creep_stats stats;
  long seen[5];                    /* CVODE's counters when last read */
};

void rs_creep_destroy(rs_creep **cp)
{
  if (!cp || !*cp) return;
  rs_creep *c = *cp;
  if (c->cvode) CVodeFree(&c->cvode);
  if (c->LS) SUNLinSolFree(c->LS);
  if (c->y) N_VDestroy(c->y);
  if (c->atol) N_VDestroy(c->atol);
  if (c->ctx) SUNContext_Free(&c->ctx);
  free(c->q);
  free(c->R_last);
  free(c->H_last);
  free(c->F_last);
  free(c->P);
  free(c->Er);
  free(c->Sr);
  free(c->St);
  free(c->cr);
  free(c->ct);
  free(c->work);
  free(c);
  *cp = NULL;
}

static int creep_rhs(sunrealtype t, N_Vector Y, N_Vector Yd, void *user)
{
  (void)t;
  rs_creep *c = user;
  const int n = c->n;
  const double *y = N_VGetArrayPointer(Y);
  double *yd = N_VGetArrayPointer(Yd);
  const double *sig = y;
  for (int j = 0; j < n; ++j) c->P[j] = -0.5 * (sig[j] + (j + 1 < n ? sig[j + 1] : 0.0));
  rs_radial_modulus_n(c->p.radial, c->P, c->Er, n);
  memset(c->Sr, 0, (size_t)n * sizeof(double));
  memset(c->St, 0, (size_t)n * sizeof(double));
  for (int a = 0; a < c->n_arm; ++a) {
    const double *q = y + n + (long)a * n, k = c->arm_rate[a];
    double *S = c->arm_radial[a] ? c->Sr : c->St;
    for (int j = 0; j < n; ++j) S[j] += k * q[j];
  }
  const double iEt = 1.0 / c->p.E_theta;
  for (int j = 0; j < n; ++j) {
    if (!(c->Er[j] > 0.0) || !isfinite(c->Er[j])) return -1; /* the law broke: unrecoverable */
    c->cr[j] = c->Sr[j] / c->Er[j];
    c->ct[j] = c->St[j] * iEt;
  }
  double *ds = yd;
  rs_creep_bvp(&c->p, c->Er, c->cr, c->ct, ds, c->work);
  /* the turns' stress rates, reusing P and Er as scratch */
  const double rc = c->p.core_radius, tt = c->p.caliper, it = 1.0 / tt;
  double *dR = c->P, *dH = c->Er;
  for (int j = 0; j < n; ++j) {
    const double hi = j + 1 < n ? ds[j + 1] : 0.0;
    dR[j] = 0.5 * (ds[j] + hi);
    dH[j] = ((rc + (j + 1) * tt) * hi - (rc + j * tt) * ds[j]) * it;
  }
  for (int a = 0; a < c->n_arm; ++a) {
    const double *q = y + n + (long)a * n;
    double *qd = yd + n + (long)a * n;
    const double w = c->arm_w[a], k = c->arm_rate[a];
    const double *dS = c->arm_radial[a] ? dR : dH, *S = c->arm_radial[a] ? c->Sr : c->St;
    for (int j = 0; j < n; ++j) qd[j] = w * (dS[j] + S[j]) - k * q[j];
  }
  for (int j = 0; j < n; ++j)
    if (!isfinite(ds[j])) return 1; /* recoverable: CVODE retries with a shorter step */
  c->stats.rhs++;
  return 0;
}

/* Nothing to set up (gamma comes with every solve), but saying that the preconditioner is
 * current (jcur) lets CVODE trust its Newton iterations: without a set-up function it took
 * 21 % more of them (155 against 128 over the bench's week). */
static int creep_psetup(sunrealtype t, N_Vector y, N_Vector fy, sunbooleantype jok,
                        sunbooleantype *jcur, sunrealtype gamma, void *user)
{
  (void)t, (void)y, (void)fy, (void)jok, (void)gamma, (void)user;
  *jcur = SUNTRUE;
  return 0;
}

/* z = P^-1 r, P = I - gamma J_arms, J_arms = diag(-1/tau_i) on the arm stresses */
static int creep_psolve(sunrealtype t, N_Vector y, N_Vector fy, N_Vector r, N_Vector z,
                        sunrealtype gamma, sunrealtype delta, int lr, void *user)
{
  (void)t, (void)y, (void)fy, (void)delta, (void)lr;
  rs_creep *c = user;
  const int n = c->n;
  const double *rv = N_VGetArrayPointer(r);
  double *zv = N_VGetArrayPointer(z);
  memcpy(zv, rv, (size_t)n * sizeof(double));
  for (int a = 0; a < c->n_arm; ++a) {
    const double f = 1.0 / (1.0 + gamma * c->arm_rate[a]);
    const double *ra = rv + n + (long)a * n;
    double *za = zv + n + (long)a * n;
    for (int j = 0; j < n; ++j) za[j] = f * ra[j];
  }
  c->stats.prec_solves++;
  return 0;
}

static rs_status creep_check(const rs_creep_params *p)
{
  if (p->n_layers < 1) return RS_ERROR(RS_ERR_INPUT, "creep: the roll has no layers (%d)", p->n_layers);
  if (!(p->core_radius > 0.0) || !(p->caliper > 0.0))
    return RS_ERROR(RS_ERR_INPUT, "creep: core radius and caliper must be > 0 m (got %g, %g)",
                    p->core_radius, p->caliper);
  if (!(p->E_theta > 0.0) || !isfinite(p->E_theta))
    return RS_ERROR(RS_ERR_INPUT, "creep: E_theta must be > 0 Pa (got %g)", p->E_theta);
  if (!(p->core_stiffness > 0.0))
    return RS_ERROR(RS_ERR_INPUT, "creep: core stiffness must be > 0 Pa (got %g)", p->core_stiffness);
  if (!(fabs(p->nu_rtheta) < 1.0))
    return RS_ERROR(RS_ERR_INPUT, "creep: nu_rtheta must lie in (-1, 1) (got %g)", p->nu_rtheta);
  if (!p->radial) return RS_ERROR(RS_ERR_INPUT, "creep: no radial law");
  if (!(p->rtol > 0.0 && p->rtol < 1.0))
    return RS_ERROR(RS_ERR_INPUT, "creep: rtol must lie in (0, 1) (got %g)", p->rtol);
  if (p->max_steps < 1) return RS_ERROR(RS_ERR_INPUT, "creep: max_steps must be >= 1");
  if (p->n_terms < 0 || p->n_terms > RS_CREEP_MAX_TERMS)
    return RS_ERROR(RS_ERR_INPUT, "creep: %d Prony terms (at most %d)", p->n_terms, RS_CREEP_MAX_TERMS);
  double sr = 0.0, st = 0.0;
  for (int i = 0; i < p->n_terms; ++i) {
    if (!(p->tau[i] > 0.0) || !isfinite(p->tau[i]))
      return RS_ERROR(RS_ERR_INPUT, "creep: viscoelastic.tau[%d] must be > 0 h (got %g)", i, p->tau[i]);
    if (!(p->w_theta[i] >= 0.0) || !(p->w_radial[i] >= 0.0))
      return RS_ERROR(RS_ERR_INPUT, "creep: viscoelastic fractions [%d] must be >= 0 (got %g, %g)", i,
                      p->w_theta[i], p->w_radial[i]);
    sr += p->w_radial[i];
    st += p->w_theta[i];
  }
  if (!(sr < 1.0) || !(st < 1.0))
    return RS_ERROR(RS_ERR_INPUT, "creep: the relaxing fractions must sum to < 1 (E_theta %g, radial %g)",
                    st, sr);
  return RS_OK;
}

rs_status rs_creep_create(const rs_creep_params *p, rs_creep **out)
{
  *out = NULL;
  rs_status st = creep_check(p);
  if (st != RS_OK) return st;
  rs_creep *c = calloc(1, sizeof *c);
  if (!c) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the creep solver");
  c->p = *p;
  c->n = p->n_layers;
  for (int dir = 1; dir >= 0; --dir) /* radial arms first */
    for (int i = 0; i < p->n_terms; ++i) {
      const double w = dir ? p->w_radial[i] : p->w_theta[i];
      if (!(w > 0.0)) continue;
      c->arm_term[c->n_arm] = i;
      c->arm_radial[c->n_arm] = dir;
      c->arm_w[c->n_arm] = w;
      c->arm_rate[c->n_arm] = 1.0 / p->tau[i];
      c->n_arm++;
    }
  const size_t n = (size_t)c->n;
  c->ny = (long)n * (1 + c->n_arm);
  c->q = calloc(n * (size_t)(c->n_arm ? c->n_arm : 1), sizeof(double));
  c->R_last = calloc(n, sizeof(double));
  c->H_last = calloc(n, sizeof(double));
  c->F_last = calloc(n, sizeof(double));
  c->P = calloc(n, sizeof(double));
  c->Er = calloc(n, sizeof(double));
  c->Sr = calloc(n, sizeof(double));
  c->St = calloc(n, sizeof(double));
  c->cr = calloc(n, sizeof(double));
  c->ct = calloc(n, sizeof(double));
  c->work = calloc(n, sizeof(double));
  if (!c->q || !c->R_last || !c->H_last || !c->F_last || !c->P || !c->Er || !c->Sr || !c->St || !c->cr ||
      !c->ct || !c->work) {
    rs_creep_destroy(&c);
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the creep solver for %d layers", p->n_layers);
  }
  if (rs_sundials_context_create(&c->ctx) != 0) goto fail;
  c->y = N_VNew_Serial(c->ny, c->ctx);
  c->atol = c->y ? N_VClone(c->y) : NULL;
  if (!c->y || !c->atol) goto fail;
  /* fused vector kernels: the vector operations on N (1 + arms) values are most of the cost */
  if (N_VEnableFusedOps_Serial(c->y, SUNTRUE) != 0 || N_VEnableFusedOps_Serial(c->atol, SUNTRUE) != 0)
    goto fail;
  rs_creep_vector_specialise(c->y); /* before CVODE clones its vectors from it */
  N_VConst(0.0, c->y);
  N_VConst(1.0, c->atol);
  c->cvode = CVodeCreate(CV_BDF, c->ctx);
  if (!c->cvode) goto fail;
  if (rs_sundials_cvode_messages(c->cvode, c->ctx, &c->msg) != 0) goto fail;
  if (CVodeInit(c->cvode, creep_rhs, 0.0, c->y) != CV_SUCCESS) goto fail;
  if (CVodeSVtolerances(c->cvode, p->rtol, c->atol) != CV_SUCCESS) goto fail;
  if (CVodeSetUserData(c->cvode, c) != CV_SUCCESS) goto fail;
  c->LS = SUNLinSol_SPGMR(c->y, SUN_PREC_LEFT, 10, c->ctx);
  if (!c->LS) goto fail;
  /* classical Gram-Schmidt: one fused multi-dot product per iteration */
  if (SUNLinSol_SPGMRSetGSType(c->LS, SUN_CLASSICAL_GS) != 0) goto fail;
  if (CVodeSetLinearSolver(c->cvode, c->LS, NULL) != CV_SUCCESS) goto fail;
  if (CVodeSetPreconditioner(c->cvode, creep_psetup, creep_psolve) != CV_SUCCESS) goto fail;
  if (CVodeSetMaxNumSteps(c->cvode, p->max_steps) != CV_SUCCESS) goto fail;
  *out = c;
  return RS_OK;
fail:
  st = RS_ERROR(RS_ERR_INTERNAL, "cannot set up CVODE for creep: %s",
                c->msg[0] ? c->msg : "allocation failed");
  rs_creep_destroy(&c);
  return st;
}

/* CVODE's counters run from its last re-initialisation; the stats add what they gained */
static void creep_add_stats(rs_creep *c, int restarted)
{
  long v[5] = {0};
  CVodeGetNumSteps(c->cvode, &v[0]);
  CVodeGetNumLinIters(c->cvode, &v[1]);
  CVodeGetNumNonlinSolvIters(c->cvode, &v[2]);
  CVodeGetNumErrTestFails(c->cvode, &v[3]);
  CVodeGetNumNonlinSolvConvFails(c->cvode, &v[4]);
  if (restarted) memset(c->seen, 0, sizeof c->seen);
  long *dst[5] = {&c->stats.steps, &c->stats.lin_iters, &c->stats.nonlin_iters,
                  &c->stats.err_fails, &c->stats.conv_fails};
  for (int i = 0; i < 5; ++i) {
    *dst[i] += v[i] - c->seen[i];
    c->seen[i] = v[i];
  }
}

static rs_status creep_commit(rs_creep *c, double hours, double *core_pressure, double *sigma_r,
                              double *sigma_theta);

rs_status rs_creep_hold(rs_creep *c, double hours, double *core_pressure, double *sigma_r,
                        double *sigma_theta)
{
  if (!(hours >= 0.0) || !isfinite(hours))
    return RS_ERROR(RS_ERR_INPUT, "creep: a stage's hours must be >= 0 (got %g)", hours);
  const int n = c->n;
  double *y = N_VGetArrayPointer(c->y), *atol = N_VGetArrayPointer(c->atol);
  /* A hold that starts where the last one ended (no change in between: the same stresses,
   * bit for bit) continues CVODE's integration with its step size and order, instead of
   * restarting at order 1 with a tiny step: a week in 10 stages at constant conditions
   * costs one integration (docs/performance.md). */
  int same = c->warm && -*core_pressure == c->F_last[0];
  for (int j = 1; same && j < n; ++j) same = sigma_r[j - 1] == c->F_last[j];
  for (int j = 0; same && j < n; ++j) same = sigma_theta[j] == c->H_last[j];
  if (same && hours > 0.0 && c->n_arm > 0) {
    c->msg[0] = '\0';
    sunrealtype tret = c->t_end;
    int flag = CVodeSetStopTime(c->cvode, c->t_end + hours);
    if (flag == CV_SUCCESS) flag = CVode(c->cvode, c->t_end + hours, c->y, &tret, CV_NORMAL);
    creep_add_stats(c, 0);
    if (flag < 0)
      return RS_ERROR(RS_ERR_SOLVER,
                      "creep did not converge: CVODE (BDF, GMRES preconditioned by the arms' "
                      "relaxation, rtol %g, at most %ld steps) stopped at %.6g h of a %.6g h "
                      "stage: %s", c->p.rtol, c->p.max_steps, tret - c->t_end, hours,
                      c->msg[0] ? c->msg : CVodeGetReturnFlagName(flag));
    c->t_end += hours;
    return creep_commit(c, hours, core_pressure, sigma_r, sigma_theta);
  }
  /* face stresses now, and the scales of the error weights */
  double sr_max = 0.0, st_max = 0.0;
  y[0] = -*core_pressure;
  for (int j = 1; j < n; ++j) y[j] = sigma_r[j - 1];
  for (int j = 0; j < n; ++j) {
    sr_max = fmax(sr_max, fabs(y[j]));
    st_max = fmax(st_max, fabs(sigma_theta[j]));
  }
  if (!isfinite(sr_max) || !isfinite(st_max))
    return RS_ERROR(RS_ERR_INPUT, "creep: the roll's stresses are not finite");
  if (!(sr_max > 0.0)) sr_max = 1.0;
  if (!(st_max > 0.0)) st_max = 1.0;
  /* the change since the last hold loads the arms elastically: dq_i = w_i dS */
  for (int a = 0; a < c->n_arm; ++a) {
    const double w = c->arm_w[a], *q = c->q + (long)a * n;
    double *ya = y + n + (long)a * n;
    for (int j = 0; j < n; ++j) {
      const double S = c->arm_radial[a] ? 0.5 * (y[j] + (j + 1 < n ? y[j + 1] : 0.0)) : sigma_theta[j];
      const double S0 = c->arm_radial[a] ? c->R_last[j] : c->H_last[j];
      ya[j] = q[j] + w * (S - S0);
    }
  }
  const double rtol = c->p.rtol;
  for (int j = 0; j < n; ++j) atol[j] = rtol * sr_max;
  for (int a = 0; a < c->n_arm; ++a)
    for (int j = 0; j < n; ++j) atol[n + (long)a * n + j] = rtol * (c->arm_radial[a] ? sr_max : st_max);
  if (hours > 0.0 && c->n_arm > 0) {
    c->msg[0] = '\0';
    if (CVodeReInit(c->cvode, 0.0, c->y) != CV_SUCCESS ||
        CVodeSVtolerances(c->cvode, rtol, c->atol) != CV_SUCCESS ||
        CVodeSetStopTime(c->cvode, hours) != CV_SUCCESS)
      return RS_ERROR(RS_ERR_SOLVER, "creep: CVODE re-initialisation failed: %s", c->msg);
    sunrealtype tret = 0.0;
    const int flag = CVode(c->cvode, hours, c->y, &tret, CV_NORMAL);
    creep_add_stats(c, 1);
    if (flag < 0)
      return RS_ERROR(RS_ERR_SOLVER,
                      "creep did not converge: CVODE (BDF, GMRES preconditioned by the arms' "
                      "relaxation, rtol %g, at most %ld steps) stopped at %.6g h of a %.6g h "
                      "stage: %s", rtol, c->p.max_steps, tret, hours,
                      c->msg[0] ? c->msg : CVodeGetReturnFlagName(flag));
  }
  c->warm = hours > 0.0 && c->n_arm > 0;
  c->t_end = hours;
  return creep_commit(c, hours, core_pressure, sigma_r, sigma_theta);
}

/* the hold's end: face stresses (the hoop stress by the turns' equilibrium), arms, turn stresses */
static rs_status creep_commit(rs_creep *c, double hours, double *core_pressure, double *sigma_r,
                              double *sigma_theta)
{
  const int n = c->n;
  const double *y = N_VGetArrayPointer(c->y);
  for (long i = 0; i < c->ny; ++i)
    if (!isfinite(y[i]))
      return RS_ERROR(RS_ERR_SOLVER, "creep: non-finite stresses after a %.6g h stage", hours);
  /* commit: face stresses (the hoop stress by the turns' equilibrium), arms, turn stresses */
  const double rc = c->p.core_radius, t = c->p.caliper;
  double prev_d = y[0] + *core_pressure; /* the change of face 0's sigma_r */
  *core_pressure = -y[0];
  for (int j = 0; j < n; ++j) {
    const double d_hi = j + 1 < n ? y[j + 1] - sigma_r[j] : 0.0;
    sigma_theta[j] += ((rc + (j + 1) * t) * d_hi - (rc + j * t) * prev_d) / t;
    if (j + 1 < n) sigma_r[j] = y[j + 1];
    prev_d = d_hi;
    c->R_last[j] = 0.5 * (y[j] + (j + 1 < n ? y[j + 1] : 0.0));
    c->H_last[j] = sigma_theta[j];
    c->F_last[j] = y[j];
  }
  memcpy(c->q, y + n, (size_t)c->n_arm * (size_t)n * sizeof(double));
  return RS_OK;
}

void rs_creep_get_stats(const rs_creep *c, rs_creep_stats *stats)
{
  *stats = c->stats;
}
