/* The commands and their options as data: one table each, read by the parser (args.c)
 * and the help texts (usage.c), so a flag the parser takes is a flag the help lists. */
#ifndef RS_CLI_OPTIONS_H
#define RS_CLI_OPTIONS_H

/* One bit per command, for the commands an option applies to. */
enum {
  CLI_RUN = 1u << 0,
  CLI_CHECK = 1u << 1,
  CLI_COMPARE = 1u << 2,
  CLI_PLOT = 1u << 3,
  CLI_STUDY = 1u << 4,
  CLI_NIP = 1u << 5,
  CLI_SWEEP = 1u << 6,
  CLI_OPTIMIZE = 1u << 7,
  CLI_EVERY = (1u << 8) - 1
};

typedef enum cli_opt {
  CLI_OPT_HELP,
  CLI_OPT_OUTPUT,
  CLI_OPT_SET,
  CLI_OPT_CSV,
  CLI_OPT_QUIET,
  CLI_OPT_VERBOSE,
  CLI_OPT_KEEP_PARTIAL,
  CLI_OPT_QUICK,
  CLI_OPT_JOBS,
  CLI_OPT_RADIUS,
  CLI_OPT_JSON,
  CLI_OPT_VARY,
  CLI_OPT_SAMPLE,
  CLI_OPT_THREADS,
  CLI_OPT_PROFILES,
  CLI_OPT_MINIMIZE,
  CLI_OPT_MAXIMIZE,
  CLI_OPT_SUBJECT_TO,
  CLI_OPT_TARGET_PROFILE,
  CLI_OPT_HISTORY,
  CLI_OPT_VARIANT,
  CLI_N_OPTS
} cli_opt;

/* One option as a set of commands sees it. The same option may have several rows with
 * disjoint command sets when its meaning differs (-o FILE for run, -o DIR for plot). */
typedef struct cli_option {
  cli_opt id;
  const char *name;  /* long name, without "--" */
  char short_name;   /* 0: none */
  const char *arg;   /* the argument's name in the help ("FILE"); NULL: takes none */
  const char *needs; /* what a missing argument is ("a file name"), for the message */
  unsigned cmds;     /* CLI_RUN | ...: the commands that take it */
  const char *help;  /* its help, lines separated by '\n' */
} cli_option;

typedef struct cli_command {
  const char *name;
  unsigned bit;
  const char *operand;  /* "scene file" or "file": the positional argument */
  int many;             /* takes one or more operands (compare) instead of exactly one */
  const char *synopsis; /* after "usage: " */
  const char *summary;  /* for the general help: lines after the first indented by 17 */
  const char *about;    /* the command's help, before its options */
  const char *footer;   /* after its options (exit statuses) */
} cli_command;

extern const cli_option cli_options[];
extern const int cli_n_options;
extern const cli_command cli_commands[];
extern const int cli_n_commands;

/* The command of that name, or NULL. */
const cli_command *cli_command_find(const char *name);

/* The row of option `id` for command `cmd` (a CLI_* bit), or NULL if it does not take it. */
const cli_option *cli_option_for(cli_opt id, unsigned cmd);

#endif
