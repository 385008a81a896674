/* reelsim plot FILE.h5 [-o DIR] [--quiet]: PNG plots of a run or compare file. */
#include <stdio.h>

#include "cli/cli.h"
#include "reelsim/plot.h"

int cli_plot(const cli_args *a)
{
  char **written = NULL;
  int n = 0;
  rs_status st = rs_plot_file(a->scene, a->output ? a->output : ".", NULL, &written, &n);
  if (st != RS_OK) return cli_fail_status(st);
  if (!a->quiet)
    for (int i = 0; i < n; ++i) printf("%s\n", written[i]);
  rs_plot_list_free(&written, n);
  return CLI_EXIT_OK;
}
