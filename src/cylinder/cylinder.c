/* The cylinder handle: constants, the per-mode cache and the large-n expansion of the
 * mode compliance used by the accelerated series. */
#include "cylinder/internal.h"
#include "util/error.h"

#include <math.h>
#include <stdlib.h>

/* F(n) = F_alg(1/n) + O(rho0^(2n)) with F_alg analytic at 0 (docs/cylinder.md), so the
 * expansion F ~ e0 + e1/n + e2/n^2 comes from derivatives of F_alg at eps = 0, by
 * 5-point central differences (truncation h^4, round-off 1e-16/h^2). Any values would
 * keep the accelerated series exact; accurate ones make it converge like n^-3. */
static rs_status expansion(rs_cylinder *c)
{
  const double h = 1e-2;
  double F[5][2][2];
  for (int k = -2; k <= 2; ++k) {
    rs_status st = rs_cyl_mode_algebraic(&c->nd, k * h, F[k + 2]);
    if (st) return st;
  }
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      double fm2 = F[0][i][j], fm1 = F[1][i][j], f0 = F[2][i][j], f1 = F[3][i][j], f2 = F[4][i][j];
      c->Fexp[0][i][j] = f0;
      c->Fexp[1][i][j] = (8 * (f1 - fm1) - (f2 - fm2)) / (12 * h);
      c->Fexp[2][i][j] = 0.5 * (-f2 + 16 * f1 - 30 * f0 + 16 * fm1 - fm2) / (12 * h * h);
    }
  return RS_OK;
}

rs_status rs_cylinder_create(const rs_ortho *c, double R, double R0, rs_cylinder **out)
{
  if (!out) return RS_ERROR(RS_ERR_INPUT, "NULL output");
  *out = NULL;
  rs_status st = rs_cyl_check_ortho(c);
  if (st) return st;
  if (!(isfinite(R) && R > 0 && R0 > 0 && R0 / R >= 1e-3 && R0 / R <= 0.999))
    return RS_ERROR(RS_ERR_INPUT, "need 1e-3 <= R0/R <= 0.999 (R = %g m, R0 = %g m)", R, R0);
  rs_cylinder *cyl = calloc(1, sizeof *cyl);
  if (!cyl) return RS_ERROR(RS_ERR_MEMORY, "cylinder");
  cyl->c = *c;
  cyl->R = R;
  cyl->R0 = R0;
  cyl->rho0 = R0 / R;
  cyl->A_ref = fmax(c->A_rr, c->A_tt);
  cyl->nd = (rs_cyl_nd){c->A_rr / cyl->A_ref, c->A_rt / cyl->A_ref, c->A_tt / cyl->A_ref,
                        c->G_rt / cyl->A_ref};
  st = expansion(cyl);
  if (st) {
    free(cyl);
    return st;
  }
  *out = cyl;
  return RS_OK;
}

void rs_cylinder_destroy(rs_cylinder **cyl)
{
  if (!cyl || !*cyl) return;
  free((*cyl)->cache);
  free(*cyl);
  *cyl = NULL;
}

double rs_cylinder_radius(const rs_cylinder *cyl) { return cyl->R; }
double rs_cylinder_core_radius(const rs_cylinder *cyl) { return cyl->R0; }
const rs_ortho *rs_cylinder_constants(const rs_cylinder *cyl) { return &cyl->c; }

rs_status rs_cyl_cache_reserve(rs_cylinder *cyl, long nmax)
{
  if (nmax < cyl->ncache) return RS_OK;
  if (nmax >= cyl->capcache) {
    long cap = cyl->capcache ? cyl->capcache : 1024;
    while (cap <= nmax) cap *= 2;
    rs_cyl_mode *p = realloc(cyl->cache, (size_t)cap * sizeof *p);
    if (!p) return RS_ERROR(RS_ERR_MEMORY, "mode cache of %ld modes", cap);
    cyl->cache = p;
    cyl->capcache = cap;
  }
  for (long n = cyl->ncache; n <= nmax; ++n) {
    rs_status st = rs_cyl_mode_solve(&cyl->nd, cyl->rho0, n, cyl->cache[n].F);
    if (st) return st;
    cyl->ncache = n + 1;
  }
  return RS_OK;
}

rs_status rs_cylinder_prepare(rs_cylinder *cyl, long nmax)
{
  if (!cyl || nmax < 0) return RS_ERROR(RS_ERR_INPUT, "bad arguments");
  return rs_cyl_cache_reserve(cyl, nmax);
}

rs_status rs_cylinder_mode_compliance(const rs_cylinder *cyl, long n, double C[2][2])
{
  if (!cyl || !C) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  double F[2][2];
  rs_status st = rs_cyl_mode_solve(&cyl->nd, cyl->rho0, n, F);
  if (st) return st;
  double f = cyl->R / cyl->A_ref / (n >= 1 ? (double)n : 1.0);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) C[i][j] = f * F[i][j];
  return RS_OK;
}

rs_status rs_cylinder_mode_field(const rs_cylinder *cyl, long n, double P, double Q, double r,
                                 double *U, double *V)
{
  if (!cyl || !U || !V) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  if (!(r > 0) || !isfinite(r)) return RS_ERROR(RS_ERR_INPUT, "radius r = %g", r);
  /* r - R and R0 - r are exact near the surfaces (Sterbenz), so n ln(r/R) keeps its
   * relative accuracy even for n = 1e5 */
  double L = log1p((r - cyl->R) / cyl->R), L0 = log1p((cyl->R0 - r) / r);
  rs_status st = rs_cyl_mode_eval(&cyl->nd, cyl->rho0, n, P, Q, r / cyl->R, L, L0, U, V);
  if (st) return st;
  *U *= cyl->R / cyl->A_ref;
  *V *= cyl->R / cyl->A_ref;
  return RS_OK;
}
