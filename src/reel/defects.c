/* Defect-risk indicators (docs/defects.md): each rule compares the final stress profile
 * with a threshold and says where the roll is prone to a defect. They are screening
 * rules from winding practice, not models of the defects. */
#include "reel/defects_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

const char *rs_defect_verdict_name(rs_defect_verdict v)
{
  switch (v) {
  case RS_DEFECT_NOT_ASSESSED: return "not assessed";
  case RS_DEFECT_OK: return "ok";
  case RS_DEFECT_RISK: return "risk";
  case RS_DEFECT_PRESENT: return "present";
  }
  return "?";
}

const char *rs_starring_criterion_name(rs_starring_criterion c)
{
  switch (c) {
  case RS_STARRING_NONE: return "none";
  case RS_STARRING_STRENGTH: return "hoop_strength";
  case RS_STARRING_PACKET: return "packet_buckling";
  }
  return "?";
}

/* The drive's share at the core: center winding (and unwinding on a core brake) puts the
 * whole torque there, surface winding none (the drum drives the surface), center-surface
 * its torque_share, a two-drum winder none. */
double rs_defect_core_share(const rs_problem *pb)
{
  if (pb->nip.model == RS_NIP_NONE) return 1.0;
  /* two drums drive the roll's surface; its core is free (docs/nip.md, "Two-drum winders") */
  if (pb->winder.type == RS_WINDER_TYPE_TWO_DRUM) return 0.0;
  switch (pb->nip.winder) {
  case RS_WINDER_CENTER: return 1.0;
  case RS_WINDER_SURFACE: return 0.0;
  case RS_WINDER_CENTER_SURFACE: return pb->nip.torque_share;
  }
  return 0.0; /* a winder driven at the surface */
}

void rs_defect_limits_from_problem(const rs_problem *pb, rs_defect_limits *lim)
{
  lim->pressure_limit = pb->material.pressure_limit;
  lim->core_rating = pb->core.rating;
  lim->accel_torque = pb->accel_torque;
  lim->friction_layer = pb->material.friction_layer;
  lim->E_theta = pb->material.E_theta;
  lim->radial = &pb->material.radial;
  lim->caliper = pb->material.caliper;
  lim->hoop_strength = pb->material.hoop_strength;
  lim->core_stiffness = rs_core_stiffness(&pb->core);
  lim->acceleration = pb->acceleration;
  lim->density = pb->material.density;
  lim->core_share = rs_defect_core_share(pb);
  lim->core_friction = pb->core_friction;
}

void rs_defect_report_destroy(rs_defect_report **rep)
{
  if (!rep || !*rep) return;
  free((*rep)->hoop.ranges);
  free((*rep)->starring.ranges);
  free((*rep)->slip.ranges);
  free(*rep);
  *rep = NULL;
}

/* Hoop compression, sigma_theta < 0: reported as information. It is the necessary
 * condition for a layer to buckle (starring), not a sufficient one: interior layers of
 * most rolls carry a small compressive residual (a few per cent of T0/t) and do not buckle.
 * The buckling rule below weighs it against the layer's critical stress. */
static rs_status assess_hoop(const rs_reel_result *res, unsigned char *flag, rs_defect_report *rep)
{
  int n = res->n_layers;
  rep->hoop.verdict = RS_DEFECT_NOT_ASSESSED;
  if (n == 0) return RS_OK;
  rep->hoop.min = INFINITY;
  for (int j = 0; j < n; ++j) {
    flag[j] = res->sigma_theta[j] < 0.0;
    if (res->sigma_theta[j] < rep->hoop.min) {
      rep->hoop.min = res->sigma_theta[j];
      rep->hoop.min_radius = res->radius[j];
    }
  }
  rep->hoop.layers = rs_defect_flag_ranges(flag, n, res->radius, &rep->hoop.ranges, &rep->hoop.n_ranges);
  if (rep->hoop.layers < 0) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the hoop ranges");
  rep->hoop.verdict = rep->hoop.layers > 0 ? RS_DEFECT_PRESENT : RS_DEFECT_OK;
  return RS_OK;
}

/* Greatest pressure on the web, P = -sigma_r over the layers and the core contact,
 * against the pressure the material stands: risk when P_max > limit (crushing of
 * bulky webs, blocking of tacky or coated ones). */
static void assess_pressure(const rs_reel_result *res, double limit, rs_defect_report *rep)
{
  int n = res->n_layers;
  rep->pressure.verdict = RS_DEFECT_NOT_ASSESSED;
  rep->pressure.limit = limit;
  if (n == 0) return;
  rep->pressure.max = res->core_pressure;
  rep->pressure.max_radius = res->core_radius;
  for (int j = 0; j < n; ++j)
    if (0.0 - res->sigma_r[j] > rep->pressure.max) {
      rep->pressure.max = 0.0 - res->sigma_r[j];
      rep->pressure.max_radius = res->radius[j];
    }
  if (!(limit > 0.0)) return;
  rep->pressure.ratio = rep->pressure.max / limit;
  rep->pressure.verdict = rep->pressure.max > limit ? RS_DEFECT_RISK : RS_DEFECT_OK;
}

/* Interlayer slip (cinching): the interface at the outer radius r_j of layer j (between
 * layers j and j+1; the outer surface has none) transmits at most M_f = mu P_j 2 pi r_j^2
 * (N m/m) and carries rs_defect_interface_torque; risk where M_f < the torque. The web
 * on the core likewise with core.friction and the core pressure. */
static rs_status assess_slip(const rs_reel_result *res, const rs_defect_limits *lim,
                             unsigned char *flag, rs_defect_report *rep)
{
  int n = res->n_layers, m = n - 1; /* interfaces */
  const double mu = lim->friction_layer;
  rep->slip.verdict = RS_DEFECT_NOT_ASSESSED;
  rep->slip.mu = mu;
  rep->slip.core_margin = NAN;
  rep->slip.margin_min = NAN;
  if (!(mu > 0.0) || m < 1) return RS_OK;
  rs_slip_load L;
  rs_defect_slip_load(res, lim, &L);
  const double R = L.R, rc = res->core_radius, s = L.s, TR = L.TR, M_acc = L.M_acc;
  rep->slip.alpha = L.alpha;
  rep->slip.torque = M_acc;
  rep->slip.tension_torque = TR;
  rep->slip.core_share = s;
  rep->slip.margin_min = INFINITY;
  /* The outermost wraps take the torque entering at the surface, M(R) over the outermost
   * interface, by capstan friction (Euler-Eytelwein: tension T0 + M/R held against T0 over
   * k wraps while 1 + M / (T0 R) <= e^(2 pi mu k)), not by a uniform shear on the pressure
   * of the layers above them: the check starts k_c wraps below the surface. */
  const double T0 = res->wound_on_tension ? res->wound_on_tension[n - 1] : TR / R;
  const double M_out = rs_defect_interface_torque(s, TR, M_acc, res->radius[m - 1], rc, R);
  int kc = 1;
  if (T0 > 0.0 && M_out > 0.0) {
    double k = ceil(log1p(M_out / (T0 * R)) / (2.0 * pi * mu));
    kc = k < 1.0 ? 1 : k > m ? m : (int)k;
  }
  rep->slip.capstan_layers = kc;
  for (int j = 0; j < m; ++j) flag[j] = 0;
  for (int j = 0; j < m - kc; ++j) {
    double M = rs_defect_interface_torque(s, TR, M_acc, res->radius[j], rc, R);
    double cap = rs_defect_slip_capacity(mu, 0.0 - res->sigma_r[j], res->radius[j]);
    double margin = M > 0.0 ? cap / M : INFINITY;
    flag[j] = margin < 1.0;
    if (margin < rep->slip.margin_min) {
      rep->slip.margin_min = margin;
      rep->slip.margin_radius = res->radius[j];
      rep->slip.margin_torque = M;
    }
  }
  if (lim->core_friction > 0.0) {
    double M = rs_defect_interface_torque(s, TR, M_acc, rc, rc, R);
    double cap = rs_defect_slip_capacity(lim->core_friction, res->core_pressure, rc);
    rep->slip.core_margin = M > 0.0 ? cap / M : INFINITY;
  }
  rep->slip.layers = rs_defect_flag_ranges(flag, m, res->radius, &rep->slip.ranges, &rep->slip.n_ranges);
  if (rep->slip.layers < 0) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the slip ranges");
  rep->slip.verdict = rep->slip.layers > 0 || rep->slip.core_margin < 1.0 ? RS_DEFECT_RISK
                                                                           : RS_DEFECT_OK;
  return RS_OK;
}

/* Core pressure against the core's rating (the external pressure it is rated to carry
 * without crushing or collapsing onto the shaft): risk when p_core > rating. */
static void assess_core(const rs_reel_result *res, double rating, rs_defect_report *rep)
{
  rep->core.verdict = RS_DEFECT_NOT_ASSESSED;
  rep->core.pressure = res->core_pressure;
  rep->core.rating = rating;
  if (!(rating > 0.0) || res->n_layers == 0) return;
  rep->core.ratio = res->core_pressure / rating;
  rep->core.verdict = res->core_pressure > rating ? RS_DEFECT_RISK : RS_DEFECT_OK;
}

rs_status rs_defects_assess(const rs_reel_result *res, const rs_defect_limits *lim,
                            rs_defect_report **out)
{
  *out = NULL;
  if (!res || !lim || res->n_layers < 0)
    return RS_ERROR(RS_ERR_INTERNAL, "no result or no limits to assess");
  rs_defect_report *rep = calloc(1, sizeof *rep);
  unsigned char *flag = malloc(res->n_layers > 0 ? (size_t)res->n_layers : 1);
  rs_status st = RS_OK;
  if (!rep || !flag) {
    st = RS_ERROR(RS_ERR_MEMORY, "out of memory assessing %d layers", res->n_layers);
  } else {
    st = assess_hoop(res, flag, rep);
    if (st == RS_OK) st = rs_defects_starring(res, lim, flag, rep);
    assess_pressure(res, lim->pressure_limit, rep);
    if (st == RS_OK) st = assess_slip(res, lim, flag, rep);
    assess_core(res, lim->core_rating, rep);
  }
  free(flag);
  if (st != RS_OK) rs_defect_report_destroy(&rep);
  *out = rep;
  return st;
}

double rs_defect_report_value(const rs_defect_report *rep, const char *name)
{
  if (!rep || !name) return NAN;
  const int st = rep->starring.verdict != RS_DEFECT_NOT_ASSESSED && rep->starring.compressed > 0;
  const int sl = rep->slip.verdict != RS_DEFECT_NOT_ASSESSED;
  const struct { const char *name; int ok; double v; } f[] = {
      {"starring.layers", rep->starring.verdict != RS_DEFECT_NOT_ASSESSED, rep->starring.layers},
      {"starring.margin_min", st, rep->starring.margin_min},
      {"starring.margin_radius", st, rep->starring.margin_radius},
      {"starring.packet_margin", st, rep->starring.packet_margin},
      {"starring.strength_margin", st, rep->starring.strength_margin},
      {"starring.mode", st, rep->starring.mode},
      {"starring.zone_from_core", st, rep->starring.zone_from_core},
      {"starring.zone_to_core", st, rep->starring.zone_to_core},
      {"slip.layers", sl, rep->slip.layers},
      {"slip.margin_min", sl, rep->slip.margin_min},
      {"slip.margin_radius", sl, rep->slip.margin_radius},
      {"slip.capstan_layers", sl, rep->slip.capstan_layers},
      {"hoop_compression.layers", 1, rep->hoop.layers},
      {"hoop_compression.min_sigma_theta", 1, rep->hoop.min},
      {"hoop_compression.min_sigma_theta_radius", 1, rep->hoop.min_radius},
      {"pressure.max_pressure", 1, rep->pressure.max},
      {"pressure.max_pressure_radius", 1, rep->pressure.max_radius},
      {"pressure.limit", 1, rep->pressure.limit},
      {"pressure.ratio", 1, rep->pressure.ratio},
      {"core.core_pressure", 1, rep->core.pressure},
      {"core.rating", 1, rep->core.rating},
      {"core.ratio", 1, rep->core.ratio},
  };
  for (size_t i = 0; i < sizeof f / sizeof f[0]; ++i)
    if (strcmp(f[i].name, name) == 0) return f[i].ok ? f[i].v : NAN;
  return NAN;
}

const char *rs_defect_report_text(const rs_defect_report *rep, const char *name)
{
  if (!rep || !name) return "";
  const int st = rep->starring.verdict != RS_DEFECT_NOT_ASSESSED && rep->starring.compressed > 0;
  if (strcmp(name, "starring.verdict") == 0) return rs_defect_verdict_name(rep->starring.verdict);
  if (strcmp(name, "starring.criterion") == 0)
    return rs_starring_criterion_name(rep->starring.criterion);
  if (strcmp(name, "starring.interlayers") == 0)
    return st ? (rep->starring.bonded ? "bonded" : "slipping") : "";
  if (strcmp(name, "slip.verdict") == 0) return rs_defect_verdict_name(rep->slip.verdict);
  if (strcmp(name, "hoop_compression.verdict") == 0) return rs_defect_verdict_name(rep->hoop.verdict);
  if (strcmp(name, "pressure.verdict") == 0) return rs_defect_verdict_name(rep->pressure.verdict);
  if (strcmp(name, "core.verdict") == 0) return rs_defect_verdict_name(rep->core.verdict);
  return "";
}
