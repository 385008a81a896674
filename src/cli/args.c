/* Options shared by the commands: SCENE, -o FILE, --set key.path=value, --quiet. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"

int cli_fail(int code, const char *fmt, ...)
{
  va_list ap;
  fputs("reelsim: ", stderr);
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
  return code;
}

int cli_fail_status(rs_status st)
{
  int code = rs_status_exit_code(st);
  if (st == RS_ERR_INPUT) return cli_fail(code, "%s", rs_error_message());
  if (st == RS_ERR_SOLVER)
    return cli_fail(code, "solver failure: %s\nreelsim:   (at %s)", rs_error_message(),
                    rs_error_where());
  return cli_fail(code, "%s: %s\nreelsim:   (at %s)", rs_status_name(st), rs_error_message(),
                  rs_error_where());
}

void cli_args_free(cli_args *a)
{
  free(a->sets);
  free(a->scenes);
  free(a->owned);
  a->sets = NULL;
  a->scenes = NULL;
  a->owned = NULL;
}

int cli_parse(int argc, char **argv, int first, cli_args *a)
{
  memset(a, 0, sizeof *a);
  a->cmd = argv[first - 1];
  /* room for every argument as a --set, plus -o's output.file */
  a->sets = calloc((size_t)argc + 1, sizeof *a->sets);
  a->scenes = calloc((size_t)argc + 1, sizeof *a->scenes);
  if (!a->sets || !a->scenes) return cli_fail(CLI_EXIT_OTHER, "out of memory");
  const int many = strcmp(a->cmd, "compare") == 0;
  for (int i = first; i < argc; ++i) {
    const char *arg = argv[i];
    if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
      cli_usage(stdout, a->cmd);
      return CLI_EXIT_OK;
    } else if (strcmp(arg, "--set") == 0 || strcmp(arg, "-s") == 0) {
      if (i + 1 >= argc)
        return cli_fail(CLI_EXIT_USAGE, "%s: --set needs key.path=value", a->cmd);
      a->sets[a->n_sets++] = argv[++i];
    } else if (strncmp(arg, "--set=", 6) == 0) {
      a->sets[a->n_sets++] = arg + 6;
    } else if (strcmp(arg, "-o") == 0 || strcmp(arg, "--output") == 0) {
      if (i + 1 >= argc) return cli_fail(CLI_EXIT_USAGE, "%s: %s needs a file name", a->cmd, arg);
      a->output = argv[++i];
    } else if (strncmp(arg, "--output=", 9) == 0) {
      a->output = arg + 9;
    } else if (strcmp(arg, "--csv") == 0 || strncmp(arg, "--csv=", 6) == 0) {
      if (strcmp(a->cmd, "run") != 0)
        return cli_fail(CLI_EXIT_USAGE, "%s: --csv only applies to run", a->cmd);
      if (arg[5] == '=')
        a->csv_dir = arg + 6;
      else if (i + 1 < argc)
        a->csv_dir = argv[++i];
      if (!a->csv_dir || !a->csv_dir[0])
        return cli_fail(CLI_EXIT_USAGE, "%s: --csv needs a directory", a->cmd);
    } else if (strcmp(arg, "-q") == 0 || strcmp(arg, "--quiet") == 0) {
      a->quiet = 1;
    } else if (strcmp(arg, "--keep-partial") == 0 && strcmp(a->cmd, "run") == 0) {
      a->keep_partial = 1;
    } else if (arg[0] == '-' && arg[1] != '\0') {
      return cli_fail(CLI_EXIT_USAGE, "%s: unknown option '%s' (see reelsim %s --help)", a->cmd,
                      arg, a->cmd);
    } else if (a->scene && !many) {
      return cli_fail(CLI_EXIT_USAGE, "%s: one scene file at a time (got '%s' and '%s')", a->cmd,
                      a->scene, arg);
    } else {
      if (!a->scene) a->scene = arg;
      a->scenes[a->n_scenes++] = arg;
    }
  }
  if (!a->scene)
    return cli_fail(CLI_EXIT_USAGE, "%s: missing the scene file (usage: reelsim %s SCENE ...)",
                    a->cmd, a->cmd);
  if (a->output) {
    if (!a->output[0]) return cli_fail(CLI_EXIT_USAGE, "%s: -o needs a file name", a->cmd);
    /* recorded as an override so the resolved scene in the file names the real output */
    size_t n = strlen(a->output) + sizeof "output.file=";
    char *set = malloc(n);
    if (!set) return cli_fail(CLI_EXIT_OTHER, "out of memory");
    snprintf(set, n, "output.file=%s", a->output);
    a->owned = set;
    a->sets[a->n_sets++] = set;
    a->output = set + strlen("output.file=");
  }
  return -1;
}
