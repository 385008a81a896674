/* Help texts, made from the command and option tables (options.h). */
#ifndef RS_CLI_USAGE_H
#define RS_CLI_USAGE_H

#include <stdio.h>

#include "cli/options.h"

/* The general help (cmd NULL: every command, the global options) or one command's
 * (its synopsis, what it does, every option it takes, its exit statuses). */
void cli_usage(FILE *out, const cli_command *cmd);

/* "run, check, ..., help" into buf: the command names, for messages. */
void cli_command_names(char *buf, size_t size);

#endif
