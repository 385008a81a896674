/* reelsim fit roll SCENE --measured DATA.csv --vary KEY=LO:HI [--vary ...] [-o best.yaml]
 *     [--set key=value ...] [--threads K] [--json]
 * Scene keys fitted to what the plant measured on a roll (docs/calibrate.md). Exit 0 ok,
 * 2 bad input, 3 a reel failed, 130/143 interrupted (nothing written). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/json.h"
#include "cli/signals.h"
#include "reelsim/output.h"
#include "reelsim/scene.h"
#include "reelsim/version.h"
#include "sweep/fitroll.h"

enum { FR_MAX_ARGS = 64 };

typedef struct fr_args {
  const char *scene, *measured, *out;
  const char *vary[RS_FIT_MAX_PARAMS], *sets[FR_MAX_ARGS];
  int n_vary, n_sets, threads, json;
} fr_args;

static int parse(int argc, char **argv, fr_args *a)
{
  memset(a, 0, sizeof *a);
  for (int i = 3; i < argc; ++i) {
    const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (strcmp(o, "--measured") == 0 && v) a->measured = argv[++i];
    else if (strcmp(o, "-o") == 0 && v) a->out = argv[++i];
    else if (strcmp(o, "--vary") == 0 && v) {
      if (a->n_vary == RS_FIT_MAX_PARAMS)
        return cli_fail(CLI_EXIT_USAGE, "fit roll: at most %d --vary keys", RS_FIT_MAX_PARAMS);
      a->vary[a->n_vary++] = argv[++i];
    } else if (strcmp(o, "--set") == 0 && v) {
      if (a->n_sets == FR_MAX_ARGS) return cli_fail(CLI_EXIT_USAGE, "fit roll: too many --set");
      a->sets[a->n_sets++] = argv[++i];
    } else if (strcmp(o, "--threads") == 0 && v) a->threads = atoi(argv[++i]);
    else if (strcmp(o, "--json") == 0) a->json = 1;
    else if (o[0] == '-')
      return cli_fail(CLI_EXIT_USAGE, "fit roll: unknown option or missing value '%s' (see "
                                      "docs/calibrate.md)", o);
    else if (!a->scene) a->scene = o;
    else return cli_fail(CLI_EXIT_USAGE, "fit roll: one scene at a time (got '%s' too)", o);
  }
  if (!a->scene || !a->measured || a->n_vary == 0)
    return cli_fail(CLI_EXIT_USAGE, "usage: reelsim fit roll SCENE --measured DATA.csv --vary "
                                    "KEY=LO:HI [--vary ...] [-o best.yaml] [--set key=value ...]");
  return -1;
}

static int on_progress(void *user, int done, int total)
{
  (void)user;
  (void)done;
  (void)total;
  return cli_signal_caught() != 0;
}

static void after(void *user, int evaluation, const double *x, double rms)
{
  const fr_problem *p = user;
  if (!isatty(2)) return;
  fprintf(stderr, "\rfit roll: reel %d, RMS %.4g at", evaluation, rms);
  for (int k = 0; k < p->n_vars; ++k) fprintf(stderr, " %s=%.6g", p->vars[k].key, x[k]);
  fprintf(stderr, "   ");
  fflush(stderr);
}

/* The best scene, resolved, through the atomic writer (rs_output_write_file: a new
 * O_EXCL | O_NOFOLLOW temporary, fsync, rename): whole or absent, never through a
 * planted symlink. */
static int write_best(const fr_problem *p, const double *x, const char *path)
{
  int n = 0;
  char **sets = fr_sets_of(p, x, &n);
  rs_scene *sc = NULL;
  rs_status st = sets ? rs_scene_load(p->scene, n, (const char *const *)sets, &sc) : RS_ERR_MEMORY;
  free(sets);
  if (st == RS_OK) {
    const char *text = rs_scene_resolved_text(sc);
    st = rs_output_write_file(path, text, strlen(text));
  }
  rs_scene_destroy(&sc);
  return st ? cli_fail_status(st) : -1;
}

static void report(const fr_args *a, const fr_problem *p, const fr_result *r)
{
  const fr_data *d = p->data;
  if (a->json) {
    cli_json j;
    cli_json_init(&j, stdout);
    cli_json_object(&j, NULL);
    cli_json_string(&j, "reelsim", RS_VERSION_STRING);
    cli_json_string(&j, "command", "fit roll");
    cli_json_string(&j, "scene", a->scene);
    cli_json_string(&j, "measured", a->measured);
    cli_json_string(&j, "quantity", fr_y_name(d->ykind));
    cli_json_int(&j, "points", d->n);
    cli_json_array(&j, "parameters");
    for (int k = 0; k < p->n_vars; ++k) {
      cli_json_object(&j, NULL);
      cli_json_string(&j, "name", p->vars[k].key);
      cli_json_number(&j, "value", r->x[k]);
      cli_json_number(&j, "ci95_low", r->x[k] - r->half_width[k]);
      cli_json_number(&j, "ci95_high", r->x[k] + r->half_width[k]);
      cli_json_end(&j);
    }
    cli_json_end(&j);
    cli_json_number(&j, "rms_residual", r->rms);
    cli_json_object(&j, "worst");
    cli_json_int(&j, "index", r->worst);
    cli_json_number(&j, fr_x_name(d->xkind), d->x[r->worst]);
    cli_json_number(&j, "measured", d->y[r->worst]);
    cli_json_number(&j, "residual", r->worst_residual);
    cli_json_end(&j);
    cli_json_int(&j, "reels", r->evaluations);
    cli_json_string(&j, "best", a->out);
    cli_json_end(&j);
    printf("\n");
    return;
  }
  printf("%s fitted to %s (%s against %s, %d points): %d reels, BOBYQA %s\n", a->scene, a->measured,
         fr_y_name(d->ykind), fr_x_name(d->xkind), d->n, r->evaluations, r->nlopt);
  printf("  %-28s %-14s %s\n", "key", "value", "95 % confidence interval");
  for (int k = 0; k < p->n_vars; ++k) {
    printf("  %-28s %-14.6g", p->vars[k].key, r->x[k]);
    if (r->intervals_ok) printf(" %.6g .. %.6g\n", r->x[k] - r->half_width[k], r->x[k] + r->half_width[k]);
    else printf(" not determined (the data do not constrain every key)\n");
  }
  printf("  RMS residual %.4g\n", r->rms);
  printf("  worst point  #%d: %s %.6g, measured %.6g, model %.6g (%+.3g)\n", r->worst + 1,
         fr_x_name(d->xkind), d->x[r->worst], d->y[r->worst], d->y[r->worst] + r->worst_residual,
         r->worst_residual);
  if (a->out) printf("  best scene   %s\n", a->out);
}

int cli_fit_roll(int argc, char **argv)
{
  fr_args a;
  int code = parse(argc, argv, &a);
  if (code >= 0) return code;
  sweep_vary vars[RS_FIT_MAX_PARAMS];
  memset(vars, 0, sizeof vars);
  fr_data d = {0};
  char err[1024];
  rs_status st = RS_OK;
  for (int k = 0; k < a.n_vary && !st; ++k) {
    st = sweep_vary_parse(a.vary[k], SWEEP_VARY_RANGE, &vars[k]);
    if (!st) st = sweep_vary_check(a.scene, a.n_sets, a.sets, &vars[k]);
  }
  if (st) code = cli_fail_status(st);
  else if (fr_data_read(a.measured, &d, err, sizeof err) != 0) code = cli_fail(CLI_EXIT_USAGE, "%s", err);
  if (code < 0) {
    rs_reel_options wind = {on_progress, NULL};
    fr_problem p = {.scene = a.scene, .n_sets = a.n_sets, .sets = a.sets, .n_vars = a.n_vary,
                    .vars = vars, .data = &d, .wind = &wind, .threads = a.threads,
                    .after = after};
    p.user = &p;
    fr_result r;
    cli_signals sig;
    cli_signals_install(&sig);
    st = fr_run(&p, &r);
    int caught = cli_signal_caught();
    cli_signals_restore(&sig);
    if (isatty(2)) fprintf(stderr, "\n");
    if (caught || r.stopped)
      code = cli_fail(cli_signal_exit_code(caught ? caught : 2), "fit roll: interrupted after %d "
                      "reels (no output written)", r.evaluations);
    else if (st) code = cli_fail_status(st);
    else if (a.out && (code = write_best(&p, r.x, a.out)) >= 0) {
    } else {
      report(&a, &p, &r);
      code = CLI_EXIT_OK;
    }
  }
  for (int k = 0; k < a.n_vary; ++k) sweep_vary_clear(&vars[k]);
  fr_data_free(&d);
  return code;
}
