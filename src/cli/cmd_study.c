/* reelsim study SCENE [-o DIR] [--set k=v ...] [--quick] [--jobs N] [--quiet]:
 * what accuracy costs in time (docs/accuracy.md, docs/cli.md).
 *
 * Plans the runs (src/study: a tight reference, a tighter one, the shipped defaults, each
 * knob alone, a small grid), loads every run's scene before winding any (bad input: exit
 * 2, nothing wound), winds them one at a time by default (--jobs N: N at once; the times
 * are the study's measurements, and runs sharing two cores slow each other down), measures
 * each against the reference, prints a table and writes DIR/study.h5, DIR/study.csv and
 * DIR/study.png. A run other than the references and the defaults that fails is reported
 * and left out of the front; a failed reference or default run stops the study (exit 3). */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/outdir.h"
#include "cli/signals.h"
#include "reelsim/clock.h"
#include "reelsim/output.h"
#include "reelsim/plot.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/study.h"
#include "sweep/app_error.h"

static const char DIR_LABEL[] = "study: output directory";

static int on_progress(void *user, int done, int total)
{
  (void)user;
  (void)done;
  (void)total;
  return cli_signal_caught() != 0;
}

/* Errors print as %.2e; an exact zero as "0" and errors below the reference's uncertainty
 * get a '~' (they cannot be told from the reference). */
static void fmt_err(char *buf, size_t size, double e, double noise)
{
  if (isnan(e)) snprintf(buf, size, "-");
  else if (e == 0.0) snprintf(buf, size, "0");
  else snprintf(buf, size, "%s%.2e", e <= noise ? "~" : "", e);
}

static void print_setting(const rs_study_setting *s, int has_nip, int contact)
{
  printf("rtol %g, %d layer%s per step", s->rtol, s->layers_per_step, s->layers_per_step == 1 ? "" : "s");
  if (contact) printf(", nip %d nodes, %d terms", s->nodes, s->terms);
  if (has_nip) {
    if (s->update_every > 0) printf(", nip every %d layer%s", s->update_every, s->update_every == 1 ? "" : "s");
    else printf(", nip adaptive (T0_rtol %g)", s->T0_rtol);
  }
}

static void print_report(const rs_study_plan *plan, const rs_study_report *rep,
                         const rs_reel_job *jobs)
{
  static const char *const head[RS_N_FIGURES] = {"core P", "peak P", "sigma_r", "sigma_t", "T0", "max"};
  char e[RS_N_FIGURES][24];
  printf("\n%-34s %8s %8s %9s", "run", "wall s", "cpu s", "steps");
  if (plan->has_nip) printf(" %7s", "nip");
  for (int f = 0; f < RS_N_FIGURES; ++f) printf(" %10s", head[f]);
  printf("  front\n");
  for (int i = 0; i < plan->n_runs; ++i) {
    const rs_study_row *r = &rep->rows[i];
    printf("%-34s %8.2f %8.2f %9ld", plan->runs[i].label, r->wall_seconds, r->cpu_seconds,
           r->cvode_steps);
    if (plan->has_nip) printf(" %7ld", r->nip_solves);
    if (jobs[i].status != RS_OK) {
      printf("  FAILED (%s)\n", rs_status_name(jobs[i].status));
      continue;
    }
    for (int f = 0; f < RS_N_FIGURES; ++f) {
      fmt_err(e[f], sizeof e[f], r->err[f], rep->uncertainty[f]);
      printf(" %10s", e[f]);
    }
    printf("  %s%s%s\n", r->on_front ? "*" : "", i == 2 ? " <- defaults" : "",
           plan->runs[i].knob == RS_KNOB_HISTORY
               ? (r->identical_to_default ? " (answer identical to the defaults)"
                                          : " (answer DIFFERS from the defaults)")
               : "");
  }
}

static void print_summary(const rs_study_plan *plan, const rs_study_report *rep)
{
  const rs_study_row *d = &rep->rows[2];
  printf("\nerrors are relative to the reference: core and peak pressure, sigma_r (max over layers),\n"
         "sigma_t = hoop stress (max over layers, against T0/caliper of each layer: it crosses zero),\n"
         "T0 at the finish; '~' marks an error below the reference's uncertainty.\n");
  printf("reference:  ");
  print_setting(&plan->runs[0].set, plan->has_nip, plan->contact);
  printf("\nreference2: ");
  print_setting(&plan->runs[1].set, plan->has_nip, plan->contact);
  printf("\nreference uncertainty (reference2 against it): core %.2e, peak %.2e, sigma_r %.2e, "
         "sigma_t %.2e, T0 %.2e\n",
         rep->uncertainty[RS_FIG_CORE], rep->uncertainty[RS_FIG_PEAK], rep->uncertainty[RS_FIG_SIGMA_R],
         rep->uncertainty[RS_FIG_SIGMA_THETA], rep->uncertainty[RS_FIG_T0]);
  if (rep->smallest_run >= 0)
    printf("smallest error reported: %.2e (%s): %s\n", rep->smallest_error,
           plan->runs[rep->smallest_run].label,
           rep->uncertainty[RS_FIG_MAX] < rep->smallest_error
               ? "the reference's uncertainty is below it"
               : "NOT above the reference's uncertainty; errors marked '~' are at its noise");
  printf("defaults: core pressure error %.2e (%s 0.1%%), max %.2e, %.2f s CPU (the least of %d "
         "runs of the same work, which spread by %.0f%%); %s the Pareto front of CPU time and max "
         "error (within %.0f%% in time)\n",
         d->err[RS_FIG_CORE], d->err[RS_FIG_CORE] <= 1e-3 ? "within" : "OVER", d->err[RS_FIG_MAX],
         rep->default_cpu, rep->default_timings, 100 * rep->default_spread,
         rep->default_on_front ? "on" : "NOT on", 100 * rep->time_noise);
  printf("Pareto front (%d runs):", rep->n_front);
  for (int i = 0; i < plan->n_runs; ++i)
    if (rep->rows[i].on_front) printf(" %s;", plan->runs[i].label);
  printf("\nobserved order p in error ~ x^p per knob (core pressure / max error; x = rtol, "
         "layers_per_step - 1,\n  1/nodes, 1/terms, T0_rtol, update_every; points above the floor):\n");
  for (int k = RS_KNOB_RTOL; k <= RS_KNOB_EVERY; ++k) {
    int used = 0;
    for (int i = 0; i < plan->n_runs; ++i) used |= plan->runs[i].knob == (rs_study_knob)k;
    if (!used) continue;
    printf("  %-16s", rs_study_knob_name((rs_study_knob)k));
    for (int f = 0; f < 2; ++f) {
      const rs_study_knob_order *o = &rep->order[k][f];
      if (isnan(o->order) && isnan(o->floor)) printf(" %s n/a (no sweep)", f ? "/" : "");
      else if (isnan(o->order))
        printf(" %s n/a (%d point%s above %.1e)", f ? "/" : "", o->points, o->points == 1 ? "" : "s",
               o->floor);
      else printf(" %s %5.2f (%d points)", f ? "/" : "", o->order, o->points);
    }
    printf("\n");
  }
  int hist = 0, same = 1;
  for (int i = 0; i < plan->n_runs; ++i)
    if (plan->runs[i].knob == RS_KNOB_HISTORY) {
      hist = 1;
      same &= rep->rows[i].identical_to_default;
    }
  if (hist)
    printf("output.history_every: only time; the answers are %s those of the defaults\n",
           same ? "bit for bit" : "NOT");
}

/* Releases the stress history of a finished run: the study only times it (a fine history
 * of a long reel holds hundreds of MB). */
static void slim(rs_reel_result *res) { rs_reel_result_drop_history(res); }


/* One study's runs: their scenes, jobs and what the analysis reads of them. */
typedef struct study_runs {
  int n;
  rs_scene **scenes;
  rs_reel_job *jobs;
  const rs_reel_result **results;
  double *wall, *cpu;
} study_runs;

static void study_runs_free(study_runs *r)
{
  for (int i = 0; r->jobs && i < r->n; ++i) rs_reel_result_destroy(&r->jobs[i].result);
  for (int i = 0; r->scenes && i < r->n; ++i) rs_scene_destroy(&r->scenes[i]);
  free(r->scenes);
  free(r->jobs);
  free(r->results);
  free(r->wall);
  free(r->cpu);
}

/* Every run is the scene with the user's overrides, then the run's own. */
static int load_runs(const cli_args *a, const rs_study_plan *plan, study_runs *r)
{
  const int n = plan->n_runs;
  r->n = n;
  r->scenes = calloc((size_t)n, sizeof *r->scenes);
  r->jobs = calloc((size_t)n, sizeof *r->jobs);
  r->results = calloc((size_t)n, sizeof *r->results);
  r->wall = calloc((size_t)n, sizeof *r->wall);
  r->cpu = calloc((size_t)n, sizeof *r->cpu);
  const char **sets = calloc((size_t)a->n_sets + RS_STUDY_MAX_SETS, sizeof *sets);
  int code = CLI_EXIT_OK;
  if (!r->scenes || !r->jobs || !r->results || !r->wall || !r->cpu || !sets)
    code = cli_fail(CLI_EXIT_OTHER, "out of memory");
  for (int i = 0; code == CLI_EXIT_OK && i < n; ++i) {
    const rs_study_run *run = &plan->runs[i];
    for (int k = 0; k < a->n_sets; ++k) sets[k] = a->sets[k];
    for (int k = 0; k < run->n_sets; ++k) sets[a->n_sets + k] = run->sets[k];
    rs_status st = rs_scene_load(a->scene, a->n_sets + run->n_sets, sets, &r->scenes[i]);
    if (st != RS_OK) {
      app_error_wrap("study run '%s'", run->label);
      code = cli_fail_status(st);
      fprintf(stderr, "reelsim: study: nothing was wound\n");
    } else {
      r->jobs[i].problem = rs_scene_problem(r->scenes[i]);
      r->jobs[i].opts.progress = on_progress;
    }
  }
  free(sets);
  return code;
}

/* The runs wound a->jobs at a time; a signal stops the study, and so does a failure of
 * one of the first three runs (the reference and the defaults the others are held to). */
static int wind_runs(const cli_args *a, const rs_study_plan *plan, study_runs *r)
{
  const int n = r->n;
  for (int first = 0; first < n; first += a->jobs) {
    int m = n - first < a->jobs ? n - first : a->jobs;
    rs_status st = rs_reel_wind_many(m, r->jobs + first, m, NULL);
    if (st != RS_OK) return cli_fail_status(st);
    int sig = cli_signal_caught();
    if (sig)
      return cli_fail(cli_signal_exit_code(sig), "study: %s (no output written)",
                      cli_signal_word(sig));
    for (int i = first; i < first + m; ++i) {
      rs_reel_job *job = &r->jobs[i];
      slim(job->result);
      r->wall[i] = job->wall_seconds;
      r->cpu[i] = job->cpu_seconds;
      r->results[i] = job->status == RS_OK ? job->result : NULL;
      if (!a->quiet) {
        printf("  [%2d/%d] %-34s %8.2f s%s%s\n", i + 1, n, plan->runs[i].label, job->wall_seconds,
               job->status ? "  FAILED: " : "", job->status ? job->message : "");
        fflush(stdout);
      }
      if (job->status != RS_OK && i < 3)
        return cli_fail(rs_status_exit_code(job->status), "study: the %s run failed: %s",
                        plan->runs[i].label, job->message);
    }
  }
  return CLI_EXIT_OK;
}

/* study.h5, study.csv and study.png in dir (made now: a failed study leaves none). */
static int write_study(const cli_args *a, const rs_scene *base, const rs_study_report *rep,
                       const char *dir, cli_outdir *made, double t_start)
{
  char path[RS_PATH_MAX + 32];
  int code = cli_outdir_make(DIR_LABEL, dir, made);
  if (code != CLI_EXIT_OK) return code;
  snprintf(path, sizeof path, "%s/study.h5", dir);
  rs_status st = rs_study_write(path, base, rep);
  if (st == RS_OK) {
    snprintf(path, sizeof path, "%s/study.csv", dir);
    st = rs_study_write_csv(path, rep);
  }
  if (st != RS_OK) return cli_fail_status(st);
  snprintf(path, sizeof path, "%s/study.png", dir);
  st = rs_study_plot(rep, rs_scene_title(base), path, NULL);
  if (st != RS_OK)
    return cli_fail(CLI_EXIT_OTHER, "study: the plot: %s (study.h5 and study.csv are written)",
                    app_error_message());
  if (!a->quiet)
    printf("output %s/study.h5, %s/study.csv, %s/study.png (%.1f s in all)\n", dir, dir, dir,
           rs_clock_wall() - t_start);
  return CLI_EXIT_OK;
}

int cli_study(const cli_args *a)
{
  int code = CLI_EXIT_OK;
  double t_start = rs_clock_wall();
  rs_scene *base = NULL;
  rs_study_plan *plan = NULL;
  study_runs runs = {0};
  rs_study_report rep = {0};
  cli_outdir made = {NULL, NULL};
  char name[256], dir[RS_PATH_MAX];
  cli_signals sig_saved;
  cli_signals_install(&sig_saved);

  rs_status st = rs_scene_load(a->scene, a->n_sets, a->sets, &base);
  if (st == RS_OK) cli_scene_warnings(base);
  if (st == RS_OK) st = rs_study_plan_create(base, a->quick, &plan);
  if (st != RS_OK) {
    code = cli_fail_status(st);
    goto done;
  }
  if ((code = load_runs(a, plan, &runs)) != CLI_EXIT_OK) goto done;
  rs_scene_name(base, name, sizeof name);
  if (a->output) snprintf(dir, sizeof dir, "%s", a->output);
  else snprintf(dir, sizeof dir, "study-%s", name);
  /* checked now, made when there is something to write: an interrupted or failed study
   * leaves no empty directory */
  if ((code = cli_outdir_check(DIR_LABEL, dir)) != CLI_EXIT_OK) goto done;
  if (!a->quiet) {
    printf("study: %s (%s), %d layers: %d runs%s, %d at a time\n", a->scene, rs_scene_title(base),
           rs_scene_problem(base)->n_layers, runs.n, a->quick ? " (quick)" : "", a->jobs);
    fflush(stdout);
  }
  if ((code = wind_runs(a, plan, &runs)) != CLI_EXIT_OK) goto done;
  st = rs_study_analyze(plan, runs.results, runs.wall, runs.cpu,
                        rs_scene_problem(base)->material.caliper, &rep);
  if (st != RS_OK) {
    code = cli_fail_status(st);
    goto done;
  }
  if (!a->quiet) {
    print_report(plan, &rep, runs.jobs);
    print_summary(plan, &rep);
  }
  code = write_study(a, base, &rep, dir, &made, t_start);
done:
  /* the directories made for a study that then failed go again when they are empty */
  if (code != CLI_EXIT_OK) cli_outdir_undo(&made);
  else cli_outdir_free(&made);
  rs_study_report_free(&rep);
  study_runs_free(&runs);
  rs_study_plan_destroy(&plan);
  rs_scene_destroy(&base);
  cli_signals_restore(&sig_saved);
  return code;
}
