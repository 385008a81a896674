/* The reelsim command line: argument parsing, the commands, and exit statuses.
 * Exit status: 0 ok, 2 bad input or usage, 3 solver failure, 130 interrupted (SIGINT),
 * 143 terminated (SIGTERM), 1 anything else (see docs/cli.md). */
#ifndef RS_CLI_H
#define RS_CLI_H

#include <stdio.h>

#include "reelsim/defects.h"
#include "reelsim/status.h"

enum { CLI_EXIT_OK = 0, CLI_EXIT_OTHER = 1, CLI_EXIT_USAGE = 2, CLI_EXIT_SOLVER = 3,
       CLI_EXIT_INTERRUPTED = 130, CLI_EXIT_TERMINATED = 143 };

typedef struct cli_args {
  const char *cmd;      /* "run", "check" or "compare" */
  const char *scene;    /* the first scene */
  int n_scenes;         /* compare: every scene, in order (others: 1) */
  const char **scenes;
  const char *output;   /* -o FILE, or NULL */
  int quiet;
  int keep_partial;     /* run --keep-partial: write what finished when the run stops early */
  const char *csv_dir;  /* run --csv DIR, or NULL */
  int n_sets;           /* --set key.path=value, in order; -o adds output.file=FILE last */
  const char **sets;
  char *owned;          /* the "output.file=FILE" made from -o */
} cli_args;

/* Parses the options after the command name (argv[first..]). Returns -1 when the
 * command should run, otherwise the exit status (0 after --help, 2 on bad usage). */
int cli_parse(int argc, char **argv, int first, cli_args *a);
void cli_args_free(cli_args *a);

int cli_check(const cli_args *a);
/* reelsim nip SCENE --radius R [--json] [--set k=v]...: one contact nip (cmd_nip.c). */
int cli_nip(int argc, char **argv, int first);
int cli_run(const cli_args *a);
int cli_compare(const cli_args *a);
/* reelsim plot parses its own arguments (argv[0] is the program, argv[1] "plot"). */
int cli_plot(int argc, char **argv);
/* reelsim study SCENE [-o DIR] [--set k=v]... [--quick] [--jobs N] (cmd_study.c), likewise. */
int cli_study(int argc, char **argv);

/* Help: the general text (cmd NULL) or one command's. 0 if cmd is known, else 2. */
int cli_usage(FILE *out, const char *cmd);

/* "reelsim: ..." on stderr; returns `code`. */
int cli_fail(int code, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Prints the recorded library error and returns the exit status for it. */
int cli_fail_status(rs_status st);

/* summary_defects.c: Pa as "12.34 kPa" below 1 MPa, else "1.234 MPa"; the defect-risk
 * lines of the run summary. */
void cli_fmt_stress(char *buf, size_t size, double pa);
void cli_print_defects(FILE *out, const rs_defect_report *rep);

#endif
