/* PNG plots of a reelsim file, drawn by gnuplot (reelsim plot; docs/cli.md).
 *
 * For a run file: <stem>-pressure.png (interlayer pressure -sigma_r, kPa, against
 * radius, mm; with stages of /history and the pressure limit and slip ranges of /defects
 * when the file has them), <stem>-hoop.png (hoop stress, MPa; history stages, hoop
 * compression ranges), <stem>-tension.png (wound-on tension T0 with the web tension and
 * nip load of the recipe) and <stem>-nip-<i>.png for each /nip/profiles/<i> (pressure and
 * shears across the nip, stick zones shaded). For a comparison file the runs are overlaid
 * in <stem>-pressure.png, <stem>-hoop.png and <stem>-tension.png, and each run's nip
 * profiles get <stem>-<run>-nip-<i>.png. For a sweep file (/sweep), <stem>-<figure>.png
 * for each figure of the runs (core_pressure, ...): against the one parameter that varies,
 * or a heat map over the first two that do; for an optimisation's file (/optimize),
 * <stem>-optimize.png, the objective at each evaluation. <stem> is the file's name
 * without directory and extension. */
#ifndef REELSIM_PLOT_H
#define REELSIM_PLOT_H

#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

typedef struct rs_plot_options {
  const char *gnuplot; /* program to run; NULL: "gnuplot" from PATH */
  int width, height;   /* pixels; <= 0: 1000 x 650 */
} rs_plot_options;

/* Draws the plots of `file` into the existing directory `dir`, each PNG staged (temporary
 * + rename) so it is whole or absent. *written (may be NULL) gets the paths written, in
 * order (free with rs_plot_list_free), *n_written their number.
 * RS_ERR_INPUT: `file` missing, not HDF5 or not a reelsim file, or `dir` missing or not
 * a directory. RS_ERR_IO: gnuplot missing ("gnuplot not found (apt-get install
 * gnuplot-nox)") or failed, or a PNG could not be written. */
rs_status rs_plot_file(const char *file, const char *dir, const rs_plot_options *opts,
                       char ***written, int *n_written);
void rs_plot_list_free(char ***list, int n);

RS_END_DECLS
#endif
