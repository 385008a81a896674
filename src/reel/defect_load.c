/* Helpers the defect rules share (src/reel/defects.c, starring.c): the flagged ranges and
 * the torque each interface carries (docs/defects.md, section 4). */
#include <math.h>
#include <stdlib.h>

#include "reel/defects_internal.h"
#include "reel/result_internal.h"

static const double pi = 3.14159265358979323846;

/* The torque the interface at r passes on (module comment of defects.h): the drive enters
 * as s (T R + I alpha) at the core and (1 - s)(T R + I alpha) at the surface; the layers
 * inside r take I_in alpha of it, so the interface carries s (T R + I alpha) - I_in alpha,
 * |.| worst over the sign of alpha (a start or a stop): s T R + |s - f_in| I |alpha|. */
double rs_defect_interface_torque(double s, double TR, double M_acc, double r, double r_c,
                                  double R)
{
  double d = R * R * R * R - r_c * r_c * r_c * r_c;
  double f_in = d > 0.0 ? (r * r * r * r - r_c * r_c * r_c * r_c) / d : 0.0;
  return s * TR + fabs(s - f_in) * M_acc;
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

/* Collects the runs of consecutive flagged layers 0..n-1 into *ranges (malloc'd, NULL
 * when none). Returns the number of flagged layers, or -1 when out of memory. */
int rs_defect_flag_ranges(const unsigned char *flag, int n, const double *radius,
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

/* The inertia torque I |alpha| (N m/m) of the wound layers in a speed change: the given
 * winding.accel_torque, or rho pi (R^4 - r_c^4) / 2 per unit width times alpha = a / R from
 * winding.acceleration (a at the surface, m/s^2). *alpha gets |alpha| where known. */
static double inertia_torque(const rs_defect_limits *lim, double r_c, double R, double *alpha)
{
  double I = lim->density > 0.0 ? lim->density * pi * (R * R * R * R - r_c * r_c * r_c * r_c) / 2.0
                                : 0.0;
  *alpha = 0.0;
  if (lim->accel_torque > 0.0) {
    if (I > 0.0) *alpha = lim->accel_torque / I;
    return lim->accel_torque;
  }
  if (lim->acceleration > 0.0 && I > 0.0) {
    *alpha = lim->acceleration / R;
    return I * *alpha;
  }
  return 0.0;
}

void rs_defect_slip_load(const rs_reel_result *res, const rs_defect_limits *lim, rs_slip_load *L)
{
  const int n = res->n_layers;
  L->R = n > 0 ? res->radius[n - 1] : res->core_radius;
  L->s = lim->core_share;
  L->TR = (res->web_tension && n > 0 ? res->web_tension[n - 1] : 0.0) * L->R;
  L->M_acc = inertia_torque(lim, res->core_radius, L->R, &L->alpha);
}

