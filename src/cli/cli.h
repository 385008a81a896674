/* The reelsim commands (docs/cli.md). Each takes the parsed command line and returns the
 * exit status (fail.h). */
#ifndef RS_CLI_H
#define RS_CLI_H

#include <stdio.h>

#include "cli/args.h"
#include "cli/fail.h"
#include "reelsim/defects.h"
#include "reelsim/scene.h"
#include "reelsim/storage.h"

int cli_run(const cli_args *a);
int cli_check(const cli_args *a);
int cli_compare(const cli_args *a);
/* reelsim plot FILE.h5 [-o DIR]: a->scene is the file, a->output the directory. */
int cli_plot(const cli_args *a);
/* reelsim study SCENE [-o DIR] [--set k=v]... [--quick] [--jobs N] (cmd_study.c). */
int cli_study(const cli_args *a);
/* reelsim nip SCENE --radius R [--json] [--set k=v]...: one contact nip (cmd_nip.c). */
int cli_nip(const cli_args *a);
/* reelsim fit stack TEST.csv --law LAW ...: the stack law fitted to a stack test
 * (cmd_fit.c; parses its own arguments). */
int cli_fit(int argc, char **argv);
void cli_fit_usage(FILE *out);
extern const char cli_fit_stack_flags[], cli_fit_roll_flags[];
/* reelsim fit roll SCENE --measured DATA.csv --vary KEY=LO:HI ... (cmd_fit_roll.c). */
int cli_fit_roll(int argc, char **argv);
/* reelsim optimize SCENE --vary KEY=LO:HI ... (--minimize | --maximize) FIGURE ...
 * (cmd_optimize.c). */
int cli_optimize(const cli_args *a);
/* reelsim sweep SCENE --vary KEY=... [--sample ...] [-o FILE] ... (cmd_sweep.c). */
int cli_sweep(const cli_args *a);

/* complete.c: `reelsim --bash-completion`, the bash completion script from the tables. */
int cli_bash_completion(FILE *out);

/* summary_defects.c: Pa as "12.34 kPa" below 1 MPa, else "1.234 MPa"; the defect-risk
 * lines of the run summary. */
void cli_fmt_stress(char *buf, size_t size, double pa);
void cli_print_defects(FILE *out, const rs_defect_report *rep);
/* The lanes' block and defect lines (nothing without lanes; lanes_print.c) */
void cli_print_lanes(FILE *out, const rs_scene *scene, const rs_reel_result *res);
/* compare's table of the lanes' figures (ridge_height, max_lane_pressure, slack_lanes; "-"
 * for a run without lanes or that failed): nothing when no run has lanes (lanes_print.c). */
void cli_print_compare_lanes(FILE *out, int n, const char (*names)[256],
                             const rs_scene *const *scenes, const rs_reel_job *jobs);
/* The storage stages and the stage where each defect rule reads worst (summary_storage.c). */
void cli_print_storage(FILE *out, const rs_storage_result *sr);
/* compare's table of its runs after storage (summary_storage.c): nothing when no run has
 * storage stages (storage[i] NULL). */
void cli_print_compare_storage(FILE *out, int n, const char (*names)[256],
                               const rs_storage_result *const *storage);
/* warnings.c: the scene's slip warnings on stderr ("reelsim: warning: ..."), one a line */
void cli_scene_warnings(const rs_scene *scene);

#endif
