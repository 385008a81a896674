/* Influence kernels of eq. (19) from the Fourier series of the mode compliances.
 *
 * For a basis function with cosine coefficients a_n (on the circle; t = offset / R):
 *   pu(t) = R/A [a_0 F0_11 + sum a_n F11/n cos nt]            (m/Pa)
 *   pe(t) = 1/A [-a_0 F0_11 + sum a_n (F21 - F11/n) cos nt]   (1/Pa)
 *   qu(t) = R/A [sum a_n (-F12/n) sin nt]
 *   qe(t) = 1/A [sum a_n (F12/n - F22) sin nt]
 * (F = n C A/R, C the mode compliance; eps = (v_r + dv_t/dtheta)/R.) The accelerated
 * series subtracts from each multiplier m(n) its expansion e0 + e1/n + e2/n^2 and adds
 * e0 S0 + e1 S1 + e2 S2 back, S_k the closed-form sums of sums.c. */
#include "cylinder/kernel_sum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/cancel.h"
#include "util/error.h"
#include "util/vector_clones.h"


void rs_kernels_free(rs_kernels *k)
{
  if (!k) return;
  free(k->pu);
  free(k->pe);
  free(k->qu);
  free(k->qe);
  memset(k, 0, sizeof *k);
}

static rs_status ensure_capacity(rs_kernels *k, int n)
{
  if (k->capacity >= n && k->pu && k->pe && k->qu && k->qe) return RS_OK;
  free(k->pu);
  free(k->pe);
  free(k->qu);
  free(k->qe);
  k->pu = calloc((size_t)n, sizeof(double));
  k->pe = calloc((size_t)n, sizeof(double));
  k->qu = calloc((size_t)n, sizeof(double));
  k->qe = calloc((size_t)n, sizeof(double));
  if (!k->pu || !k->pe || !k->qu || !k->qe) {
    rs_kernels_free(k);
    return RS_ERROR(RS_ERR_MEMORY, "kernels of %d values", n);
  }
  k->capacity = n;
  return RS_OK;
}

/* Expansion coefficients e[kernel][0..2] of the multipliers, from F ~ c0 + c1/n + c2/n^2. */
static void multiplier_expansion(const rs_cylinder *c, double e[NK][3])
{
  const double(*F)[2][2] = c->Fexp;
  e[KPU][0] = 0;
  e[KPU][1] = F[0][0][0];
  e[KPU][2] = F[1][0][0];
  e[KPE][0] = F[0][1][0];
  e[KPE][1] = F[1][1][0] - F[0][0][0];
  e[KPE][2] = F[2][1][0] - F[1][0][0];
  e[KQU][0] = 0;
  e[KQU][1] = -F[0][0][1];
  e[KQU][2] = -F[1][0][1];
  e[KQE][0] = -F[0][1][1];
  e[KQE][1] = F[0][0][1] - F[1][1][1];
  e[KQE][2] = F[1][0][1] - F[2][1][1];
}

/* The sweeps over the offsets, as functions with restrict arguments and a trip count that
 * is a multiple of 4 (K & ~3 == K), which is what lets -O2 vectorise them. */
static void sweep1(int K, double *restrict a, double m, const double *restrict x)
{
  K &= ~3;
  for (int k = 0; k < K; ++k) a[k] += m * x[k];
}

static void sweep2(int K, double *restrict a, double ma, double *restrict b, double mb,
                   const double *restrict x)
{
  K &= ~3;
  for (int k = 0; k < K; ++k) {
    a[k] += ma * x[k];
    b[k] += mb * x[k];
  }
}

/* (c, s) <- (c cos t - s sin t, s cos t + c sin t): cos and sin of (n + 1) t */
RS_VECTOR_CLONES static void rotate(int K, double *restrict c, double *restrict s,
                                    const double *restrict ct, const double *restrict st)
{
  K &= ~3;
  for (int k = 0; k < K; ++k) {
    double ck = c[k], sk = s[k];
    c[k] = ck * ct[k] - sk * st[k];
    s[k] = sk * ct[k] + ck * st[k];
  }
}

/* One mode of two kernels and the rotation to the next, in one pass over the offsets
 * (sweep2 on x = c, or on x = s when on_sin, then rotate): the same arithmetic as the
 * two passes. The two loops differ only in x: one loop selecting x costs 2.5 M more
 * instructions on the contact reel. */
RS_VECTOR_CLONES static void sweep2_rotate(int K, int on_sin, double *restrict a, double ma,
                                           double *restrict b, double mb, double *restrict c,
                                           double *restrict s, const double *restrict ct,
                                           const double *restrict st)
{
  K &= ~3;
  if (on_sin) {
    for (int k = 0; k < K; ++k) {
      double ck = c[k], sk = s[k];
      a[k] += ma * sk;
      b[k] += mb * sk;
      c[k] = ck * ct[k] - sk * st[k];
      s[k] = sk * ct[k] + ck * st[k];
    }
  } else {
    for (int k = 0; k < K; ++k) {
      double ck = c[k], sk = s[k];
      a[k] += ma * ck;
      b[k] += mb * ck;
      c[k] = ck * ct[k] - sk * st[k];
      s[k] = sk * ct[k] + ck * st[k];
    }
  }
}

/* (c, s) <- cos, sin of n t from the library functions (the rotation's restart) */
static void reseed(int K, const double *t, long n, double *c, double *s)
{
  for (int k = 0; k < K; ++k) {
    c[k] = cos((double)n * t[k]);
    s[k] = sin((double)n * t[k]);
  }
}

/* a[i] = a_(n1 + i), i <= n2 - n1, the basis' cosine coefficients (rs_cyl_basis_coef_sin):
 * sin(n y) advanced by rotation like the offsets' cos/sin (restarted from the library's
 * every 256 modes: n1 is a restart), instead of a sin() a mode */
static void basis_coefs(rs_basis basis, double w, long n1, long n2, double *a)
{
  const double y = basis == RS_BASIS_HAT ? 0.5 * w : w, c1 = cos(y), s1 = sin(y);
  double c = 0, s = 0;
  for (long n = n1; n <= n2; ++n) {
    if ((n - n1) % 256 == 0) {
      c = cos((double)n * y);
      s = sin((double)n * y);
    }
    a[n - n1] = rs_cyl_basis_coef_sin(basis, w, n, s);
    double cn = c * c1 - s * s1;
    s = s * c1 + c * s1;
    c = cn;
  }
}

/* Adds modes n1..n2 to the partial sums of the requested kernels (cos: pu, pe; sin: qu,
 * qe). cos/sin(n t) advance by rotation, restarted from the library functions every 256
 * modes (error growth stays ~ 256 eps). */
static void add_modes(const rs_cylinder *cyl, rs_basis basis, double w, int accel,
                      const double e[NK][3], unsigned what, long n1, long n2, work *wk)
{
  const int K = wk->K;
  double *c = wk->c, *s = wk->s;
  double *apu = wk->acc[KPU], *ape = wk->acc[KPE], *aqu = wk->acc[KQU], *aqe = wk->acc[KQE];
  const int cpu = !!(what & RS_KERNEL_PU), cpe = !!(what & RS_KERNEL_PE);
  const int squ = !!(what & RS_KERNEL_QU), sqe = !!(what & RS_KERNEL_QE);
  double *acoef = wk->acoef;
  basis_coefs(basis, w, n1, n2, acoef);
  for (long n = n1; n <= n2; ++n) {
    if ((n - n1) % 256 == 0) reseed(K, wk->t, n, c, s);
    const double(*F)[2] = cyl->cache[n].F;
    double in = 1.0 / (double)n, an = acoef[n - n1];
    double mpu = F[0][0] * in, mpe = F[1][0] - F[0][0] * in;
    double mqu = -F[0][1] * in, mqe = F[0][1] * in - F[1][1];
    if (accel) {
      mpu -= e[KPU][0] + in * (e[KPU][1] + in * e[KPU][2]);
      mpe -= e[KPE][0] + in * (e[KPE][1] + in * e[KPE][2]);
      mqu -= e[KQU][0] + in * (e[KQU][1] + in * e[KQU][2]);
      mqe -= e[KQE][0] + in * (e[KQE][1] + in * e[KQE][2]);
    }
    if (cpu && cpe && !squ && !sqe) { /* the nip's pressure kernels */
      sweep2_rotate(K, 0, apu, mpu * an, ape, mpe * an, c, s, wk->ct, wk->st);
      continue;
    }
    if (cpu && cpe) sweep2(K, apu, mpu * an, ape, mpe * an, c);
    else if (cpu) sweep1(K, apu, mpu * an, c);
    else if (cpe) sweep1(K, ape, mpe * an, c);
    if (squ && sqe) sweep2(K, aqu, mqu * an, aqe, mqe * an, s);
    else if (squ) sweep1(K, aqu, mqu * an, s);
    else if (sqe) sweep1(K, aqe, mqe * an, s);
    rotate(K, c, s, wk->ct, wk->st);
  }
}

static rs_status kernel_check(const rs_cylinder *cyl, rs_basis basis, double dx, double shift,
                              int M, double *w)
{
  if (basis != RS_BASIS_HAT && basis != RS_BASIS_BOX)
    return RS_ERROR(RS_ERR_INPUT, "unknown basis %d", (int)basis);
  if (M < 2 || M > 1000000) return RS_ERROR(RS_ERR_INPUT, "M = %d out of range", M);
  if (!(dx > 0) || !isfinite(shift)) return RS_ERROR(RS_ERR_INPUT, "dx = %g, shift = %g", dx, shift);
  *w = basis == RS_BASIS_HAT ? dx / cyl->R : 0.5 * dx / cyl->R;
  if (*w > 0.25 * RS_PI)
    return RS_ERROR(RS_ERR_INPUT, "element too coarse: dx/R = %g (basis half-width %g rad > pi/4)",
                    dx / cyl->R, *w);
  return RS_OK;
}

/* Doubling: converged when the last doubling moved each requested kernel by less than
 * tol/4 of its largest value. */
static int series_converged(const kernel_sum *ks, unsigned what, double tol)
{
  for (int j = 0; j < NK; ++j) {
    if (!(what & kernel_bit[j])) continue;
    double mx = 0, dmax = 0;
    for (int i = 0; i < ks->nk; ++i) {
      double v = ks->closed[j][i] + ks->wk.acc[j][i];
      mx = fmax(mx, fabs(v));
      dmax = fmax(dmax, fabs(v - ks->prev[j][i]));
    }
    if (!(dmax <= 0.25 * tol * mx)) return 0;
  }
  return 1;
}

/* Sums the series: o->terms modes when given, else 64, 128, ... until converged. Modes are
 * added in chunks of whole 256-mode restarts (bit for bit one call), asking between them
 * whether to stop: 65536 terms at 1024 nodes take seconds. */
static rs_status series_sum(rs_cylinder *cyl, rs_basis basis, double w, const rs_series_opts *o,
                            const double e[NK][3], unsigned what, kernel_sum *ks, long *done_to)
{
  long N = o->terms > 0 ? o->terms : 64;
  *done_to = 0;
  for (;;) {
    rs_status st = rs_cyl_cache_reserve(cyl, N);
    if (st) return st;
    for (long n1 = *done_to + 1; n1 <= N; n1 += MODE_CHUNK) {
      if (rs_cancel_requested())
        return RS_ERROR(RS_ERR_INTERRUPTED, "interrupted while summing the kernel series");
      add_modes(cyl, basis, w, o->accelerate, e, what, n1,
                n1 + MODE_CHUNK - 1 < N ? n1 + MODE_CHUNK - 1 : N, &ks->wk);
    }
    *done_to = N;
    if (o->terms > 0) return RS_OK;
    if (ks->prevmem) {
      if (series_converged(ks, what, o->tol)) return RS_OK;
    } else {
      ks->prevmem = malloc((size_t)ks->K * NK * sizeof(double));
      if (!ks->prevmem) return RS_ERROR(RS_ERR_MEMORY, "kernel work space");
      for (int j = 0; j < NK; ++j) ks->prev[j] = ks->prevmem + (size_t)j * ks->K;
    }
    for (int j = 0; j < NK; ++j)
      for (int i = 0; i < ks->nk; ++i) ks->prev[j][i] = ks->closed[j][i] + ks->wk.acc[j][i];
    if (2 * N > o->max_terms)
      return RS_ERROR(RS_ERR_SOLVER, "kernel series not converged to %g with %ld terms "
                      "(max_terms %ld)", o->tol, N, o->max_terms);
    N *= 2;
  }
}

rs_status rs_cylinder_kernels(rs_cylinder *cyl, rs_basis basis, double dx, double shift, int M,
                              unsigned what, const rs_series_opts *opts, rs_kernels *out)
{
  if (!cyl || !out) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  double w = 0;
  rs_status st = kernel_check(cyl, basis, dx, shift, M, &w);
  if (st) return st;
  rs_series_opts o = {0, 1e-6, 1L << 22, 1};
  if (opts) o = *opts;
  if (o.tol <= 0) o.tol = 1e-6;
  if (o.max_terms <= 0) o.max_terms = 1L << 22;
  what &= RS_KERNEL_ALL;
  if (!what) what = RS_KERNEL_ALL;
  st = ensure_capacity(out, 2 * M - 1);
  if (st) return st;

  kernel_sum ks = {0};
  double e[NK][3];
  long done_to = 0;
  multiplier_expansion(cyl, e);
  st = rs_cyl_offsets_build(cyl, dx, shift, M, &ks);
  if (!st) st = rs_cyl_closed_parts(cyl, basis, w, o.accelerate, e, what, shift, M, 1, &ks);
  if (!st) st = series_sum(cyl, basis, w, &o, e, what, &ks, &done_to);
  if (!st) {
    rs_cyl_sum_scatter(cyl, &ks, what, out);
    out->M = M;
    out->basis = basis;
    out->dx = dx;
    out->shift = shift;
    out->terms = done_to;
  }
  rs_cyl_sum_free(&ks);
  return st;
}

/* Modes n1..n2 of the two shear kernels of the nip at once, on the same offsets: the box's
 * qu (partial sums in bx->wk.acc[KQU]) and the hat's qe (hx->wk.acc[KQE]). The arithmetic
 * of each is add_modes' (the same multipliers, sweeps and rotation), so each kernel is bit
 * for bit the one rs_cylinder_kernels gives; the offsets' cos/sin advance once for both. */
static void add_modes_shear(const rs_cylinder *cyl, double wb, double wh, int accel, const double e[NK][3],
                            long n1, long n2, work *bx, work *hx)
{
  const int K = bx->K;
  double *c = bx->c, *s = bx->s, *aqu = bx->acc[KQU], *aqe = hx->acc[KQE];
  basis_coefs(RS_BASIS_BOX, wb, n1, n2, bx->acoef);
  basis_coefs(RS_BASIS_HAT, wh, n1, n2, hx->acoef);
  for (long n = n1; n <= n2; ++n) {
    if ((n - n1) % 256 == 0) reseed(K, bx->t, n, c, s);
    const double(*F)[2] = cyl->cache[n].F;
    double in = 1.0 / (double)n;
    double ab = bx->acoef[n - n1], ah = hx->acoef[n - n1];
    double mqu = -F[0][1] * in, mqe = F[0][1] * in - F[1][1];
    if (accel) {
      mqu -= e[KQU][0] + in * (e[KQU][1] + in * e[KQU][2]);
      mqe -= e[KQE][0] + in * (e[KQE][1] + in * e[KQE][2]);
    }
    sweep2_rotate(K, 1, aqu, mqu * ab, aqe, mqe * ah, c, s, bx->ct, bx->st);
  }
}

rs_status rs_cylinder_kernels_shear(rs_cylinder *cyl, double dx, double shift, int M,
                                    const rs_series_opts *opts, rs_kernels *box_qu, rs_kernels *hat_qe)
{
  if (!cyl || !box_qu || !hat_qe || !opts) return RS_ERROR(RS_ERR_INPUT, "NULL argument");
  rs_status st;
  if (opts->terms <= 0) { /* the automatic series decides per kernel: one at a time */
    st = rs_cylinder_kernels(cyl, RS_BASIS_BOX, dx, shift, M, RS_KERNEL_QU, opts, box_qu);
    return st ? st : rs_cylinder_kernels(cyl, RS_BASIS_HAT, dx, shift, M, RS_KERNEL_QE, opts, hat_qe);
  }
  double wb = 0, wh = 0;
  st = kernel_check(cyl, RS_BASIS_BOX, dx, shift, M, &wb);
  if (!st) st = kernel_check(cyl, RS_BASIS_HAT, dx, shift, M, &wh);
  if (!st) st = ensure_capacity(box_qu, 2 * M - 1);
  if (!st) st = ensure_capacity(hat_qe, 2 * M - 1);
  if (st) return st;
  kernel_sum kb = {0}, kh = {0};
  double e[NK][3];
  const long N = opts->terms;
  multiplier_expansion(cyl, e);
  st = rs_cyl_offsets_build(cyl, dx, shift, M, &kb);
  if (!st) st = rs_cyl_offsets_share(&kb, &kh); /* the same offsets: built once */
  if (!st) st = rs_cyl_closed_parts(cyl, RS_BASIS_BOX, wb, opts->accelerate, e, RS_KERNEL_QU, shift, M, 1, &kb);
  if (!st) st = rs_cyl_closed_parts(cyl, RS_BASIS_HAT, wh, opts->accelerate, e, RS_KERNEL_QE, shift, M, 0, &kh);
  if (!st) st = rs_cyl_cache_reserve(cyl, N);
  for (long n1 = 1; !st && n1 <= N; n1 += MODE_CHUNK) {
    if (rs_cancel_requested())
      st = RS_ERROR(RS_ERR_INTERRUPTED, "interrupted while summing the kernel series");
    else
      add_modes_shear(cyl, wb, wh, opts->accelerate, e, n1, n1 + MODE_CHUNK - 1 < N ? n1 + MODE_CHUNK - 1 : N,
                      &kb.wk, &kh.wk);
  }
  if (!st) {
    rs_cyl_sum_scatter(cyl, &kb, RS_KERNEL_QU, box_qu);
    rs_cyl_sum_scatter(cyl, &kh, RS_KERNEL_QE, hat_qe);
    rs_kernels *out[2] = {box_qu, hat_qe};
    for (int j = 0; j < 2; ++j) {
      out[j]->M = M;
      out[j]->basis = j ? RS_BASIS_HAT : RS_BASIS_BOX;
      out[j]->dx = dx;
      out[j]->shift = shift;
      out[j]->terms = N;
    }
  }
  rs_cyl_sum_free(&kb);
  rs_cyl_sum_free(&kh);
  return st;
}

/* Half-plane scaling. On the orthotropic half-plane a basis scaled by lam = dx / from->dx
 * (its offsets d dx + shift too, shift / dx fixed) gives, from w = -(H11/pi) int p ln|x - s|
 * and u, eps from sign and 1/x kernels:
 *   pu(lam dx) = lam pu(dx) - (H11/pi) lam dx ln lam,  qu(lam dx) = lam qu(dx),
 *   pe, qe unchanged (strains: functions of the offset / dx only).
 * On the cylinder the rest is curvature, O(ln lam dx M / R) of each kernel (docs/cylinder.md,
 * "Rescaled kernels"). All four arrays of `from` are mapped (unrequested ones included). */
rs_status rs_kernels_rescale(const rs_kernels *from, double dx, double H11, rs_kernels *to)
{
  if (!from || !to || from == to || !(dx > 0) || !(from->dx > 0) || from->M < 2)
    return RS_ERROR(RS_ERR_INPUT, "kernel rescaling: bad arguments");
  const int n = 2 * from->M - 1;
  rs_status st = ensure_capacity(to, n);
  if (st) return st;
  const double lam = dx / from->dx, c = H11 / RS_PI * dx * log(lam);
  for (int i = 0; i < n; ++i) {
    to->pu[i] = lam * from->pu[i] - c;
    to->qu[i] = lam * from->qu[i];
  }
  memcpy(to->pe, from->pe, (size_t)n * sizeof(double));
  memcpy(to->qe, from->qe, (size_t)n * sizeof(double));
  to->M = from->M;
  to->basis = from->basis;
  to->dx = dx;
  to->shift = from->shift * lam;
  to->terms = from->terms;
  return RS_OK;
}
