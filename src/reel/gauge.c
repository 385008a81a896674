/* What gauges read (docs/output.md, "What gauges read"): the roll's real radii, with the
 * stack compressed by its pressure, and the wound-in tension.
 *
 * A layer j of caliper t between nodes j and j + 1 (node 0 the core's face; node j + 1
 * under sigma_r[j]) at node pressures P_j, P_j+1 is compressed by
 *     t (eps(P_j) + eps(P_j+1)) / 2,    eps(P) = integral over [0, P] of dp / E_r(p)
 * (the trapezoid rule of the integral of eps_r through the stack; the stack law loaded
 * from zero, path independent: the strain a stack test measures at that pressure). The
 * core gives way by u_c = -r_c P_c / E_c (the core condition's effective modulus; rigid 0),
 * and the air films (entrained air) are compressed by the pressure at their node:
 *     R_j = r_c + u_c + sum over i <= j of (t + h_i(P_i) - t (eps(P_i) + eps(P_i+1)) / 2).
 * The web's Poisson strain through the thickness under its hoop stress (nu sigma_theta /
 * E_theta, ~1e-5) is left out, as the engine's compatibility cancels it. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/material.h"
#include "reel/gauge.h"
#include "reelsim/reel.h"
#include "util/error.h"
#include "util/vector_clones.h"

enum { STRAIN_TABLE = 256 };

/* eps(P) on [0, P_max] at the nodes P_max (i/M)^2 (closer near 0, where 1/E_r varies most),
 * a cubic Hermite between them with the exact slopes 1/E_r: O(h^4), one tabulation for a
 * whole roll instead of a quadrature per layer */
typedef struct strain_table {
  double Pmax, eps[STRAIN_TABLE + 1], inv[STRAIN_TABLE + 1];
} strain_table;

static void strain_table_fill(strain_table *tb, const rs_radial_law *law, double Pmax)
{
  double P[STRAIN_TABLE + 1], E[STRAIN_TABLE + 1], d[STRAIN_TABLE];
  tb->Pmax = Pmax;
  for (int i = 0; i <= STRAIN_TABLE; ++i) {
    const double s = (double)i / STRAIN_TABLE;
    P[i] = Pmax * s * s;
  }
  rs_radial_strain_steps(law, P, STRAIN_TABLE, d);
  rs_radial_modulus_n(law, P, E, STRAIN_TABLE + 1);
  tb->eps[0] = 0.0;
  tb->inv[0] = 1.0 / E[0];
  for (int i = 1; i <= STRAIN_TABLE; ++i) {
    tb->eps[i] = tb->eps[i - 1] + d[i - 1];
    tb->inv[i] = 1.0 / E[i];
  }
}

/* eps(P) of the table (its strains eps_t and slopes inv_t at the nodes Pmax (i/M)^2) for
 * 0 <= P: the cubic Hermite of the interval P is in, extrapolated by the last above Pmax.
 * One formula for a pressure and for an array of them (strain_table_eval_stress_n). */
static inline double strain_table_at(const double *eps_t, const double *inv_t, double Pmax,
                                     double P)
{
  int i = (int)(STRAIN_TABLE * sqrt(P / Pmax));
  i = i < STRAIN_TABLE - 1 ? i : STRAIN_TABLE - 1;
  const double s0 = (double)i / STRAIN_TABLE, s1 = (double)(i + 1) / STRAIN_TABLE;
  const double a = Pmax * s0 * s0, h = Pmax * s1 * s1 - a, x = (P - a) / h;
  const double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x);
  const double h01 = x * x * (3 - 2 * x), h11 = x * x * (x - 1);
  return h00 * eps_t[i] + h10 * h * inv_t[i] + h01 * eps_t[i + 1] + h11 * h * inv_t[i + 1];
}

static double strain_table_eval(const strain_table *tb, double P)
{
  if (!(P > 0.0) || !(tb->Pmax > 0.0)) return 0.0;
  return strain_table_at(tb->eps, tb->inv, tb->Pmax, P);
}

/* out[j] = strain_table_eval(-sigma[j]) for j < n (Pmax > 0), the same operations in a loop
 * over arrays that vectorises (gathers from the table: AVX2): a pressure at or below 0, or
 * NaN, is read as 0, whose strain is 0 (the first node's eps_t[0] = 0, its other terms 0) */
RS_VECTOR_CLONES static void strain_table_eval_stress_n(const double *restrict eps_t,
                                                        const double *restrict inv_t, double Pmax,
                                                        const double *restrict sigma,
                                                        double *restrict out, int n)
{
  for (int j = 0; j < n; ++j) {
    const double P = -sigma[j];
    out[j] = strain_table_at(eps_t, inv_t, Pmax, P > 0.0 ? P : 0.0);
  }
}

struct rs_reel_strain {
  strain_table tb;
};

rs_reel_strain *rs_reel_strain_new(const rs_radial_law *law, double Pmax)
{
  rs_reel_strain *s = malloc(sizeof *s);
  if (s) strain_table_fill(&s->tb, law, Pmax > 0.0 ? Pmax : 0.0);
  return s;
}

double rs_reel_strain_eval(const rs_reel_strain *s, double P) { return strain_table_eval(&s->tb, P); }
double rs_reel_strain_max(const rs_reel_strain *s) { return s->tb.Pmax; }

void rs_reel_strain_free(rs_reel_strain **s)
{
  if (!s) return;
  free(*s);
  *s = NULL;
}

/* u_c = -r_c P_c / E_c (m): the core face's radial displacement under the core pressure
 * P_c (compression positive; a pressure below zero, or a rigid core, moves it by 0) */
double rs_reel_core_displacement(const rs_problem *pb, double core_pressure)
{
  const double Ec = rs_core_stiffness(&pb->core);
  return isfinite(Ec) ? -pb->core.radius * (core_pressure > 0.0 ? core_pressure : 0.0) / Ec : 0.0;
}

/* The largest pressure, core_pressure and -sigma_r[j] (j < n), as fmax() takes it in that
 * order (a NaN pressure skipped, a NaN so far replaced by the next pressure): as four
 * running maxima side by side where none is a NaN (a maximum does not depend on the order
 * it is taken in but for the sign of a zero, which the table's Pmax > 0 test does not
 * see), in order otherwise */
double rs_reel_deformed_pmax(double core_pressure, const double *restrict sigma_r, int n)
{
  double m[4] = {core_pressure, core_pressure, core_pressure, core_pressure};
  int nan = isnan(core_pressure), j = 0;
  for (; j + 3 < n; j += 4)
    for (int k = 0; k < 4; ++k) {
      const double P = -sigma_r[j + k];
      nan |= P != P;
      m[k] = P > m[k] ? P : m[k];
    }
  for (; j < n; ++j) {
    const double P = -sigma_r[j];
    nan |= P != P;
    m[0] = P > m[0] ? P : m[0];
  }
  if (!nan) {
    const double a = m[0] > m[1] ? m[0] : m[1], b = m[2] > m[3] ? m[2] : m[3];
    return a > b ? a : b;
  }
  double Pmax = core_pressure;
  for (int i = 0; i < n; ++i) { /* fmax without the call */
    const double P = -sigma_r[i];
    if (P > Pmax || isnan(Pmax)) Pmax = P;
  }
  return Pmax;
}

rs_status rs_reel_deformed_radius(const rs_problem *pb, double core_pressure, const double *sigma_r,
                                  const double *film, int n, double *out)
{
  if (n < 1) return RS_OK;
  strain_table *tb = malloc(sizeof *tb);
  if (!tb) return RS_ERROR(RS_ERR_MEMORY, "deformed radius: out of memory");
  const double t = pb->material.caliper, pa = pb->air.pressure;
  const double Pmax = rs_reel_deformed_pmax(core_pressure, sigma_r, n);
  strain_table_fill(tb, &pb->material.radial, Pmax > 0.0 ? Pmax : 0.0);
  double r = pb->core.radius + rs_reel_core_displacement(pb, core_pressure);
  double P_in = core_pressure, e_in = strain_table_eval(tb, core_pressure);
  /* the strains of nodes 1..n-1 first, in one pass (out[j] holds node j + 1's until the sum
   * writes it), unless out overlaps sigma_r (then node by node: the same values) */
  const uintptr_t o = (uintptr_t)out, sg = (uintptr_t)sigma_r;
  const uintptr_t bytes = (uintptr_t)n * sizeof(double);
  const int batched = tb->Pmax > 0.0 && (o + bytes <= sg || sg + bytes <= o);
  if (batched) strain_table_eval_stress_n(tb->eps, tb->inv, tb->Pmax, sigma_r, out, n - 1);
  for (int j = 0; j < n; ++j) {
    const double P_out = j + 1 < n ? -sigma_r[j] : 0.0;
    const double e_out = j + 1 >= n ? 0.0 : batched ? out[j] : strain_table_eval(tb, P_out);
    r += t * (1.0 - 0.5 * (e_in + e_out));
    if (film) r += rs_air_compressed_film(film[j], P_in, pa);
    out[j] = r;
    P_in = P_out;
    e_in = e_out;
  }
  free(tb);
  return RS_OK;
}

/* T_w = sigma_theta t, N/m */
void rs_reel_wound_in_tension(const rs_problem *pb, const double *sigma_theta, int n, double *out)
{
  for (int j = 0; j < n; ++j) out[j] = sigma_theta[j] * pb->material.caliper;
}

/* ---- the wound radius: the deformed outer radius as each layer went on --------------- */

/* the next state recorded after n layers: every layer up to 1/RS_GAUGE_STEP, then at
 * n (1 + RS_GAUGE_STEP) (the pressure builds fastest over the first layers: the shortfall's
 * curvature falls like 1/n); ln(N)/RS_GAUGE_STEP states, O(N/RS_GAUGE_STEP) work in all */
static int gauge_next(int n)
{
  const int step = (int)(n * RS_GAUGE_STEP);
  return n + (step > 1 ? step : 1);
}

rs_status rs_reel_gauge_init(rs_reel_gauge *g, int N)
{
  memset(g, 0, sizeof *g);
  g->cap = 2;
  for (int n = 0; n < N; n = gauge_next(n)) ++g->cap;
  g->layers = malloc((size_t)g->cap * sizeof(int));
  g->shortfall = malloc((size_t)g->cap * sizeof(double));
  g->radius = malloc((size_t)N * sizeof(double));
  if (!g->layers || !g->shortfall || !g->radius) {
    rs_reel_gauge_free(g);
    return RS_ERROR(RS_ERR_MEMORY, "wound radius: out of memory (%d layers)", N);
  }
  g->layers[0] = 0;
  g->shortfall[0] = 0.0;
  g->n = 1;
  return RS_OK;
}

void rs_reel_gauge_free(rs_reel_gauge *g)
{
  free(g->layers);
  free(g->shortfall);
  free(g->radius);
  g->layers = NULL;
  g->shortfall = g->radius = NULL;
}

int rs_reel_gauge_due(const rs_reel_gauge *g, int n)
{
  return n > g->layers[g->n - 1] && n >= gauge_next(g->layers[g->n - 1]);
}

rs_status rs_reel_gauge_record(rs_reel_gauge *g, const rs_problem *pb, int n, double core_pressure,
                               const double *sigma_r, const double *film, int force)
{
  if (n <= g->layers[g->n - 1] || (!force && !rs_reel_gauge_due(g, n))) return RS_OK;
  while (g->n > 1 && g->layers[g->n - 1] >= n) g->n--; /* a rewind (adaptive nip) */
  if (g->n == g->cap) return RS_OK;
  rs_status st = rs_reel_deformed_radius(pb, core_pressure, sigma_r, film, n, g->radius);
  if (st) return st;
  g->layers[g->n] = n;
  g->shortfall[g->n++] = pb->core.radius + n * pb->material.caliper - g->radius[n - 1];
  return RS_OK;
}

void rs_reel_gauge_rewind(rs_reel_gauge *g, int layers)
{
  while (g->n > 1 && g->layers[g->n - 1] > layers) g->n--;
}

/* wound[j] = r_c + (j + 1) t - shortfall(j + 1), the shortfall (core, stack, films)
 * interpolated linearly in the layers between the states recorded */
void rs_reel_gauge_finish(const rs_reel_gauge *g, const rs_problem *pb, int n, double *wound)
{
  int k = 0;
  for (int j = 0; j < n; ++j) {
    const int m = j + 1;
    while (k + 2 < g->n && g->layers[k + 1] < m) ++k;
    double s;
    if (k + 1 >= g->n) s = g->shortfall[k];
    else {
      const double x = (double)(m - g->layers[k]) / (g->layers[k + 1] - g->layers[k]);
      s = g->shortfall[k] + x * (g->shortfall[k + 1] - g->shortfall[k]);
    }
    wound[j] = pb->core.radius + m * pb->material.caliper - s;
  }
}
