/* reelsim plot FILE.h5 [-o DIR] [--quiet]: PNG plots of a run or compare file, or the
 * picture of a study file (plot_study.c: the study is an application beside plot, so the
 * CLI picks by the file's kind). DIR is made as needed (mkdir -p), and removed again if
 * the plot fails and leaves it empty. Ctrl-C, SIGTERM, SIGHUP or SIGQUIT stops gnuplot and
 * removes the session's temporary folder (/tmp/reelsim-plot-*): exit 130/143/129/131. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/outdir.h"
#include "cli/plot_study.h"
#include "cli/signals.h"
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
  rs_status st;
  char png[8192];
  cli_signals sig;
  cli_signals_install(&sig);
  if (cli_is_study_file(a->scene)) {
    /* DIR/<file name>-study.png, as the run plots are named */
    const char *base = strrchr(a->scene, '/');
    base = base ? base + 1 : a->scene;
    size_t stem = strlen(base);
    if (stem > 3 && strcmp(base + stem - 3, ".h5") == 0) stem -= 3;
    snprintf(png, sizeof png, "%s/%.*s-study.png", made.path, (int)stem, base);
    st = cli_plot_study(a->scene, png);
    if (st == RS_OK) {
      written = malloc(sizeof *written);
      if (written && (written[0] = malloc(strlen(png) + 1))) {
        strcpy(written[0], png);
        n = 1;
      }
    }
  } else {
    st = rs_plot_file(a->scene, made.path, NULL, &written, &n);
  }
  int caught = cli_signal_caught();
  cli_signals_restore(&sig);
  if (st != RS_OK && caught) {
    code = cli_fail(cli_signal_exit_code(caught), "plot: %s (no plots written)", cli_signal_word(caught));
    cli_outdir_undo(&made);
    return code;
  }
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
