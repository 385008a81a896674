/* The nip contact handle: configuration checks, the bodies, cached kernels, warm start. */
#include "nip/contact_internal.h"
#include "util/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int finite_nonneg(double v) { return isfinite(v) && v >= 0; }

rs_status rs_nip_contact_create(const rs_nip_contact_config *cfg, rs_nip_contact **out)
{
  if (!cfg || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  *out = NULL;
  if (!finite_nonneg(cfg->mu_roll))
    return RS_ERROR(RS_ERR_INPUT, "nip.friction.roll must be >= 0 (got %g)", cfg->mu_roll);
  if (!finite_nonneg(cfg->mu_drum))
    return RS_ERROR(RS_ERR_INPUT, "nip.friction.drum must be >= 0 (got %g)", cfg->mu_drum);
  if (!(isfinite(cfg->drum_radius) && cfg->drum_radius > 0))
    return RS_ERROR(RS_ERR_INPUT, "nip.drum.radius must be > 0 (got %g m)", cfg->drum_radius);
  if (!(cfg->drum_core_radius > 0 && cfg->drum_core_radius < cfg->drum_radius))
    return RS_ERROR(RS_ERR_INPUT, "nip.drum.core_radius must lie in (0, nip.drum.radius = %g m) "
                    "(got %g m)", cfg->drum_radius, cfg->drum_core_radius);
  if (cfg->nodes < 4 || cfg->nodes > 4096)
    return RS_ERROR(RS_ERR_INPUT, "nip.nodes must lie in [4, 4096] (got %d)", cfg->nodes);
  if (cfg->winder == RS_WINDER_CENTER_SURFACE &&
      !(cfg->torque_share >= 0 && cfg->torque_share <= 1))
    return RS_ERROR(RS_ERR_INPUT, "nip.torque_share must lie in [0, 1] (got %g)", cfg->torque_share);
  if (!(cfg->sheet.h > 0 && isfinite(cfg->sheet.c11) && isfinite(cfg->sheet.c12) &&
        isfinite(cfg->sheet.c22)))
    return RS_ERROR(RS_ERR_INPUT, "sheet: half-thickness and compliances must be finite, h > 0");

  rs_nip_contact *nc = calloc(1, sizeof *nc);
  if (!nc) return RS_ERROR(RS_ERR_MEMORY, "nip contact");
  nc->cfg = *cfg;
  if (nc->cfg.max_iterations <= 0) nc->cfg.max_iterations = 4 * cfg->nodes + 40;
  if (!(nc->cfg.load_rtol > 0)) nc->cfg.load_rtol = 1e-9;
  /* Default series: 256 accelerated terms (docs/cylinder.md: ~1e-6 on the kernels; the
   * half-width moves by 5e-7 against a 1e-7 automatic series). The automatic mode doubles
   * terms to meet its tolerance and overshoots to thousands of terms at every new roll
   * radius: 7x slower for the same T0. nip.terms sets it; the accuracy study measures it. */
  if (nc->cfg.series.terms <= 0 && !(nc->cfg.series.tol > 0)) {
    nc->cfg.series.terms = 256;
    nc->cfg.series.accelerate = 1;
    nc->stiff_body_terms = 1;
  }
  const int M = cfg->nodes, n = 3 * M, E = M - 1;
  nc->M = M;
  nc->n = n;
  nc->R[1] = cfg->drum_radius;
  nc->R0[1] = cfg->drum_core_radius;
  double H[2][2];
  nc->H11[1] = rs_ortho_halfplane(&cfg->drum, H) ? (rs_error_clear(), 0.0) : H[0][0];
  rs_status st = rs_cylinder_create(&cfg->drum, cfg->drum_radius, cfg->drum_core_radius, &nc->body[1]);
  if (st) {
    free(nc);
    return rs_error_wrap("nip.drum");
  }
  nc->state = calloc((size_t)2 * E, 1);
  nc->keep = malloc((size_t)2 * E * sizeof(double));
  nc->A = malloc((size_t)n * n * sizeof(double));
  nc->rhs = malloc((size_t)n * sizeof(double));
  nc->z = malloc((size_t)n * sizeof(double));
  nc->visited = malloc((size_t)nc->cfg.max_iterations * 2 * E);
  nc->eps_sheet = malloc((size_t)4 * E * sizeof(double));
  if (!nc->state || !nc->keep || !nc->A || !nc->rhs || !nc->z || !nc->visited || !nc->eps_sheet ||
      rs_nipc_lin_alloc(nc)) {
    rs_nip_contact_destroy(&nc);
    return RS_ERROR(RS_ERR_MEMORY, "nip contact work space (M = %d)", M);
  }
  nc->eps_body[0] = nc->eps_sheet + E;
  nc->eps_body[1] = nc->eps_sheet + 2 * E;
  nc->pbar = nc->eps_sheet + 3 * E;
  *out = nc;
  return RS_OK;
}

void rs_nip_contact_destroy(rs_nip_contact **pnc)
{
  if (!pnc || !*pnc) return;
  rs_nip_contact *nc = *pnc;
  for (int b = 0; b < 2; ++b) {
    rs_cylinder_destroy(&nc->body[b]);
    for (int k = 0; k < NKER; ++k) {
      rs_kernels_free(&nc->ker[b][k]);
      rs_kernels_free(&nc->ref[b][k]);
    }
  }
  free(nc->state);
  free(nc->keep);
  free(nc->A);
  free(nc->rhs);
  free(nc->z);
  rs_nipc_lin_free(nc);
  free(nc->visited);
  free(nc->eps_sheet);
  free(nc);
  *pnc = NULL;
}

rs_status rs_nip_contact_set_roll(rs_nip_contact *nc, const rs_ortho *roll, double R, double R0)
{
  if (!nc || !roll) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (nc->have_roll && R == nc->R[0] && R0 == nc->R0[0] && !memcmp(roll, &nc->roll_c, sizeof *roll))
    return RS_OK;
  rs_cylinder *c = NULL;
  rs_status st = rs_cylinder_create(roll, R, R0, &c);
  if (st) return rs_error_wrap("roll (radius %g m, core %g m)", R, R0);
  double C0[2][2];
  st = rs_cylinder_mode_compliance(c, 0, C0);
  if (st) {
    rs_cylinder_destroy(&c);
    return rs_error_wrap("roll (radius %g m, core %g m)", R, R0);
  }
  rs_cylinder_destroy(&nc->body[0]);
  nc->body[0] = c;
  /* the n = 0 part of the nip pressure, P / (2 pi R), shrinks the roll's circumference:
   * mean surface strain -C0_11 P / (2 pi R^2) (the wound-on condition uses it) */
  nc->roll_mean_strain = -C0[0][0] / (2 * 3.14159265358979323846 * R * R);
  double H[2][2];
  nc->H11[0] = rs_ortho_halfplane(roll, H) ? (rs_error_clear(), 0.0) : H[0][0];
  nc->roll_c = *roll;
  nc->R[0] = R;
  nc->R0[0] = R0;
  nc->have_roll = 1;
  ++nc->roll_version;
  return RS_OK;
}

rs_status rs_nip_contact_set_friction(rs_nip_contact *nc, double mu_roll, double mu_drum)
{
  if (!nc) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!finite_nonneg(mu_roll))
    return RS_ERROR(RS_ERR_INPUT, "nip.friction.roll must be >= 0 (got %g)", mu_roll);
  if (!finite_nonneg(mu_drum))
    return RS_ERROR(RS_ERR_INPUT, "nip.friction.drum must be >= 0 (got %g)", mu_drum);
  nc->cfg.mu_roll = mu_roll;
  nc->cfg.mu_drum = mu_drum;
  return RS_OK;
}

void rs_nip_contact_forget(rs_nip_contact *nc)
{
  if (!nc) return;
  nc->have_warm = 0;
  nc->hist_n = 0;
  nc->hist_slope_n = 0;
  nc->k_a = 0; /* also drop the kernels and the factorization: a cold solve recomputes */
  nc->ref_a[0] = nc->ref_a[1] = 0;
  nc->lin.valid = 0;
}

/* Kernels of eq. (19) for both bodies at half-width a (see contact_internal.h). The
 * pressure kernels set the number of series terms (automatic, to the configured
 * tolerance); the shear kernels then use the same number, which keeps the error of the
 * slowly converging coupling kernel qu (box edges) at the tolerance relative to pu. */
/* The series terms of body b's kernels. With the default series (256 accelerated terms)
 * a body at least STIFF_RATIO times stiffer than the other (its half-plane compliance H11:
 * the steel drum under a paper roll, 4e4 times) takes STIFF_TERMS: the accelerated series'
 * error falls about as terms^-3 (docs/cylinder.md), 64x the default's ~1e-6 of its own
 * kernels at 64 terms, and a body's kernels enter the contact weighted by its share of the
 * compliance, <= 1e-3: <= 1e-7 (measured: T0 1e-11, a 1.5e-8, test_nip_reel
 * .stiff_drum_terms). A given nip.terms (or tolerance) holds for both bodies. */
enum { STIFF_TERMS = 64 };
static const double STIFF_RATIO = 1e3;

static long body_terms(const rs_nip_contact *nc, int b)
{
  long N = nc->cfg.series.terms;
  double hb = nc->H11[b], ho = nc->H11[1 - b];
  if (nc->stiff_body_terms && N > STIFF_TERMS && hb > 0 && STIFF_RATIO * hb <= ho) return STIFF_TERMS;
  return N;
}

/* A stiff body's kernels at a nearby half-width: its summed ones (at ref_a) rescaled as the
 * half-plane's (rs_kernels_rescale). Their error is the curvature's and the core's: at most
 * RESCALE_C |ln(a / ref_a)| a / L of the body's own kernels, L = min(R, R - R0) (measured on
 * steel cylinders R = 0.3 m, R0 = 0.03 - 0.295 m, a = 1 - 20 mm, drifts 1 and 10 %: C <= 1.41,
 * the box shear's qu the largest, after the parts the approach, the nip's shift and xi2 take
 * up: docs/cylinder.md, "Rescaled kernels"), and it enters the contact weighted by the body's
 * share of the compliance, H11_b / (H11_roll + H11_drum) <= 1e-3 (body_terms), as the 64-term
 * series' error does. Rescaled only while that product stays below RESCALE_TOL, a tenth of
 * the default series' own ~1e-6 of the kernels (docs/nip.md, "Limitations"); beyond it the
 * kernels are summed anew and become the reference. */
static const double RESCALE_C = 1.5, RESCALE_TOL = 1e-7;

static int rescalable(const rs_nip_contact *nc, int b, double a)
{
  if (nc->no_rescale || !(nc->ref_a[b] > 0) || body_terms(nc, b) >= nc->cfg.series.terms) return 0;
  if (b == 0 && nc->ref_version != nc->roll_version) return 0;
  double share = nc->H11[b] / (nc->H11[0] + nc->H11[1]);
  double L = fmin(nc->R[b], nc->R[b] - nc->R0[b]);
  return share * RESCALE_C * fabs(log(a / nc->ref_a[b])) * a / L <= RESCALE_TOL;
}

static rs_status kernels_rescale(rs_nip_contact *nc, int b, double a)
{
  const double dx = 2 * a / (nc->M - 1);
  rs_status st = RS_OK;
  for (int k = 0; !st && k < NKER; ++k) st = rs_kernels_rescale(&nc->ref[b][k], dx, nc->H11[b], &nc->ker[b][k]);
  if (!st) ++nc->stats_rescaled;
  return st;
}

/* keeps body b's kernels just summed at a as the reference of the rescaled ones */
static rs_status kernels_keep(rs_nip_contact *nc, int b, double a)
{
  if (body_terms(nc, b) >= nc->cfg.series.terms) return RS_OK;
  const double dx = 2 * a / (nc->M - 1);
  rs_status st = RS_OK;
  for (int k = 0; !st && k < NKER; ++k) st = rs_kernels_rescale(&nc->ker[b][k], dx, nc->H11[b], &nc->ref[b][k]);
  nc->ref_a[b] = st ? 0.0 : a;
  if (b == 0) nc->ref_version = nc->roll_version;
  return st;
}

rs_status rs_nipc_kernels(rs_nip_contact *nc, double a)
{
  if (!nc->have_roll) return RS_ERROR(RS_ERR_INPUT, "nip contact: the roll is not set");
  const int M = nc->M;
  const double dx = 2 * a / (M - 1);
  int roll_ok = nc->k_a == a && nc->k_roll_version == nc->roll_version;
  int drum_ok = nc->k_a == a && (nc->cfg.series.terms <= 0 || nc->ker[1][KP].terms == body_terms(nc, 1));
  for (int b = 0; b < 2; ++b) {
    if (b == 0 ? roll_ok : drum_ok) continue;
    rs_cylinder *c = nc->body[b];
    rs_kernels *k = nc->ker[b];
    rs_series_opts o = nc->cfg.series;
    if (o.terms > 0) o.terms = body_terms(nc, b);
    rs_status st;
    if (rescalable(nc, b, a)) {
      st = kernels_rescale(nc, b, a);
    } else {
      st = rs_cylinder_kernels(c, RS_BASIS_HAT, dx, 0.0, M, RS_KERNEL_PU | RS_KERNEL_PE, &o, &k[KP]);
      if (!st) {
        if (o.terms <= 0) o.terms = k[KP].terms;
        st = rs_cylinder_kernels_shear(c, dx, -0.5 * dx, M, &o, &k[KQU], &k[KQE]);
      }
      if (!st) st = kernels_keep(nc, b, a);
    }
    if (st) {
      nc->k_a = 0;
      return rs_error_wrap("%s kernels at half-width a = %g m (M = %d)", b ? "drum" : "roll", a, M);
    }
  }
  nc->k_a = a;
  nc->k_roll_version = nc->roll_version;
  return RS_OK;
}
