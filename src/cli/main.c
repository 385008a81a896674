/* reelsim: wind a reel described by a scene file (see docs/cli.md). */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "reelsim_version.h"

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
  if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
    if (strcmp(cmd, "help") == 0 && argc > 2) return cli_usage(stdout, argv[2]);
    return cli_usage(stdout, NULL);
  }
  if (strcmp(cmd, "nip") == 0) return cli_nip(argc, argv, 2);
  if (strcmp(cmd, "plot") == 0) return cli_plot(argc, argv);
  if (strcmp(cmd, "study") == 0) return cli_study(argc, argv);
  if (strcmp(cmd, "run") != 0 && strcmp(cmd, "check") != 0 && strcmp(cmd, "compare") != 0) {
    if (cmd[0] == '-')
      return cli_fail(CLI_EXIT_USAGE, "unknown option '%s' (see reelsim --help)", cmd);
    return cli_fail(CLI_EXIT_USAGE,
                    "unknown command '%s' (commands: run, check, compare, plot, study, nip, help)", cmd);
  }

  cli_args a;
  int code = cli_parse(argc, argv, 2, &a);
  if (code < 0)
    code = strcmp(cmd, "run") == 0       ? cli_run(&a)
           : strcmp(cmd, "compare") == 0 ? cli_compare(&a)
                                         : cli_check(&a);
  cli_args_free(&a);
  return code;
}
