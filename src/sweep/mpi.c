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

#include "reelsim/clock.h"
#include "sweep/mpi_module.h"
#include "sweep/mpi_wait.h"

static int started, rank, size = 1;

enum { TAG_DONE = 1, TAG_PROFILE = 2, TAG_WORK = 3, TAG_STOP = 4, TAG_TEXT = 5 };

/* Stop notices (sweep.h): what this rank sent to each rank (cumulative), the sends' requests,
 * the first notice received and from whom. */
static int *sent_to, notice_out, peer_value, peer_rank = -1, received;
static MPI_Request *sends;
static int n_sends;
static double last_probe;

/* A program run on its own (not launched by mpirun: sweep_mpi_launched) does not start MPI
 * at all: no singleton start-up, no MPI in plain runs. */
void sweep_mpi_begin(void)
{
  int already = 0;
  if (!sweep_mpi_launched() || MPI_Initialized(&already) != MPI_SUCCESS || already) return;
  if (MPI_Init(NULL, NULL) != MPI_SUCCESS) return;
  started = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  sent_to = calloc((size_t)size, sizeof *sent_to);
  sends = calloc((size_t)size, sizeof *sends);
  if (!sent_to || !sends) {
    fprintf(stderr, "reelsim: sweep: out of memory on rank %d\n", rank);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
}

void sweep_mpi_end(void)
{
  if (started) MPI_Finalize();
  free(sent_to);
  free(sends);
  sent_to = NULL;
  sends = NULL;
  started = n_sends = notice_out = peer_value = received = 0;
  peer_rank = -1;
  rank = 0;
  size = 1;
}

int sweep_mpi_rank(void) { return rank; }
int sweep_mpi_size(void) { return size; }

/* Waits for a request without spinning: Open MPI's blocking calls poll at full speed,
 * which on an oversubscribed machine takes a core from the ranks that wind. poll (if not
 * NULL) is asked at every look. */
void sweep_mpi_wait(MPI_Request *req, MPI_Status *status, rs_reel_progress_fn poll, void *user)
{
  int flag = 0;
  struct timespec nap = {0, 200000}; /* 0.2 ms: small against a run's 10-100 ms */
  for (;;) {
    MPI_Test(req, &flag, status ? status : MPI_STATUS_IGNORE);
    if (flag) return;
    if (poll) poll(user, 0, 0);
    nanosleep(&nap, NULL);
  }
}

int sweep_mpi_agree(int code)
{
  if (size > 1) {
    MPI_Request req;
    MPI_Ibcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD, &req);
    sweep_mpi_wait(&req, NULL, NULL, NULL);
  }
  return code;
}

void sweep_mpi_notify(int value)
{
  if (size <= 1 || notice_out || !value) return;
  notice_out = value; /* the buffer of every send: it stays until they complete */
  for (int r = 0; r < size; ++r)
    if (r != rank) {
      MPI_Isend(&notice_out, 1, MPI_INT, r, TAG_STOP, MPI_COMM_WORLD, &sends[n_sends++]);
      ++sent_to[r];
    }
}

static void take_notice(int from)
{
  int value;
  MPI_Recv(&value, 1, MPI_INT, from, TAG_STOP, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  ++received;
  if (!peer_value) {
    peer_value = value;
    peer_rank = from;
  }
}

int sweep_mpi_peer_stop(int *from)
{
  if (size > 1) {
    int flag = 1;
    MPI_Status st;
    while (flag) {
      MPI_Iprobe(MPI_ANY_SOURCE, TAG_STOP, MPI_COMM_WORLD, &flag, &st);
      if (flag) take_notice(st.MPI_SOURCE);
    }
  }
  if (from) *from = peer_rank;
  return peer_value;
}

int sweep_mpi_poll(int local)
{
  if (size <= 1) return local;
  if (local) {
    sweep_mpi_notify(local);
    return local;
  }
  double now = rs_clock_wall();
  if (!peer_value && now - last_probe >= 0.02) {
    last_probe = now;
    sweep_mpi_peer_stop(NULL);
  }
  return peer_value;
}

void sweep_mpi_settle(void)
{
  if (size <= 1) return;
  int expected = 0;
  MPI_Request req;
  MPI_Ireduce_scatter_block(sent_to, &expected, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &req);
  sweep_mpi_wait(&req, NULL, NULL, NULL);
  while (received < expected) take_notice(MPI_ANY_SOURCE); /* all sent: they arrive */
  MPI_Waitall(n_sends, sends, MPI_STATUSES_IGNORE);
  n_sends = 0;
}

/* a worker's message: [run index or -1 for none, figures..., layers, length of the text
 * that follows (why the run failed, with its NUL; 0: none)] */
enum { MSG = SWEEP_N_FIGURES + 3, WHY = 1024 };

static void store(sweep_result *out, const double *msg)
{
  int i = (int)msg[0];
  for (int f = 0; f < SWEEP_N_FIGURES; ++f)
    out->figures[(size_t)f * out->n_runs + i] = msg[1 + f];
}

static int stop_asked(const sweep_spec *spec)
{
  return spec->progress && spec->progress(NULL, 0, 0);
}

/* The profile and the text that follow a worker's message. */
static void receive_extras(const sweep_spec *spec, sweep_result *out, const double *msg, int from)
{
  int layers = (int)msg[MSG - 2], len = (int)msg[MSG - 1];
  if (msg[0] >= 0 && spec->profiles && layers > 0) {
    double *block = malloc(3 * (size_t)layers * sizeof *block);
    if (!block) { /* the profile is on its way and has nowhere to go */
      fprintf(stderr, "reelsim: sweep: out of memory for the profiles on rank 0\n");
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    MPI_Recv(block, 3 * layers, MPI_DOUBLE, from, TAG_PROFILE, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    out->profiles[(int)msg[0]] = (rs_output_profile){layers, block, block + layers, block + 2 * layers};
  }
  if (len > 0) {
    char why[WHY];
    MPI_Recv(why, len, MPI_CHAR, from, TAG_TEXT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    why[WHY - 1] = '\0';
    if (msg[0] >= 0 && !stop_asked(spec)) sweep_say_failed((int)msg[0], why);
  }
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
    /* a signal here is told to the workers at once (spec->progress notifies) */
    sweep_mpi_wait(&req, &status, spec->progress, NULL);
    int from = status.MPI_SOURCE;
    if (msg[0] >= 0) store(out, msg);
    receive_extras(spec, out, msg, from);
    int job = -1;
    if (next < n && !stop_asked(spec)) job = next++;
    else if (next < n) out->stopped = 1;
    MPI_Send(&job, 1, MPI_INT, from, TAG_WORK, MPI_COMM_WORLD);
    if (job < 0) --workers;
  }
  for (int i = 0; i < n; ++i) out->failed += out->figures[(size_t)SWEEP_FIG_STATUS * n + i] != 0;
  return RS_OK;
}

/* Asks for work with the last run's figures (then its profile and why it failed), winds
 * what it is given, until told -1. Once told to stop (its own signal or another rank's
 * notice) it winds nothing more and only asks, so that rank 0 tells it -1. */
static void worker(const sweep_spec *spec)
{
  double msg[MSG];
  rs_output_profile prof = {0};
  char why[WHY] = "";
  msg[0] = -1;
  for (int f = 0; f < SWEEP_N_FIGURES; ++f) msg[1 + f] = NAN;
  for (;;) {
    int len = msg[0] >= 0 && why[0] ? (int)strlen(why) + 1 : 0;
    msg[MSG - 2] = prof.n;
    msg[MSG - 1] = len;
    MPI_Send(msg, MSG, MPI_DOUBLE, 0, TAG_DONE, MPI_COMM_WORLD);
    if (prof.n > 0)
      MPI_Send((void *)prof.radius, 3 * prof.n, MPI_DOUBLE, 0, TAG_PROFILE, MPI_COMM_WORLD);
    if (len > 0) MPI_Send(why, len, MPI_CHAR, 0, TAG_TEXT, MPI_COMM_WORLD);
    free((void *)prof.radius);
    prof = (rs_output_profile){0};
    int job;
    MPI_Request req;
    MPI_Irecv(&job, 1, MPI_INT, 0, TAG_WORK, MPI_COMM_WORLD, &req);
    sweep_mpi_wait(&req, NULL, NULL, NULL);
    if (job < 0) return;
    msg[0] = -1;
    if (stop_asked(spec)) {
      struct timespec nap = {0, 1000000}; /* until rank 0 sees the notice too */
      nanosleep(&nap, NULL);
      continue;
    }
    sweep_run_one(spec, job, msg + 1, spec->profiles ? &prof : NULL, why, sizeof why);
    if (stop_asked(spec)) why[0] = '\0'; /* "interrupted": the job's end says why */
    msg[0] = job;
  }
}

rs_status sweep_mpi_wind(const sweep_spec *spec, sweep_result *out)
{
  memset(out, 0, sizeof *out);
  rs_status st = RS_OK;
  if (rank == 0) {
    st = master(spec, out);
    if (st != RS_OK) MPI_Abort(MPI_COMM_WORLD, 1);
  } else {
    worker(spec);
  }
  return st;
}

#else /* one process */

void sweep_mpi_begin(void) {}
void sweep_mpi_end(void) {}
int sweep_mpi_rank(void) { return 0; }
int sweep_mpi_size(void) { return 1; }
int sweep_mpi_agree(int code) { return code; }
int sweep_mpi_poll(int local) { return local; }
void sweep_mpi_notify(int value) { (void)value; }
int sweep_mpi_peer_stop(int *from)
{
  if (from) *from = -1;
  return 0;
}
void sweep_mpi_settle(void) {}
rs_status sweep_mpi_wind(const sweep_spec *spec, sweep_result *out)
{
  (void)spec;
  memset(out, 0, sizeof *out);
  return APP_ERROR(RS_ERR_INTERNAL, "this reelsim was built without MPI");
}

#endif
