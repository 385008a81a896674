/* The roll build-up engine: Hakiel-type accretion (Hakiel 1987, Tappi J. 70(5)),
 * each increment integrated with SUNDIALS CVODE in a scale-free form.
 *
 * One increment winds layers onto the roll [r_c, s]. Its stress change ds(r) solves
 *     r^2 ds'' + 3 r ds' - (g^2 - 1) ds = 0,     g^2(r) = E_theta / E_r(P(r)),
 * with r_c ds'(r_c) = kc ds(r_c), kc = E_theta/E_c + nu_rtheta - 1 (0 = E_theta/E_c for a
 * rigid core), and ds(s) = -T/s. The core condition is homogeneous, so ds = A y(r) with
 * y(r_c) = 1. Instead of y, which grows like (r/r_c)^(g-1) and overflows for g ~ 700,
 * CVODE integrates the bounded pair, in x = ln r,
 *     w = r y'/y = dy/dx / y :   dw/dx = g^2 - 1 - 2 w - w^2,    w(r_c) = kc   (Riccati)
 *     L = ln y               :   dL/dx = w,                       L(r_c) = 0
 * and ds(r_j) = -(T/s) exp(L(r_j) - L(s)) <= T/s in magnitude, r ds' = w ds. The stable
 * equilibrium of the Riccati equation is w = g - 1 (rate -2g in x), so w stays between kc
 * and g - 1: nothing can overflow. The equation is stiff where g is large: BDF. In x = ln r
 * a roll of constant g has w constant and L linear, so CVODE's steps are set by how g
 * varies, not by the 1/r^q derivatives of ln r (3x fewer steps than integrating in r).
 *
 * Where a layer's load goes (rs_load_placement): by default the new layer k joins at hoop
 * stress T0/t and presses on the roll beneath it, so its increment lives on [r_c, s_{k-1}]
 * with ds(s_{k-1}) = -T0/s_{k-1} and its own outer face is traction free; Hakiel's original
 * condition puts ds(s_k) = -T0/s_k at its outer radius. In the engine the two differ only
 * in the node a layer loads (k - shift) and in whether that node's layer takes the load in
 * its hoop stress (docs/roll-model.md).
 *
 * E_r is frozen at the pressures before the increment (Hakiel). The pressures live at the
 * nodes r_0 = r_c (core) and r_j = s_j (outer radius of layer j); between nodes ln g^2 is a
 * C^1 cubic Hermite (centred slopes). A continuous, once-differentiable g keeps BDF at high
 * order instead of shrinking its steps at every layer boundary (measured: 30% fewer steps
 * than linear interpolation), g^2 stays positive, and a constant E_r gives a constant g.
 *
 * A lumped increment of m layers (numerics.layers_per_step) is the sum of its m single-layer
 * increments, all read off one integration: y comes from the core, so layer i's load can be
 * put at its own radius s_i exactly (ds_i = -(T_i/s_i) y/y(s_i)). What one integration cannot
 * give is each layer's own modulus (Hakiel: the pressures just before that layer), so it is
 * a predictor-corrector: integrate with the modulus frozen before the block, take from those
 * sub-increments the mean pressure each node would have carried before each of the layers
 * that reach it, integrate again with the modulus there (RS_LUMP_CORRECTED). Error first
 * order in m - 1, ~60x below the first scheme's (frozen modulus, the whole block's load at
 * the outer radius: RS_LUMP_FROZEN, kept for comparison; docs/accuracy.md). For m = 1 both
 * are exact Hakiel accretion, bit for bit.
 *
 * An increment need not be integrated from the core: below the newest layers the modulus
 * barely changes, so it keeps the deep part of the last integration from the core and
 * integrates from a start node up, the error this adds held to rtol x T0/s
 * (roll_reuse_start; numerics.reuse; docs/roll-model.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>

#include "reelsim/roll.h"
#include "vector2.h"

enum { RS_CVODE_MSG_LEN = 512 };

struct rs_roll {
  rs_roll_params p;
  double kc;            /* core condition r y'/y at r_c */
  int shift;            /* 1: a layer's load on the node beneath it (RS_LOAD_BENEATH), 0:
                           at its own outer radius (Hakiel): layer k loads node k - shift */
  int n;                /* layers wound */
  double core_sigma;    /* sigma_r at r_c, Pa (compression negative) */
  double *sigma_r;      /* [cap] per layer at s_j */
  double *sigma_theta;  /* [cap] */
  /* work arrays over nodes 0..n (node 0 = core) */
  double *Er;           /* E_r at the nodes for the current increment; g^2 = E_theta/E_r */
  double *lg2;          /* ln g^2, computed when the interpolation first needs it */
  unsigned long long *lg2_epoch, epoch; /* lg2[j] is current when lg2_epoch[j] == epoch */
  /* the Hermite cubic of the interval last evaluated (CVODE's calls cluster): its index,
   * the epoch it belongs to, and ln g^2 and its slopes at the two ends */
  int hj;
  unsigned long long hepoch;
  double hy0, hy1, hm0, hm1;
  /* g^2 and d(g^2)/dx at the x last evaluated: a step's Newton iterations and the jet at
   * its end all look at the same x */
  double gx, g2x, dg2x;
  unsigned long long gepoch;
  double x_anchor, r_anchor; /* r_anchor = exp(x_anchor) exactly, near where CVODE is */
  double *w, *L;        /* (w, ln y) at the nodes */
  double *xnode;        /* ln r_j: CVODE's independent variable at the nodes */
  double *block_share;  /* [m] frozen lumping: share of the block's tension at or above a node */
  double *P_node;       /* [cap + 1] pressure that sets the increment's modulus at each node, Pa */
  double *P_mean;       /* [cap + 1] corrected lumping: mean pressure increment seen, Pa */
  double *dsr, *dsh;    /* [cap + 1] the increment's ds and ds + r ds' at the nodes */
  /* CVODE */
  SUNContext sunctx;
  void *cvode;
  N_Vector y;
  SUNNonlinearSolver NLS;
  char cvode_msg[RS_CVODE_MSG_LEN];
  rs_roll_stats stats;
  int nodes_in_use;     /* nodes the RHS may look at (k + 1) */
  /* Reuse of the deep solution (roll_reuse_start): the last integration from the core is
   * the reference; below the node an integration starts from, (w, L) stay the reference's */
  double *Er_ref;       /* [cap + 1] the modulus the reference was integrated with */
  double *scan_eps;     /* [cap + 1] max over nodes 0..j of |E_r / Er_ref - 1| */
  double *scan_L;       /* [cap + 1] max over nodes 0..j of L */
  int ref_top;          /* w, L at the nodes 0..ref_top are still the reference's; -1: none */
  int ref_age;          /* integrations since the reference */
  int start;            /* node the last integration started from (0: the core) */
  /* Below the start node the increment's shape is the reference's: e_j = y(r_j)/y(r_A) and
   * e_j (1 + w_j) of the reference's own increment (A its block's bottom node), kept for
   * nodes 0..shape_top; -1: none. An increment that starts at j0 <= shape_top is
   *   ds_j = c e_j,  ds_j + r ds_j' = c e_j (1 + w_j),   c = ds_{j0} / e_{j0}    (j < j0),
   * two multiplications a node (roll_block_increment, roll_commit). */
  double *shape_e, *shape_h;
  int shape_top;
  /* the last increment's nodes below deep_lo are c_deep (shape_e, shape_h) */
  int deep_lo;
  double c_deep;
};

/* ---- the increment ODE --------------------------------------------------------------- */

/* e^d by its Taylor sum to d^7: relative error below d^8/8! (2e-17 at |d| = 0.03) */
static inline double roll_exp_small(double d)
{
  return 1.0 + d * (1.0 + d * (1.0 / 2 + d * (1.0 / 6 + d * (1.0 / 24 + d * (1.0 / 120 +
         d * (1.0 / 720 + d * (1.0 / 5040)))))));
}

static inline double roll_lg2(rs_roll *roll, int j)
{
  if (roll->lg2_epoch[j] != roll->epoch) {
    roll->lg2[j] = log(roll->p.E_theta / roll->Er[j]);
    roll->lg2_epoch[j] = roll->epoch;
  }
  return roll->lg2[j];
}

/* r = e^x near the anchor as r_anchor e^(x - x_anchor) by a Taylor sum (relative error
 * below 1e-16 for |x - x_anchor| < 0.02); the anchor itself is always an exact exp(), so
 * nothing accumulates. CVODE evaluates within a step or two of where it was. */
static inline double roll_radius_at(rs_roll *roll, double x)
{
  const double d = x - roll->x_anchor;
  if (!(fabs(d) < 0.02)) {
    roll->x_anchor = x;
    roll->r_anchor = exp(x);
    return roll->r_anchor;
  }
  return roll->r_anchor * roll_exp_small(d);
}

/* g^2 at x = ln r: a cubic Hermite in ln g^2 between the nodes (Catmull-Rom slopes), in
 * the layer coordinate xi = (r - r_c)/t, and d(g^2)/dx = g^2 v'(xi) r/t (continuous: the
 * interpolant is C^1), which the node interpolation needs. */
static double roll_g2_eval(rs_roll *roll, double x, double *dg2)
{
  const double r = roll_radius_at(roll, x), xi = (r - roll->p.core_radius) / roll->p.caliper;
  const int last = roll->nodes_in_use - 1;
  int j = xi <= 0.0 ? -1 : (int)xi;
  if (j < 0 || j >= last) {
    *dg2 = 0.0;
    return roll->p.E_theta / roll->Er[j < 0 ? 0 : last];
  }
  double f = xi - j;
  if (j != roll->hj || roll->hepoch != roll->epoch) {
    double y0 = roll_lg2(roll, j), y1 = roll_lg2(roll, j + 1);
    roll->hm0 = j > 0 ? 0.5 * (y1 - roll_lg2(roll, j - 1)) : y1 - y0;
    roll->hm1 = j + 1 < last ? 0.5 * (roll_lg2(roll, j + 2) - y0) : y1 - y0;
    roll->hy0 = y0;
    roll->hy1 = y1;
    roll->hj = j;
    roll->hepoch = roll->epoch;
  }
  const double y0 = roll->hy0, y1 = roll->hy1, m0 = roll->hm0, m1 = roll->hm1;
  double f2 = f * f, f3 = f2 * f;
  double v = (2 * f3 - 3 * f2 + 1) * y0 + (f3 - 2 * f2 + f) * m0 + (-2 * f3 + 3 * f2) * y1 + (f3 - f2) * m1;
  double g2 = exp(v);
  double dv = (6 * f2 - 6 * f) * (y0 - y1) + (3 * f2 - 4 * f + 1) * m0 + (3 * f2 - 2 * f) * m1;
  *dg2 = g2 * dv * r / roll->p.caliper;
  return g2;
}

/* roll_g2_eval at x, kept for the next call at the same x (dg2 may be NULL) */
static double roll_g2_at(rs_roll *roll, double x, double *dg2)
{
  if (x != roll->gx || roll->gepoch != roll->epoch) {
    roll->g2x = roll_g2_eval(roll, x, &roll->dg2x);
    roll->gx = x;
    roll->gepoch = roll->epoch;
  }
  if (dg2) *dg2 = roll->dg2x;
  return roll->g2x;
}

/* f(x, [w, L]) = [g^2 - 1 - 2w - w^2, w],  x = ln r */
static int roll_rhs(sunrealtype x, N_Vector yv, N_Vector ydot, void *user)
{
  rs_roll *roll = user;
  const sunrealtype *y = NV_DATA_S(yv); /* the macro: the library's getter is a call */
  sunrealtype *f = NV_DATA_S(ydot);
  double g2 = roll_g2_at(roll, x, NULL), w = y[0];
  f[0] = g2 - 1.0 - 2.0 * w - w * w;
  f[1] = w;
  return isfinite(f[0]) ? 0 : 1; /* recoverable: CVODE retries with a smaller step */
}

/* J = df/d(w, L) = [[-(2 + 2w), 0], [1, 0]] */
static int roll_jac(double x, const double y[2], double J[2][2], void *user)
{
  (void)x;
  (void)user;
  J[0][0] = -(2.0 + 2.0 * y[0]);
  J[0][1] = 0.0;
  J[1][0] = 1.0;
  J[1][1] = 0.0;
  return 0;
}

/* CVODE's error weights 1/(rtol |y_i| + atol), as CVodeSStolerances would form them, in
 * one function instead of five vector operations */
static int roll_ewt(N_Vector yv, N_Vector ewt, void *user)
{
  const rs_roll *roll = user;
  const sunrealtype *y = NV_DATA_S(yv);
  sunrealtype *e = NV_DATA_S(ewt);
  const double rtol = roll->p.rtol, atol = roll->p.atol;
  const double d0 = rtol * fabs(y[0]) + atol, d1 = rtol * fabs(y[1]) + atol;
  if (!(d0 > 0.0 && d1 > 0.0)) return -1;
  e[0] = 1.0 / d0;
  e[1] = 1.0 / d1;
  return 0;
}

static void roll_cvode_err(int code, const char *module, const char *function, char *msg,
                           void *user)
{
  rs_roll *roll = user;
  snprintf(roll->cvode_msg, sizeof roll->cvode_msg, "%s %s (code %d): %s", module, function, code,
           msg);
}

/* ---- create / destroy ---------------------------------------------------------------- */

void rs_roll_destroy(rs_roll **rollp)
{
  if (!rollp || !*rollp) return;
  rs_roll *roll = *rollp;
  if (roll->cvode) CVodeFree(&roll->cvode);
  if (roll->NLS) SUNNonlinSolFree(roll->NLS); /* CVODE does not free a solver it was given */
  if (roll->y) N_VDestroy(roll->y);
  if (roll->sunctx) SUNContext_Free(&roll->sunctx);
  free(roll->sigma_r);
  free(roll->sigma_theta);
  free(roll->Er);
  free(roll->lg2);
  free(roll->lg2_epoch);
  free(roll->w);
  free(roll->L);
  free(roll->xnode);
  free(roll->block_share);
  free(roll->P_node);
  free(roll->P_mean);
  free(roll->dsr);
  free(roll->dsh);
  free(roll->Er_ref);
  free(roll->scan_eps);
  free(roll->scan_L);
  free(roll->shape_e);
  free(roll->shape_h);
  free(roll);
  *rollp = NULL;
}

static rs_status roll_check_params(const rs_roll_params *p)
{
  if (!(p->core_radius > 0.0) || !isfinite(p->core_radius))
    return RS_ERROR(RS_ERR_INPUT, "core radius must be > 0 m (got %g)", p->core_radius);
  if (!(p->caliper > 0.0) || !isfinite(p->caliper))
    return RS_ERROR(RS_ERR_INPUT, "caliper must be > 0 m (got %g)", p->caliper);
  if (!(p->E_theta > 0.0) || !isfinite(p->E_theta))
    return RS_ERROR(RS_ERR_INPUT, "E_theta must be > 0 Pa (got %g)", p->E_theta);
  if (!(p->core_stiffness > 0.0))
    return RS_ERROR(RS_ERR_INPUT, "core stiffness must be > 0 Pa (got %g)", p->core_stiffness);
  if (!(p->nu_rtheta > -1.0 && p->nu_rtheta < 1.0))
    return RS_ERROR(RS_ERR_INPUT, "nu_rtheta must lie in (-1, 1) (got %g)", p->nu_rtheta);
  if (p->max_layers < 1)
    return RS_ERROR(RS_ERR_INPUT, "the roll needs room for at least one layer (got %d)",
                    p->max_layers);
  if (!(p->rtol > 0.0 && p->rtol < 1.0))
    return RS_ERROR(RS_ERR_INPUT, "rtol must lie in (0, 1) (got %g)", p->rtol);
  if (p->lumping != RS_LUMP_CORRECTED && p->lumping != RS_LUMP_FROZEN)
    return RS_ERROR(RS_ERR_INPUT, "unknown lumping scheme %d", (int)p->lumping);
  if (p->reuse != RS_REUSE_ON && p->reuse != RS_REUSE_OFF)
    return RS_ERROR(RS_ERR_INPUT, "unknown reuse setting %d", (int)p->reuse);
  if (p->placement != RS_LOAD_BENEATH && p->placement != RS_LOAD_HAKIEL)
    return RS_ERROR(RS_ERR_INPUT, "unknown load placement %d", (int)p->placement);
  return RS_OK;
}

rs_status rs_roll_create(const rs_roll_params *params, rs_roll **out)
{
  *out = NULL;
  rs_status st = roll_check_params(params);
  if (st) return st;
  rs_roll *roll = calloc(1, sizeof *roll);
  if (!roll) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the roll");
  roll->p = *params;
  if (roll->p.atol <= 0.0) roll->p.atol = roll->p.rtol;
  if (roll->p.max_steps <= 0) roll->p.max_steps = 100000;
  roll->shift = params->placement == RS_LOAD_BENEATH;
  roll->kc = (isinf(params->core_stiffness) ? 0.0 : params->E_theta / params->core_stiffness) +
             params->nu_rtheta - 1.0;
  size_t cap = (size_t)params->max_layers;
  roll->sigma_r = calloc(cap, sizeof(double));
  roll->sigma_theta = calloc(cap, sizeof(double));
  roll->Er = calloc(cap + 1, sizeof(double));
  roll->lg2 = calloc(cap + 1, sizeof(double));
  roll->lg2_epoch = calloc(cap + 1, sizeof *roll->lg2_epoch);
  roll->w = calloc(cap + 1, sizeof(double));
  roll->L = calloc(cap + 1, sizeof(double));
  roll->xnode = calloc(cap + 1, sizeof(double));
  roll->block_share = calloc(cap + 1, sizeof(double));
  roll->P_node = calloc(cap + 1, sizeof(double));
  roll->P_mean = calloc(cap + 1, sizeof(double));
  roll->dsr = calloc(cap + 1, sizeof(double));
  roll->dsh = calloc(cap + 1, sizeof(double));
  roll->Er_ref = calloc(cap + 1, sizeof(double));
  roll->scan_eps = calloc(cap + 1, sizeof(double));
  roll->scan_L = calloc(cap + 1, sizeof(double));
  roll->shape_e = calloc(cap + 1, sizeof(double));
  roll->shape_h = calloc(cap + 1, sizeof(double));
  roll->shape_top = -1;
  roll->ref_top = -1;
  if (!roll->sigma_r || !roll->sigma_theta || !roll->Er || !roll->lg2 || !roll->lg2_epoch ||
      !roll->w || !roll->L || !roll->xnode || !roll->block_share || !roll->P_node ||
      !roll->P_mean || !roll->dsr || !roll->dsh || !roll->Er_ref || !roll->scan_eps ||
      !roll->scan_L || !roll->shape_e || !roll->shape_h) {
    rs_roll_destroy(&roll);
    return RS_ERROR(RS_ERR_MEMORY, "cannot allocate a roll of %d layers", params->max_layers);
  }

  for (size_t j = 0; j <= cap; ++j) roll->xnode[j] = log(params->core_radius + j * params->caliper);

  /* SUNDIALS 6.x: SUNContext_Create takes a communicator pointer (7.x changes it). */
  if (SUNContext_Create(NULL, &roll->sunctx) != 0) goto cvode_fail;
  roll->y = N_VNew_Serial(2, roll->sunctx);
  if (!roll->y) goto cvode_fail;
  /* fused vector kernels: fewer calls per step, and steps are what this engine is made of */
  if (N_VEnableFusedOps_Serial(roll->y, SUNTRUE) != 0) goto cvode_fail;
  /* and the hot ones as straight-line 2-component code (src/roll/vector2.c) */
  if (rs_roll_vector2_specialise(roll->y) != 0) goto cvode_fail;
  N_VConst(0.0, roll->y);
  roll->cvode = CVodeCreate(CV_BDF, roll->sunctx);
  if (!roll->cvode) goto cvode_fail;
  if (CVodeSetErrHandlerFn(roll->cvode, roll_cvode_err, roll) != CV_SUCCESS) goto cvode_fail;
  if (CVodeInit(roll->cvode, roll_rhs, log(params->core_radius), roll->y) != CV_SUCCESS) goto cvode_fail;
  if (CVodeWFtolerances(roll->cvode, roll_ewt) != CV_SUCCESS) goto cvode_fail;
  if (CVodeSetUserData(roll->cvode, roll) != CV_SUCCESS) goto cvode_fail;
  /* Newton with the exact 2 x 2 Jacobian (src/roll/vector2.c) */
  roll->NLS = rs_roll_newton2_create(roll->sunctx, roll->y, roll->cvode, roll_jac, roll);
  if (!roll->NLS || rs_roll_newton2_attach(roll->NLS) != 0) goto cvode_fail;
  /* one CVode call = one step here; the per-increment budget is counted by the engine */
  if (CVodeSetMaxNumSteps(roll->cvode, 10) != CV_SUCCESS) goto cvode_fail;
  /* CVODE keeps its step (and its order) while the step it could take is within a band of
   * the current one, [0, 1.5] by default: it never shrinks a step until one fails its error
   * test. Near the surface, where every step must be ~10 % shorter than the last, that
   * made one step in five fail (~20 a roll crossing). [0.8, 1.05]: it shrinks a step before
   * it fails (1.85 -> 1.47 right-hand sides a step, 8 % fewer instructions), and moves up
   * to order 5 on the way up from a restart in the smooth interior, where a partial
   * integration starts (and 5 % fewer steps from the core). docs/performance.md, fifth round. */
  if (CVodeSetEtaFixedStepBounds(roll->cvode, 0.8, 1.05) != CV_SUCCESS) goto cvode_fail;
  *out = roll;
  return RS_OK;

cvode_fail:
  st = RS_ERROR(RS_ERR_INTERNAL, "cannot set up CVODE for the roll: %s",
                roll->cvode_msg[0] ? roll->cvode_msg : "allocation failed");
  rs_roll_destroy(&roll);
  return st;
}

/* ---- one increment ----------------------------------------------------------------- */

/* P_node = the pressures (Pa, compression positive) at the nodes 0..k before the
 * increment, plus add[j] where add != NULL; the layers being wound carry none yet. Plain
 * loops: they vectorise. */
static void roll_gather_pressure(rs_roll *roll, int k, const double *add)
{
  double *restrict P = roll->P_node;
  const int n = roll->n < k ? roll->n : k;
  P[0] = -roll->core_sigma;
  for (int j = 1; j <= n; ++j) P[j] = -roll->sigma_r[j - 1];
  for (int j = n + 1; j <= k; ++j) P[j] = 0.0;
  if (add)
    for (int j = 0; j <= k; ++j) P[j] += add[j];
}

/* The state (w, L) at x with its first two x-derivatives, from the equations:
 *   w' = g^2 - 1 - 2w - w^2,   w'' = (g^2)' - 2 (1 + w) w',   L' = w,   L'' = w'. */
typedef struct roll_jet {
  double x, w, dw, d2w, L;
} roll_jet;

static roll_jet roll_jet_at(rs_roll *roll, double x, double w, double L)
{
  double dg2 = 0.0, g2 = roll_g2_at(roll, x, &dg2);
  double dw = g2 - 1.0 - 2.0 * w - w * w;
  return (roll_jet){x, w, dw, dg2 - 2.0 * (1.0 + w) * dw, L};
}

/* (w, L) inside the step [a, b] by the quintic Hermite interpolant of the values and first
 * two derivatives at its ends (error h^6 y^(6) / 46080 at most: far below the step's own
 * local error, of order h^6 y^(6) / 6 for BDF5), instead of asking CVODE for its
 * interpolant node by node (CVodeGetDky was a tenth of the engine's time). The quintic is
 * kept as its monomial coefficients in s = (x - a)/h, so a node costs two Horner sums. */
typedef struct roll_quintic {
  double a, inv_h, cw[6], cL[6];
} roll_quintic;

/* coefficients of p(s) from p, h p', h^2 p'' at s = 0 (p0, d0, c0) and s = 1 (p1, d1, c1) */
static void roll_quintic_coef(double p0, double d0, double c0, double p1, double d1, double c1,
                              double c[6])
{
  c[0] = p0;
  c[1] = d0;
  c[2] = 0.5 * c0;
  c[3] = 10.0 * (p1 - p0) - 6.0 * d0 - 4.0 * d1 - 1.5 * c0 + 0.5 * c1;
  c[4] = 15.0 * (p0 - p1) + 8.0 * d0 + 7.0 * d1 + 1.5 * c0 - c1;
  c[5] = 6.0 * (p1 - p0) - 3.0 * (d0 + d1) - 0.5 * (c0 - c1);
}

static void roll_quintic_make(const roll_jet *a, const roll_jet *b, roll_quintic *q)
{
  const double h = b->x - a->x, hh = h * h;
  q->a = a->x;
  q->inv_h = 1.0 / h;
  roll_quintic_coef(a->w, h * a->dw, hh * a->d2w, b->w, h * b->dw, hh * b->d2w, q->cw);
  roll_quintic_coef(a->L, h * a->w, hh * a->dw, b->L, h * b->w, hh * b->dw, q->cL);
}

/* (w, L) at the n nodes x[0..n) inside the step (a plain loop over arrays: it vectorises) */
static void roll_quintic_fill(const roll_quintic *q, const double *restrict x, double *restrict w,
                              double *restrict L, int n)
{
  const double a = q->a, inv_h = q->inv_h;
  const double w0 = q->cw[0], w1 = q->cw[1], w2 = q->cw[2], w3 = q->cw[3], w4 = q->cw[4], w5 = q->cw[5];
  const double l0 = q->cL[0], l1 = q->cL[1], l2 = q->cL[2], l3 = q->cL[3], l4 = q->cL[4], l5 = q->cL[5];
  for (int i = 0; i < n; ++i) {
    const double s = (x[i] - a) * inv_h;
    w[i] = ((((w5 * s + w4) * s + w3) * s + w2) * s + w1) * s + w0;
    L[i] = ((((l5 * s + l4) * s + l3) * s + l2) * s + l1) * s + l0;
  }
}

/* The first step: BDF starts at order 1 (backward Euler), local error h^2 |w''| / 2, so
 * h0 = sqrt(2 (rtol |w0| + atol) / |w''(x0)|) passes the first error test instead of
 * failing it and shrinking; capped by the relaxation scales (w relaxes from w0 (kc at the
 * core) towards g - 1 over dx ~ 1/(2g), and from a large kc (a core much softer than the
 * web) like 1/(x - x_c + 1/kc): start inside the shorter one, or the first Newton
 * iterations diverge). g2 is g^2 at x0. */
static double roll_first_step(const rs_roll *roll, const roll_jet *j0, double g2)
{
  const double cap = 0.05 / fmax(sqrt(g2 + 1.0), fabs(j0->w) + 1.0);
  const double tol = roll->p.rtol * fabs(j0->w) + roll->p.atol, d2 = fabs(j0->d2w);
  if (!(d2 > 0.0)) return cap;
  const double h = 0.5 * sqrt(2.0 * tol / d2); /* half: a margin for the error estimate */
  return h < cap ? h : cap;
}

/* Integrations from the core between two references: a reference serves 32 increments.
 * Accuracy does not need a refresh (roll_reuse_start bounds the error whatever the
 * reference's age); cost does: the start node sinks as the modulus drifts, and an
 * integration from the core costs ~150 steps against ~90 from the interior. Refreshing
 * every 16, 32 or 64 increments gives the same steps within 0.5 % (docs/performance.md). */
enum { RS_REUSE_REFRESH = 32 };

/* The node to start the integration of an increment onto k from, keeping the reference's
 * (w, L) below it, or -1: from the core, as a new reference.
 *
 * Node j's reference (w, L) solves the Riccati equation with E_ref instead of E_r. The
 * equation relaxes to w = g - 1 at rate 2g, so a relative change eps of g^2 = E_theta/E_r
 * moves w by ~ (w + 1) eps / 2: the increment below a start node s0 is off by a relative
 * ~ (eps / 2) (L(s0) - L_j), and above it by ~ eps / 4 (the start value's error, relaxing).
 * The increment itself is (T0/s) exp(L_j - L_s) there. So the error in units of T0/s is
 * at most ~ E(s0) = max_{j <= s0} eps_j x exp(max_{j <= s0} L_j - L_s) x (at most e^-1 / 2
 * from the factor u e^-u of the nodes below): the start node is the highest with E(s0) <=
 * rtol, the tolerance CVODE's own local errors are held to. E grows with s0 (both maxima
 * do), so it is found by bisection. L_s is the top of the last increment (L[n - shift]),
 * one increment below the new one: the bound is on the safe side.
 *
 * The error has one sign (pressures only grow, so E_r drifts one way); measured on the
 * 6054-layer newsprint reel at rtol 1e-6, the stresses move by 7e-7 of the core pressure
 * against integrating every increment from the core, a thirtieth of CVODE's own global
 * error there (2.3e-5; docs/roll-model.md). */
static int roll_reuse_start(rs_roll *roll)
{
  const int n = roll->n;
  if (roll->p.reuse == RS_REUSE_OFF || roll->ref_top < 1 || n < 1 ||
      roll->ref_age >= RS_REUSE_REFRESH)
    return -1;
  /* below the top of the last integration, so the new one (one node higher) has length */
  const int top = roll->ref_top < n - roll->shift ? roll->ref_top : n - roll->shift;
  const double *restrict Er = roll->Er, *restrict Eref = roll->Er_ref, *restrict L = roll->L;
  double *restrict pe = roll->scan_eps, *restrict pl = roll->scan_L;
  double me = 0.0, ml = -INFINITY;
  for (int j = 0; j <= top; ++j) {
    const double e = fabs(Er[j] - Eref[j]) / Eref[j];
    me = e > me ? e : me;
    ml = L[j] > ml ? L[j] : ml;
    pe[j] = me;
    pl[j] = ml;
  }
  const double Ls = L[n - roll->shift], tol = roll->p.rtol;
  int lo = -1, hi = top + 1; /* E(lo) <= tol < E(hi) */
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    if (pe[mid] * exp(pl[mid] - Ls) <= tol)
      lo = mid;
    else
      hi = mid;
  }
  return lo >= 1 ? lo : -1; /* node 0 alone saves nothing: start a new reference */
}

/* Integrates (w, L) from r_c to s = r_{k}, storing them at every node 0..k, or, when
 * roll_reuse_start finds a start node j0, from r_{j0} with the reference's (w, L) there,
 * keeping the reference's values below it.
 * One CVODE step at a time; the nodes inside each step are interpolated between its ends
 * (roll_quintic_fill), so the cost per node is a short polynomial, not a CVODE call. */
static rs_status roll_integrate(rs_roll *roll, int k)
{
  if (k == 0) { /* the first layer's load on the core: nothing to integrate */
    roll->w[0] = roll->kc;
    roll->L[0] = 0.0;
    roll->start = 0;
    roll->stats.full_integrations++;
    return RS_OK;
  }
  const double *xn = roll->xnode, xs = xn[k];
  const int j0 = roll_reuse_start(roll), from_core = j0 < 0, first = from_core ? 0 : j0;
  const double x0 = xn[first];
  sunrealtype *y = N_VGetArrayPointer(roll->y);
  if (from_core) {
    roll->w[0] = roll->kc;
    roll->L[0] = 0.0;
  }
  /* from the core (0, kc); else the reference's values, whose L carries the reference's
   * origin: every L difference the increment is built from stays consistent */
  y[0] = roll->w[first];
  y[1] = roll->L[first];
  roll->cvode_msg[0] = '\0';
  /* every integration anchors r = e^x afresh at its start: its radii do not depend on
   * where the last integration ended */
  roll->x_anchor = x0;
  roll->r_anchor = exp(x0);
  roll_jet prev = roll_jet_at(roll, x0, y[0], y[1]);
  const double g2_start = roll_g2_at(roll, x0, NULL);
  if (CVodeReInit(roll->cvode, x0, roll->y) != CV_SUCCESS ||
      CVodeSetStopTime(roll->cvode, xs) != CV_SUCCESS ||
      CVodeSetInitStep(roll->cvode, roll_first_step(roll, &prev, g2_start)) != CV_SUCCESS)
    return RS_ERROR(RS_ERR_SOLVER, "CVODE re-initialisation failed: %s", roll->cvode_msg);
  roll->start = first;
  if (from_core) { /* a new reference: nodes 0..k, with the modulus it is integrated with */
    memcpy(roll->Er_ref, roll->Er, (size_t)(k + 1) * sizeof(double));
    roll->ref_top = k;
    roll->ref_age = 0;
    roll->shape_top = -1; /* until its increment is built (roll_block_increment) */
    roll->stats.full_integrations++;
  } else { /* the nodes above j0 are overwritten: they are no longer the reference's */
    roll->ref_top = j0;
    roll->ref_age++;
  }

  int next = first + 1; /* next node to fill */
  long steps = 0;
  sunrealtype tret = x0;
  while (next <= k) {
    if (++steps > roll->p.max_steps)
      return RS_ERROR(RS_ERR_SOLVER,
                      "CVODE needed more than %ld steps to cross the roll (reached r = %.6g m of "
                      "%.6g m); raise numerics.max_steps or loosen numerics.rtol",
                      roll->p.max_steps, exp(tret), exp(xs));
    int flag = CVode(roll->cvode, xs, roll->y, &tret, CV_ONE_STEP);
    if (flag < 0)
      return RS_ERROR(RS_ERR_SOLVER, "CVODE failed at r = %.9g m (roll outer radius %.9g m): %s",
                      exp(tret), exp(xs),
                      roll->cvode_msg[0] ? roll->cvode_msg : CVodeGetReturnFlagName(flag));
    const roll_jet cur = roll_jet_at(roll, tret, y[0], y[1]);
    if (xn[next] <= tret) {
      roll_quintic q;
      roll_quintic_make(&prev, &cur, &q);
      /* the last node inside the step: r_j = r_c + j t, so j = (e^x - r_c)/t up to rounding,
       * settled against the stored ln r_j */
      int last = (int)((exp(tret) - roll->p.core_radius) / roll->p.caliper);
      if (last < next) last = next;
      if (last > k) last = k;
      while (last > next && xn[last] > tret) --last;
      while (last < k && xn[last + 1] <= tret) ++last;
      roll_quintic_fill(&q, xn + next, roll->w + next, roll->L + next, last - next + 1);
      next = last + 1;
      if (next > k) { /* the outer node is the step's end: exact, not interpolated */
        roll->w[k] = cur.w;
        roll->L[k] = cur.L;
      }
    }
    prev = cur;
  }
  long nfe = 0;
  CVodeGetNumRhsEvals(roll->cvode, &nfe); /* counters restart at every CVodeReInit */
  roll->stats.cvode_steps += steps;
  roll->stats.rhs_evals += nfe;
  roll->stats.jac_evals = rs_roll_newton2_jacobians(roll->NLS); /* counts across increments */
  return RS_OK;
}

/* E_r(P) at the nodes 0..k, P from roll->P_node: the modulus an integration sees
 * (g^2 = E_theta / E_r, and ln g^2, are formed only where the steps look: roll_lg2). */
static rs_status roll_set_modulus(rs_roll *roll, int k)
{
  rs_radial_modulus_n(&roll->p.radial, roll->P_node, roll->Er, k + 1);
  /* linear and Pfeiffer moduli are positive and finite at every finite P >= 0 (K1, K2,
   * E_r > 0 checked at load; the pressures are finite: roll_commit); a polynomial or a
   * table can leave its range */
  const rs_radial_kind law = roll->p.radial.law;
  if (law != RS_RADIAL_LINEAR && law != RS_RADIAL_PFEIFFER)
    for (int j = 0; j <= k; ++j)
      if (!(roll->Er[j] > 0.0 && roll->Er[j] < INFINITY))
        return RS_ERROR(RS_ERR_SOLVER,
                        "radial modulus E_r = %g Pa at r = %.6g m (pressure %g Pa) is not "
                        "positive: the radial law is outside its range",
                        roll->Er[j], roll->p.core_radius + j * roll->p.caliper, roll->P_node[j]);
  /* ln g^2 only where CVODE's steps look (a few nodes per step, ~1/4 of the nodes of a
   * long roll): a log at every node at every increment was 7 % of the engine's time */
  roll->epoch++;
  roll->nodes_in_use = k + 1;
  return RS_OK;
}

/* exp(d) for the decay over one layer, d = L_j - L_{j+1} = -int w dx, |d| ~ w t / r, small:
 * the Taylor sum to d^7 (relative error d^8/8! < 2e-17 for |d| < 0.03) costs 8 flops where
 * exp() costs ~20 ns, and the product down the roll carries ~N x 1e-16 of rounding (1e-12
 * for 10,000 layers). A larger step (a very soft web, g t / r > 0.03) takes exp(). */
static inline double roll_exp_step(double d)
{
  return fabs(d) >= 0.03 ? exp(d) : roll_exp_small(d);
}

/* e_j = y(r_j)/y(r_top) for j = top-1 .. lo, into e[lo..top): the products, from the top
 * down, of the one-layer decays exp(L_j - L_{j+1}) (roll_exp_step: the Taylor sums in a
 * plain loop that vectorises, then the running product, which takes exp() where a decay
 * is large). Below 1e-290 the product is 0: no subnormals. */
static void roll_decays(const double *restrict L, double *restrict e, int lo, int top)
{
  for (int j = lo; j < top; ++j) {
    const double d = L[j] - L[j + 1];
    e[j] = roll_exp_small(d);
  }
  double p = 1.0;
  for (int j = top - 1; j >= lo; --j) {
    double t = e[j];
    /* |d| >= 0.03 gives a value outside [e^-0.03, e^0.03] = [0.97045, 1.03045] (the sum is
     * increasing there, and far below 1 or negative for d < -0.03): look only then */
    if (!(t > 0.9705 && t < 1.0304)) t = roll_exp_step(L[j] - L[j + 1]);
    p = p > 1e-290 ? p * t : 0.0;
    e[j] = p;
  }
}

/* The increment of a block of m layers wound onto k_old, from one integration's (w, L).
 * Block layer i loads node q_i = k_old + 1 + i - shift (radius s_i: its own outer radius
 * for Hakiel, the outer radius of the layer beneath it by default), and its sub-increment
 * is exactly
 *     ds_i(r_j) = -(T_i / s_i) exp(L_j - L(s_i)),     j <= q_i,
 * because y, integrated from the core, does not depend on where the load is applied.
 * Summed from the top of the block down, S_b = T_b/s_b + exp(L_b - L_{b+1}) S_{b+1}: every
 * exponent is a decay over one layer or from a node to the bottom of the block, so nothing
 * overflows. Fills dsr = sum of ds_i at each node, dsh = sum over the layers strictly above
 * it of ds_i (1 + w) (= ds_i + r ds_i'; with the load beneath a layer, the sub-increments
 * at or above it: that layer is part of the loaded body). With mean != NULL also the mean, over the
 * sub-increments that reach a node, of the pressure the block has added there before each:
 *     mean_j = (1/n_j) sum_i sum_{i' < i} -ds_i'(r_j)
 * (n_j = m below the block, m - b at block node b, which exists from sub-increment b on).
 * For m = 1 these are the single-layer formulas of Hakiel accretion, operation for
 * operation. */
static void roll_block_increment(rs_roll *roll, int k_old, int m, const double *T0, double *mean)
{
  const double rc = roll->p.core_radius, t = roll->p.caliper;
  const double *L = roll->L, *w = roll->w;
  /* block layer b loads node bottom + b: its own outer radius (Hakiel), or the outer radius
   * of the layer beneath it (then that layer's hoop stress takes the load too, and the new
   * outermost layer's outer face stays traction free) */
  const int shift = roll->shift, bottom = k_old + 1 - shift;
  double S = 0.0, V = 0.0; /* V_b = sum_{i >= b} (m - 1 - i) T_i/s_i exp(L_b - L(s_i)) */
  for (int b = m - 1; b >= 0; --b) {
    const int j = bottom + b;
    const double decay = b == m - 1 ? 0.0 : exp(L[j] - L[j + 1]);
    const double above = S * decay, c = T0[b] / (rc + j * t);
    S = above + c;
    roll->dsr[j] = -S;
    roll->dsh[j] = -above * (1.0 + w[j]); /* Hakiel's hoop accounting (unused beneath) */
    if (mean) {
      V = V * decay + (m - 1 - b) * c;
      mean[j] = V / (m - b);
    }
  }
  if (shift) /* the outermost layer: no load above it */
    roll->dsr[k_old + m] = 0.0;
  /* below the block: ds_j = -S e_j, e_j = y(r_j)/y(s_b), from the one-layer decays down to
   * the start node lo of the integration, and below it from the reference's shape */
  double *restrict dsr = roll->dsr, *restrict dsh = roll->dsh;
  const int j0 = roll->start;
  const int lo = j0 >= 1 && j0 <= roll->shape_top && roll->shape_e[j0] > 1e-280 ? j0 : 0;
  roll_decays(L, dsr, lo, bottom);
  if (j0 == 0) { /* a reference: keep its shape (the nodes below the block) */
    memcpy(roll->shape_e, dsr, (size_t)bottom * sizeof(double));
    if (!shift)
      for (int j = 0; j < bottom; ++j) roll->shape_h[j] = dsr[j] * (1.0 + w[j]);
    roll->shape_top = bottom - 1;
  }
  roll->deep_lo = lo;
  roll->c_deep = lo > 0 ? -S * dsr[lo] / roll->shape_e[lo] : 0.0;
  if (mean) {
    for (int j = lo; j < bottom; ++j) mean[j] = V * dsr[j] / m;
    const double cm = lo > 0 ? V * dsr[lo] / (m * roll->shape_e[lo]) : 0.0;
    for (int j = 0; j < lo; ++j) mean[j] = cm * roll->shape_e[j];
  }
  for (int j = lo; j < bottom; ++j) dsr[j] *= -S;
  if (!shift)
    for (int j = lo; j < bottom; ++j) dsh[j] = dsr[j] * (1.0 + w[j]);
}

/* With the load beneath each layer, a layer's hoop stress is its mean over the turn, i.e.
 * its tension per unit width over t, and the turn's equilibrium gives it exactly from the
 * radial stresses on its two faces:
 *     sigma_theta_j = (s_j sigma_r(s_j) - s_{j-1} sigma_r(s_{j-1})) / t,
 * because every increment satisfies sigma_theta = d(r sigma_r)/dr (the integral of its hoop
 * stress over the turn is [r ds]) and the layer joined at T0_j/t while pressing T0_j on
 * the face beneath it (docs/roll-model.md). The outermost layer, whose outer face is free,
 * gets T0/t. A point value at s_j would differ from the mean by a first-order-in-t amount
 * that, for g ~ 60, is of the size of the hoop stress itself deep in the roll. Layers
 * 1..k (arrays 0..k-1); node 0 is the core. */
static void roll_hoop_from_equilibrium(rs_roll *roll, int k)
{
  const double rc = roll->p.core_radius, t = roll->p.caliper, inv_t = 1.0 / t;
  const double *restrict sr = roll->sigma_r;
  double *restrict sth = roll->sigma_theta;
  double below = rc * roll->core_sigma; /* r sigma_r on the inner face of layer j */
  for (int j = 1; j <= k; ++j) {
    const double above = (rc + j * t) * sr[j - 1];
    sth[j - 1] = (above - below) * inv_t;
    below = above;
  }
}

/* RS_OK when ds[0..k] and dh[0..k] (an increment's radial and hoop stress at the nodes)
 * are all finite; else the error naming the lowest node that is not. */
static rs_status roll_check_increment(const rs_roll *roll, const double *ds, const double *dh, int k)
{
  /* the nodes below deep_lo are c_deep times the reference's shape, which is finite (its
   * own increment passed this check): c_deep says for them. Above, x - x is 0 for a finite
   * x and NaN for an infinite or NaN one: one sum says whether all are finite (four sums,
   * independent, so that the compiler can vectorise them: a floating-point sum's order is
   * otherwise fixed) */
  const double rc = roll->p.core_radius, t = roll->p.caliper;
  if (!isfinite(roll->c_deep))
    return RS_ERROR(RS_ERR_SOLVER, "non-finite stress increment at the core (outer radius %.9g m)",
                    rc + k * t);
  double z0 = 0.0, z1 = 0.0, z2 = 0.0, z3 = 0.0;
  int j = roll->deep_lo;
  for (; j + 3 <= k; j += 4) {
    z0 += (ds[j] - ds[j]) + (dh[j] - dh[j]);
    z1 += (ds[j + 1] - ds[j + 1]) + (dh[j + 1] - dh[j + 1]);
    z2 += (ds[j + 2] - ds[j + 2]) + (dh[j + 2] - dh[j + 2]);
    z3 += (ds[j + 3] - ds[j + 3]) + (dh[j + 3] - dh[j + 3]);
  }
  for (; j <= k; ++j) z0 += (ds[j] - ds[j]) + (dh[j] - dh[j]);
  const int bad = (z0 + z1) + (z2 + z3) != 0.0;
  for (j = roll->deep_lo; bad && j <= k; ++j)
    if (!isfinite(ds[j]) || !isfinite(dh[j]))
      return j == 0 ? RS_ERROR(RS_ERR_SOLVER,
                               "non-finite stress increment at the core (outer radius %.9g m)",
                               rc + k * t)
                    : RS_ERROR(RS_ERR_SOLVER, "non-finite stress increment at r = %.9g m (layer %d)",
                               rc + j * t, j);
  return RS_OK;
}

/* The first lumping scheme (RS_LUMP_FROZEN): every block layer's sub-increment taken as
 * the outermost one's (load at s, frozen modulus), the block's nodes getting the share of
 * the block's tension wound at or above them. Kept for comparison (docs/accuracy.md). */
static rs_status roll_commit_frozen(rs_roll *roll, int m, const double *T0, double total)
{
  const int k_old = roll->n, k = roll->n + m, shift = roll->shift, top = k - shift;
  const double rc = roll->p.core_radius, t = roll->p.caliper, s = rc + top * t;
  double above = 0.0;
  for (int i = m - 1; i >= 0; --i) {
    above += T0[i];
    roll->block_share[i] = total > 0.0 ? above / total : 0.0;
  }
  const double scale = -total / s;
  /* First every node's increment (ds, and ds + r ds'), then the state: an increment that
   * fails leaves the roll exactly as it was, every finished layer intact. From the top
   * down, e_j = y(r_j)/y(s) by the same one-layer decays as the corrected scheme
   * (roll_block_increment). */
  double *restrict dsr = roll->dsr, *restrict dsh = roll->dsh;
  roll_decays(roll->L, dsr, 0, top); /* e_j = y(r_j)/y(s), j < top */
  dsr[top] = 1.0;
  for (int j = 0; j <= top; ++j) {
    const double ds = scale * dsr[j];
    dsr[j] = ds;
    dsh[j] = ds * (1.0 + roll->w[j]);
  }
  if (shift) { /* the outermost layer's outer face: traction free */
    dsr[k] = 0.0;
    dsh[k] = 0.0;
  }
  roll->deep_lo = 0;
  roll->c_deep = 0.0;
  rs_status st = roll_check_increment(roll, dsr, dsh, k);
  if (st) return st;
  roll->core_sigma += dsr[0];
  for (int j = 1; j <= k; ++j) {
    double ds = dsr[j], hoop = dsh[j];
    if (j <= k_old) {
      roll->sigma_r[j - 1] += ds;
      roll->sigma_theta[j - 1] += hoop;
    } else {
      int b = j - k_old - 1; /* position in the block, 0 = innermost */
      /* the tension wound at or above the node's radius: with the load beneath a layer,
       * a block layer's own tension is not on its outer face */
      double share_above = b + 1 < m ? roll->block_share[b + 1] : 0.0;
      double share_at = shift ? share_above : roll->block_share[b];
      roll->sigma_r[j - 1] = share_at * ds;
      roll->sigma_theta[j - 1] = T0[b] / t + share_above * hoop;
    }
  }
  if (shift) roll_hoop_from_equilibrium(roll, k);
  return RS_OK;
}

/* Adds dsr (and with Hakiel's placement dsh) to the roll; the block's own layers start
 * from their own share. */
static rs_status roll_commit(rs_roll *roll, int m, const double *T0)
{
  const int k_old = roll->n, k = roll->n + m;
  const double t = roll->p.caliper;
  rs_status st = roll_check_increment(roll, roll->dsr, roll->shift ? roll->dsr : roll->dsh, k);
  if (st) return st;
  if (roll->shift) { /* the radial stresses; the hoop stresses follow from them */
    const int lo = roll->deep_lo;
    const double c = roll->c_deep, *restrict se = roll->shape_e, *restrict ds = roll->dsr;
    double *restrict sr = roll->sigma_r;
    roll->core_sigma += lo > 0 ? c * se[0] : ds[0];
    for (int j = 1; j < lo; ++j) sr[j - 1] += c * se[j];
    for (int j = lo > 1 ? lo : 1; j <= k_old; ++j) sr[j - 1] += ds[j];
    for (int j = k_old + 1; j <= k; ++j) sr[j - 1] = ds[j];
    roll_hoop_from_equilibrium(roll, k);
    return RS_OK;
  }
  /* below deep_lo the increment is c_deep times the reference's shape (roll_block_increment) */
  const int lo = roll->deep_lo;
  const double c = roll->c_deep;
  const double *restrict se = roll->shape_e, *restrict sh = roll->shape_h;
  double *restrict sr = roll->sigma_r, *restrict st_ = roll->sigma_theta;
  roll->core_sigma += lo > 0 ? c * se[0] : roll->dsr[0];
  for (int j = 1; j < lo; ++j) {
    sr[j - 1] += c * se[j];
    st_[j - 1] += c * sh[j];
  }
  for (int j = lo > 1 ? lo : 1; j <= k_old; ++j) {
    sr[j - 1] += roll->dsr[j];
    st_[j - 1] += roll->dsh[j];
  }
  for (int j = k_old + 1; j <= k; ++j) {
    roll->sigma_r[j - 1] = roll->dsr[j];
    roll->sigma_theta[j - 1] = T0[j - k_old - 1] / t + roll->dsh[j];
  }
  return RS_OK;
}

rs_status rs_roll_add_layers(rs_roll *roll, int m, const double *T0)
{
  if (m < 1) return RS_ERROR(RS_ERR_INPUT, "an increment winds at least one layer (got %d)", m);
  if (roll->n + m > roll->p.max_layers)
    return RS_ERROR(RS_ERR_INPUT, "the roll holds %d layers; cannot wind %d more onto %d",
                    roll->p.max_layers, m, roll->n);
  double total = 0.0;
  for (int i = 0; i < m; ++i) {
    if (!(T0[i] >= 0.0) || !isfinite(T0[i]))
      return RS_ERROR(RS_ERR_INPUT, "wound-on tension of layer %d must be finite and >= 0 (got %g N/m)",
                      roll->n + i + 1, T0[i]);
    total += T0[i];
  }
  const int k_old = roll->n, k = roll->n + m;
  const int top = k - roll->shift; /* the highest node the increment loads */

  /* the predictor: the modulus frozen at the pressures before the increment (Hakiel) */
  roll_gather_pressure(roll, top, NULL);
  rs_status st = roll_set_modulus(roll, top);
  if (st == RS_OK) st = roll_integrate(roll, top);
  if (st) return st;

  /* for one layer the two schemes are the same increment: one code path, bit for bit */
  if (roll->p.lumping == RS_LUMP_FROZEN && m > 1) {
    st = roll_commit_frozen(roll, m, T0, total);
  } else {
    const int correct = m > 1;
    roll_block_increment(roll, k_old, m, T0, correct ? roll->P_mean : NULL);
    if (correct) {
      /* the corrector: each node's modulus at the mean pressure the m single-layer
       * increments would have seen there (the pressure before each, averaged over those
       * that reach the node), from the predictor's sub-increments; integrate again */
      roll_gather_pressure(roll, top, roll->P_mean);
      st = roll_set_modulus(roll, top);
      if (st == RS_OK) st = roll_integrate(roll, top);
      if (st) return st;
      roll_block_increment(roll, k_old, m, T0, NULL);
    }
    st = roll_commit(roll, m, T0);
  }
  if (st) return st;
  roll->n = k;
  roll->stats.increments++;
  return RS_OK;
}

/* ---- queries --------------------------------------------------------------------------- */

int rs_roll_layers(const rs_roll *roll) { return roll->n; }
double rs_roll_layer_radius(const rs_roll *roll, int j)
{
  return roll->p.core_radius + (j + 1) * roll->p.caliper;
}
double rs_roll_outer_radius(const rs_roll *roll)
{
  return roll->p.core_radius + roll->n * roll->p.caliper;
}
const double *rs_roll_sigma_r(const rs_roll *roll) { return roll->sigma_r; }
const double *rs_roll_sigma_theta(const rs_roll *roll) { return roll->sigma_theta; }
double rs_roll_core_pressure(const rs_roll *roll) { return -roll->core_sigma; }
double rs_roll_surface_modulus(const rs_roll *roll)
{
  const int node = roll->n - roll->shift; /* the outermost loaded interface */
  double P = node > 0 ? -roll->sigma_r[node - 1] : node == 0 && roll->n > 0 ? -roll->core_sigma : 0.0;
  return rs_radial_modulus(&roll->p.radial, P);
}

void rs_roll_get_stats(const rs_roll *roll, rs_roll_stats *stats)
{
  *stats = roll->stats;
}

/* ---- save / restore ------------------------------------------------------------------- */

struct rs_roll_state {
  int n, capacity;
  double core_sigma;
  double *sigma_r, *sigma_theta;
};

rs_status rs_roll_state_create(rs_roll_state **out)
{
  *out = calloc(1, sizeof **out);
  return *out ? RS_OK : RS_ERROR(RS_ERR_MEMORY, "cannot allocate a roll state");
}

void rs_roll_state_destroy(rs_roll_state **state)
{
  if (!state || !*state) return;
  free((*state)->sigma_r);
  free((*state)->sigma_theta);
  free(*state);
  *state = NULL;
}

rs_status rs_roll_save(const rs_roll *roll, rs_roll_state *st)
{
  if (st->capacity < roll->n || !st->sigma_r) { /* also before the first layer: memcpy needs arrays */
    int cap = roll->p.max_layers;
    double *a = realloc(st->sigma_r, (size_t)cap * sizeof(double));
    if (a) st->sigma_r = a;
    double *b = realloc(st->sigma_theta, (size_t)cap * sizeof(double));
    if (b) st->sigma_theta = b;
    if (!a || !b) return RS_ERROR(RS_ERR_MEMORY, "cannot save a roll of %d layers", roll->n);
    st->capacity = cap;
  }
  st->n = roll->n;
  st->core_sigma = roll->core_sigma;
  if (roll->n > 0) { /* an empty roll has no arrays yet: memcpy of NULL is undefined */
    memcpy(st->sigma_r, roll->sigma_r, (size_t)roll->n * sizeof(double));
    memcpy(st->sigma_theta, roll->sigma_theta, (size_t)roll->n * sizeof(double));
  }
  return RS_OK;
}

rs_status rs_roll_restore(rs_roll *roll, const rs_roll_state *st)
{
  if (st->n > roll->p.max_layers)
    return RS_ERROR(RS_ERR_INTERNAL, "a state of %d layers does not fit a roll of %d", st->n,
                    roll->p.max_layers);
  roll->n = st->n;
  roll->core_sigma = st->core_sigma; /* the work counters keep counting: rewinding costs */
  if (st->n > 0) { /* the state of an empty roll has no arrays */
    memcpy(roll->sigma_r, st->sigma_r, (size_t)st->n * sizeof(double));
    memcpy(roll->sigma_theta, st->sigma_theta, (size_t)st->n * sizeof(double));
  }
  return RS_OK;
}
