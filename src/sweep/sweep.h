/* reelsim sweep's runs: every run of a plan checked, then wound over threads (one
 * process) or MPI ranks (mpirun), each run's figures and, if asked, its final profiles
 * collected in run order on the process that writes the file (docs/cli.md, docs/scale.md). */
#ifndef RS_SWEEP_SWEEP_H
#define RS_SWEEP_SWEEP_H

#include <stddef.h>
#include <stdint.h>

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
 * ...): <the scene's message>"; RS_ERR_INTERRUPTED when spec->progress(NULL, 0, 0), asked
 * before each run, says stop. *digest (if not NULL): FNV-1a (64 bits) of every run's
 * resolved scene text in run order, without comment lines and `source:` lines (what MPI
 * ranks compare: sweep_mpi_agree_all). */
rs_status sweep_check_runs(const sweep_spec *spec, uint64_t *digest);

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
 * the three arrays share one block), and why it failed into why[why_size] ("" when it did
 * not; why may be NULL). wall_seconds is the load and the winding. */
void sweep_run_one(const sweep_spec *spec, int i, double fig[SWEEP_N_FIGURES],
                   rs_output_profile *prof, char *why, size_t why_size);
/* "reelsim: sweep: run I failed: WHY" on stderr (i from 0). */
void sweep_say_failed(int i, const char *why);

/* The two ways sweep_wind goes (sweep/wind.c picks): threads in one process (run.c) and
 * MPI ranks (mpi.c, below). */
rs_status sweep_wind_threads(const sweep_spec *spec, sweep_result *out);

/* MPI (sweep/mpi.c; without MPI these say: one process, rank 0). sweep_mpi_begin starts
 * MPI only when the program was launched by mpirun (its environment says so); a binary
 * built with MPI and run on its own is one process and never calls MPI_Init. */
void sweep_mpi_begin(void);
void sweep_mpi_end(void);
int sweep_mpi_rank(void);
int sweep_mpi_size(void);
/* Every rank gets rank 0's `code` (so all go on or all stop together); the others wait
 * for it without spinning. */
int sweep_mpi_agree(int code);

/* Stop notices between ranks (sweep/mpi.c). A rank that catches a signal, or fails while
 * the others still check, tells every other rank once (sweep_mpi_notify: value = the
 * signal's number, or minus the exit status of the failure); the others see it at their
 * next poll and stop too, so that no rank checks or winds for minutes while another has
 * stopped. With one process these do nothing (sweep_mpi_poll returns `local`).
 *
 * sweep_mpi_poll(local): the progress callbacks' question, from the thread that calls MPI:
 * local (this process's caught signal, 0 none) nonzero: notify the others, return it; else
 * the first notice received from another rank (probed at most every 20 ms), 0 none. */
int sweep_mpi_poll(int local);
void sweep_mpi_notify(int value);
/* The first notice received (0: none); *from (if not NULL): the rank that sent it. */
int sweep_mpi_peer_stop(int *from);
/* Collective: every notice sent so far is received (the counts summed over the ranks),
 * every send completed. Called where all ranks meet, so that none is left in flight. */
void sweep_mpi_settle(void);

/* What the ranks agreed after checking, or after winding (sweep_mpi_agree_all). */
typedef struct sweep_agreement {
  int code;   /* the exit status every rank takes (0: go on) */
  int signal; /* nonzero: a signal caught on rank `rank` stops the job (code is then 0) */
  int rank;   /* the rank whose status decided (the signal's, the failure's, the scene's) */
} sweep_agreement;
/* A code: this rank stopped because another told it to (it has nothing to say). */
enum { SWEEP_STOPPED = -1 };
/* What each rank's messages may hold at most when sent to rank 0. */
enum { SWEEP_TEXT_MAX = 2048 };
/* Collective (sweep/mpi_agree.c), every rank with its own status: `code` its exit status
 * (0 ok, SWEEP_STOPPED), `digest` of what it loaded (sweep_check_runs), `text` what it
 * printed (NULL: nothing), `caught` this process's signal (polled while waiting for the
 * others: a signal then is told to them at once). Rank 0 decides, in this order: a
 * signal caught on any rank (the lowest such rank; 128 + the signal is the CLI's
 * business); rank 0's failure; another rank's failure (printing, on rank 0, the text of
 * each failed rank unless it is rank 0's or the previous one's, each line as
 * "reelsim: rank R: ..."); a digest differing from rank 0's (exit 2, naming the ranks);
 * else 0. Every rank gets the same answer. One process: {code, caught(), 0}. */
sweep_agreement sweep_mpi_agree_all(int code, uint64_t digest, const char *text,
                                    int (*caught)(void));
/* The MPI schedule of sweep_wind (size > 1). */
rs_status sweep_mpi_wind(const sweep_spec *spec, sweep_result *out);
/* The buffers of a result for n runs (figures NaN). */
rs_status sweep_result_alloc(sweep_result *r, int n, int profiles);

#endif
