/* The MPI module's side (sweep/mpi_module.h): reelsim-mpi.so is sweep/mpi.c and
 * sweep/mpi_agree.c compiled with MPI, this file, and Open MPI. The program's functions
 * they call are reached through the table the program hands over; the module exports only
 * rs_sweep_mpi_module (sweep/mpi_module.map). */
#include <stddef.h>

#include "reelsim/clock.h"
#include "sweep/mpi_module.h"

static const sweep_mpi_host *host;

double rs_clock_wall(void) { return host->clock_wall(); }
rs_status sweep_result_alloc(sweep_result *r, int n, int profiles)
{
  return host->result_alloc(r, n, profiles);
}
void sweep_run_one(const sweep_spec *spec, int i, double fig[SWEEP_N_FIGURES],
                   rs_output_profile *prof, char *why, size_t why_size)
{
  host->run_one(spec, i, fig, prof, why, why_size);
}
void sweep_say_failed(int i, const char *why) { host->say_failed(i, why); }

static const sweep_mpi_ops ops = {
    SWEEP_MPI_ABI,       sweep_mpi_begin,      sweep_mpi_end,    sweep_mpi_rank,
    sweep_mpi_size,      sweep_mpi_agree,      sweep_mpi_poll,   sweep_mpi_notify,
    sweep_mpi_peer_stop, sweep_mpi_settle,     sweep_mpi_agree_all, sweep_mpi_wind};

__attribute__((visibility("default"))) const sweep_mpi_ops *
rs_sweep_mpi_module(const sweep_mpi_host *h)
{
  if (!h || h->abi != SWEEP_MPI_ABI) return NULL;
  host = h;
  return &ops;
}
