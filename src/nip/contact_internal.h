/* Private parts of the nip contact solver (nip/nip_contact.h). */
#ifndef RS_NIP_CONTACT_INTERNAL_H
#define RS_NIP_CONTACT_INTERNAL_H

#include <lapacke.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_nvector.h>

#include "nip/contact_woodbury.h"
#include "nip/nip_contact.h"

/* per body: [KP] hat pressure -> w and eps at the nodes (pu, pe, shift 0);
 * [KQU] box shear -> w at the nodes (shift -dx/2); [KQE] box shear -> eps averaged over
 * the dual cell [x_i - dx/2, x_i + dx/2] = eps of a hat centred at the element midpoint,
 * evaluated at the node (HAT, shift -dx/2). */
enum { KP, KQU, KQE, NKER };

/* The unknowns' columns and the stick/slip rows of the system (contact_solve.c), for M
 * nodes in scope: pressure p_j (j = 1..M-2), traction q_k,e (k 0 roll, 1 drum; element e),
 * stick/slip row of contact k at element e. */
#define COL_P(j) ((j) - 1)
#define COL_Q(k, e) ((M - 2) + (k) * (M - 1) + (e))
#define ROW_STICK(k, e) (M + (k) * (M - 1) + (e))

/* contact_linear.c: the kept factorization and the Krylov solver refining from it */
typedef struct rs_nipc_lin {
  double *LU;             /* n x n, equilibrated and factored (dgetrf) */
  lapack_int *ipiv;
  double *rs, *cs;        /* total row / column scales: A_eq = diag(rs) A diag(cs) */
  signed char *state;     /* the stick/slip rows it was made with */
  double anorm, rcond;    /* 1-norm of A_eq; dgecon estimate (< 0: not yet) */
  double a;               /* half-width it was made at */
  int valid;
  int solved_state_differs; /* the last solve had other stick/slip rows than the LU */
  int fresh;              /* the last solve factored the matrix it solved */
  int single;             /* the kept LU was made in single precision (sgetrf, a preconditioner
                             only: every solve with it is refined by GMRES) */
  int double_only;        /* a refinement from a single-precision LU failed: double from now on */
  int want_double;        /* the caller (the LCP) needs the factorization a solve makes in double */
  float *LUs;             /* n x n: the single-precision factorization's work space */
  double *work;           /* vectors */
  lapack_int *iwork;
  /* SUNDIALS' SPGMR, right-preconditioned with the kept LU */
  SUNContext sunctx;
  SUNLinearSolver spgmr;
  N_Vector nx, nb;        /* solution and right-hand side (own data) */
  double *gm_rs;          /* the row scales of the system SPGMR is on */
  /* the rank-k correction of the kept LU for the rows whose stick/slip kind changed */
  double *B0;             /* n x n: the equilibrated matrix the LU was made of */
  double *colsum;         /* n: its column sums of |entries| */
  int *krows;             /* n: the changed rows */
  rs_nipc_wb wb;
} rs_nipc_lin;

struct rs_nip_contact {
  rs_nip_contact_config cfg;
  int M, n;                  /* nodes, unknowns (3M) */
  rs_cylinder *body[2];      /* 0 = roll (upper), 1 = drum (lower) */
  rs_ortho roll_c;
  double R[2], R0[2];
  double roll_mean_strain;   /* mean circumferential strain of the roll surface per unit nip
                                load, -C0_11 / (2 pi R^2) (m/N), C0 the n = 0 compliance */
  int have_roll;
  long roll_version;         /* bumped when the roll changes */
  /* kernels of the current half-width */
  double k_a;                /* a of the kernels, 0 = none */
  long k_roll_version;
  rs_kernels ker[2][NKER];
  /* a much stiffer body's kernels as last summed, at half-width ref_a[b] (0: none), of roll
   * version ref_version for the roll: nearby half-widths rescale them (contact.c) */
  rs_kernels ref[2][NKER];
  double ref_a[2];
  long ref_version;
  long stats_rescaled;       /* kernel sets rescaled instead of summed (benchmarks) */
  int no_rescale;            /* tests: sum every kernel set */
  /* active set: per contact (0 upper, 1 lower) and element: 0 stick, +1 / -1 slip with
   * the sign of the friction traction on the cylinder */
  signed char *state;        /* 2 (M-1) */
  int have_warm;             /* state holds a converged set */
  double warm_slope;         /* d ln P / d ln a of the last load search */
  double hist_slope[2], hist_slope_Rs[2]; /* the last two searches' slopes and their R*
                                             (the first step's slope, contact_load.c) */
  int hist_slope_n;
  /* the last converged load searches, newest first: R*, P, E*, a (the half-width
   * predictor, contact_load.c) */
  int hist_n;
  double hist_Rs[4], hist_P[4], hist_Es[4], hist_a[4];
  double last_a;             /* the half-width returned last (its kernels are cached) */
  double H11[2];             /* half-plane compliance H11 of roll and drum: E* = 2/(H1 + H2) */
  /* linear algebra: the assembled system (column-major, unscaled) and its solver */
  double *A, *rhs, *z;
  double *keep;              /* the assembly's stick rows: 1 stick, 0 slip (2 (M-1)) */
  rs_nipc_lin lin;
  int defer_cond;            /* the load search: the condition number of its last state only */
  int stiff_body_terms;      /* the default series: a much stiffer body takes fewer terms
                                (contact.c, body_terms) */
  long stats_lu, stats_gmres_it; /* factorizations and GMRES iterations (benchmarks) */
  long stats_lu_single;          /* of which in single precision */
  long stats_lcp_pivots;         /* Lemke pivots (the LCP fallback) */
  signed char *visited;      /* max_iterations states of 2(M-1) */
  double *eps_sheet, *eps_body[2], *pbar; /* M-1 each: at the upstream node of element e
                                             (pbar: element mean pressure) */
  /* scene glue (create_from_spec) */
  int from_spec;
  rs_material mat;
  rs_nip_spec spec;
};

/* contact.c: the eight kernel arrays for half-width a (cached). */
rs_status rs_nipc_kernels(rs_nip_contact *nc, double a);

/* contact_solve.c: the stick/slip iteration at a fixed half-width; fills out. */
rs_status rs_nipc_solve_fixed(rs_nip_contact *nc, double a, double Ti, rs_nip_solution *out);

/* contact_assemble.c: physical scales of the unknowns (col) and rows (row) at half-width a. */
void rs_nipc_scales(const rs_nip_contact *nc, double a, double *col, double *row);

/* contact_linear.c: see there. */
rs_status rs_nipc_lin_alloc(rs_nip_contact *nc);
void rs_nipc_lin_free(rs_nip_contact *nc);
rs_status rs_nipc_lin_solve(rs_nip_contact *nc, double a);
rs_status rs_nipc_lin_cond(rs_nip_contact *nc, double a, double *cond);
/* a new factorization of the current matrix in double precision (dgetrf): the LCP's
 * responses and the condition estimate use it as is */
rs_status rs_nipc_lin_refactor(rs_nip_contact *nc, double a);

/* contact_lu.c: x <- A^-1 x with dgetrf's factors of the n x n column-major A (LU, ipiv),
 * as dgetrs does for one right-hand side, the triangles swept four columns at a time. */
void rs_nipc_lu_solve(int n, const double *LU, const lapack_int *ipiv, double *x);
/* y(0..m-1) -= a0 x0 + a1 x1 + a2 x2 + a3 x3, and d[m] = sum_i c_m[i] x[i] for four
 * columns: the vectorised four-column sweeps of the solves (contact_lu.c) */
void rs_nipc_sub4(int m, double *restrict y, double x0, double x1, double x2, double x3,
                  const double *restrict a0, const double *restrict a1, const double *restrict a2,
                  const double *restrict a3);
void rs_nipc_dot4(int len, const double *restrict x, const double *restrict c0, const double *restrict c1,
                  const double *restrict c2, const double *restrict c3, double d[4]);
/* x <- A^-T x with the same factors (dgetrs 'T' for one right-hand side) */
void rs_nipc_lu_solve_t(int n, const double *LU, const lapack_int *ipiv, double *x);

/* contact_assemble.c: assembles A z = rhs for the active set in nc->state. */
void rs_nipc_assemble(rs_nip_contact *nc, double a, double Ti);

/* contact_lcp.c: the stick/slip LCP at half-width a by Lemke's method; the active set of
 * its solution in state_out (2 (M-1)), or RS_ERR_SOLVER (ray or pivot cap). */
rs_status rs_nipc_lcp(rs_nip_contact *nc, double a, double Ti, signed char *state_out, int *pivots);

/* contact_lemke.c: Lemke's method on the LCP w = c + Mt u of contact_lcp.c given by its
 * starting tableau: the right-hand side c (m = 2 S) and the stored s+ columns U (m x S,
 * column-major). The revised (product) form for the first revised_max pivots, then the
 * tableau; the same pivots and numbers either way. Returns 1 at a solution (its active set
 * in state_out, S; the basic variables' values in x_out, m, when not NULL), 0 on a
 * secondary ray or past the pivot cap (*pivots > cap), -1 out of memory. */
int rs_nipc_lemke(int m, int S, const double *U, const double *c, int revised_max, int cap,
                  signed char *state_out, double *x_out, int *pivots);
/* the revised form while it is the cheaper: pivot k costs ~k m against the tableau's
 * ~m (m + S), and the tableau formed from it ~(m + S) k m */
#define RS_NIPC_LEMKE_REVISED_MAX(m) (m)

/* contact_solve.c: allocates the solution arrays for M nodes. */
rs_status rs_nipc_solution_reserve(rs_nip_solution *s, int M);

/* 1/R* = 1/R1 + 1/R2 */
static inline double rs_nipc_rstar(const rs_nip_contact *nc)
{
  return 1.0 / (1.0 / nc->R[0] + 1.0 / nc->R[1]);
}

/* M1/R1 = share * Ti (eq. (20)): share of the incoming tension the roll's drive carries. */
static inline double rs_nipc_share(const rs_nip_contact *nc)
{
  switch (nc->cfg.winder) {
  case RS_WINDER_CENTER: return 1.0;
  case RS_WINDER_SURFACE: return 0.0;
  case RS_WINDER_CENTER_SURFACE: return nc->cfg.torque_share;
  }
  return 1.0;
}

#endif
