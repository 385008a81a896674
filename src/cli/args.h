/* The command line of every command, parsed by one getopt_long loop (args.c) from the
 * option table (options.h). */
#ifndef RS_CLI_ARGS_H
#define RS_CLI_ARGS_H

#include "cli/options.h"

typedef struct cli_args {
  const cli_command *cmd;
  const char *scene;    /* the first operand: the scene (plot: the file) */
  int n_scenes;         /* compare: every scene, in order (others: 1) */
  const char **scenes;
  const char *output;   /* -o FILE (run, check, compare) or DIR (plot, study), or NULL */
  int quiet;
  int verbose;          /* --verbose: errors also say where in the code */
  int keep_partial;     /* run --keep-partial: write what finished when the run stops early */
  const char *csv_dir;  /* run --csv DIR, or NULL */
  int quick;            /* study --quick */
  int jobs;             /* study --jobs N (default 1) */
  const char *radius;   /* nip --radius R, as given */
  int json;             /* nip --json */
  int n_vary;           /* sweep, optimize --vary KEY=..., in order */
  const char **vary;
  const char *sample;   /* sweep --sample grid|lhs:R, or NULL */
  int threads;          /* sweep --threads K (0: one per core) */
  int profiles;         /* sweep --profiles */
  const char *minimize, *maximize; /* optimize --minimize / --maximize FIGURE */
  int n_subject_to;     /* optimize --subject-to, in order */
  const char **subject_to;
  const char *target_profile; /* optimize --target-profile FILE.csv */
  const char *history;  /* optimize --history FILE.h5 */
  int n_variants;       /* compare --variant 'NAME: KEY=VALUE ...', in order */
  const char **variants;
  int *variant_of;      /* per variant: the index in scenes of the scene before it (-1: none) */
  int n_sets;           /* --set key.path=value, in order; run/check/compare -o adds
                           output.file=FILE last */
  const char **sets;
  char *owned;          /* the "output.file=FILE" made from -o */
} cli_args;

/* Parses argv[first..] for the command argv[first - 1]. Returns -1 when the command should
 * run, otherwise the exit status (0 after --help, 2 on bad usage, with the message printed).
 * Free with cli_args_free in every case. */
int cli_parse(int argc, char **argv, int first, const cli_command *cmd, cli_args *a);
void cli_args_free(cli_args *a);

/* Do the two paths name one existing file (the same device and inode, links followed)?
 * Refusing `run s.yaml -o s.yaml` and the like (exit 2) before anything is written. */
int cli_same_file(const char *a, const char *b);

#endif
