/* reelsim compare: wind several scenes side by side, print their key figures in one
 * table, write them all to one HDF5 file (docs/cli.md).
 *
 * Every scene is loaded and checked before any winding starts, so bad input in any of
 * them costs nothing (exit 2). The reels are wound in parallel (rs_reel_wind_many, one
 * thread per core, at most one per scene); the HDF5 file is built afterwards on this
 * thread. A run that fails does not stop the others: they are all reported, but the
 * file is written only when every run succeeded (exit 3 otherwise), because a
 * comparison that silently lacks a recipe reads as if it were complete. */

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "cli/compare_runs.h"
#include "cli/outdir.h"
#include "cli/summary_json.h"
#include "reelsim/version.h"
#include "reelsim/clock.h"
#include "cli/signals.h"
#include "reelsim/output.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/storage.h"
#include "sweep/app_error.h"

static const char default_output[] = "compare.h5";


static int on_progress(void *user, int layers_done, int layers_total)
{
  (void)user;
  (void)layers_done;
  (void)layers_total;
  return cli_signal_caught() != 0;
}

typedef struct compare_state {
  int n;
  rs_scene **scenes;
  rs_reel_job *jobs;
  rs_reel_summary *sums;
  rs_defect_report **defects; /* each successful run's verdicts */
  rs_storage_result **storage; /* each run's storage stages, NULL without */
  char (*names)[256];
  const char *output;
  compare_runs runs;           /* the scenes and variants */
} compare_state;

/* Loads every scene; prints the error of each bad one. Returns the exit status of the
 * worst failure (2 for bad input), or CLI_EXIT_OK. */
static int load_all(compare_state *c)
{
  int code = CLI_EXIT_OK;
  for (int i = 0; i < c->n; ++i) {
    const compare_run *r = &c->runs.run[i];
    rs_status st = rs_scene_load(r->scene, r->n_sets, r->sets, &c->scenes[i]);
    if (st == RS_OK) {
      cli_scene_warnings(c->scenes[i]);
      continue;
    }
    if (r->variant) app_error_wrap("--variant '%s'", r->variant);
    int k = cli_fail_status(st);
    /* bad input decides the status; an I/O or memory failure only if there is none */
    if (code != CLI_EXIT_USAGE && (k == CLI_EXIT_USAGE || code == CLI_EXIT_OK)) code = k;
  }
  return code;
}

static void print_table(const compare_state *c, double wall, int threads)
{
  printf("compare: %d scene%s on %d thread%s\n", c->n, c->n == 1 ? "" : "s", threads,
         threads == 1 ? "" : "s");
  char shown[1024];
  for (int i = 0; i < c->n; ++i)
    printf("  %-24s %s\n", c->names[i], cli_shown(rs_scene_title(c->scenes[i]), shown, sizeof shown));
  printf("\n%-24s %7s %8s %10s %10s %7s %10s %7s %17s %8s\n", "run", "layers", "final r",
         "core P", "peak P", "at r", "min hoop", "at r", "wound-on T0", "wall");
  printf("%-24s %7s %8s %10s %10s %7s %10s %7s %17s %8s\n", "", "", "mm", "kPa", "kPa", "mm",
         "kPa", "mm", "N/m", "s");
  for (int i = 0; i < c->n; ++i) {
    const rs_reel_job *job = &c->jobs[i];
    if (job->status != RS_OK) {
      printf("%-24s FAILED (%s)\n", c->names[i], rs_status_name(job->status));
      continue;
    }
    const rs_reel_summary *s = &c->sums[i];
    char wot[64];
    snprintf(wot, sizeof wot, "%.1f .. %.1f", s->wot_min, s->wot_max);
    printf("%-24s %7d %8.1f %10.2f %10.2f %7.1f %10.2f %7.1f %17s %8.2f\n", c->names[i],
           s->layers, s->final_radius * 1e3, s->core_pressure / 1e3, s->peak_pressure / 1e3,
           s->peak_pressure_radius * 1e3, s->min_hoop / 1e3, s->min_hoop_radius * 1e3, wot,
           job->wall_seconds);
  }
  /* each run's defect verdicts (rules: docs/defects.md), the rules the run summary lists */
  printf("\n%-24s %-13s %-13s %-13s %-13s %s\n", "defect risk", "hoop stress",
         "starring", "pressure", "slip", "core");
  for (int i = 0; i < c->n; ++i) {
    const rs_defect_report *d = c->defects[i];
    if (!d) {
      printf("%-24s -\n", c->names[i]);
      continue;
    }
    printf("%-24s %-13s %-13s %-13s %-13s %s\n", c->names[i],
           rs_defect_verdict_name(d->hoop.verdict), rs_defect_verdict_name(d->starring.verdict),
           rs_defect_verdict_name(d->pressure.verdict), rs_defect_verdict_name(d->slip.verdict),
           rs_defect_verdict_name(d->core.verdict));
  }
  cli_print_compare_lanes(stdout, c->n, (const char(*)[256])c->names,
                          (const rs_scene *const *)c->scenes, c->jobs);
  cli_print_compare_storage(stdout, c->n, (const char(*)[256])c->names,
                            (const rs_storage_result *const *)c->storage);
  printf("\nwall time %.2f s in all\n", wall);
}

/* compare --json: one object with every run (docs/cli.md, "JSON"); output is NULL when
 * no file was written. */
static void print_json(const compare_state *c, double wall, int threads, const char *output)
{
  cli_json j;
  cli_json_init(&j, stdout);
  cli_json_object(&j, NULL);
  cli_json_string(&j, "reelsim", RS_VERSION_STRING);
  cli_json_string(&j, "command", "compare");
  cli_json_int(&j, "threads", threads);
  cli_json_number(&j, "wall_seconds", wall);
  cli_json_string(&j, "output", output);
  cli_json_array(&j, "runs");
  for (int i = 0; i < c->n; ++i) {
    const rs_reel_job *job = &c->jobs[i];
    cli_json_object(&j, NULL);
    cli_json_string(&j, "name", c->names[i]);
    cli_json_string(&j, "status", job->status == RS_OK ? "ok" : rs_status_name(job->status));
    if (job->status == RS_OK) {
      cli_json_null(&j, "error");
      cli_json_run_fields(&j, c->scenes[i], job->result, c->defects[i]);
      if (c->storage[i]) cli_json_storage(&j, c->storage[i]);
      if (c->runs.run[i].name) cli_json_string(&j, "variant", c->runs.run[i].variant);
    } else {
      cli_json_string(&j, "error", job->message);
      cli_json_string(&j, "scene", rs_scene_path(c->scenes[i]));
      cli_json_string(&j, "title", rs_scene_title(c->scenes[i]));
    }
    cli_json_number(&j, "wall_seconds", job->wall_seconds);
    cli_json_end(&j);
  }
  cli_json_end(&j);
  cli_json_end(&j);
  fflush(stdout);
}

/* The defect verdicts of every run that succeeded. */
static int assess_all(compare_state *c)
{
  for (int i = 0; i < c->n; ++i) {
    if (c->jobs[i].status != RS_OK) continue;
    rs_defect_limits limits;
    rs_defect_limits_from_problem(rs_scene_problem(c->scenes[i]), &limits);
    rs_status st = rs_defects_assess(c->jobs[i].result, &limits, &c->defects[i]);
    if (st != RS_OK) return cli_fail_status(st);
  }
  return CLI_EXIT_OK;
}

/* The storage stages of every run that succeeded and whose scene has them (docs/storage.md):
 * a failure is the run's failure. */
static void store_all(compare_state *c)
{
  for (int i = 0; i < c->n; ++i) {
    rs_reel_job *job = &c->jobs[i];
    const rs_problem *p = rs_scene_problem(c->scenes[i]);
    if (job->status != RS_OK || !rs_storage_requested(p)) continue;
    double t0 = rs_clock_wall();
    rs_status st = rs_storage_run(p, job->result, &c->storage[i]);
    job->wall_seconds += rs_clock_wall() - t0;
    if (st == RS_OK) continue;
    job->status = st;
    snprintf(job->message, sizeof job->message, "during storage: %s", app_error_message());
    job->where[0] = '\0';
    rs_storage_result_destroy(&c->storage[i]);
  }
}

/* compare --csv DIR: each run's CSV files, named by the run (01-taper-profile.csv, ...). */
static int write_csv(const compare_state *c, const char *dir)
{
  cli_outdir made;
  int code = cli_outdir_make("--csv", dir, &made);
  if (code != CLI_EXIT_OK) {
    cli_outdir_undo(&made);
    return code;
  }
  rs_status st = RS_OK;
  for (int i = 0; st == RS_OK && i < c->n; ++i)
    st = rs_output_write_csv_stored(dir, c->names[i], c->jobs[i].result, c->storage[i]);
  if (st != RS_OK) {
    cli_outdir_undo(&made);
    return cli_fail_status(st);
  }
  cli_outdir_free(&made);
  return CLI_EXIT_OK;
}

/* Reports each failed run; returns the exit status (3 for a solver failure). */
static int check_jobs(compare_state *c)
{
  int code = CLI_EXIT_OK;
  for (int i = 0; i < c->n; ++i) {
    rs_reel_job *job = &c->jobs[i];
    const char *what = NULL;
    if (job->status == RS_OK) {
      rs_reel_summarize(job->result, &c->sums[i]);
      if (rs_reel_summary_finite(&c->sums[i], &what)) continue;
      job->status = RS_ERR_SOLVER;
      snprintf(job->message, sizeof job->message, "the %s is not a finite number", what);
      job->where[0] = '\0';
    }
    int k = rs_status_exit_code(job->status);
    if (job->status == RS_ERR_INPUT)
      cli_fail(k, "%s: %s", rs_scene_path(c->scenes[i]), job->message);
    else if (job->status == RS_ERR_SOLVER)
      cli_fail(k, "%s: solver failure: %s", rs_scene_path(c->scenes[i]), job->message);
    else
      cli_fail(k, "%s: %s: %s", rs_scene_path(c->scenes[i]), rs_status_name(job->status), job->message);
    if (cli_fail_is_verbose() && job->where[0]) fprintf(stderr, "reelsim:   (at %s)\n", job->where);
    if (job->result && job->status == RS_ERR_SOLVER)
      fprintf(stderr, "reelsim:   %d of %d layers were wound\n", rs_reel_result_n_layers(job->result),
              rs_scene_problem(c->scenes[i])->n_layers);
    if (code == CLI_EXIT_OK || k == CLI_EXIT_USAGE) code = k;
  }
  return code;
}

static void free_state(compare_state *c)
{
  for (int i = 0; c->jobs && i < c->n; ++i) rs_reel_result_destroy(&c->jobs[i].result);
  for (int i = 0; c->scenes && i < c->n; ++i) rs_scene_destroy(&c->scenes[i]);
  for (int i = 0; c->defects && i < c->n; ++i) rs_defect_report_destroy(&c->defects[i]);
  for (int i = 0; c->storage && i < c->n; ++i) rs_storage_result_destroy(&c->storage[i]);
  free(c->defects);
  free(c->storage);
  compare_runs_free(&c->runs);
  free(c->scenes);
  free(c->jobs);
  free(c->sums);
  free(c->names);
}

static int alloc_state(compare_state *c)
{
  c->scenes = calloc((size_t)c->n, sizeof *c->scenes);
  c->jobs = calloc((size_t)c->n, sizeof *c->jobs);
  c->sums = calloc((size_t)c->n, sizeof *c->sums);
  c->names = calloc((size_t)c->n, sizeof *c->names);
  c->defects = calloc((size_t)c->n, sizeof *c->defects);
  c->storage = calloc((size_t)c->n, sizeof *c->storage);
  if (!c->scenes || !c->jobs || !c->sums || !c->names || !c->defects || !c->storage)
    return cli_fail(CLI_EXIT_OTHER, "out of memory");
  return CLI_EXIT_OK;
}

/* A missing output directory, or a --csv that cannot be a directory, should not cost the
 * whole comparison: both are found before the winding. */
static int check_targets(const cli_args *a, const compare_state *c)
{
  rs_status st = rs_output_check_target(c->output);
  if (st == RS_OK && a->csv_dir) {
    struct stat sb;
    if (stat(a->csv_dir, &sb) == 0 && !S_ISDIR(sb.st_mode))
      st = APP_ERROR(RS_ERR_INPUT, "--csv '%s' is not a directory", a->csv_dir);
  }
  return st != RS_OK ? cli_fail_status(st) : CLI_EXIT_OK;
}

/* Every run wound (in parallel); a signal stops the comparison with nothing written. */
static int wind_all(compare_state *c, int *threads)
{
  for (int i = 0; i < c->n; ++i) {
    c->jobs[i].problem = rs_scene_problem(c->scenes[i]);
    c->jobs[i].opts.progress = on_progress;
    rs_output_run_name(i, c->n, c->runs.run[i].name ? c->runs.run[i].name : rs_scene_path(c->scenes[i]),
                       c->names[i], sizeof c->names[i]);
  }
  rs_status st = rs_reel_wind_many(c->n, c->jobs, 0, threads);
  if (st != RS_OK) return cli_fail_status(st);
  int sig = cli_signal_caught();
  if (sig)
    return cli_fail(cli_signal_exit_code(sig), "compare: %s (no output written)",
                    cli_signal_word(sig));
  return CLI_EXIT_OK;
}

/* The comparison file (every run under its name) and, with --csv, the CSV files. */
static int write_compare(const cli_args *a, const compare_state *c)
{
  rs_output_run *runs = calloc((size_t)c->n, sizeof *runs);
  const char **names = calloc((size_t)c->n, sizeof *names);
  rs_status st = RS_OK;
  if (!runs || !names) st = APP_ERROR(RS_ERR_MEMORY, "out of memory");
  for (int i = 0; st == RS_OK && i < c->n; ++i) {
    runs[i] = (rs_output_run){c->scenes[i], c->jobs[i].result};
    names[i] = c->runs.run[i].name;
  }
  if (st == RS_OK)
    st = rs_output_write_compare_stored(c->output, c->n, runs,
                                        (const rs_storage_result *const *)c->storage, names);
  free(runs);
  free(names);
  if (st != RS_OK) return cli_fail_status(st);
  return a->csv_dir ? write_csv(c, a->csv_dir) : CLI_EXIT_OK;
}

int cli_compare(const cli_args *a)
{
  double t0 = rs_clock_wall();
  compare_state c = {.n = 0, .output = a->output ? a->output : default_output};
  /* every stored scene names the file it went to, as with run -o */
  const char **sets = calloc((size_t)a->n_sets + 1, sizeof *sets);
  char *out_set = NULL;
  int n_sets = a->n_sets, code = CLI_EXIT_OK, threads = 0;
  cli_signals sig_saved;
  cli_signals_install(&sig_saved);

  if (!sets) {
    code = cli_fail(CLI_EXIT_OTHER, "out of memory");
    goto done;
  }
  if (a->n_sets) memcpy(sets, a->sets, (size_t)a->n_sets * sizeof *sets);
  if (!a->output) {
    size_t len = sizeof "output.file=" + strlen(c.output);
    if (!(out_set = malloc(len))) {
      code = cli_fail(CLI_EXIT_OTHER, "out of memory");
      goto done;
    }
    snprintf(out_set, len, "output.file=%s", c.output);
    sets[n_sets++] = out_set;
  }
  if ((code = compare_runs_make(a, n_sets, sets, &c.runs)) >= 0) {
    fprintf(stderr, "reelsim: compare: nothing was wound\n");
    goto done;
  }
  c.n = c.runs.n;
  if ((code = alloc_state(&c)) != CLI_EXIT_OK) goto done;
  if ((code = load_all(&c)) != CLI_EXIT_OK) {
    if (code == CLI_EXIT_USAGE) fprintf(stderr, "reelsim: compare: nothing was wound\n");
    goto done;
  }
  if ((code = check_targets(a, &c)) != CLI_EXIT_OK) goto done;
  if ((code = wind_all(&c, &threads)) != CLI_EXIT_OK) goto done;
  store_all(&c);
  code = check_jobs(&c);
  int assessed = assess_all(&c);
  if (code == CLI_EXIT_OK) code = assessed;
  if (!a->quiet && !a->json) print_table(&c, rs_clock_wall() - t0, threads);
  if (code != CLI_EXIT_OK) {
    fprintf(stderr, "reelsim: compare: a run failed; no output written\n");
    if (a->json) print_json(&c, rs_clock_wall() - t0, threads, NULL);
    goto done;
  }
  code = write_compare(a, &c);
  if (code != CLI_EXIT_OK) goto done;
  if (a->json) print_json(&c, rs_clock_wall() - t0, threads, c.output);
  else if (!a->quiet) printf("output %s%s%s\n", c.output, a->csv_dir ? " and " : "", a->csv_dir ? a->csv_dir : "");
done:
  free_state(&c);
  free(sets);
  free(out_set);
  cli_signals_restore(&sig_saved);
  return code;
}
