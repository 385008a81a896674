/* reelsim plot on a study file (plot_study.c). */
#ifndef RS_CLI_PLOT_STUDY_H
#define RS_CLI_PLOT_STUDY_H

#include "reelsim/status.h"

/* 1 when `path` is a reelsim study file (it has /study/runs); 0 otherwise, error cleared. */
int cli_is_study_file(const char *path);
/* Draws the study's picture (rs_study_plot) from the file into `png`. */
rs_status cli_plot_study(const char *path, const char *png);

#endif
