/* reelsim sweep's runs: every run of a plan checked, then wound over threads (one
 * process) or MPI ranks (mpirun), each run's figures and, if asked, its final profiles
 * collected in run order on the process that writes the file (docs/cli.md, docs/scale.md). */
#ifndef RS_SWEEP_SWEEP_H
#define RS_SWEEP_SWEEP_H

#include "reelsim/output.h"
#include "reelsim/reel.h"
#include "reelsim/status.h"
#include "sweep/figures.h"
#include "sweep/plan.h"

typedef struct sweep_spec {
  const char *scene_path;
  int n_sets;                   /* --set overrides, before each run's KEY=VALUE */
  const char *const *sets;
  const sweep_plan *plan;
  int threads;                  /* one process: threads (<= 0: one per core) */
  int profiles;                 /* keep each run's final profiles */
  rs_reel_progress_fn progress; /* polled during every run; nonzero stops the sweep */
} sweep_spec;

typedef struct sweep_result {
  int n_runs;
  double *figures;             /* SWEEP_N_FIGURES x n_runs, row-major */
  rs_output_profile *profiles; /* n_runs (with spec->profiles), else NULL; owned */
  int failed;                  /* runs whose status is not 0 */
  int threads;                 /* threads used (one process), or 1 per rank */
  int ranks;                   /* MPI ranks that wound (0: no MPI) */
  int stopped;                 /* the progress callback stopped the sweep */
} sweep_result;

/* Loads every run's scene (the --set overrides, then the run's values) and drops it: bad
 * input anywhere is found before anything is wound. RS_ERR_INPUT "run I of R (KEY=VALUE
 * ...): <the scene's message>". */
rs_status sweep_check_runs(const sweep_spec *spec);

/* Winds every run. In one process: batches of runs over spec->threads threads
 * (rs_reel_wind_many). Under mpirun with more than one rank: rank 0 hands out run indices
 * one at a time to the ranks that ask, the others wind them and send back the figures
 * (and profiles), so *out is filled on rank 0 only (n_runs 0 elsewhere). A failed run
 * is a status in its figures, not a failure of the sweep. Errors: RS_ERR_MEMORY,
 * RS_ERR_INTERNAL. */
rs_status sweep_wind(const sweep_spec *spec, sweep_result *out);
void sweep_result_free(sweep_result *r);

/* One run: load the scene at run i's values, wind it, its figures into fig and (when
 * prof is not NULL) its final profiles into *prof (malloc'd arrays: free prof->radius;
 * the three arrays share one block). wall_seconds is the load and the winding. */
void sweep_run_one(const sweep_spec *spec, int i, double fig[SWEEP_N_FIGURES],
                   rs_output_profile *prof);

/* MPI (sweep/mpi.c; without MPI these say: one process, rank 0). sweep_mpi_begin starts
 * MPI only when the program was launched by mpirun (its environment says so); a binary
 * built with MPI and run on its own is one process and never calls MPI_Init. */
void sweep_mpi_begin(void);
void sweep_mpi_end(void);
int sweep_mpi_rank(void);
int sweep_mpi_size(void);
/* Every rank gets rank 0's `code` (so all go on or all stop together). */
int sweep_mpi_agree(int code);
/* The MPI schedule of sweep_wind (size > 1). */
rs_status sweep_mpi_wind(const sweep_spec *spec, sweep_result *out);
/* The buffers of a result for n runs (figures NaN). */
rs_status sweep_result_alloc(sweep_result *r, int n, int profiles);

#endif
