/* Defect-risk indicators (docs/defects.md): each rule compares the final stress profile
 * with a threshold and says where the roll is prone to a defect. They are screening
 * rules from winding practice, not models of the defects. */
#include "reelsim/defects.h"

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

void rs_defect_limits_from_problem(const rs_problem *pb, rs_defect_limits *lim)
{
  lim->pressure_limit = pb->material.pressure_limit;
  lim->core_rating = pb->core.rating;
  lim->accel_torque = pb->accel_torque;
  lim->friction_layer = pb->material.friction_layer;
  lim->E_theta = pb->material.E_theta;
  lim->radial = &pb->material.radial;
}

double rs_defect_critical_hoop_stress(double E_theta, double E_r)
{
  return E_theta > 0.0 && E_r > 0.0 ? sqrt(E_theta * E_r / 3.0) : 0.0;
}

/* Coulomb friction on the cylindrical interface of radius r (per unit width): shear
 * stress at most mu P over the area 2 pi r, acting at lever arm r (Roisum 1994; the
 * "torque transmission capacity" of cinching, Walker 2007). A gap (P <= 0) carries none. */
double rs_defect_slip_capacity(double mu, double P, double r)
{
  return P > 0.0 ? mu * P * 2.0 * pi * r * r : 0.0;
}

void rs_defect_report_destroy(rs_defect_report **rep)
{
  if (!rep || !*rep) return;
  free((*rep)->hoop.ranges);
  free((*rep)->buckling.ranges);
  free((*rep)->slip.ranges);
  free(*rep);
  *rep = NULL;
}

/* Collects the runs of consecutive flagged layers 0..n-1 into *ranges (malloc'd, NULL
 * when none). Returns the number of flagged layers, or -1 when out of memory. */
static int flag_ranges(const unsigned char *flag, int n, const double *radius,
                       rs_defect_range **ranges, int *n_ranges)
{
  int runs = 0, count = 0;
  *ranges = NULL;
  *n_ranges = 0;
  for (int j = 0; j < n; ++j) {
    count += flag[j];
    runs += flag[j] && (j == 0 || !flag[j - 1]);
  }
  if (runs == 0) return 0;
  rs_defect_range *r = malloc((size_t)runs * sizeof *r);
  if (!r) return -1;
  int k = -1;
  for (int j = 0; j < n; ++j) {
    if (!flag[j]) continue;
    if (j == 0 || !flag[j - 1]) r[++k].first = j;
    r[k].last = j;
  }
  for (int i = 0; i < runs; ++i) {
    r[i].r_first = radius[r[i].first];
    r[i].r_last = radius[r[i].last];
  }
  *ranges = r;
  *n_ranges = runs;
  return count;
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
  rep->hoop.layers = flag_ranges(flag, n, res->radius, &rep->hoop.ranges, &rep->hoop.n_ranges);
  if (rep->hoop.layers < 0) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the hoop ranges");
  rep->hoop.verdict = rep->hoop.layers > 0 ? RS_DEFECT_PRESENT : RS_DEFECT_OK;
  return RS_OK;
}

/* Interlayer pressure (Pa, compression positive, a gap as 0) on the inner face of layer j
 * (the core contact for the first) and on its outer face. */
static double pressure_below(const rs_reel_result *res, int j)
{
  double P = j == 0 ? res->core_pressure : 0.0 - res->sigma_r[j - 1];
  return P > 0.0 ? P : 0.0;
}

static double pressure_above(const rs_reel_result *res, int j)
{
  double P = 0.0 - res->sigma_r[j];
  return P > 0.0 ? P : 0.0;
}

/* Hoop buckling (starring): layer j buckles on the stack's elastic foundation where its
 * compression exceeds sigma_cr = sqrt(E_theta E_r / 3) (rs_defect_critical_hoop_stress),
 * E_r the stack's tangent radial modulus at the softer of its two faces (the lesser
 * E_r(P) of the interfaces below and above it). Risk where -sigma_theta > sigma_cr. */
static rs_status assess_buckling(const rs_reel_result *res, const rs_defect_limits *lim,
                                 unsigned char *flag, rs_defect_report *rep)
{
  int n = res->n_layers;
  rep->buckling.verdict = RS_DEFECT_NOT_ASSESSED;
  if (n == 0 || !lim->radial || !(lim->E_theta > 0.0)) return RS_OK;
  rep->buckling.margin_min = INFINITY;
  for (int j = 0; j < n; ++j) {
    flag[j] = 0;
    double c = 0.0 - res->sigma_theta[j];
    if (!(c > 0.0)) continue;
    double E_lo = rs_radial_modulus(lim->radial, pressure_below(res, j));
    double E_hi = rs_radial_modulus(lim->radial, pressure_above(res, j));
    double crit = rs_defect_critical_hoop_stress(lim->E_theta, E_lo < E_hi ? E_lo : E_hi);
    double margin = crit / c;
    rep->buckling.compressed++;
    flag[j] = c > crit;
    if (margin < rep->buckling.margin_min) {
      rep->buckling.margin_min = margin;
      rep->buckling.margin_radius = res->radius[j];
      rep->buckling.margin_critical = crit;
      rep->buckling.margin_sigma = res->sigma_theta[j];
    }
  }
  if (rep->buckling.compressed == 0) rep->buckling.margin_min = 0.0;
  rep->buckling.layers =
      flag_ranges(flag, n, res->radius, &rep->buckling.ranges, &rep->buckling.n_ranges);
  if (rep->buckling.layers < 0)
    return RS_ERROR(RS_ERR_MEMORY, "out of memory for the buckling ranges");
  rep->buckling.verdict = rep->buckling.layers > 0 ? RS_DEFECT_RISK : RS_DEFECT_OK;
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
 * layers j and j+1; the outer surface has none) transmits at most
 * M_f = mu P_j 2 pi r_j^2 (N m/m). Risk where M_f < M, M the applied torque: taking the
 * whole torque at every interface is conservative, since an interface only passes on
 * the torque that accelerates the layers outside it. */
static rs_status assess_slip(const rs_reel_result *res, double torque, double mu,
                             unsigned char *flag, rs_defect_report *rep)
{
  int n = res->n_layers, m = n - 1; /* interfaces */
  rep->slip.verdict = RS_DEFECT_NOT_ASSESSED;
  rep->slip.torque = torque;
  rep->slip.mu = mu;
  if (!(torque > 0.0 && mu > 0.0) || m < 1) return RS_OK;
  rep->slip.margin_min = INFINITY;
  for (int j = 0; j < m; ++j) {
    double margin = rs_defect_slip_capacity(mu, 0.0 - res->sigma_r[j], res->radius[j]) / torque;
    flag[j] = margin < 1.0;
    if (margin < rep->slip.margin_min) {
      rep->slip.margin_min = margin;
      rep->slip.margin_radius = res->radius[j];
    }
  }
  rep->slip.layers = flag_ranges(flag, m, res->radius, &rep->slip.ranges, &rep->slip.n_ranges);
  if (rep->slip.layers < 0) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the slip ranges");
  rep->slip.verdict = rep->slip.layers > 0 ? RS_DEFECT_RISK : RS_DEFECT_OK;
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
    if (st == RS_OK) st = assess_buckling(res, lim, flag, rep);
    assess_pressure(res, lim->pressure_limit, rep);
    if (st == RS_OK) st = assess_slip(res, lim->accel_torque, lim->friction_layer, flag, rep);
    assess_core(res, lim->core_rating, rep);
  }
  free(flag);
  if (st != RS_OK) rs_defect_report_destroy(&rep);
  *out = rep;
  return st;
}
