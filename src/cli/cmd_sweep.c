/* reelsim sweep: one scene wound at many values of some of its keys (docs/cli.md).
 *
 * Everything that can be refused is refused before anything is wound: the --sample and
 * --vary arguments, each key against the scene, then every run's scene (loaded with its
 * values). The runs go over threads, or over MPI ranks under mpirun (src/sweep); only rank
 * 0 prints and writes. A failed run is recorded (status, NaN figures) and the sweep goes
 * on: its exit status is 0 when it ran, and the last line counts the failures. */
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/capture.h"
#include "cli/cli.h"
#include "cli/signals.h"
#include "reelsim/clock.h"
#include "reelsim/output.h"
#include "reelsim/scene.h"
#include "sweep/sweep.h"

static const char default_output[] = "sweep.h5";

/* Nonzero (the signal's number, or another rank's notice) stops the sweep: asked before
 * every check and during every run. Under mpirun a signal caught here is told to every
 * other rank, so that the whole job stops (sweep_mpi_poll). */
static int on_progress(void *user, int layers_done, int layers_total)
{
  (void)user;
  (void)layers_done;
  (void)layers_total;
  return sweep_mpi_poll(cli_signal_caught());
}

/* A check that returned st: exit 2 naming what is wrong, or SWEEP_STOPPED (said later). */
static int checked(rs_status st)
{
  return st == RS_ERR_INTERRUPTED ? SWEEP_STOPPED : cli_fail_status(st);
}

typedef struct sweep_state {
  sweep_vary *vary;
  int n_vary;
  sweep_sample sample;
  sweep_plan plan;
  sweep_result result;
  rs_scene *base;          /* the scene with --set alone: its resolved text for the file */
  const char *output;
} sweep_state;

/* The arguments, the keys against the scene, every run: exit 2 naming what is wrong. */
static int prepare(sweep_state *s, const cli_args *a)
{
  rs_status st = sweep_sample_parse(a->sample ? a->sample : "grid", &s->sample);
  if (st != RS_OK) return cli_fail_status(st);
  if (a->n_vary == 0)
    return cli_fail(CLI_EXIT_USAGE, "sweep: nothing to vary (give --vary KEY=LO:HI:N or "
                                    "--vary KEY=V1,V2,...)");
  s->vary = calloc((size_t)a->n_vary, sizeof *s->vary);
  if (!s->vary) return cli_fail(CLI_EXIT_OTHER, "out of memory");
  for (int k = 0; k < a->n_vary; ++k) {
    ++s->n_vary;
    if ((st = sweep_vary_parse(a->vary[k], sweep_sample_vary_forms(&s->sample), &s->vary[k])) != RS_OK)
      return cli_fail_status(st);
    for (int j = 0; j < k; ++j)
      if (strcmp(s->vary[j].key, s->vary[k].key) == 0)
        return cli_fail(CLI_EXIT_USAGE, "--vary %s: %s is already varied by --vary %s",
                        a->vary[k], s->vary[k].key, a->vary[j]);
  }
  /* a 1e12-run grid is refused at once, not after loading the scene for every value */
  if ((st = sweep_plan_check_size(s->n_vary, s->vary, &s->sample)) != RS_OK)
    return cli_fail_status(st);
  if ((st = rs_scene_load(a->scene, a->n_sets, a->sets, &s->base)) != RS_OK)
    return cli_fail_status(st);
  cli_scene_warnings(s->base);
  /* a grid key may have 10^7 values, lhs 10^7 runs: each step can be stopped */
  for (int k = 0; k < s->n_vary; ++k)
    if ((st = sweep_vary_check_stoppable(a->scene, a->n_sets, a->sets, &s->vary[k],
                                         on_progress)) != RS_OK)
      return checked(st);
  if ((st = sweep_plan_make_stoppable(s->n_vary, s->vary, &s->sample, on_progress, &s->plan)) != RS_OK)
    return checked(st);
  return CLI_EXIT_OK;
}

/* The figures a run of the scene has (sweep_figure_list: the storage_* ones with storage
 * stages, the lanes' with lanes), in table order: their names and units, and their rows of
 * the result copied into *rows (malloc'd, n_figures x runs). Returns the count, -1 when out
 * of memory. */
static int figures_kept(const sweep_state *s, const char **names, const char **units,
                        const char **help, double **rows)
{
  int idx[SWEEP_N_FIGURES], nf = sweep_figure_list(rs_scene_problem(s->base), idx);
  size_t n = (size_t)s->plan.n_runs, total = (size_t)nf * n;
  *rows = malloc((total ? total : 1) * sizeof **rows);
  if (!*rows) return -1;
  for (int k = 0; k < nf; ++k) {
    names[k] = sweep_figures[idx[k]].name;
    units[k] = sweep_figures[idx[k]].unit;
    help[k] = sweep_figures[idx[k]].help;
    memcpy(*rows + (size_t)k * n, s->result.figures + (size_t)idx[k] * n, n * sizeof **rows);
  }
  return nf;
}

static int write_files(const sweep_state *s, const cli_args *a)
{
  int n = s->plan.n_runs, nk = s->n_vary;
  const char **keys = calloc((size_t)nk, sizeof *keys);
  int *n_words = calloc((size_t)nk, sizeof *n_words);
  const char *const **words = calloc((size_t)nk, sizeof *words);
  const char *names[SWEEP_N_FIGURES], *units[SWEEP_N_FIGURES], *help[SWEEP_N_FIGURES];
  double *figures = NULL;
  int n_figures = keys && n_words && words ? figures_kept(s, names, units, help, &figures) : -1;
  if (n_figures < 0) {
    free(keys);
    free(n_words);
    free(words);
    return cli_fail(CLI_EXIT_OTHER, "out of memory");
  }
  for (int k = 0; k < nk; ++k) {
    keys[k] = s->vary[k].key;
    if (s->vary[k].words) {
      n_words[k] = s->vary[k].n;
      words[k] = (const char *const *)s->vary[k].words;
    }
  }
  char sample[64];
  sweep_sample_name(&s->sample, sample, sizeof sample);
  rs_output_sweep sw = {
      .scene_path = a->scene,
      .scene_text = rs_scene_resolved_text(s->base),
      .sample = sample,
      .seed = s->sample.kind == SWEEP_SAMPLE_LHS ? (long long)SWEEP_LHS_SEED : 0,
      .n_keys = nk,
      .keys = keys,
      .n_words = n_words,
      .words = words,
      .n_runs = n,
      .values = s->plan.points,
      .n_figures = n_figures,
      .figure_names = names,
      .figure_units = units,
      .figure_help = help,
      .figures = figures,
      .profiles = s->result.profiles,
  };
  int code = CLI_EXIT_OK;
  rs_status st = rs_output_write_sweep(s->output, &sw);
  if (st == RS_OK && a->csv_dir) st = rs_output_write_sweep_csv(a->csv_dir, &sw);
  if (st != RS_OK) code = cli_fail_status(st);
  free(keys);
  free(n_words);
  free(words);
  free(figures);
  return code;
}

static void free_state(sweep_state *s)
{
  for (int k = 0; k < s->n_vary; ++k) sweep_vary_clear(&s->vary[k]);
  free(s->vary);
  sweep_plan_free(&s->plan);
  sweep_result_free(&s->result);
  rs_scene_destroy(&s->base);
}

/* The exit status of an agreement, with the message of a signal (on rank 0): "sweep:
 * terminated (SIGTERM) on rank 2 before winding (no output written)". */
static int said(const sweep_agreement *ag, const char *when)
{
  if (!ag->signal) return ag->code;
  char on[32] = "";
  if (ag->rank > 0) snprintf(on, sizeof on, " on rank %d", ag->rank);
  if (sweep_mpi_rank() != 0) return cli_signal_exit_code(ag->signal);
  return cli_fail(cli_signal_exit_code(ag->signal), "sweep: %s%s%s%s (no output written)",
                  cli_signal_word(ag->signal), on, when[0] ? " " : "", when);
}

/* Every rank's checks (the arguments, the scene, every run; rank 0 also the output's
 * folder), then their agreement (sweep_mpi_agree_all): under mpirun each rank's messages
 * are captured and rank 0 prints them. Returns the exit status all ranks take; a signal
 * on any rank is said here. */
static int check_everywhere(sweep_state *s, const cli_args *a, const sweep_spec *spec, int root)
{
  cli_capture cap = {NULL, -1};
  if (sweep_mpi_size() > 1) cli_capture_begin(&cap);
  uint64_t digest = 0;
  rs_status st = RS_OK;
  int code = prepare(s, a);
  if (code == CLI_EXIT_OK && (st = sweep_check_runs(spec, &digest)) != RS_OK) code = checked(st);
  /* a missing output directory should not cost the sweep (rank 0's view decides) */
  if (code == CLI_EXIT_OK && root && (st = rs_output_check_target(s->output)) == RS_OK &&
      a->csv_dir)
    st = rs_output_check_target(a->csv_dir);
  if (code == CLI_EXIT_OK && root && st != RS_OK) code = cli_fail_status(st);
  char *text = cli_capture_end(&cap, root ? (size_t)1 << 20 : SWEEP_TEXT_MAX);
  if (root && text) fputs(text, stderr);
  sweep_agreement ag = sweep_mpi_agree_all(code, digest, text, cli_signal_caught);
  free(text);
  return said(&ag, "before winding");
}

int cli_sweep(const cli_args *a)
{
  double t0 = rs_clock_wall();
  sweep_mpi_begin();
  int root = sweep_mpi_rank() == 0;
  /* only rank 0 prints: the others' messages reach it (check_everywhere, and a failed
   * run's through the schedule) */
  if (!root && (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr))) {
    /* nothing to say it with: go on, the messages are rank 0's anyway */
  }
  sweep_state s = {.output = a->output ? a->output : default_output};
  cli_signals sig_saved;
  cli_signals_install(&sig_saved);
  sweep_spec spec = {a->scene, a->n_sets, a->sets, &s.plan, a->threads, a->profiles, on_progress};

  int code = check_everywhere(&s, a, &spec, root);
  if (code == CLI_EXIT_USAGE && root) fprintf(stderr, "reelsim: sweep: nothing was wound\n");
  if (code != CLI_EXIT_OK) goto done;

  if (!a->quiet && root && sweep_mpi_size() == 2) /* docs/scale.md */
    fprintf(stderr, "reelsim: note: under mpirun rank 0 only hands out the runs: -n 2 winds "
                    "them on one rank, slower than one process (--threads); give -n P+1 for P "
                    "winding ranks\n");
  if (!a->quiet && root)
    printf("sweep: %d run%s of %s (%d key%s)\n", s.plan.n_runs, s.plan.n_runs == 1 ? "" : "s",
           a->scene, s.n_vary, s.n_vary == 1 ? "" : "s");
  fflush(stdout);
  rs_status st = sweep_wind(&spec, &s.result);
  code = st != RS_OK ? cli_fail_status(st) : CLI_EXIT_OK;
  /* every rank has stopped winding; a signal anywhere means no file */
  sweep_agreement ag = sweep_mpi_agree_all(code, 0, NULL, cli_signal_caught);
  if (ag.signal == 0 && ag.code == CLI_EXIT_OK && s.result.stopped) ag.signal = SIGINT;
  if ((code = said(&ag, "")) != CLI_EXIT_OK) goto done;
  if (root) code = write_files(&s, a);
  if (code == CLI_EXIT_OK && root && !a->quiet) {
    char where[64];
    if (s.result.ranks > 0)
      snprintf(where, sizeof where, "%d MPI rank%s", s.result.ranks, s.result.ranks == 1 ? "" : "s");
    else
      snprintf(where, sizeof where, "%d thread%s", s.result.threads, s.result.threads == 1 ? "" : "s");
    printf("output %s%s%s\n", s.output, a->csv_dir ? " and " : "", a->csv_dir ? a->csv_dir : "");
    printf("sweep: %d run%s on %s in %.2f s, %d failed\n", s.plan.n_runs,
           s.plan.n_runs == 1 ? "" : "s", where, rs_clock_wall() - t0, s.result.failed);
  }
  code = sweep_mpi_agree(code);

done:
  free_state(&s);
  cli_signals_restore(&sig_saved);
  sweep_mpi_end();
  return code;
}
