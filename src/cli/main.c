/* reelsim: wind a reel described by a scene file (see docs/cli.md). */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/heap.h"
#include "cli/usage.h"
#include "reelsim/version.h"

typedef int (*command_fn)(const cli_args *a);

static const struct {
  const char *name;
  command_fn fn;
} commands[] = {{"run", cli_run},     {"check", cli_check}, {"compare", cli_compare},
                {"plot", cli_plot},   {"study", cli_study}, {"nip", cli_nip},
                {"sweep", cli_sweep},
                {"optimize", cli_optimize}};

static int unknown_command(const char *what, const char *cmd)
{
  char names[256];
  cli_command_names(names, sizeof names);
  return cli_fail(CLI_EXIT_USAGE, "%sunknown command '%s' (commands: %s)", what, cmd, names);
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    cli_usage(stderr, NULL);
    return CLI_EXIT_USAGE;
  }
  const char *cmd = argv[1];
  if (strcmp(cmd, "--version") == 0 || strcmp(cmd, "version") == 0) {
    printf("reelsim %s\n", RS_VERSION_STRING);
    return CLI_EXIT_OK;
  }
  (void)cli_heap_prepare(CLI_HEAP_RESERVE, NULL); /* before the first allocation of a command */
  if (strcmp(cmd, "fit") == 0) return cli_fit(argc, argv); /* its own arguments: cmd_fit.c */
  if (strcmp(cmd, "--bash-completion") == 0) return cli_bash_completion(stdout);
  if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
    if (strcmp(cmd, "help") != 0 || argc < 3 || strcmp(argv[2], "help") == 0 ||
        strcmp(argv[2], "--help") == 0 || strcmp(argv[2], "-h") == 0) {
      cli_usage(stdout, NULL);
      return CLI_EXIT_OK;
    }
    if (strcmp(argv[2], "fit") == 0) {
      cli_fit_usage(stdout);
      return CLI_EXIT_OK;
    }
    const cli_command *c = cli_command_find(argv[2]);
    if (!c) return unknown_command("help: ", argv[2]);
    cli_usage(stdout, c);
    return CLI_EXIT_OK;
  }
  for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i) {
    if (strcmp(cmd, commands[i].name) != 0) continue;
    const cli_command *c = cli_command_find(cmd);
    if (!c) return cli_fail(CLI_EXIT_OTHER, "internal error: no help for command '%s'", cmd);
    cli_args a;
    int code = cli_parse(argc, argv, 2, c, &a);
    if (code < 0) {
      cli_fail_verbose(a.verbose);
      code = commands[i].fn(&a);
    }
    cli_args_free(&a);
    return code;
  }
  if (cmd[0] == '-') return cli_fail(CLI_EXIT_USAGE, "unknown option '%s' (see reelsim --help)", cmd);
  return unknown_command("", cmd);
}
