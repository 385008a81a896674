/* The nip's LU solves (src/nip/contact_lu.c: the GMRES preconditioner, and the transposed
 * solve of the condition estimate) against LAPACK's dgetrs on the same factors: sizes with
 * every remainder modulo the four-column blocks, and the contact system's size (M = 64
 * nodes: n = 192). */
#include "check.h"
#include "nip/contact_internal.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a reproducible matrix that needs pivoting: small diagonal, entries of mixed sign */
static double entry(unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return ((double)((*s >> 8) & 0xffff) / 65536.0) - 0.5;
}

static void one_size(int n, char trans, double *worst)
{
  double *A = malloc((size_t)n * n * sizeof *A), *x = malloc((size_t)n * sizeof *x),
         *y = malloc((size_t)n * sizeof *y);
  lapack_int *ipiv = malloc((size_t)n * sizeof *ipiv);
  unsigned s = 12345u + (unsigned)n;
  for (int c = 0; c < n; ++c)
    for (int r = 0; r < n; ++r) A[(size_t)c * n + r] = entry(&s) + (r == c ? 1e-3 : 0.0);
  for (int r = 0; r < n; ++r) x[r] = y[r] = entry(&s);
  CHECK(LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, A, n, ipiv) == 0);
  int swaps = 0;
  for (int i = 0; i < n; ++i) swaps += ipiv[i] != i + 1;
  CHECK(n < 4 || swaps > 0); /* the interchanges are exercised */
  CHECK(LAPACKE_dgetrs(LAPACK_COL_MAJOR, trans, n, 1, A, n, ipiv, y, n) == 0);
  if (trans == 'N')
    rs_nipc_lu_solve(n, A, ipiv, x);
  else
    rs_nipc_lu_solve_t(n, A, ipiv, x);
  double mx = 0, d = 0;
  for (int r = 0; r < n; ++r) {
    mx = fmax(mx, fabs(y[r]));
    d = fmax(d, fabs(x[r] - y[r]));
  }
  *worst = fmax(*worst, d / mx);
  free(A);
  free(x);
  free(y);
  free(ipiv);
}

static void against(char trans)
{
  double worst = 0;
  const int sizes[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 13, 64, 191, 192, 193, 194};
  for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; ++k) one_size(sizes[k], trans, &worst);
  CHECK_LOG("largest |x - x_dgetrs| / max |x_dgetrs|", worst);
  CHECK_LT(worst, 1e-11); /* both are backward stable; the matrices' condition ~1e4 - 1e6 */
}

static void against_dgetrs(void)
{
  against('N');
}

static void transposed_against_dgetrs(void)
{
  against('T');
}

static const check_case cases[] = {{"against_dgetrs", against_dgetrs},
                                   {"transposed_against_dgetrs", transposed_against_dgetrs}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
