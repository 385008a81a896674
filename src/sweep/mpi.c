/* reelsim sweep over MPI ranks (docs/scale.md): rank 0 hands out run indices one at a
 * time to whichever rank asks (runs differ in cost: a static split would leave ranks idle),
 * the other ranks wind them and send back the figures and, with --profiles, the final
 * profiles. Only rank 0 holds the results and writes the files. Without MPI (a build
 * without it, or a program not started by mpirun) there is one process of rank 0. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sweep/app_error.h"
#include "sweep/sweep.h"

#ifdef RS_HAVE_MPI
#include <mpi.h>

static int started, rank, size = 1;

/* Launched by mpirun (Open MPI, or a PMI/PMIx launcher such as srun)? A program run on its
 * own does not start MPI at all: no singleton start-up, no MPI in plain runs. */
static int launched(void)
{
  static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE",
                                     "PMI_RANK"};
  for (size_t i = 0; i < sizeof vars / sizeof vars[0]; ++i)
    if (getenv(vars[i])) return 1;
  return 0;
}

void sweep_mpi_begin(void)
{
  int already = 0;
  if (!launched() || MPI_Initialized(&already) != MPI_SUCCESS || already) return;
  if (MPI_Init(NULL, NULL) != MPI_SUCCESS) return;
  started = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
}

void sweep_mpi_end(void)
{
  if (started) MPI_Finalize();
  started = 0;
  rank = 0;
  size = 1;
}

int sweep_mpi_rank(void) { return rank; }
int sweep_mpi_size(void) { return size; }

int sweep_mpi_agree(int code)
{
  if (size > 1) MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return code;
}

enum { TAG_DONE = 1, TAG_PROFILE = 2, TAG_WORK = 3 };
/* a worker's message: [run index or -1 for the first request, figures..., layers] */
enum { MSG = SWEEP_N_FIGURES + 2 };

/* Waits for a message without spinning: Open MPI's blocking receive polls at full speed,
 * which on an oversubscribed machine takes a core from the ranks that wind. */
static void wait_quietly(MPI_Request *req, MPI_Status *status)
{
  int flag = 0;
  struct timespec nap = {0, 200000}; /* 0.2 ms: small against a run's 10-100 ms */
  for (;;) {
    MPI_Test(req, &flag, status);
    if (flag) return;
    nanosleep(&nap, NULL);
  }
}

static void store(sweep_result *out, const double *msg)
{
  int i = (int)msg[0];
  for (int f = 0; f < SWEEP_N_FIGURES; ++f)
    out->figures[(size_t)f * out->n_runs + i] = msg[1 + f];
}

static rs_status master(const sweep_spec *spec, sweep_result *out)
{
  int n = spec->plan->n_runs, next = 0, workers = size - 1;
  rs_status st = sweep_result_alloc(out, n, spec->profiles);
  if (st != RS_OK) return st; /* the workers still wait: the caller aborts */
  out->ranks = workers;
  out->threads = 1;
  double msg[MSG];
  while (workers > 0) {
    MPI_Request req;
    MPI_Status status;
    MPI_Irecv(msg, MSG, MPI_DOUBLE, MPI_ANY_SOURCE, TAG_DONE, MPI_COMM_WORLD, &req);
    wait_quietly(&req, &status);
    int from = status.MPI_SOURCE;
    if (msg[0] >= 0) {
      store(out, msg);
      int layers = (int)msg[MSG - 1];
      if (spec->profiles && layers > 0) {
        double *block = malloc(3 * (size_t)layers * sizeof *block);
        if (!block) { /* the profile is on its way and has nowhere to go */
          fprintf(stderr, "reelsim: sweep: out of memory for the profiles on rank 0\n");
          MPI_Abort(MPI_COMM_WORLD, 1);
        }
        MPI_Recv(block, 3 * layers, MPI_DOUBLE, from, TAG_PROFILE, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        out->profiles[(int)msg[0]] =
            (rs_output_profile){layers, block, block + layers, block + 2 * layers};
      }
    }
    int job = -1;
    if (next < n && !(spec->progress && spec->progress(NULL, 0, 0))) job = next++;
    else if (next < n) out->stopped = 1;
    MPI_Send(&job, 1, MPI_INT, from, TAG_WORK, MPI_COMM_WORLD);
    if (job < 0) --workers;
  }
  for (int i = 0; i < n; ++i) out->failed += out->figures[(size_t)SWEEP_FIG_STATUS * n + i] != 0;
  return RS_OK;
}

/* Asks for work with the last run's figures (and then its profile), winds what it is
 * given, until told -1. */
static void worker(const sweep_spec *spec)
{
  double msg[MSG];
  rs_output_profile prof = {0};
  msg[0] = -1;
  for (int f = 0; f < SWEEP_N_FIGURES; ++f) msg[1 + f] = NAN;
  for (;;) {
    msg[MSG - 1] = prof.n;
    MPI_Send(msg, MSG, MPI_DOUBLE, 0, TAG_DONE, MPI_COMM_WORLD);
    if (prof.n > 0)
      MPI_Send((void *)prof.radius, 3 * prof.n, MPI_DOUBLE, 0, TAG_PROFILE, MPI_COMM_WORLD);
    free((void *)prof.radius);
    prof = (rs_output_profile){0};
    int job;
    MPI_Request req;
    MPI_Status status;
    MPI_Irecv(&job, 1, MPI_INT, 0, TAG_WORK, MPI_COMM_WORLD, &req);
    wait_quietly(&req, &status);
    if (job < 0) return;
    sweep_run_one(spec, job, msg + 1, spec->profiles ? &prof : NULL);
    msg[0] = job;
  }
}

rs_status sweep_mpi_wind(const sweep_spec *spec, sweep_result *out)
{
  memset(out, 0, sizeof *out);
  if (rank == 0) {
    rs_status st = master(spec, out);
    if (st != RS_OK) MPI_Abort(MPI_COMM_WORLD, 1);
    return st;
  }
  worker(spec);
  return RS_OK;
}

#else /* one process */

void sweep_mpi_begin(void) {}
void sweep_mpi_end(void) {}
int sweep_mpi_rank(void) { return 0; }
int sweep_mpi_size(void) { return 1; }
int sweep_mpi_agree(int code) { return code; }
rs_status sweep_mpi_wind(const sweep_spec *spec, sweep_result *out)
{
  (void)spec;
  memset(out, 0, sizeof *out);
  return APP_ERROR(RS_ERR_INTERNAL, "this reelsim was built without MPI");
}

#endif
