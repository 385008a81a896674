/* Driving gnuplot (internal to the plot module).
 *
 * A session owns a private temporary directory (mkdtemp) holding the data files, the
 * script and gnuplot's PNGs. gnuplot is started with posix_spawnp and the script's path
 * as its one argument: no shell, so no file or title can inject a command, and every
 * string that goes into the script is quoted by rs_gp_string. Each PNG is then copied
 * onto its final name by the atomic-file helper (util/atomic_file.h: temporary + rename), and the
 * directory is removed. */
#ifndef RS_PLOT_GNUPLOT_H
#define RS_PLOT_GNUPLOT_H

#include <stddef.h>
#include <stdio.h>

#include "reelsim/status.h"

typedef struct rs_gp {
  char *dir;        /* the private temporary directory */
  char *script;     /* its script file */
  FILE *out;        /* the script being written */
  int n_data;       /* data files written so far */
  int n_png;        /* plots declared so far */
  char **final;     /* final path of each plot */
  int n_terms;      /* items in the current plot command */
  int width, height;
} rs_gp;

/* Makes the directory and starts the script (terminal pngcairo if gnuplot has it, else
 * png; UTF-8; no enhanced text, so titles print as given). */
rs_status rs_gp_begin(rs_gp *gp, int width, int height);
/* Removes the directory and everything in it; frees the session. Safe after a failure. */
void rs_gp_end(rs_gp *gp);

/* Appends to the script. */
void rs_gp_printf(rs_gp *gp, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Appends s as an inert gnuplot string: single-quoted (no `command`, @macro or escape
 * processing; a quote doubled), a newline kept as a line break by joining 'a'."\n".'b',
 * other control characters made spaces. */
void rs_gp_string(rs_gp *gp, const char *s);

/* Writes a data file of n rows and ncols columns (cols[c][i]), skipping rows that hold
 * a NaN; *name (malloc'd) is its path, for rs_gp_string. *rows gets the rows written. */
rs_status rs_gp_data(rs_gp *gp, int ncols, const double *const *cols, size_t n, char **name,
                     size_t *rows);

/* Starts a new figure: reset, then output to a new PNG that rs_gp_run will put at
 * final_path. */
rs_status rs_gp_figure(rs_gp *gp, const char *final_path);

/* Builds one plot command item by item: rs_gp_plot_item writes "plot " before the first
 * item and ", \" before the others; rs_gp_plot_end ends the command. */
void rs_gp_plot_item(rs_gp *gp);
void rs_gp_plot_end(rs_gp *gp);

/* Ends the script, runs `program` (NULL: "gnuplot" from PATH) on it and checks that it
 * succeeded and wrote every PNG; then stages each PNG onto its final path.
 * RS_ERR_IO: gnuplot missing ("gnuplot not found (apt-get install gnuplot-nox)"), failed
 * (its last messages quoted), or a PNG could not be written. */
rs_status rs_gp_run(rs_gp *gp, const char *program);

#endif
