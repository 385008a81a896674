/* The roll of the engine benchmarks: cases/newsprint-rider.yaml's physics (Pfeiffer
 * newsprint, 70 um on a 76.2 mm core of E_c = 1 GPa), n layers at CVODE tolerance rtol.
 * Its wound-on tension is BENCH_NEWSPRINT_T0 (350 N/m + 0.19 x 1750 N/m). */
#ifndef REELSIM_BENCH_NEWSPRINT_H
#define REELSIM_BENCH_NEWSPRINT_H

#include "roll/roll.h"

#define BENCH_NEWSPRINT_T0 (350.0 + 0.19 * 1750.0)

static inline rs_roll_params bench_newsprint_params(int n, double rtol)
{
  rs_roll_params p = {0};
  p.core_radius = 0.0762;
  p.caliper = 70e-6;
  p.E_theta = 3.5e9;
  p.core_stiffness = 1e9;
  p.radial.law = RS_RADIAL_PFEIFFER;
  p.radial.K1 = 5e3;
  p.radial.K2 = 60;
  p.max_layers = n;
  p.rtol = rtol;
  return p;
}

#endif
