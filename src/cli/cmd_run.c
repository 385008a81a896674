/* reelsim run: load the scene, wind the reel, write the result, print a summary.
 *
 * Ctrl-C (and SIGTERM) sets a flag that the engine's progress callback returns, so the run
 * stops after the current step; nothing is written and the exit status is 128 + the
 * signal (130, 143). A second signal kills the program the usual way (SA_RESETHAND).
 * SIGXFSZ is ignored while running, so a file-size limit (ulimit -f) makes the write fail
 * with "File too large" and the output module removes its temporary, instead of the
 * signal killing the program with a partial temporary left behind.
 * --keep-partial: when the solver fails or the run is stopped, the layers finished are
 * still written (attribute complete = 0); by default nothing is. */

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "cli/cli.h"
#include "reelsim/output.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

static volatile sig_atomic_t interrupted = 0; /* the signal number, 0 if none */

static void on_signal(int sig) { interrupted = sig; }

typedef struct progress {
  int done, total;
} progress;

static int on_progress(void *user, int layers_done, int layers_total)
{
  progress *p = user;
  p->done = layers_done;
  p->total = layers_total;
  return interrupted != 0;
}

static double now_seconds(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Pa as kPa below 1 MPa, else MPa */
static void fmt_stress(char *buf, size_t size, double pa)
{
  if (fabs(pa) < 1e6)
    snprintf(buf, size, "%.2f kPa", pa / 1e3);
  else
    snprintf(buf, size, "%.3f MPa", pa / 1e6);
}

/* A figure a user reads must be a number: anything else is a broken solution. */
static int summary_finite(const rs_reel_summary *s, const char **what)
{
  const struct {
    const char *name;
    double v;
  } f[] = {
      {"final radius", s->final_radius},
      {"core pressure", s->core_pressure},
      {"peak pressure", s->peak_pressure},
      {"radius of the peak pressure", s->peak_pressure_radius},
      {"minimum hoop stress", s->min_hoop},
      {"radius of the minimum hoop stress", s->min_hoop_radius},
      {"least wound-on tension", s->wot_min},
      {"greatest wound-on tension", s->wot_max},
  };
  for (size_t i = 0; i < sizeof f / sizeof f[0]; ++i)
    if (!isfinite(f[i].v)) {
      *what = f[i].name;
      return 0;
    }
  return 1;
}

static void print_summary(const rs_scene *scene, const rs_reel_result *res,
                          const rs_reel_summary *s, double wall)
{
  char a[64], b[64];
  printf("%s\n", scene->title);
  printf("active effects:\n");
  rs_scene_print_effects(scene, stdout);
  printf("result:\n");
  printf("  final radius       %.1f mm\n", s->final_radius * 1e3);
  printf("  layers             %d\n", s->layers);
  fmt_stress(a, sizeof a, s->core_pressure);
  printf("  core pressure      %s\n", a);
  fmt_stress(a, sizeof a, s->peak_pressure);
  printf("  peak pressure      %s at r = %.1f mm\n", a, s->peak_pressure_radius * 1e3);
  fmt_stress(b, sizeof b, s->min_hoop);
  printf("  min hoop stress    %s at r = %.1f mm\n", b, s->min_hoop_radius * 1e3);
  printf("  wound-on tension   %.1f .. %.1f N/m\n", s->wot_min, s->wot_max);
  printf("  wall time          %.2f s (solver %.2f s, %ld increments, %ld CVODE steps)\n", wall,
         res->wall_seconds, res->increments, res->cvode_steps);
  printf("  output             %s\n", scene->output.file);
}

/* Writes the finished part of a run that stopped early (--keep-partial). Returns 1 when a
 * file was written; otherwise says why not. */
static int write_partial(const rs_scene *scene, const rs_reel_result *res)
{
  rs_reel_summary sum;
  const char *what = NULL;
  rs_reel_summarize(res, &sum);
  for (int j = 0; j < res->n_layers; ++j)
    if (!isfinite(res->sigma_r[j]) || !isfinite(res->sigma_theta[j])) what = "a layer's stress";
  if (what || !summary_finite(&sum, &what)) {
    fprintf(stderr, "reelsim:   --keep-partial: not written, the %s is not a finite number\n",
            what);
    return 0;
  }
  if (rs_output_write(scene->output.file, scene, res) != RS_OK) {
    fprintf(stderr, "reelsim:   --keep-partial: %s\n", rs_error_message());
    return 0;
  }
  return 1;
}

int cli_run(const cli_args *a)
{
  double t0 = now_seconds();
  struct sigaction sa, old_int, old_term, old_xfsz, ign;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  /* a shell starts background jobs with SIGINT ignored: keep it that way for them */
  if (old_int.sa_handler == SIG_IGN) sigaction(SIGINT, &old_int, NULL);
  if (old_term.sa_handler == SIG_IGN) sigaction(SIGTERM, &old_term, NULL);
  memset(&ign, 0, sizeof ign);
  ign.sa_handler = SIG_IGN;
  sigemptyset(&ign.sa_mask);
  sigaction(SIGXFSZ, &ign, &old_xfsz);

  rs_scene *scene = NULL;
  rs_reel_result *res = NULL;
  int code = CLI_EXIT_OK;
  rs_status st = rs_scene_load(a->scene, a->n_sets, a->sets, &scene);
  if (st != RS_OK) {
    code = cli_fail_status(st);
    goto done;
  }

  progress prog = {0, scene->n_layers};
  rs_reel_options opts = {.progress = on_progress, .user = &prog};
  st = rs_reel_wind(scene, &opts, &res);
  if (st == RS_ERR_INTERRUPTED || (st == RS_OK && interrupted)) {
    int k = res ? res->n_layers : prog.done, sig = interrupted;
    const char *how = sig == SIGTERM ? "terminated (SIGTERM)" : "interrupted";
    if (a->keep_partial && res && write_partial(scene, res))
      cli_fail(0, "%s at layer %d of %d (partial result written to %s, complete = 0)", how, k,
               scene->n_layers, scene->output.file);
    else
      cli_fail(0, "%s at layer %d of %d (no output written)", how, k, scene->n_layers);
    code = sig == SIGTERM ? CLI_EXIT_TERMINATED : CLI_EXIT_INTERRUPTED;
    goto done;
  }
  if (st != RS_OK) {
    if (st == RS_ERR_INPUT) rs_error_wrap("%s", scene->path); /* e.g. a nip model not built */
    code = cli_fail_status(st);
    if (res && st == RS_ERR_SOLVER) {
      if (a->keep_partial && write_partial(scene, res))
        fprintf(stderr,
                "reelsim:   %d of %d layers were wound; partial result written to %s "
                "(complete = 0)\n",
                res->n_layers, scene->n_layers, scene->output.file);
      else
        fprintf(stderr, "reelsim:   %d of %d layers were wound; no output written\n",
                res->n_layers, scene->n_layers);
    }
    goto done;
  }

  rs_reel_summary sum;
  const char *what = NULL;
  rs_reel_summarize(res, &sum);
  if (!summary_finite(&sum, &what)) {
    code = cli_fail(CLI_EXIT_SOLVER,
                    "solver failure: the %s is not a finite number; no output written", what);
    goto done;
  }

  st = rs_output_write(scene->output.file, scene, res);
  if (st != RS_OK) {
    code = cli_fail_status(st);
    goto done;
  }
  if (!a->quiet) print_summary(scene, res, &sum, now_seconds() - t0);

done:
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&scene);
  sigaction(SIGINT, &old_int, NULL);
  sigaction(SIGTERM, &old_term, NULL);
  sigaction(SIGXFSZ, &old_xfsz, NULL);
  return code;
}
