/* The kernel series' summation state (kernel_sum.h): the offsets summed and their work
 * arrays, the closed-form parts of the accelerated sums at them (on the grid of half cells
 * where the offsets lie on it: sums.c) and the kernels' values at every offset from the
 * sums, by parity. */
#include "cylinder/kernel_sum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/error.h"

void rs_cyl_sum_free(kernel_sum *ks)
{
  free(ks->prevmem);
  free(ks->mem);
  if (!ks->shared) {
    free(ks->src);
    free(ks->h2);
  }
}

/* The work arrays of a sum over nk offsets (padded to Kp): t, c, s, ct, st, all offsets'
 * t, the partial sums and the closed parts; the sums and the closed parts zeroed. */
static rs_status work_alloc(int Kp, int nk, kernel_sum *ks)
{
  double *mem = ks->mem = malloc(((size_t)Kp * (6 + 2 * NK) + MODE_CHUNK) * sizeof(double));
  if (!mem) return RS_ERROR(RS_ERR_MEMORY, "kernel work space");
  memset(mem + 6 * (size_t)Kp, 0, (size_t)Kp * 2 * NK * sizeof(double));
  const int nkp = (nk + 3) & ~3;
  ks->wk = (work){nkp, mem, mem + Kp, mem + 2 * Kp, mem + 3 * Kp, mem + 4 * Kp, {0}, NULL};
  for (int j = 0; j < NK; ++j) {
    ks->wk.acc[j] = mem + (size_t)(6 + j) * Kp;
    ks->closed[j] = mem + (size_t)(6 + NK + j) * Kp;
  }
  ks->wk.acoef = mem + (size_t)(6 + 2 * NK) * Kp;
  for (int i = nk; i < nkp; ++i) { /* padding offsets t = 0, never read back */
    mem[i] = 0.0;
    ks->wk.ct[i] = 1.0;
    ks->wk.st[i] = 0.0;
  }
  return RS_OK;
}

/* The offsets to sum. Parity: pu, pe are even and qu, qe odd in the offset, so an offset
 * u = d + shift/dx (in cells) whose mirror -u is also in the set is computed once. With
 * 2 shift/dx an integer s2 the mirror of index k is 2(M-1) - s2 - k, and the offsets lie
 * on the grid of half cells (h2 = 2u). */
rs_status rs_cyl_offsets_build(const rs_cylinder *cyl, double dx, double shift, int M,
                               kernel_sum *ks)
{
  const int K = 2 * M - 1;
  double s2r = 2 * shift / dx;
  long s2 = lround(s2r);
  int mirror = fabs(s2r - (double)s2) <= 1e-12 * fmax(1.0, fabs(s2r)) && labs(s2) < 2L * K;
  const int Kp = (K + 3) & ~3; /* work arrays padded (see work.K) */
  ks->K = K;
  ks->src = malloc((size_t)K * sizeof *ks->src);
  ks->h2 = mirror ? malloc((size_t)K * sizeof *ks->h2) : NULL;
  rs_status st = ks->src && (ks->h2 || !mirror) ? work_alloc(Kp, K, ks)
                                                 : RS_ERROR(RS_ERR_MEMORY, "kernel work space");
  if (st) return st;
  double *t = ks->mem, *tall = ks->mem + 5 * Kp;
  int nk = 0;
  for (int k = 0; k < K; ++k) {
    tall[k] = rs_cyl_wrap(((double)(k - (M - 1)) * dx + shift) / cyl->R);
    long km = mirror ? 2L * (M - 1) - s2 - k : -1;
    double u = (double)(k - (M - 1)) + s2r / 2;
    if (km >= 0 && km < K && km != k && u < 0) {
      ks->src[k] = -1 - (int)km;
    } else {
      if (mirror) ks->h2[nk] = 2L * (k - (M - 1)) + s2;
      ks->src[k] = nk;
      t[nk++] = tall[k];
    }
  }
  ks->nk = nk;
  ks->t = t;
  ks->wk.K = (nk + 3) & ~3;
  for (int i = nk; i < ks->wk.K; ++i) {
    t[i] = 0.0;
    ks->wk.ct[i] = 1.0;
    ks->wk.st[i] = 0.0;
  }
  return RS_OK;
}

/* A second sum on the offsets of `from` (its own partial sums and closed parts). */
rs_status rs_cyl_offsets_share(const kernel_sum *from, kernel_sum *ks)
{
  const int Kp = (from->K + 3) & ~3;
  rs_status st = work_alloc(Kp, from->nk, ks);
  if (st) return st;
  ks->shared = 1;
  ks->K = from->K;
  ks->nk = from->nk;
  ks->src = from->src;
  ks->h2 = from->h2;
  memcpy(ks->mem, from->t, (size_t)ks->wk.K * sizeof(double));
  ks->t = ks->mem;
  return RS_OK;
}

/* The accelerated sums' closed-form parts at the summed offsets: on the grid of half
 * cells when the offsets lie on it away from +-pi (neighbouring offsets share their
 * pieces' boundary values), else offset by offset. */
static rs_status closed_sums(rs_basis basis, double w, unsigned cmask, const kernel_sum *ks,
                             double (*S)[6])
{
  int grid = ks->h2 != NULL;
  for (int i = 0; grid && i < ks->nk; ++i) grid = fabs(ks->t[i]) + 2 * w < 3.0;
  if (grid) return rs_cyl_closed_sums_grid(basis, w, ks->nk, ks->h2, cmask, S);
  for (int i = 0; i < ks->nk; ++i) rs_cyl_closed_sums_part(basis, w, ks->t[i], cmask, S[i]);
  return RS_OK;
}

/* cos t, sin t of each summed offset (trig: for the rotation of the modes' sweep), and the
 * closed-form part of each kernel there: the accelerated sums' e0 S0 + e1 S1 + e2 S2 and
 * the n = 0 term (uniform pressure; uniform shear, torsion, gives no w and no eps). */
rs_status rs_cyl_closed_parts(rs_cylinder *cyl, rs_basis basis, double w, int accelerate,
                              const double e[NK][3], unsigned what, double shift, int M,
                              int trig, kernel_sum *ks)
{
  const unsigned cmask = (what & (RS_KERNEL_PU | RS_KERNEL_PE) ? 1u : 0u) |
                         (what & (RS_KERNEL_QU | RS_KERNEL_QE) ? 2u : 0u);
  double *const *closed = ks->closed;
  for (int i = 0; i < ks->nk; ++i) {
    double ti = ks->t[i];
    if (trig) {
      ks->wk.ct[i] = cos(ti);
      ks->wk.st[i] = sin(ti);
    }
    if ((what & RS_KERNEL_QE) && basis == RS_BASIS_BOX && fabs(fabs(ti) - w) < 1e-10 * w) {
      int k = 0;
      while (ks->src[k] != i) ++k;
      return RS_ERROR(RS_ERR_INPUT, "shear-to-strain kernel of a box is log-singular at its "
                      "edge (offset %d dx %+g m)", k - (M - 1), shift);
    }
  }
  if (accelerate) {
    double (*S)[6] = malloc((size_t)ks->nk * sizeof *S);
    rs_status st = S ? closed_sums(basis, w, cmask, ks, S)
                     : RS_ERROR(RS_ERR_MEMORY, "closed sums at %d offsets", ks->nk);
    if (st) {
      free(S);
      return st;
    }
    for (int i = 0; i < ks->nk; ++i) {
      closed[KPU][i] = e[KPU][1] * S[i][1] + e[KPU][2] * S[i][2];
      closed[KPE][i] = e[KPE][0] * S[i][0] + e[KPE][1] * S[i][1] + e[KPE][2] * S[i][2];
      closed[KQU][i] = e[KQU][1] * S[i][4] + e[KQU][2] * S[i][5];
      closed[KQE][i] = e[KQE][0] * S[i][3] + e[KQE][1] * S[i][4] + e[KQE][2] * S[i][5];
    }
    free(S);
  }
  rs_status st = rs_cyl_cache_reserve(cyl, 0);
  if (st) return st;
  double a0 = rs_cyl_basis_coef(basis, w, 0), F0 = cyl->cache[0].F[0][0];
  for (int i = 0; i < ks->nk; ++i) {
    closed[KPU][i] += a0 * F0;
    closed[KPE][i] -= a0 * F0;
  }
  return RS_OK;
}

/* The kernels at every offset: the summed ones scaled (R/A for displacements, 1/A for
 * strains), the mirrored ones by parity (even p, odd q). */
void rs_cyl_sum_scatter(const rs_cylinder *cyl, const kernel_sum *ks, unsigned what,
                        rs_kernels *out)
{
  double fu = cyl->R / cyl->A_ref, fe = 1.0 / cyl->A_ref;
  double *dst[NK] = {out->pu, out->pe, out->qu, out->qe};
  double fac[NK] = {fu, fe, fu, fe}, par[NK] = {1, 1, -1, -1};
  const int *src = ks->src;
  for (int j = 0; j < NK; ++j) {
    if (!(what & kernel_bit[j])) continue;
    for (int k = 0; k < ks->K; ++k)
      if (src[k] >= 0) dst[j][k] = fac[j] * (ks->closed[j][src[k]] + ks->wk.acc[j][src[k]]);
    for (int k = 0; k < ks->K; ++k)
      if (src[k] < 0) dst[j][k] = par[j] * dst[j][-1 - src[k]];
  }
}

