/* Shared by the defect rules' files (src/reel/defects.c, starring.c). */
#ifndef RS_REEL_DEFECTS_INTERNAL_H
#define RS_REEL_DEFECTS_INTERNAL_H

#include "reelsim/defects.h"

/* One compressive zone weighed as a ring packet (starring.c). */
typedef struct rs_starring_zone {
  double r_a, r_b;  /* m, inner radius of its first layer, outer radius of its last */
  double N, N_cr;   /* N/m, hoop force and critical force */
  double k, D;      /* Pa/m foundation, N m bending stiffness */
  int mode, bonded;
} rs_starring_zone;

/* What drives the interfaces' torque (rs_defect_interface_torque): the drive's core share
 * s, the tension's torque T R, the inertia torque I |alpha| and the roll's outer radius. */
typedef struct rs_slip_load {
  double s, TR, M_acc, alpha, R;
} rs_slip_load;
void rs_defect_slip_load(const rs_reel_result *res, const rs_defect_limits *lim, rs_slip_load *L);

/* Runs of flagged layers 0..n-1 into *ranges (malloc'd, NULL when none); the number of
 * flagged layers, or -1 when out of memory. */
int rs_defect_flag_ranges(const unsigned char *flag, int n, const double *radius,
                          rs_defect_range **ranges, int *n_ranges);

/* The starring rule (a)-(c) into rep->starring; flag is scratch of n_layers. */
rs_status rs_defects_starring(const rs_reel_result *res, const rs_defect_limits *lim,
                              unsigned char *flag, rs_defect_report *rep);

#endif
