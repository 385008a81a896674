/* rs_plot_file: which figures a file gets (the figures: plot_run.c, plot_compare.c,
 * plot_nip.c; the pieces they share: figure.c). */
#include "reelsim/plot.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "plot/figures.h"
#include "plot/plot_internal.h"
#include "util/error.h"
#include "util/path_stem.h"

void rs_plot_list_free(char ***list, int n)
{
  rs_reader_free_strings(list, n > 0 ? (size_t)n : 0);
}

/* ---- the entry point ------------------------------------------------------------------- */

static rs_status check_dir(const char *dir)
{
  struct stat sb;
  if (!dir || !dir[0]) return RS_ERROR(RS_ERR_INPUT, "no output directory given");
  if (stat(dir, &sb) != 0) {
    if (errno == ENOENT)
      return RS_ERROR(RS_ERR_INPUT, "output directory '%s' does not exist", dir);
    return RS_ERROR(RS_ERR_INPUT, "output directory '%s': %s", dir, strerror(errno));
  }
  if (!S_ISDIR(sb.st_mode))
    return RS_ERROR(RS_ERR_INPUT, "output directory '%s' is not a directory", dir);
  if (access(dir, W_OK | X_OK) != 0)
    return RS_ERROR(RS_ERR_INPUT, "output directory '%s' is not writable: %s", dir,
                    strerror(errno));
  return RS_OK;
}

static rs_status draw(plot_ctx *c, run_data *runs, int n)
{
  if (rsi_plot_is_search_file(c)) return rsi_plot_search_figures(c);
  rs_status st = RS_OK;
  for (int i = 0; st == RS_OK && i < n; ++i) st = rsi_plot_run_read(c, i, &runs[i]);
  if (st != RS_OK) return st;
  if (rs_reader_is_compare(c->rd)) st = rsi_plot_compare_figures(c, runs, n);
  else st = rsi_plot_run_figures(c, &runs[0]);
  for (int i = 0; st == RS_OK && i < n; ++i)
    st = rsi_plot_nip_figures(c, &runs[i], rs_reader_is_compare(c->rd));
  return st;
}

rs_status rs_plot_file(const char *file, const char *dir, const rs_plot_options *opts,
                       char ***written, int *n_written)
{
  if (written) *written = NULL;
  if (n_written) *n_written = 0;
  plot_ctx c = {.dir = dir};
  rs_status st = rs_reader_open(file, &c.rd);
  if (st == RS_OK) st = check_dir(dir);
  if (st != RS_OK) {
    rs_reader_close(&c.rd);
    return st;
  }
  rs_path_stem(file, c.stem, sizeof c.stem);
  int n = rs_reader_runs(c.rd);
  run_data *runs = calloc((size_t)n, sizeof *runs);
  if (!runs) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) st = rs_gp_begin(&c.gp, opts ? opts->width : 0, opts ? opts->height : 0);
  if (st == RS_OK) st = draw(&c, runs, n);
  if (st == RS_OK) st = rs_gp_run(&c.gp, opts ? opts->gnuplot : NULL);
  if (st == RS_OK && written) {
    *written = c.gp.final; /* handed over: rs_gp_end then frees nothing of it */
    if (n_written) *n_written = c.gp.n_png;
    c.gp.final = NULL;
    c.gp.n_png = 0;
  }
  for (int i = 0; runs && i < n; ++i) rsi_plot_run_free(&runs[i]);
  free(runs);
  rs_gp_end(&c.gp);
  rs_reader_close(&c.rd);
  return st;
}
