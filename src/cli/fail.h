/* Exit statuses and the messages on standard error (docs/cli.md, "Exit status").
 * Exit status: 0 ok, 2 bad input or usage, 3 solver failure, 130 interrupted (SIGINT),
 * 143 terminated (SIGTERM), 1 anything else. */
#ifndef RS_CLI_FAIL_H
#define RS_CLI_FAIL_H

#include <stddef.h>

#include "reelsim/status.h"

enum { CLI_EXIT_OK = 0, CLI_EXIT_OTHER = 1, CLI_EXIT_USAGE = 2, CLI_EXIT_SOLVER = 3,
       CLI_EXIT_INTERRUPTED = 130, CLI_EXIT_TERMINATED = 143 };

/* "reelsim: ..." on stderr; returns `code`. */
int cli_fail(int code, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Prints the recorded library error and returns the exit status for it. The place in the
 * code that recorded it ("reelsim:   (at check_dir (staging.c:39))") only with --verbose:
 * users read what went wrong, a bug report also where. */
int cli_fail_status(rs_status st);

/* --verbose: cli_fail_status (and compare's per-run failures) also show where. */
void cli_fail_verbose(int on);
int cli_fail_is_verbose(void);

/* Text from a scene (a title) as it may be printed: control characters written as
 * escapes (\n, \t, \x1b), so a title cannot move the cursor, recolour or retitle the
 * terminal, or forge lines of output. Returns buf. */
const char *cli_shown(const char *s, char *buf, size_t size);

#endif
