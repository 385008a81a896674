/* The runs of `reelsim compare` (docs/cli.md): each scene as it is, or, when --variant
 * options follow it, one run per variant: the scene with the variant's overrides after
 * the --set ones, named by the variant. */
#ifndef RS_CLI_COMPARE_RUNS_H
#define RS_CLI_COMPARE_RUNS_H

#include "cli/args.h"

typedef struct compare_run {
  const char *scene;   /* the scene file */
  const char *name;    /* the variant's name, or NULL (named by the scene file) */
  const char *variant; /* the --variant as given, or NULL */
  int n_sets;          /* --set, the variant's KEY=VALUE, then output.file= */
  const char **sets;
} compare_run;

typedef struct compare_runs {
  int n;
  compare_run *run;
  char **texts;        /* the variants' copies the sets point into */
  int n_texts;
} compare_runs;

/* The runs of the command line; sets[n_sets] are the overrides of every run. Returns -1
 * (go on) or an exit status after saying what is wrong: a --variant before any scene, an
 * empty or bad name (letters, digits, '_' and '-'), a part that is not KEY=VALUE. */
int compare_runs_make(const cli_args *a, int n_sets, const char *const *sets, compare_runs *r);
void compare_runs_free(compare_runs *r);

#endif
