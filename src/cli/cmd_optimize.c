/* reelsim optimize: the best recipe within ranges of scene values, under constraints on
 * the run's figures (docs/cli.md, docs/optimize.md). Everything the command line says is
 * checked before anything is wound (exit 2 naming the argument); then the search
 * (sweep/optimize.h), the best values and figures on stdout, the best scene as YAML (-o)
 * and every evaluation in an HDF5 history file. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/signals.h"
#include "reelsim/output.h"
#include "reelsim/scene.h"
#include "sweep/app_error.h"
#include "sweep/optimize.h"

typedef struct opt_cli {
  int n_vars;
  opt_var *vars;
  opt_constraint *cons;
  opt_target target;
  int has_target;
  char output[RS_PATH_MAX], history[RS_PATH_MAX];
  int quiet;
} opt_cli;

static int on_progress(void *user, int layers_done, int layers_total)
{
  (void)user;
  (void)layers_done;
  (void)layers_total;
  return cli_signal_caught() != 0;
}

static const char *quantity_name(const opt_problem *p, int q)
{
  return q < OPT_N_FIGURES ? opt_figure_name(q) : p->vars[q - OPT_N_FIGURES].key;
}

/* A table column: as wide as its name, at least 12. */
static int width(const char *name)
{
  int n = (int)strlen(name);
  return n > 12 ? n : 12;
}

/* One line per evaluation: its number, phase, values, objective, feasible or why not. */
static int after_each(void *user, const opt_history *h)
{
  const opt_problem *p = user;
  int i = h->n - 1;
  printf("%4d %-6s", i + 1, h->phase[i] ? "cobyla" : "start");
  for (int k = 0; k < p->n_vars; ++k)
    printf(" %*.6g", width(p->vars[k].key), h->values[(size_t)i * (size_t)p->n_vars + (size_t)k]);
  double st = h->figures[(size_t)i * OPT_N_FIGURES + OPT_STATUS];
  int w = width(quantity_name(p, p->objective));
  if (st != 0) {
    printf(" %*s", w, "-");
    for (int j = 0; j < p->n_cons; ++j) printf(" %*s", width(quantity_name(p, p->cons[j].quantity)), "-");
    printf("  %s\n", st == 2 ? "refused" : st == 3 ? "solver failed" : "failed");
  } else {
    printf(" %*.6g", w, opt_quantity(p, h, i, p->objective));
    /* each constraint's quantity, so that "infeasible" says by how much */
    for (int j = 0; j < p->n_cons; ++j)
      printf(" %*.6g", width(quantity_name(p, p->cons[j].quantity)),
             opt_quantity(p, h, i, p->cons[j].quantity));
    printf("  %s\n", opt_feasible(p, h, i) ? "feasible" : "infeasible");
  }
  fflush(stdout);
  return cli_signal_caught() != 0;
}

/* The figure or key name, with its unit, in a way a reader takes in. */
static void print_quantity(const opt_problem *p, const opt_history *h, int i, int q)
{
  double v = opt_quantity(p, h, i, q);
  const char *unit = q < SWEEP_N_FIGURES ? sweep_figures[q].unit : q == OPT_MISFIT ? "Pa" : "";
  printf("  %-22s %.10g%s%s\n", quantity_name(p, q), v, unit[0] ? " " : "", unit);
}

static int parse_all(const cli_args *a, opt_cli *c, opt_problem *p)
{
  c->n_vars = a->n_vary;
  c->vars = calloc((size_t)(a->n_vary ? a->n_vary : 1), sizeof *c->vars);
  c->cons = calloc((size_t)(a->n_subject_to ? a->n_subject_to : 1), sizeof *c->cons);
  if (!c->vars || !c->cons) return cli_fail(CLI_EXIT_OTHER, "out of memory");
  if (a->n_vary == 0)
    return cli_fail(CLI_EXIT_USAGE, "optimize: give at least one --vary KEY=LO:HI");
  for (int k = 0; k < a->n_vary; ++k) {
    rs_status st = sweep_vary_parse(a->vary[k], SWEEP_VARY_RANGE, &c->vars[k]);
    if (st != RS_OK) return cli_fail_status(st);
    for (int j = 0; j < k; ++j)
      if (strcmp(c->vars[j].key, c->vars[k].key) == 0)
        return cli_fail(CLI_EXIT_USAGE, "optimize: --vary %s: %s is varied twice", a->vary[k],
                        c->vars[k].key);
  }
  if (!a->minimize == !a->maximize)
    return cli_fail(CLI_EXIT_USAGE, "optimize: give %s --minimize FIGURE or --maximize FIGURE",
                    a->minimize ? "only one of" : "one of");
  const char *obj = a->minimize ? a->minimize : a->maximize;
  char names[512];
  opt_figure_list(names, sizeof names);
  p->objective = opt_quantity_index(obj, c->n_vars, c->vars);
  if (p->objective < 0)
    return cli_fail(CLI_EXIT_USAGE, "optimize: %s %s: unknown figure (figures: %s, or a varied key)",
                    a->minimize ? "--minimize" : "--maximize", obj, names);
  p->maximize = a->maximize != NULL;
  for (int j = 0; j < a->n_subject_to; ++j) {
    char why[256];
    if (opt_constraint_parse(a->subject_to[j], c->n_vars, c->vars, &c->cons[j], why, sizeof why) != 0)
      return cli_fail(CLI_EXIT_USAGE, "optimize: --subject-to '%s': %s%s%s", a->subject_to[j], why,
                      strstr(why, "unknown figure") ? " (figures: " : "",
                      strstr(why, "unknown figure") ? names : "");
  }
  int uses_misfit = p->objective == OPT_MISFIT;
  for (int j = 0; j < a->n_subject_to; ++j) uses_misfit |= c->cons[j].quantity == OPT_MISFIT;
  if (a->target_profile) {
    char err[1024];
    if (opt_target_read(a->target_profile, &c->target, err, sizeof err) != 0)
      return cli_fail(CLI_EXIT_USAGE, "optimize: --target-profile %s", err);
    c->has_target = 1;
  } else if (uses_misfit) {
    return cli_fail(CLI_EXIT_USAGE, "optimize: the misfit needs --target-profile FILE.csv");
  }
  p->n_vars = c->n_vars;
  p->vars = c->vars;
  p->n_cons = a->n_subject_to;
  p->cons = c->cons;
  p->target = c->has_target ? &c->target : NULL;
  return -1;
}

/* -o (default <scene name>-best.yaml) and the history file (--history, default the -o
 * name with .h5 for its .yaml/.yml extension). */
static int name_outputs(const cli_args *a, opt_cli *c)
{
  if (a->output) snprintf(c->output, sizeof c->output, "%s", a->output);
  else {
    char name[256];
    const char *base = strrchr(a->scene, '/');
    snprintf(name, sizeof name, "%s", base ? base + 1 : a->scene);
    char *dot = strrchr(name, '.');
    if (dot && dot != name) *dot = '\0';
    snprintf(c->output, sizeof c->output, "%s-best.yaml", name);
  }
  if (a->history) snprintf(c->history, sizeof c->history, "%s", a->history);
  else {
    snprintf(c->history, sizeof c->history, "%s", c->output);
    char *dot = strrchr(c->history, '.'), *slash = strrchr(c->history, '/');
    if (dot && (!slash || dot > slash + 1) && (!strcmp(dot, ".yaml") || !strcmp(dot, ".yml")))
      *dot = '\0';
    size_t len = strlen(c->history);
    if (len + 4 > sizeof c->history) return cli_fail(CLI_EXIT_USAGE, "optimize: -o %s: name too long", c->output);
    strcat(c->history, ".h5");
  }
  const char *files[2] = {c->output, c->history}, *flags[2] = {"-o", "--history"};
  for (int i = 0; i < 2; ++i) { /* the folder must be there: found now, not after the search */
    char dir[RS_PATH_MAX];
    snprintf(dir, sizeof dir, "%s", files[i]);
    char *slash = strrchr(dir, '/');
    if (!slash) continue;
    if (slash == dir) slash[1] = '\0';
    else *slash = '\0';
    struct stat st;
    if (stat(dir, &st) != 0)
      return cli_fail(CLI_EXIT_USAGE, "optimize: %s %s: directory '%s' does not exist", flags[i],
                      files[i], dir);
    if (!S_ISDIR(st.st_mode))
      return cli_fail(CLI_EXIT_USAGE, "optimize: %s %s: %s is not a directory", flags[i], files[i], dir);
  }
  if (strcmp(c->output, c->history) == 0)
    return cli_fail(CLI_EXIT_USAGE, "optimize: -o and --history name the same file (%s)", c->output);
  return -1;
}

/* The best scene, resolved (defaults filled, overrides and the best values applied), to
 * c->output; then loaded back to be sure it stands on its own. */
/* The best scene's title: the scene's own, then what made it the best ("..., optimized:
 * winding.tension=133.5 for the greatest winding.tension"), so the file does not pass for
 * the scene it came from. */
static void best_title(const opt_problem *p, const opt_history *h, const char *old, char *buf,
                       size_t size)
{
  size_t used = (size_t)snprintf(buf, size, "title=%s, optimized:", old && old[0] ? old : "reelsim scene");
  for (int k = 0; k < p->n_vars && used < size; ++k) {
    char num[32];
    used += (size_t)snprintf(buf + used, size - used, "%s %s=%s", k ? "," : "", p->vars[k].key,
                             rs_output_shortest(num, h->values[(size_t)h->best * (size_t)p->n_vars + (size_t)k]));
  }
  if (used < size)
    snprintf(buf + used, size - used, " for the %s %s", p->maximize ? "greatest" : "least",
             quantity_name(p, p->objective));
}

/* The best scene, resolved (defaults filled, overrides and the best values applied, a
 * title that says so), to c->output; then loaded back to be sure it stands on its own. */
static int write_best(const cli_args *a, const opt_cli *c, const opt_problem *p, const opt_history *h)
{
  int n;
  char **sets = opt_sets_of(p, h, h->best, &n);
  if (!sets) return cli_fail(CLI_EXIT_OTHER, "out of memory");
  const char **all = calloc((size_t)n + 2, sizeof *all);
  char title[1024];
  rs_scene *scene = NULL;
  rs_status st = all ? rs_scene_load(a->scene, n, (const char *const *)sets, &scene)
                     : APP_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) {
    best_title(p, h, rs_scene_title(scene), title, sizeof title);
    rs_scene_destroy(&scene);
    memcpy(all, sets, (size_t)n * sizeof *all);
    all[n] = title;
    st = rs_scene_load(a->scene, n + 1, all, &scene);
  }
  free(sets);
  free(all);
  if (st != RS_OK) return cli_fail_status(st);
  int code = -1;
  const char *text = rs_scene_resolved_text(scene);
  st = rs_output_write_file(c->output, text, strlen(text));
  if (st != RS_OK) code = cli_fail_status(st);
  rs_scene_destroy(&scene);
  if (code >= 0) return code;
  st = rs_scene_load(c->output, 0, NULL, &scene);
  rs_scene_destroy(&scene);
  if (st != RS_OK) {
    cli_fail_status(st);
    return cli_fail(CLI_EXIT_OTHER, "optimize: internal error: the best scene %s does not load again", c->output);
  }
  return -1;
}

static void print_head(const opt_problem *p)
{
  printf("optimize: %s %s", p->maximize ? "maximize" : "minimize", quantity_name(p, p->objective));
  for (int j = 0; j < p->n_cons; ++j)
    printf("%s %s %s %.10g", j ? "," : " subject to", quantity_name(p, p->cons[j].quantity),
           p->cons[j].ge ? ">=" : "<=", p->cons[j].bound);
  int K = p->n_vars;
  int n0 = p->settings.n_start > 0 ? p->settings.n_start : 4 * K + 4;
  int maxeval = p->settings.maxeval > 0 ? p->settings.maxeval : 30 * K + 30;
  printf("\n  over");
  for (int k = 0; k < K; ++k) printf(" %s in [%.10g, %.10g]", p->vars[k].key, p->vars[k].lo, p->vars[k].hi);
  printf("\n  values rounded to");
  for (int k = 0; k < K; ++k) printf("%s %g (%s)", k ? "," : "", opt_resolution(&p->vars[k]), p->vars[k].key);
  printf("\n  %d Latin-hypercube points, then COBYLA from the best (at most %d runs, xtol_rel %g)\n",
         n0, maxeval, p->settings.xtol_rel);
  printf("\n%4s %-6s", "run", "phase");
  for (int k = 0; k < K; ++k) printf(" %*s", width(p->vars[k].key), p->vars[k].key);
  printf(" %*s", width(quantity_name(p, p->objective)), quantity_name(p, p->objective));
  for (int j = 0; j < p->n_cons; ++j)
    printf(" %*s", width(quantity_name(p, p->cons[j].quantity)), quantity_name(p, p->cons[j].quantity));
  printf("\n");
}

/* Before any winding: the scene as given, then every key at LO and HI; a figure the scene
 * does not have (a storage figure without storage stages, a lanes' figure without lanes:
 * never met) is refused. Returns -1 when all is well, else the exit code. */
static int check_before(const cli_args *a, const opt_cli *c, const opt_problem *p)
{
  int code = -1;
  for (int k = 0; k < c->n_vars && code < 0; ++k) {
    rs_status st = sweep_vary_check(a->scene, a->n_sets, a->sets, &c->vars[k]);
    if (st != RS_OK) code = cli_fail_status(st);
  }
  if (code >= 0) return code;
  rs_scene *base = NULL;
  if (rs_scene_load(a->scene, a->n_sets, a->sets, &base) == RS_OK) {
    int q[64], nq = 0;
    q[nq++] = p->objective;
    for (int j = 0; j < p->n_cons && nq < 64; ++j) q[nq++] = p->cons[j].quantity;
    for (int k = 0; k < nq && code < 0; ++k) {
      const char *lacks = q[k] < SWEEP_N_FIGURES ? sweep_figure_lacks(rs_scene_problem(base), q[k]) : NULL;
      if (lacks)
        code = cli_fail(CLI_EXIT_USAGE, "optimize: %s: %s has %s", opt_figure_name(q[k]), a->scene, lacks);
    }
  }
  app_error_clear();
  rs_scene_destroy(&base);
  return code;
}

/* The best run's settings and figures, and the files written. */
static void print_best(const opt_cli *c, const opt_problem *p, const opt_history *h)
{
  int failed = 0;
  for (int i = 0; i < h->n; ++i) failed += h->figures[(size_t)i * OPT_N_FIGURES + OPT_STATUS] != 0;
  printf("\nbest: run %d of %d (%d in the start, %d refused or failed; COBYLA: %s)\n", h->best + 1,
         h->n, h->n_start, failed, opt_result_text(h));
  for (int k = 0; k < p->n_vars; ++k) print_quantity(p, h, h->best, OPT_N_FIGURES + k);
  printf("figures:\n");
  for (int f = 0; f < OPT_N_FIGURES; ++f)
    if (f != OPT_STATUS && opt_figure_recorded(p, h, f)) print_quantity(p, h, h->best, f);
  printf("wrote %s (the best scene) and %s (every run)\n", c->output, c->history);
}

int cli_optimize(const cli_args *a)
{
  opt_cli c;
  memset(&c, 0, sizeof c);
  opt_problem p;
  memset(&p, 0, sizeof p);
  opt_settings_default(&p.settings);
  p.scene = a->scene;
  p.n_sets = a->n_sets;
  p.sets = a->sets;
  opt_history h;
  memset(&h, 0, sizeof h);
  int code = parse_all(a, &c, &p);
  if (code < 0) code = name_outputs(a, &c);
  if (code < 0) code = check_before(a, &c, &p);
  if (code >= 0) goto done;
  rs_scene *base = NULL;
  if (rs_scene_load(a->scene, a->n_sets, a->sets, &base) == RS_OK) cli_scene_warnings(base);
  app_error_clear();
  rs_scene_destroy(&base);

  cli_signals sig;
  cli_signals_install(&sig);
  rs_reel_options wind = {on_progress, NULL};
  p.wind = &wind;
  if (!a->quiet) {
    print_head(&p);
    p.after = after_each;
  }
  p.user = &p;
  char why[512];
  int rc = opt_run(&p, &h, why, sizeof why);
  int caught = cli_signal_caught();
  cli_signals_restore(&sig);
  if (caught) {
    code = cli_fail(cli_signal_exit_code(caught), "optimize: %s after %d run%s (no output written)",
                    cli_signal_word(caught), h.n, h.n == 1 ? "" : "s");
    goto done;
  }
  if (rc != 0) {
    code = cli_fail(CLI_EXIT_OTHER, "optimize: %s", why);
    goto done;
  }
  if (opt_history_write(c.history, &p, &h, why, sizeof why) != 0) {
    code = cli_fail(CLI_EXIT_OTHER, "optimize: %s", why);
    goto done;
  }
  if (h.best < 0) {
    code = cli_fail(CLI_EXIT_OTHER, "optimize: no run of the %d met every constraint (every run in %s)",
                    h.n, c.history);
    goto done;
  }
  code = write_best(a, &c, &p, &h);
  if (code >= 0) goto done;
  code = CLI_EXIT_OK;
  if (a->quiet) goto done;
  print_best(&c, &p, &h);
done:
  for (int k = 0; k < c.n_vars; ++k) sweep_vary_clear(&c.vars[k]);
  free(c.vars);
  free(c.cons);
  opt_target_free(&c.target);
  opt_history_free(&h);
  return code;
}
