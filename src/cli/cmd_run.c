/* reelsim run: load the scene, wind the reel, write the result, print a summary.
 *
 * Ctrl-C (and SIGTERM) sets a flag that the engine's progress callback returns, so the run
 * stops after the current step; nothing is written and the exit status is 128 + the
 * signal (130, 143). A second signal kills the program the usual way (SA_RESETHAND).
 * SIGXFSZ is ignored while running, so a file-size limit (ulimit -f) makes the write fail
 * with "File too large" and the output module removes its temporary, instead of the
 * signal killing the program with a partial temporary left behind.
 * --keep-partial: when the solver fails or the run is stopped, the layers finished are
 * still written (attribute complete = 0); by default nothing is.
 *
 * The same callback draws a progress line on stderr (progress.c: layers, radius, time
 * left) once a run has taken a second, at most ten times a second, and only when stderr
 * is a terminal and --quiet is off: logs, pipes and test output never see it. */

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/summary_json.h"
#include "reelsim/version.h"
#include "reelsim/clock.h"
#include "reelsim/output.h"
#include "cli/outdir.h"
#include "cli/progress.h"
#include "cli/signals.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/storage.h"
#include "sweep/app_error.h"

static int on_progress(void *user, int layers_done, int layers_total)
{
  (void)layers_total;
  cli_progress_update(user, layers_done, rs_clock_wall());
  return cli_signal_caught() != 0;
}

static void print_summary(const rs_scene *scene, const rs_reel_result *res,
                          const rs_reel_summary *s, const rs_defect_report *defects,
                          const rs_storage_result *storage, const char *csv_dir, double wall)
{
  char a[64], b[64];
  char shown[1024];
  printf("%s\n", cli_shown(rs_scene_title(scene), shown, sizeof shown));
  printf("active effects:\n");
  rs_scene_print_effects(scene, stdout);
  printf("result:\n");
  rs_reel_sizes z;
  rs_reel_sizes_of(res, rs_scene_problem(scene), &z);
  printf("  final radius       %.1f mm\n", s->final_radius * 1e3);
  printf("  diameter           %.1f mm (free r_c + N t: %.1f mm; the stack compressed, what a "
         "gauge reads)\n", z.deformed_diameter * 1e3, z.diameter * 1e3);
  printf("  layers             %d\n", s->layers);
  printf("  wound length       %.1f m (the layers' circumferences at mid-thickness)\n",
         z.wound_length);
  if (z.has_mass) printf("  roll mass          %.2f kg per metre of width\n", z.mass);
  if (z.has_air)
    printf("  entrained air      %.1f mm of the radius (films %.3g .. %.3g um in the reel, "
           "%.3g .. %.3g um as wound on)\n",
           z.air_thickness * 1e3, z.air_film_min * 1e6, z.air_film_max * 1e6,
           z.air_entrained_min * 1e6, z.air_entrained_max * 1e6);
  cli_fmt_stress(a, sizeof a, s->core_pressure);
  printf("  core pressure      %s\n", a);
  cli_fmt_stress(a, sizeof a, s->peak_pressure);
  printf("  peak pressure      %s at r = %.1f mm\n", a, s->peak_pressure_radius * 1e3);
  cli_fmt_stress(b, sizeof b, s->min_hoop);
  printf("  min hoop stress    %s at r = %.1f mm\n", b, s->min_hoop_radius * 1e3);
  printf("  wound-on tension   %.1f .. %.1f N/m\n", s->wot_min, s->wot_max);
  printf("  wall time          %.2f s (solver %.2f s, %ld increments, %ld from the core, %ld CVODE "
         "steps)\n",
         wall, rs_reel_result_wall_seconds(res), rs_reel_result_increments(res),
         rs_reel_result_full_integrations(res), rs_reel_result_cvode_steps(res));
  printf("  output             %s\n", rs_scene_output_file(scene));
  if (csv_dir) {
    char stem[RS_PATH_MAX], path[RS_PATH_MAX + 64];
    rs_scene_name(scene, stem, sizeof stem);
    const char *kinds = rs_reel_result_n_stages(res) > 0 ? "{profile,wot,history}" : "{profile,wot}";
    if (rs_output_csv_path(csv_dir, stem, kinds, path, sizeof path) == RS_OK)
      printf("  csv                %s\n", path);
  }
  cli_print_defects(stdout, defects);
  cli_print_lanes(stdout, scene, res);
  cli_print_storage(stdout, storage);
}

/* run --json: the summary as one JSON object (docs/cli.md, "JSON"). */
static void print_json(const rs_scene *scene, const rs_reel_result *res,
                       const rs_defect_report *defects, const rs_storage_result *storage,
                       const char *csv_dir, double wall)
{
  cli_json j;
  cli_json_init(&j, stdout);
  cli_json_object(&j, NULL);
  cli_json_string(&j, "reelsim", RS_VERSION_STRING);
  cli_json_string(&j, "command", "run");
  cli_json_run_fields(&j, scene, res, defects);
  cli_json_storage(&j, storage);
  cli_json_number(&j, "wall_seconds", wall);
  cli_json_string(&j, "output", rs_scene_output_file(scene));
  if (csv_dir) {
    char stem[RS_PATH_MAX], path[RS_PATH_MAX + 64];
    static const char *const kinds[] = {"profile", "wot", "history"};
    rs_scene_name(scene, stem, sizeof stem);
    cli_json_array(&j, "csv");
    for (int k = 0; k < (rs_reel_result_n_stages(res) > 0 ? 3 : 2); ++k)
      if (rs_output_csv_path(csv_dir, stem, kinds[k], path, sizeof path) == RS_OK)
        cli_json_string(&j, NULL, path);
    cli_json_end(&j);
  } else {
    cli_json_null(&j, "csv");
  }
  cli_json_end(&j);
  fflush(stdout);
}

/* Writes the finished part of a run that stopped early (--keep-partial). Returns 1 when a
 * file was written; otherwise says why not. */
static int write_partial(const rs_scene *scene, const rs_reel_result *res)
{
  rs_reel_summary sum;
  const char *what = NULL;
  rs_reel_summarize(res, &sum);
  int n = 0;
  const double *sr = rs_reel_result_sigma_r(res, &n), *st = rs_reel_result_sigma_theta(res, NULL);
  for (int j = 0; j < n; ++j)
    if (!isfinite(sr[j]) || !isfinite(st[j])) what = "a layer's stress";
  if (what || !rs_reel_summary_finite(&sum, &what)) {
    fprintf(stderr, "reelsim:   --keep-partial: not written, the %s is not a finite number\n",
            what);
    return 0;
  }
  if (rs_output_write(rs_scene_output_file(scene), scene, res) != RS_OK) {
    fprintf(stderr, "reelsim:   --keep-partial: %s\n", app_error_message());
    return 0;
  }
  return 1;
}

/* A winding that did not finish: interrupted (a signal, or the progress callback) or a
 * solver failure, with --keep-partial's partial file. Returns the exit code. */
static int wind_failed(const cli_args *a, const rs_scene *scene, rs_reel_result *res,
                       rs_status st, int done_layers)
{
  const int N = rs_scene_problem(scene)->n_layers;
  if (st == RS_ERR_INTERRUPTED || (st == RS_OK && cli_signal_caught())) {
    int k = res ? rs_reel_result_n_layers(res) : done_layers, sig = cli_signal_caught();
    const char *how = cli_signal_word(sig);
    if (a->keep_partial && res && write_partial(scene, res))
      cli_fail(0, "%s at layer %d of %d (partial result written to %s, complete = 0)", how, k,
               N, rs_scene_output_file(scene));
    else
      cli_fail(0, "%s at layer %d of %d (no output written)", how, k, N);
    return cli_signal_exit_code(sig);
  }
  if (st == RS_ERR_INPUT) app_error_wrap("%s", rs_scene_path(scene)); /* e.g. a nip model not built */
  int code = cli_fail_status(st);
  if (res && st == RS_ERR_SOLVER) {
    if (a->keep_partial && write_partial(scene, res))
      fprintf(stderr,
              "reelsim:   %d of %d layers were wound; partial result written to %s "
              "(complete = 0)\n",
              rs_reel_result_n_layers(res), N, rs_scene_output_file(scene));
    else
      fprintf(stderr, "reelsim:   %d of %d layers were wound; no output written\n",
              rs_reel_result_n_layers(res), N);
  }
  return code;
}

/* After the winder: the storage stages (docs/storage.md), only when the scene has them.
 * The stages are not interruptible from inside (they are short against the winding): a
 * signal during them is honoured when they return, and nothing is written. */
static int run_storage(const rs_scene *scene, const rs_reel_result *res,
                       rs_storage_result **storage)
{
  if (!rs_storage_requested(rs_scene_problem(scene))) return CLI_EXIT_OK;
  rs_status st = rs_storage_run(rs_scene_problem(scene), res, storage);
  int sig = cli_signal_caught();
  if (sig)
    return cli_fail(cli_signal_exit_code(sig), "%s during storage (the roll was wound; no "
                    "output written)", cli_signal_word(sig));
  if (st != RS_OK) {
    app_error_wrap("%s", rs_scene_path(scene));
    int code = cli_fail_status(st);
    fprintf(stderr, "reelsim:   the roll was wound; no output written\n");
    return code;
  }
  return CLI_EXIT_OK;
}

/* The run file and, with --csv, the CSV files. With --csv the HDF5 file is staged beside
 * its name and renamed into place only when the CSV files are written too: a failed run
 * leaves no file of its own. */
static int write_outputs(const cli_args *a, const rs_scene *scene, const rs_reel_result *res,
                         const rs_storage_result *storage, const rs_defect_report *defects)
{
  const char *out_path = rs_scene_output_file(scene);
  char staged[RS_PATH_MAX + 64] = "";
  rs_status st = RS_OK;
  if (a->csv_dir) snprintf(staged, sizeof staged, "%s.tmp.%ld.0", out_path, (long)getpid());
  if (staged[0]) st = rs_output_check_target(out_path);
  if (st == RS_OK)
    st = rs_output_write_assessed(staged[0] ? staged : out_path, scene, res, storage, defects);
  if (st == RS_OK && a->csv_dir) {
    char stem[RS_PATH_MAX];
    cli_outdir made;
    int code = cli_outdir_make("--csv", a->csv_dir, &made);
    if (code != CLI_EXIT_OK) {
      unlink(staged);
      cli_outdir_undo(&made);
      return code;
    }
    rs_scene_name(scene, stem, sizeof stem);
    st = rs_output_write_csv_stored(a->csv_dir, stem, res, storage);
    if (st == RS_OK && rename(staged, out_path) != 0)
      st = APP_ERROR(RS_ERR_IO, "cannot rename '%s' onto output file '%s': %s", staged, out_path,
                    strerror(errno));
    if (st != RS_OK) {
      unlink(staged);
      cli_outdir_undo(&made);
    } else {
      cli_outdir_free(&made);
    }
  } else if (staged[0]) {
    unlink(staged);
  }
  return st != RS_OK ? cli_fail_status(st) : CLI_EXIT_OK;
}

/* The winding's outcome, checked and judged: the summary's figures finite, the defects
 * assessed, the storage stages run, the files written and the summary printed. */
static int after_winding(const cli_args *a, const rs_scene *scene, const rs_reel_result *res,
                         double t0)
{
  rs_defect_report *defects = NULL;
  rs_storage_result *storage = NULL;
  rs_reel_summary sum;
  const char *what = NULL;
  rs_reel_summarize(res, &sum);
  if (!rs_reel_summary_finite(&sum, &what))
    return cli_fail(CLI_EXIT_SOLVER,
                    "solver failure: the %s is not a finite number; no output written", what);
  rs_defect_limits limits;
  rs_defect_limits_from_problem(rs_scene_problem(scene), &limits);
  rs_status st = rs_defects_assess(res, &limits, &defects);
  int code = st == RS_OK ? run_storage(scene, res, &storage) : CLI_EXIT_OK;
  if (code == CLI_EXIT_OK && st == RS_OK) code = write_outputs(a, scene, res, storage, defects);
  else if (code == CLI_EXIT_OK) code = cli_fail_status(st);
  if (code == CLI_EXIT_OK) {
    if (a->json) print_json(scene, res, defects, storage, a->csv_dir, rs_clock_wall() - t0);
    else if (!a->quiet)
      print_summary(scene, res, &sum, defects, storage, a->csv_dir, rs_clock_wall() - t0);
  }
  rs_storage_result_destroy(&storage);
  rs_defect_report_destroy(&defects);
  return code;
}

int cli_run(const cli_args *a)
{
  double t0 = rs_clock_wall();
  cli_signals sig_saved;
  cli_signals_install(&sig_saved);
  rs_scene *scene = NULL;
  rs_reel_result *res = NULL;
  int code = CLI_EXIT_OK;
  /* a --csv path that cannot be a directory must not cost a whole winding */
  if (a->csv_dir && (code = cli_outdir_check("--csv", a->csv_dir)) != CLI_EXIT_OK) goto done;
  rs_status st = rs_scene_load(a->scene, a->n_sets, a->sets, &scene);
  if (st != RS_OK) {
    code = cli_fail_status(st);
    goto done;
  }
  cli_scene_warnings(scene);
  if (cli_same_file(rs_scene_output_file(scene), a->scene)) {
    code = cli_fail(CLI_EXIT_USAGE, "run: output.file '%s' is the scene file itself (it would be "
                    "overwritten)", rs_scene_output_file(scene));
    goto done;
  }
  const rs_problem *pb = rs_scene_problem(scene);
  cli_progress prog;
  cli_progress_init(&prog, !a->quiet && isatty(STDERR_FILENO), pb->n_layers, pb->core.radius,
                    pb->material.caliper, rs_clock_wall());
  rs_reel_options opts = {.progress = on_progress, .user = &prog};
  st = rs_scene_wind(scene, &opts, &res);
  cli_progress_clear(&prog);
  if (st != RS_OK || cli_signal_caught()) code = wind_failed(a, scene, res, st, prog.done);
  else code = after_winding(a, scene, res, t0);
done:
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&scene);
  cli_signals_restore(&sig_saved);
  return code;
}
