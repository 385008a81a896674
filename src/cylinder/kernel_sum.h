/* The summation state of the cylinder's kernel series (kernels.c): the offsets summed,
 * their work arrays and the closed-form parts of the accelerated sums (kernel_sum.c).
 * Private to the cylinder module. */
#ifndef RS_CYLINDER_KERNEL_SUM_H
#define RS_CYLINDER_KERNEL_SUM_H

#include "cylinder/internal.h"

enum { KPU, KPE, KQU, KQE, NK };
static const unsigned kernel_bit[NK] = {RS_KERNEL_PU, RS_KERNEL_PE, RS_KERNEL_QU, RS_KERNEL_QE};

typedef struct work {
  int K;                   /* offsets summed (the others follow by parity), padded to a
                              multiple of 4 so that -O2 vectorises the sweeps */
  const double *t;
  double *c, *s, *ct, *st; /* cos, sin of n t and of t */
  double *acc[NK];         /* partial sums */
  double *acoef;           /* the basis' coefficients of the modes being added (MODE_CHUNK) */
} work;

enum { MODE_CHUNK = 16 * 256 }; /* modes added per call of add_modes */

/* The summation's state: the offsets summed (t, nk of them; src maps every offset k of the
 * 2M - 1 to its summed twin, src[k] >= 0, or to its mirror, -(1 + mirror); h2 their
 * positions in half cells when they lie on that grid, else NULL), the closed-form parts,
 * the partial sums (wk.acc) and the previous doubling's totals (prev). A sum may share the
 * offsets of another (shared: its t, src and h2 are the other's). */
typedef struct kernel_sum {
  int K, nk, shared;
  double *mem, *prevmem, *t, *closed[NK], *prev[NK];
  int *src;
  long *h2;
  work wk;
} kernel_sum;

void rs_cyl_sum_free(kernel_sum *ks);

/* The offsets of a sum of 2M - 1 kernel values at (k - (M - 1)) dx + shift (kernel_sum.c). */
rs_status rs_cyl_offsets_build(const rs_cylinder *cyl, double dx, double shift, int M,
                               kernel_sum *ks);

/* A second sum on the offsets of `from` (its own partial sums and closed parts). */
rs_status rs_cyl_offsets_share(const kernel_sum *from, kernel_sum *ks);

/* cos t, sin t of each summed offset (trig) and the closed-form part of each kernel. */
rs_status rs_cyl_closed_parts(rs_cylinder *cyl, rs_basis basis, double w, int accelerate,
                              const double e[NK][3], unsigned what, double shift, int M,
                              int trig, kernel_sum *ks);

/* The kernels at every offset from the sums (scaled; the mirrored ones by parity). */
void rs_cyl_sum_scatter(const rs_cylinder *cyl, const kernel_sum *ks, unsigned what,
                        rs_kernels *out);

#endif
