/* The wound radius recorded while the reel winds (src/reel/gauge.c): the roll's deformed
 * outer radius at states spaced geometrically in the layers (a relative step
 * RS_GAUGE_STEP), interpolated linearly between them per layer. */
#ifndef REELSIM_REEL_GAUGE_H
#define REELSIM_REEL_GAUGE_H

#include "reelsim/problem.h"
#include "reelsim/status.h"

/* the relative step between the states recorded (the shortfall r_c + n t - R(n) is smooth
 * in n: interpolated within 1e-5 of the compression, test_gauge.wound_radius_history) */
#define RS_GAUGE_STEP 0.02

typedef struct rs_reel_gauge {
  int n, cap;
  int *layers;        /* [cap] layers wound at each state recorded (0 first) */
  double *shortfall;  /* [cap] m, r_c + n t - deformed outer radius */
  double *radius;     /* [N] scratch: the deformed radii of a state */
} rs_reel_gauge;

rs_status rs_reel_gauge_init(rs_reel_gauge *g, int N);
void rs_reel_gauge_free(rs_reel_gauge *g);
/* 1 when a state is due at n layers (rs_reel_gauge_record without force records it). */
int rs_reel_gauge_due(const rs_reel_gauge *g, int n);
/* Records the roll of n layers (its core pressure, radial stresses, entrained films or
 * NULL) when `every` layers have gone on since the last state, or when force is set. */
rs_status rs_reel_gauge_record(rs_reel_gauge *g, const rs_problem *pb, int n, double core_pressure,
                               const double *sigma_r, const double *film, int force);
/* Drops the states beyond `layers` (the adaptive nip winds a stretch again). */
void rs_reel_gauge_rewind(rs_reel_gauge *g, int layers);
/* wound[0..n-1]: the deformed outer radius of the roll as each layer went on. */
void rs_reel_gauge_finish(const rs_reel_gauge *g, const rs_problem *pb, int n, double *wound);

/* The largest pressure of core_pressure and -sigma_r[0..n-1] as fmax() over them in that
 * order gives it (the table rs_reel_deformed_radius makes reaches it) */
double rs_reel_deformed_pmax(double core_pressure, const double *sigma_r, int n);

/* u_c = -r_c P_c / E_c (m), the core face's displacement under the core pressure P_c (Pa,
 * compression positive); 0 for a rigid core or P_c <= 0 (rs_reel_deformed_radius's) */
double rs_reel_core_displacement(const rs_problem *pb, double core_pressure);

/* eps(P) of the stack law tabulated on [0, Pmax] (the table rs_reel_deformed_radius sums
 * with; beyond Pmax extrapolated by its last cubic), for a caller that sums a stretch of
 * the stack itself (lanes_radius.c). NULL when out of memory. */
typedef struct rs_reel_strain rs_reel_strain;
rs_reel_strain *rs_reel_strain_new(const rs_radial_law *law, double Pmax);
double rs_reel_strain_eval(const rs_reel_strain *s, double P);
double rs_reel_strain_max(const rs_reel_strain *s);
void rs_reel_strain_free(rs_reel_strain **s);

#endif
