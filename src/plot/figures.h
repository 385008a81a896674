/* The figures of a file (internal to the plot module): drawn by the files named, called
 * only by rs_plot_file (plot.c), so that the figures depend on the shared pieces
 * (plot_internal.h, figure.c) and not on the entry point. */
#ifndef RS_PLOT_FIGURES_H
#define RS_PLOT_FIGURES_H

#include "plot/plot_internal.h"

rs_status rsi_plot_run_figures(plot_ctx *c, const run_data *d);      /* plot_run.c */
rs_status rsi_plot_compare_figures(plot_ctx *c, const run_data *runs, int n); /* plot_compare.c */
rs_status rsi_plot_nip_figures(plot_ctx *c, const run_data *d, int prefix_run); /* plot_nip.c */
/* A recipe-search file: /sweep (reelsim sweep) or /optimize (reelsim optimize); its
 * figures (plot_sweep.c). */
int rsi_plot_is_search_file(const plot_ctx *c);
rs_status rsi_plot_search_figures(plot_ctx *c);
/* <stem>-optimize.png: the objective (a figure or a varied key) at each evaluation,
 * feasible and infeasible runs apart, the best marked (plot_optimize.c). */
rs_status rsi_plot_optimize_history(plot_ctx *c);

#endif
