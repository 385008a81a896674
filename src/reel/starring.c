/* Starring (docs/defects.md, section 2): (a) the web's compressive strength and (b) the
 * compressive zone buckling as a ring packet on the elastic foundation beneath it, with
 * (c) the zone's extent from the core. */
#include <math.h>
#include <stdlib.h>

#include "reel/defects_internal.h"
#include "reel/result_internal.h"
#include "util/error.h"

/* Ring on a Winkler foundation (Brush & Almroth 1975, ring on an elastic foundation;
 * inextensional modes w ~ cos(m theta)): the hoop force at which mode m is neutral is
 *   N(m) = D (m^2 - 1) / R^2 + k R^2 / (m^2 - 1)        [N/m]
 * convex in x = m^2 - 1 with its minimum 2 sqrt(k D) at x* = R^2 sqrt(k / D); the least
 * over integers m >= 2 is at floor or ceil of sqrt(x* + 1). */
double rs_defect_ring_critical_force(double D, double k, double R, int *mode)
{
  if (mode) *mode = 0;
  if (!(D > 0.0 && k > 0.0 && R > 0.0)) return 0.0;
  const double ms = sqrt(R * R * sqrt(k / D) + 1.0);
  if (ms > 1e8) { /* the discrete minimum is the continuous one to ~1e-16 */
    if (mode) *mode = 100000000;
    return 2.0 * sqrt(k * D);
  }
  double best = INFINITY;
  int m0 = (int)floor(ms);
  if (m0 < 2) m0 = 2;
  for (int m = m0; m <= m0 + 1; ++m) {
    double x = (double)m * m - 1.0;
    double N = D * x / (R * R) + k * R * R / x;
    if (N < best) {
      best = N;
      if (mode) *mode = m;
    }
  }
  return best;
}

/* Interlayer pressure (Pa, compression positive, a gap as 0) under layer j (the core
 * contact for the first) and over it. */
static double p_below(const rs_reel_result *res, int j)
{
  double P = j == 0 ? res->core_pressure : 0.0 - res->sigma_r[j - 1];
  return P > 0.0 ? P : 0.0;
}

static double p_above(const rs_reel_result *res, int j)
{
  double P = 0.0 - res->sigma_r[j];
  return P > 0.0 ? P : 0.0;
}

/* Radial compliance (m/Pa) of layer j's pitch: t / E_r at the mean of its faces' pressure. */
static double layer_compliance(const rs_reel_result *res, const rs_defect_limits *lim, double t,
                               int j)
{
  double E = rs_radial_modulus(lim->radial, 0.5 * (p_below(res, j) + p_above(res, j)));
  return E > 0.0 ? t / E : INFINITY;
}

/* Interface j (over layer j, at r_j) slips: it has opened (P <= 0), or friction is used up
 * by the shear the roll carries there, M(r) / (2 pi r^2) >= mu P (M the cinching rule's
 * torque). Without mu only an open interface slips: an interface that sticks with no shear
 * on it stays stuck at the onset of buckling, whose shear is infinitesimal. */
static int interface_slips(const rs_reel_result *res, const rs_defect_limits *lim,
                           const rs_slip_load *L, int j)
{
  const double P = p_above(res, j), r = res->radius[j];
  if (!(P > 0.0)) return 1;
  if (!(lim->friction_layer > 0.0)) return 0;
  double M = rs_defect_interface_torque(L->s, L->TR, L->M_acc, r, res->core_radius, L->R);
  return M / (2.0 * 3.14159265358979323846 * r * r) >= lim->friction_layer * P;
}

/* The roll as rings on springs (rs_defect_ring_stack_critical): a run of compressed layers
 * whose interfaces stick is one ring of E (n t)^3 / 12 (bonded), every other layer a ring
 * of E t^3 / 12; forces N = -sum sigma_theta t; the springs E_r(P) / t of the interfaces
 * between rings, under the first the core's r_c / E_c in series with one caliper of stack.
 * *peak gets the layer in the middle of the ring where the mode is largest. */
static double stack_factor(const rs_reel_result *res, const rs_defect_limits *lim, double t,
                           double core_c, const unsigned char *slips, int *mode, int *peak)
{
  const int n = res->n_layers;
  double *w = malloc((size_t)n * 5 * sizeof *w);
  int *first = malloc((size_t)n * sizeof *first);
  if (!w || !first) {
    free(w);
    free(first);
    return NAN;
  }
  double *D = w, *rho = w + n, *N = w + 2 * n, *k = w + 3 * n, *rs = w + 4 * n;
  const double E = lim->E_theta;
  int e = -1;
  for (int j = 0; j < n; ++j) {
    double r_in = j ? res->radius[j - 1] : res->core_radius;
    int joined = j > 0 && res->sigma_theta[j] < 0.0 && res->sigma_theta[j - 1] < 0.0 && !slips[j - 1];
    if (!joined) {
      ++e;
      first[e] = j;
      N[e] = 0.0;
      rs[e] = r_in;
      k[e] = 1.0 / (t / rs_radial_modulus(lim->radial, p_below(res, j)) + (j ? 0.0 : core_c));
    }
    N[e] += (0.0 - res->sigma_theta[j]) * t;
    double H = (j - first[e] + 1) * t;
    D[e] = E * H * H * H / 12.0;
    rho[e] = 0.5 * (rs[e] + res->radius[j]);
  }
  rs_ring_stack st = {.n = e + 1, .D = D, .rho = rho, .N = N, .k = k, .r_spring = rs};
  int pe = 0;
  double f = rs_defect_ring_stack_critical(&st, mode, &pe);
  int last = pe + 1 < e + 1 ? first[pe + 1] - 1 : n - 1;
  *peak = (first[pe] + last) / 2;
  free(w);
  free(first);
  return f;
}

/* The zone first..last for the report: its hoop force, radii, the foundation beneath it
 * (core and stack below in series, plus one caliper), and whether it is bonded. */
static void zone_info(const rs_reel_result *res, const rs_defect_limits *lim, double t,
                      int first, int last, double below, const unsigned char *slips,
                      rs_starring_zone *z)
{
  const int n = last - first + 1;
  z->N = 0.0;
  z->bonded = n > 1;
  for (int j = first; j <= last; ++j) {
    z->N += (0.0 - res->sigma_theta[j]) * t;
    if (j < last && slips[j]) z->bonded = 0;
  }
  z->r_a = first > 0 ? res->radius[first - 1] : res->core_radius;
  z->r_b = res->radius[last];
  z->k = 1.0 / (below + layer_compliance(res, lim, t, first));
  z->D = z->bonded ? lim->E_theta * pow(n * t, 3.0) / 12.0 : n * lim->E_theta * t * t * t / 12.0;
}

static void keep_zone(rs_defect_report *rep, const rs_starring_zone *z, int first, int last,
                      double margin, double r_c)
{
  rep->starring.packet_margin = margin;
  rep->starring.zone_first = first;
  rep->starring.zone_last = last;
  rep->starring.zone_inner = z->r_a;
  rep->starring.zone_outer = z->r_b;
  rep->starring.zone_from_core = z->r_a - r_c;
  rep->starring.zone_to_core = z->r_b - r_c;
  rep->starring.force = z->N;
  rep->starring.force_critical = z->N_cr;
  rep->starring.foundation = z->k;
  rep->starring.stiffness = z->D;
  rep->starring.mode = z->mode;
  rep->starring.bonded = z->bonded;
}

/* (a): layers over the strength flagged, the least margin kept. */
static void strength_check(const rs_reel_result *res, double S, unsigned char *flag,
                           rs_defect_report *rep)
{
  rep->starring.strength_margin = NAN;
  rep->starring.strength_radius = NAN;
  if (!(S > 0.0)) return;
  double least = INFINITY;
  for (int j = 0; j < res->n_layers; ++j) {
    double c = 0.0 - res->sigma_theta[j];
    if (!(c > 0.0)) continue;
    if (c > S) flag[j] = 1;
    if (S / c < least) {
      least = S / c;
      rep->starring.strength_radius = res->radius[j];
    }
  }
  rep->starring.strength_margin = least;
}

/* (c) The compressed zones (runs of layers with sigma_theta < 0), counted into rep; the one
 * holding the mode's peak layer (or the nearest to it) kept (keep_zone) with its critical
 * force least x N. below: the compliance beneath the first layer. Its layers into *zfirst,
 * *zlast (-1 when none is compressed). */
static void find_zone(const rs_reel_result *res, const rs_defect_limits *lim, double t,
                      double below, const unsigned char *slips, int mode, int peak, double least,
                      rs_defect_report *rep, int *zfirst, int *zlast)
{
  const int n = res->n_layers;
  int zone_dist = -1;
  *zfirst = *zlast = -1;
  for (int j = 0; j < n;) {
    if (!(res->sigma_theta[j] < 0.0)) {
      below += layer_compliance(res, lim, t, j++);
      continue;
    }
    int first = j;
    while (j < n && res->sigma_theta[j] < 0.0) ++j;
    int last = j - 1;
    rep->starring.zones++;
    rep->starring.compressed += last - first + 1;
    /* the zone of the mode's peak, or the nearest one to it */
    int dist = peak < first ? first - peak : peak > last ? peak - last : 0;
    if (zone_dist < 0 || dist < zone_dist) {
      zone_dist = dist;
      *zfirst = first;
      *zlast = last;
      rs_starring_zone z;
      zone_info(res, lim, t, first, last, below, slips, &z);
      z.mode = mode;
      z.N_cr = least * z.N;
      keep_zone(rep, &z, first, last, least, res->core_radius);
    }
    for (int i = first; i <= last; ++i) below += layer_compliance(res, lim, t, i);
  }
}

/* The criterion with the least margin decides: the hoop strength's or the packet's
 * (least, the stack's load factor). */
static void decide_criterion(rs_defect_report *rep, double least)
{
  double sm = rep->starring.strength_margin;
  if (isfinite(sm) && !(least <= sm)) {
    rep->starring.criterion = RS_STARRING_STRENGTH;
    rep->starring.margin_min = sm;
    rep->starring.margin_radius = rep->starring.strength_radius;
  } else {
    rep->starring.criterion = RS_STARRING_PACKET;
    rep->starring.margin_min = least;
    rep->starring.margin_radius = 0.5 * (rep->starring.zone_inner + rep->starring.zone_outer);
  }
}

rs_status rs_defects_starring(const rs_reel_result *res, const rs_defect_limits *lim,
                              unsigned char *flag, rs_defect_report *rep)
{
  const int n = res->n_layers;
  rep->starring.verdict = RS_DEFECT_NOT_ASSESSED;
  rep->starring.criterion = RS_STARRING_NONE;
  rep->starring.packet_margin = NAN;
  rep->starring.strength_margin = NAN;
  rep->starring.margin_min = NAN;
  if (n == 0 || !lim->radial || !(lim->E_theta > 0.0)) return RS_OK;
  const double t = lim->caliper > 0.0 ? lim->caliper : res->radius[0] - res->core_radius;
  const double below = lim->core_stiffness > 0.0 && isfinite(lim->core_stiffness)
                           ? res->core_radius / lim->core_stiffness
                           : 0.0;
  rep->starring.min_sigma = INFINITY;
  for (int j = 0; j < n; ++j) {
    flag[j] = 0;
    if (res->sigma_theta[j] < rep->starring.min_sigma) {
      rep->starring.min_sigma = res->sigma_theta[j];
      rep->starring.min_sigma_radius = res->radius[j];
    }
  }
  strength_check(res, lim->hoop_strength, flag, rep);
  /* (b) the whole stack's load factor; (c) the zone its mode lives in */
  unsigned char *slips = malloc((size_t)n);
  if (!slips) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the starring stack");
  rs_slip_load L;
  rs_defect_slip_load(res, lim, &L);
  for (int j = 0; j < n; ++j) slips[j] = j + 1 < n ? (unsigned char)interface_slips(res, lim, &L, j) : 1;
  int mode = 0, peak = 0;
  double least = stack_factor(res, lim, t, below, slips, &mode, &peak);
  if (isnan(least)) {
    free(slips);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory for the starring stack");
  }
  int zfirst, zlast;
  find_zone(res, lim, t, below, slips, mode, peak, least, rep, &zfirst, &zlast);
  free(slips);
  if (zfirst >= 0 && least < 1.0)
    for (int i = zfirst; i <= zlast; ++i) flag[i] = 1;
  rep->starring.layers =
      rs_defect_flag_ranges(flag, n, res->radius, &rep->starring.ranges, &rep->starring.n_ranges);
  if (rep->starring.layers < 0)
    return RS_ERROR(RS_ERR_MEMORY, "out of memory for the starring ranges");
  rep->starring.verdict = rep->starring.layers > 0 ? RS_DEFECT_RISK : RS_DEFECT_OK;
  if (rep->starring.compressed > 0) decide_criterion(rep, least);
  return RS_OK;
}
