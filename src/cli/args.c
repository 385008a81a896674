/* One argument parser for every command: getopt_long over the option table (options.h).
 * Options and operands may come in any order; "--" ends the options. Long options take
 * their argument as "--set KEY=VALUE" or "--set=KEY=VALUE" and may be abbreviated to a
 * unique prefix (getopt_long's rule). An option that exists but not for this command says
 * which commands take it; an unknown one is named. Both exit 2. */
#define _DEFAULT_SOURCE /* getopt_long (glibc, BSD): not in POSIX */
#include "cli/args.h"

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/fail.h"
#include "cli/usage.h"

/* getopt_long returns LONG_BASE + id for a long option, the letter for a short one, 1 for
 * an operand (the leading '-' of the short string: operands in order, whatever
 * POSIXLY_CORRECT says), ':' for a missing argument and '?' for an unknown option. */
enum { LONG_BASE = 256 };

typedef struct tables {
  struct option longopts[CLI_N_OPTS + 1];
  char shorts[2 + 2 * CLI_N_OPTS + 1];
} tables;

static void build(tables *t)
{
  int n = 0, seen[CLI_N_OPTS] = {0};
  size_t k = 0;
  t->shorts[k++] = '-';
  t->shorts[k++] = ':';
  for (int i = 0; i < cli_n_options; ++i) {
    const cli_option *o = &cli_options[i];
    if (seen[o->id]) continue;
    seen[o->id] = 1;
    t->longopts[n++] = (struct option){o->name, o->arg ? required_argument : no_argument, NULL,
                                       LONG_BASE + (int)o->id};
    if (o->short_name) {
      t->shorts[k++] = o->short_name;
      if (o->arg) t->shorts[k++] = ':';
    }
  }
  t->longopts[n] = (struct option){NULL, 0, NULL, 0};
  t->shorts[k] = '\0';
}

/* The option (any row: for its names) of getopt's return value c, or NULL. */
static const cli_option *option_of(int c)
{
  if (c <= 0) return NULL;
  for (int i = 0; i < cli_n_options; ++i) {
    const cli_option *o = &cli_options[i];
    if (c >= LONG_BASE ? (int)o->id == c - LONG_BASE : o->short_name == c) return o;
  }
  return NULL;
}

/* "run and compare": the commands that take option o. */
static void takers(const cli_option *any, char *buf, size_t size)
{
  unsigned cmds = 0;
  for (int i = 0; i < cli_n_options; ++i)
    if (cli_options[i].id == any->id) cmds |= cli_options[i].cmds;
  int n = 0, total = 0;
  for (int i = 0; i < cli_n_commands; ++i) total += (cli_commands[i].bit & cmds) != 0;
  size_t used = 0;
  buf[0] = '\0';
  for (int i = 0; i < cli_n_commands && used < size; ++i) {
    if (!(cli_commands[i].bit & cmds)) continue;
    ++n;
    used += (size_t)snprintf(buf + used, size - used, "%s%s",
                             n == 1 ? "" : n == total ? " and " : ", ", cli_commands[i].name);
  }
}

void cli_args_free(cli_args *a)
{
  free(a->sets);
  free(a->vary);
  free(a->scenes);
  free(a->subject_to);
  free(a->variants);
  free(a->variant_of);
  a->variants = NULL;
  a->variant_of = NULL;
  free(a->owned);
  a->sets = NULL;
  a->vary = NULL;
  a->subject_to = NULL;
  a->scenes = NULL;
  a->owned = NULL;
}

/* Stores one option's value; returns -1 to go on, or an exit status. */
static int take(cli_args *a, const cli_option *o, const char *typed, const char *arg)
{
  const char *cmd = a->cmd->name;
  if (o->arg && !arg[0] && o->id != CLI_OPT_SET)
    return cli_fail(CLI_EXIT_USAGE, "%s: %s needs %s", cmd, typed, o->needs);
  switch (o->id) {
  case CLI_OPT_HELP:
    cli_usage(stdout, a->cmd);
    return CLI_EXIT_OK;
  case CLI_OPT_OUTPUT: a->output = arg; break;
  case CLI_OPT_SET: a->sets[a->n_sets++] = arg; break;
  case CLI_OPT_CSV: a->csv_dir = arg; break;
  case CLI_OPT_QUIET: a->quiet = 1; break;
  case CLI_OPT_VERBOSE: a->verbose = 1; break;
  case CLI_OPT_KEEP_PARTIAL: a->keep_partial = 1; break;
  case CLI_OPT_QUICK: a->quick = 1; break;
  case CLI_OPT_JSON: a->json = 1; break;
  case CLI_OPT_RADIUS: a->radius = arg; break;
  case CLI_OPT_VARY: a->vary[a->n_vary++] = arg; break;
  case CLI_OPT_MINIMIZE:
  case CLI_OPT_MAXIMIZE: {
    const char **slot = o->id == CLI_OPT_MINIMIZE ? &a->minimize : &a->maximize;
    if (*slot)
      return cli_fail(CLI_EXIT_USAGE, "%s: %s given twice ('%s' and '%s')", cmd, typed, *slot, arg);
    *slot = arg;
    break;
  }
  case CLI_OPT_SUBJECT_TO: a->subject_to[a->n_subject_to++] = arg; break;
  case CLI_OPT_TARGET_PROFILE: a->target_profile = arg; break;
  case CLI_OPT_HISTORY: a->history = arg; break;
  case CLI_OPT_VARIANT:
    a->variant_of[a->n_variants] = a->n_scenes - 1;
    a->variants[a->n_variants++] = arg;
    break;
  case CLI_OPT_SAMPLE: a->sample = arg; break;
  case CLI_OPT_PROFILES: a->profiles = 1; break;
  case CLI_OPT_THREADS: {
    char *end;
    long j = strtol(arg, &end, 10);
    if (*end || j < 1 || j > 256)
      return cli_fail(CLI_EXIT_USAGE, "%s: --threads needs a number of threads in [1, 256] (got '%s')",
                      cmd, arg);
    a->threads = (int)j;
    break;
  }
  case CLI_OPT_JOBS: {
    char *end;
    long j = strtol(arg, &end, 10);
    if (*end || j < 1 || j > 64)
      return cli_fail(CLI_EXIT_USAGE, "%s: --jobs needs a number of threads in [1, 64] (got '%s')",
                      cmd, arg);
    a->jobs = (int)j;
    break;
  }
  case CLI_N_OPTS: break;
  }
  return -1;
}

int cli_parse(int argc, char **argv, int first, const cli_command *cmd, cli_args *a)
{
  memset(a, 0, sizeof *a);
  a->cmd = cmd;
  a->jobs = 1;
  /* room for every argument as a --set or an operand, plus -o's output.file */
  a->sets = calloc((size_t)argc + 1, sizeof *a->sets);
  a->scenes = calloc((size_t)argc + 1, sizeof *a->scenes);
  a->vary = calloc((size_t)argc + 1, sizeof *a->vary);
  a->subject_to = calloc((size_t)argc + 1, sizeof *a->subject_to);
  a->variants = calloc((size_t)argc + 1, sizeof *a->variants);
  a->variant_of = calloc((size_t)argc + 1, sizeof *a->variant_of);
  if (!a->sets || !a->scenes || !a->vary || !a->subject_to || !a->variants || !a->variant_of) return cli_fail(CLI_EXIT_OTHER, "out of memory");
  tables t;
  build(&t);
  /* getopt sees the command's name as its argv[0] */
  int n = argc - first + 1, c, code = -1;
  char **v = argv + first - 1, typed[64];
  opterr = 0;
  optind = 1;
  while (code < 0 && (c = getopt_long(n, v, t.shorts, t.longopts, NULL)) != -1) {
    if (c == 1) {
      a->scenes[a->n_scenes++] = optarg;
      continue;
    }
    const cli_option *o = option_of(c == ':' || c == '?' ? optopt : c);
    if (c == '?' && o && optopt >= LONG_BASE)
      return cli_fail(CLI_EXIT_USAGE, "%s: --%s takes no value (got '%s')", cmd->name, o->name,
                      v[optind - 1]);
    if (c == '?' || !o) {
      if (optopt && optopt < LONG_BASE) snprintf(typed, sizeof typed, "-%c", optopt);
      else snprintf(typed, sizeof typed, "%s", v[optind - 1]);
      return cli_fail(CLI_EXIT_USAGE, "%s: unknown option '%s' (see reelsim %s --help)",
                      cmd->name, typed, cmd->name);
    }
    if ((c == ':' ? optopt : c) >= LONG_BASE) snprintf(typed, sizeof typed, "--%s", o->name);
    else snprintf(typed, sizeof typed, "-%c", o->short_name);
    const cli_option *mine = cli_option_for(o->id, cmd->bit);
    if (!mine) {
      char who[128];
      takers(o, who, sizeof who);
      return cli_fail(CLI_EXIT_USAGE, "%s: %s only applies to %s", cmd->name, typed, who);
    }
    if (c == ':') return cli_fail(CLI_EXIT_USAGE, "%s: %s needs %s", cmd->name, typed, mine->needs);
    code = take(a, mine, typed, optarg);
  }
  if (code >= 0) return code;
  for (int i = optind; i < n; ++i) a->scenes[a->n_scenes++] = v[i]; /* after "--" */

  if (a->n_scenes == 0)
    return cli_fail(CLI_EXIT_USAGE, "%s: missing the %s (see reelsim %s --help)", cmd->name,
                    cmd->operand, cmd->name);
  if (a->n_scenes > 1 && !cmd->many)
    return cli_fail(CLI_EXIT_USAGE, "%s: one %s at a time (got '%s' and '%s')", cmd->name,
                    cmd->operand, a->scenes[0], a->scenes[1]);
  a->scene = a->scenes[0];
  /* the outputs that name files (plot's and study's -o and run's --csv name folders) */
  const int dir_out = (cmd->bit & (CLI_PLOT | CLI_STUDY)) != 0;
  const char *outs[] = {dir_out ? NULL : a->output, cmd->bit & CLI_RUN ? NULL : a->csv_dir,
                        a->history};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; outs[k] && i < a->n_scenes; ++i)
      if (cli_same_file(outs[k], a->scenes[i]))
        return cli_fail(CLI_EXIT_USAGE, "%s: the output '%s' is the input '%s' itself (it would be "
                        "overwritten)", cmd->name, outs[k], a->scenes[i]);
  if (a->output && (cmd->bit & (CLI_RUN | CLI_CHECK | CLI_COMPARE))) {
    /* recorded as an override so the resolved scene in the file names the real output */
    size_t len = strlen(a->output) + sizeof "output.file=";
    char *set = malloc(len);
    if (!set) return cli_fail(CLI_EXIT_OTHER, "out of memory");
    snprintf(set, len, "output.file=%s", a->output);
    a->owned = set;
    a->sets[a->n_sets++] = set;
    a->output = set + strlen("output.file=");
  }
  return -1;
}

int cli_same_file(const char *a, const char *b)
{
  struct stat sa, sb;
  return a && b && stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}
