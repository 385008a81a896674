/* Waiting on an MPI request without spinning (sweep/mpi.c), for the files of the sweep that
 * call MPI themselves. Only with MPI. */
#ifndef RS_SWEEP_MPI_WAIT_H
#define RS_SWEEP_MPI_WAIT_H
#ifdef RS_HAVE_MPI
#include <mpi.h>

#include "reelsim/reel.h"

/* Tests *req every 0.2 ms, asking poll(user, 0, 0) (if not NULL) at every look, until it
 * completes; its status into *status (if not NULL). */
void sweep_mpi_wait(MPI_Request *req, MPI_Status *status, rs_reel_progress_fn poll, void *user);

#endif
#endif
