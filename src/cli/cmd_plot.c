/* reelsim plot FILE.h5 [-o DIR] [--quiet]: PNG plots of a run or compare file. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "reelsim/plot.h"

int cli_plot(int argc, char **argv)
{
  const char *file = NULL, *dir = ".";
  int quiet = 0;
  for (int i = 2; i < argc; ++i) {
    const char *arg = argv[i];
    if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
      return cli_usage(stdout, "plot");
    } else if (strcmp(arg, "-o") == 0 || strcmp(arg, "--output") == 0) {
      if (i + 1 >= argc || !argv[i + 1][0])
        return cli_fail(CLI_EXIT_USAGE, "plot: %s needs a directory", arg);
      dir = argv[++i];
    } else if (strncmp(arg, "--output=", 9) == 0 && arg[9]) {
      dir = arg + 9;
    } else if (strcmp(arg, "-q") == 0 || strcmp(arg, "--quiet") == 0) {
      quiet = 1;
    } else if (arg[0] == '-' && arg[1] != '\0') {
      return cli_fail(CLI_EXIT_USAGE, "plot: unknown option '%s' (see reelsim plot --help)", arg);
    } else if (file) {
      return cli_fail(CLI_EXIT_USAGE, "plot: one file at a time (got '%s' and '%s')", file, arg);
    } else {
      file = arg;
    }
  }
  if (!file)
    return cli_fail(CLI_EXIT_USAGE, "plot: missing the file (usage: reelsim plot FILE.h5 -o DIR)");

  char **written = NULL;
  int n = 0;
  rs_status st = rs_plot_file(file, dir, NULL, &written, &n);
  if (st != RS_OK) return cli_fail_status(st);
  if (!quiet)
    for (int i = 0; i < n; ++i) printf("%s\n", written[i]);
  rs_plot_list_free(&written, n);
  return CLI_EXIT_OK;
}
