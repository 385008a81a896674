/* The storage result as the library fills it (private: applications read it through the
 * typed accessors of reelsim/storage.h, src/storage/access.c). The library's own files
 * that fill or read it (storage, output) include this header; so may the tests. A new
 * field goes here and gets its accessor in storage.h. */
#ifndef RS_STORAGE_RESULT_H
#define RS_STORAGE_RESULT_H

#include "reelsim/storage.h"
#include "storage/storage_result.h"

/* Invariant: every array holds n_stages (S) values, or S x N row-major (row s = stage s)
 * for the stresses; defects[s] is stage s's report (NULL when it was not assessed). */
struct rs_storage_result {
  int n_stages;              /* S = storage stages + 1: stage 0 is the wound roll */
  int n_layers;              /* N */
  double *hours;             /* S: h of storage at the end of each stage, cumulative (0 first) */
  double *temperature;       /* S: C */
  double *humidity;          /* S: % RH */
  double *core_pressure;     /* S: Pa, compression positive */
  double *sigma_r;           /* S x N, row-major: Pa at each layer's outer radius */
  double *sigma_theta;       /* S x N: Pa, each layer's mean hoop stress */
  rs_defect_report **defects;/* S: the defect rules after each stage */
  long elastic_solves;       /* tridiagonal solves of the temperature/humidity changes */
  int max_substeps;          /* the most sub-steps one change needed */
  double wall_seconds;
};

#endif
