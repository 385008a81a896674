/* The ranks' agreement after checking and after winding (sweep.h, sweep_mpi_agree_all):
 * every rank says how it fared; rank 0 decides, prints what the others could not (their
 * stderr goes nowhere under mpirun) and tells every rank the same answer. No rank waits in
 * a collective another never enters: every rank comes here however its checks ended, and a
 * rank that stops early tells the others (a notice, sweep/mpi.c) so that they come soon. */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sweep/sweep.h"

#ifdef RS_HAVE_MPI
#include "sweep/mpi_wait.h"

typedef struct rank_status {
  int code, signal;
  uint64_t digest;
  char text[SWEEP_TEXT_MAX];
} rank_status;

typedef struct caught_fn {
  int (*caught)(void);
} caught_fn;

/* While waiting for the others: a signal caught meanwhile is told to them at once. */
static int tell_signal(void *user, int done, int total)
{
  (void)done;
  (void)total;
  const caught_fn *c = user;
  int sig = c->caught ? c->caught() : 0;
  if (sig) sweep_mpi_notify(sig);
  return sig;
}

/* text's lines on stderr, each as "reelsim: rank R: ..." (its own "reelsim: " dropped). */
static void say_for(int r, const char *text)
{
  while (*text) {
    size_t len = strcspn(text, "\n");
    const char *line = text;
    if (strncmp(line, "reelsim: ", 9) == 0 && len >= 9) {
      line += 9;
      len -= 9;
    }
    if (len > 0) fprintf(stderr, "reelsim: rank %d: %.*s\n", r, (int)len, line);
    text = line + len;
    if (*text == '\n') ++text;
  }
}

/* The failed ranks' messages, each text once (not rank 0's own again). */
static void say_failures(const rank_status *all, int size)
{
  const char *last = all[0].text;
  for (int r = 1; r < size; ++r) {
    if (all[r].code <= 0 || strcmp(all[r].text, all[0].text) == 0 ||
        strcmp(all[r].text, last) == 0)
      continue;
    say_for(r, all[r].text[0] ? all[r].text : "(said nothing)");
    last = all[r].text;
  }
}

static sweep_agreement decide(const rank_status *all, int size)
{
  sweep_agreement ag = {0, 0, 0};
  for (int r = 0; r < size; ++r)
    if (all[r].signal) return (sweep_agreement){0, all[r].signal, r};
  if (all[0].code > 0) {
    say_failures(all, size);
    return (sweep_agreement){all[0].code, 0, 0};
  }
  for (int r = 1; r < size; ++r)
    if (all[r].code > 0) {
      say_failures(all, size);
      return (sweep_agreement){all[r].code, 0, r};
    }
  for (int r = 0; r < size; ++r)
    if (all[r].code != 0) { /* stopped by a notice that no rank's status explains */
      fprintf(stderr, "reelsim: sweep: rank %d stopped and no rank says why\n", r);
      return (sweep_agreement){1, 0, r};
    }
  int shown = 0;
  for (int r = 1; r < size; ++r)
    if (all[r].digest != all[0].digest) {
      if (shown++ < 8)
        fprintf(stderr,
                "reelsim: sweep: rank %d resolved other scenes than rank 0 (digest %016" PRIx64
                " against %016" PRIx64 "): every rank must read the same scene and model "
                "files\n",
                r, all[r].digest, all[0].digest);
      if (!ag.code) ag = (sweep_agreement){2, 0, r};
    }
  if (shown > 8) fprintf(stderr, "reelsim: sweep: (%d more ranks differ)\n", shown - 8);
  return ag;
}

sweep_agreement sweep_mpi_agree_all(int code, uint64_t digest, const char *text,
                                    int (*caught)(void))
{
  int size = sweep_mpi_size(), rank = sweep_mpi_rank();
  caught_fn c = {caught};
  sweep_agreement ag = {code, tell_signal(&c, 0, 0), 0};
  if (size <= 1) return ag;
  if (code > 0) sweep_mpi_notify(-code); /* the others need not finish their checks */
  /* all arrive (a signal meanwhile is told), then every notice is received */
  MPI_Request req;
  MPI_Ibarrier(MPI_COMM_WORLD, &req);
  sweep_mpi_wait(&req, NULL, tell_signal, &c);
  sweep_mpi_settle();
  rank_status mine = {code, caught ? caught() : 0, digest, ""};
  if (text) snprintf(mine.text, sizeof mine.text, "%s", text);
  rank_status *all = NULL;
  if (rank == 0 && !(all = malloc((size_t)size * sizeof *all))) {
    fprintf(stderr, "reelsim: sweep: out of memory for %d ranks' status\n", size);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Igather(&mine, (int)sizeof mine, MPI_BYTE, all, (int)sizeof mine, MPI_BYTE, 0,
              MPI_COMM_WORLD, &req);
  sweep_mpi_wait(&req, NULL, NULL, NULL);
  int answer[3] = {0, 0, 0};
  if (rank == 0) {
    ag = decide(all, size);
    answer[0] = ag.code;
    answer[1] = ag.signal;
    answer[2] = ag.rank;
  }
  free(all);
  MPI_Ibcast(answer, 3, MPI_INT, 0, MPI_COMM_WORLD, &req);
  sweep_mpi_wait(&req, NULL, NULL, NULL);
  return (sweep_agreement){answer[0], answer[1], answer[2]};
}

#else /* one process */

sweep_agreement sweep_mpi_agree_all(int code, uint64_t digest, const char *text,
                                    int (*caught)(void))
{
  (void)digest;
  (void)text;
  return (sweep_agreement){code, caught ? caught() : 0, 0};
}

#endif
