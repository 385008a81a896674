/* reelsim plot FILE.h5 [-o DIR] [--quiet]: PNG plots of a run or compare file. DIR is made
 * as needed (mkdir -p), and removed again if the plot fails and leaves it empty. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/outdir.h"
#include "reelsim/plot.h"

int cli_plot(const cli_args *a)
{
  char **written = NULL;
  int n = 0;
  cli_outdir made;
  int code = cli_outdir_make("plot: output directory", a->output ? a->output : ".", &made);
  if (code != CLI_EXIT_OK) {
    cli_outdir_undo(&made);
    return code;
  }
  rs_status st = rs_plot_file(a->scene, made.path, NULL, &written, &n);
  if (st != RS_OK) {
    code = cli_fail_status(st);
    cli_outdir_undo(&made);
    return code;
  }
  cli_outdir_free(&made);
  if (!a->quiet)
    for (int i = 0; i < n; ++i) printf("%s\n", written[i]);
  rs_plot_list_free(&written, n);
  return CLI_EXIT_OK;
}
