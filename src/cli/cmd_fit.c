/* reelsim fit stack TEST.csv --law pfeiffer|hakiel|linear|table [--terms N] [--cycle K]
 *     [-o MODEL.yaml] [--base MODEL] [--plot FIT.png] [--json]
 * The radial stack law fitted to a stack test (docs/calibrate.md). Exit 0 ok, 2 bad input
 * or data that cannot determine the law, 3 the optimiser failed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/json.h"
#include "reelsim/fit.h"
#include "reelsim/version.h"

#ifndef RS_FIT_MODELS_DIR
#define RS_FIT_MODELS_DIR ""
#endif

typedef struct fit_args {
  const char *csv, *law, *out, *base, *plot;
  int terms, cycle, json;
} fit_args;

static int parse_int(const char *opt, const char *s, int *v)
{
  char *end = NULL;
  long x = s ? strtol(s, &end, 10) : 0;
  if (!s || !*s || *end || x < 0 || x > 1000000)
    return cli_fail(CLI_EXIT_USAGE, "fit stack: %s needs a whole number >= 0 (got '%s')", opt,
                    s ? s : "");
  *v = (int)x;
  return -1;
}

static int parse_args(int argc, char **argv, fit_args *f)
{
  memset(f, 0, sizeof *f);
  f->cycle = -1;
  for (int i = 3; i < argc; ++i) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    int code = -1;
    if (strcmp(a, "--law") == 0 && v) f->law = argv[++i];
    else if (strcmp(a, "-o") == 0 && v) f->out = argv[++i];
    else if (strcmp(a, "--base") == 0 && v) f->base = argv[++i];
    else if (strcmp(a, "--plot") == 0 && v) f->plot = argv[++i];
    else if (strcmp(a, "--terms") == 0) code = parse_int(a, argv[++i < argc ? i : argc - 1], &f->terms);
    else if (strcmp(a, "--cycle") == 0) code = parse_int(a, argv[++i < argc ? i : argc - 1], &f->cycle);
    else if (strcmp(a, "--json") == 0) f->json = 1;
    else if (a[0] == '-')
      return cli_fail(CLI_EXIT_USAGE, "fit stack: unknown option or missing value '%s' (see "
                                      "docs/calibrate.md)", a);
    else if (!f->csv) f->csv = a;
    else return cli_fail(CLI_EXIT_USAGE, "fit stack: one stack test at a time (got '%s' too)", a);
    if (code >= 0) return code;
  }
  if (!f->csv || !f->law)
    return cli_fail(CLI_EXIT_USAGE, "usage: reelsim fit stack TEST.csv --law "
                                    "pfeiffer|hakiel|linear|table [--terms N] [--cycle K] "
                                    "[-o MODEL.yaml] [--base MODEL] [--plot FIT.png] [--json]");
  if (rs_fit_law_parse(f->law) < 0)
    return cli_fail(CLI_EXIT_USAGE, "fit stack: --law must be pfeiffer, hakiel, linear or table "
                                    "(got '%s')", f->law);
  return -1;
}

/* the base model's text: a path, or a name looked up as a scene's `material:` is */
static char *read_base(const char *base)
{
  char path[4096];
  const char *dirs[] = {"", "models/", getenv("REELSIM_MODELS"), RS_FIT_MODELS_DIR};
  for (size_t d = 0; d < sizeof dirs / sizeof dirs[0]; ++d) {
    if (!dirs[d]) continue;
    const int plain = strchr(base, '/') || strstr(base, ".yaml");
    snprintf(path, sizeof path, "%s%s%s%s", dirs[d],
             dirs[d][0] && dirs[d][strlen(dirs[d]) - 1] != '/' ? "/" : "", base, plain ? "" : ".yaml");
    FILE *f = fopen(path, "rb");
    if (!f) continue;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (s && fread(s, 1, (size_t)n, f) == (size_t)n) s[n] = 0;
    else {
      free(s);
      s = NULL;
    }
    fclose(f);
    return s;
  }
  return NULL;
}

static void print_text(const fit_args *f, const rs_fit_stack_result *r, const double *P,
                       const double *eps)
{
  printf("stack law fitted to %s: %s, %d points, %.4g .. %.4g Pa (%d evaluations)\n", f->csv,
         f->law, r->n_points, r->P_min, r->P_max, r->evaluations);
  printf("  %-12s %-14s %s\n", "parameter", "value", "95 % confidence interval");
  for (int i = 0; i < r->n_params; ++i) {
    printf("  %-12s %-14.6g %.6g .. %.6g", r->name[i], r->value[i], r->value[i] - r->half_width[i],
           r->value[i] + r->half_width[i]);
    if (r->value[i] != 0.0) printf(" (+- %.2g %%)", 100.0 * r->half_width[i] / fabs(r->value[i]));
    printf("%s\n", r->value[i] == 0.0 ? " (at its bound 0)" : "");
  }
  printf("  RMS residual %.3g (strain)\n", r->rms);
  printf("  worst point  #%d: P = %.6g Pa, strain %.6g measured, %.6g fitted (%+.3g)\n",
         r->worst + 1, P[r->worst], eps[r->worst], eps[r->worst] + r->worst_residual,
         r->worst_residual);
  printf("  E_r at 0 and %.4g Pa: %.4g, %.4g Pa\n", r->P_max, rs_radial_modulus(&r->radial, 0.0),
         rs_radial_modulus(&r->radial, r->P_max));
}

static void print_json(const fit_args *f, const rs_fit_stack_result *r, const double *P,
                       const double *eps)
{
  cli_json j;
  cli_json_init(&j, stdout);
  cli_json_object(&j, NULL);
  cli_json_string(&j, "reelsim", RS_VERSION_STRING);
  cli_json_string(&j, "command", "fit stack");
  cli_json_string(&j, "data", f->csv);
  cli_json_string(&j, "law", f->law);
  cli_json_int(&j, "points", r->n_points);
  cli_json_number(&j, "pressure_min", r->P_min);
  cli_json_number(&j, "pressure_max", r->P_max);
  cli_json_array(&j, "parameters");
  for (int i = 0; i < r->n_params; ++i) {
    cli_json_object(&j, NULL);
    cli_json_string(&j, "name", r->name[i]);
    cli_json_number(&j, "value", r->value[i]);
    cli_json_number(&j, "ci95_low", r->value[i] - r->half_width[i]);
    cli_json_number(&j, "ci95_high", r->value[i] + r->half_width[i]);
    cli_json_end(&j);
  }
  cli_json_end(&j);
  cli_json_number(&j, "rms_residual", r->rms);
  cli_json_object(&j, "worst");
  cli_json_int(&j, "index", r->worst);
  cli_json_number(&j, "pressure", P[r->worst]);
  cli_json_number(&j, "strain", eps[r->worst]);
  cli_json_number(&j, "residual", r->worst_residual);
  cli_json_end(&j);
  cli_json_string(&j, "model", f->out);
  cli_json_end(&j);
  printf("\n");
}

static int fit_stack(int argc, char **argv)
{
  fit_args f;
  int code = parse_args(argc, argv, &f);
  if (code >= 0) return code;
  char *base = NULL;
  if (f.base && !(base = read_base(f.base)))
    return cli_fail(CLI_EXIT_USAGE, "fit stack: --base: no material model '%s' (looked beside "
                                    "the working directory, in models/, $REELSIM_MODELS and the "
                                    "shipped models)", f.base);
  double *P = NULL, *eps = NULL;
  int n = 0;
  rs_fit_stack_result r;
  rs_status st = rs_fit_stack_read(f.csv, f.cycle, &P, &eps, &n);
  if (!st) {
    st = rs_fit_stack(n, P, eps, (rs_radial_kind)rs_fit_law_parse(f.law), f.terms, &r);
    if (st) rs_error_wrap("%s", f.csv);
  }
  if (!st && f.plot) {
    char title[512];
    snprintf(title, sizeof title, "Stack test %s: %s law", f.csv, f.law);
    st = rs_fit_stack_plot(f.plot, n, P, eps, &r, title);
  }
  if (!st && f.out) st = rs_fit_stack_write_model(f.out, &r, f.csv, base);
  if (!st) {
    if (f.json) print_json(&f, &r, P, eps);
    else {
      print_text(&f, &r, P, eps);
      if (f.out) printf("  model        %s (material: %s in a scene)\n", f.out, f.out);
      if (f.plot) printf("  plot         %s\n", f.plot);
    }
  }
  free(P);
  free(eps);
  free(base);
  return st ? cli_fail_status(st) : CLI_EXIT_OK;
}

/* `reelsim fit --help`, `reelsim help fit`: fit parses its own arguments, so its help is
 * here rather than in the option table. */
void cli_fit_usage(FILE *out)
{
  fputs("usage: reelsim fit stack TEST.csv --law pfeiffer|hakiel|linear|table [--terms N]\n"
        "                 [--cycle K] [-o MODEL.yaml] [--base MODEL] [--plot FIT.png] [--json]\n"
        "       reelsim fit roll SCENE --measured DATA.csv --vary KEY=LO:HI [--vary ...]\n"
        "                 [--set KEY=VALUE ...] [--threads N] [-o BEST.yaml] [--json]\n"
        "\n"
        "fit stack: the radial stack law fitted to a stack test (columns strain,pressure\n"
        "[,cycle]): each parameter with its 95 % interval, the RMS residual and the worst\n"
        "point; -o writes a material model loadable as material:.\n"
        "fit roll: scene keys fitted to what the plant measured (columns length|radius and\n"
        "diameter|pressure|wound_in_tension), the same report, -o the best scene.\n"
        "\n"
        "Details: docs/calibrate.md. Exit status: 0 ok, 2 bad input or data that cannot\n"
        "determine the fit, 3 the solver failed.\n",
        out);
}

/* The flags of `fit stack` and `fit roll` as the parsers above take them (the bash
 * completion offers them; tests/cli/completion.sh holds them to the usage text). */
const char cli_fit_stack_flags[] = "--law --terms --cycle -o --base --plot --json";
const char cli_fit_roll_flags[] = "--measured --vary --set --threads -o --json";

static int wants_help(const char *a)
{
  return strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0;
}

int cli_fit(int argc, char **argv)
{
  if ((argc >= 3 && wants_help(argv[2])) || (argc >= 4 && wants_help(argv[3]))) {
    cli_fit_usage(stdout);
    return CLI_EXIT_OK;
  }
  if (argc >= 3 && strcmp(argv[2], "stack") == 0) return fit_stack(argc, argv);
  if (argc >= 3 && strcmp(argv[2], "roll") == 0) return cli_fit_roll(argc, argv);
  return cli_fail(CLI_EXIT_USAGE, "fit: what to fit: 'reelsim fit stack TEST.csv --law LAW ...' "
                                  "or 'reelsim fit roll SCENE --measured DATA.csv --vary KEY=LO:HI' "
                                  "(docs/calibrate.md)");
}
