/* MPI as a module (sweep/mpi_load.c, sweep/mpi_module.c): a program built with MPI does not
 * load Open MPI's seven shared libraries at every start (3 ms of a 5 ms start-up,
 * docs/performance.md), only when mpirun started it. Then sweep/mpi_load.c opens
 * reelsim-mpi.so from a fixed place beside the program (its folder, then the installed
 * <libdir>/reelsim), never a path from input or the environment, and asks its one exported
 * function for the table of sweep/mpi.c's and sweep/mpi_agree.c's functions, handing it the
 * program's functions those call. */
#ifndef RS_SWEEP_MPI_MODULE_H
#define RS_SWEEP_MPI_MODULE_H

#include <stdint.h>

#include "sweep/sweep.h"

/* Bumped when either table changes: a module of another build is refused. */
#define SWEEP_MPI_ABI 1
#define SWEEP_MPI_ENTRY "rs_sweep_mpi_module"
#define SWEEP_MPI_FILE "reelsim-mpi.so"

/* What the module calls in the program. */
typedef struct sweep_mpi_host {
  int abi;
  double (*clock_wall)(void);
  rs_status (*result_alloc)(sweep_result *r, int n, int profiles);
  void (*run_one)(const sweep_spec *spec, int i, double fig[SWEEP_N_FIGURES],
                  rs_output_profile *prof, char *why, size_t why_size);
  void (*say_failed)(int i, const char *why);
} sweep_mpi_host;

/* sweep.h's MPI functions, in the module. */
typedef struct sweep_mpi_ops {
  int abi;
  void (*begin)(void);
  void (*end)(void);
  int (*rank)(void);
  int (*size)(void);
  int (*agree)(int code);
  int (*poll)(int local);
  void (*notify)(int value);
  int (*peer_stop)(int *from);
  void (*settle)(void);
  sweep_agreement (*agree_all)(int code, uint64_t digest, const char *text,
                               int (*caught)(void));
  rs_status (*wind)(const sweep_spec *spec, sweep_result *out);
} sweep_mpi_ops;

/* The module's one exported function: its table, or NULL when host->abi differs. */
typedef const sweep_mpi_ops *(*sweep_mpi_entry_fn)(const sweep_mpi_host *host);

const sweep_mpi_ops *rs_sweep_mpi_module(const sweep_mpi_host *host);

/* Started by mpirun (Open MPI, or a PMI/PMIx launcher such as srun)? Its environment says. */
int sweep_mpi_launched(void);

#endif
