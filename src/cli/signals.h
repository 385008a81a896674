/* Signals for the commands that wind reels (run, compare, study): one handler, so each
 * stops the same way on SIGINT and SIGTERM. */
#ifndef RS_CLI_SIGNALS_H
#define RS_CLI_SIGNALS_H

#include <signal.h>

typedef struct cli_signals {
  struct sigaction old_int, old_term, old_xfsz;
} cli_signals;

/* The first SIGINT or SIGTERM asks the winding to stop after its current increment (the
 * progress callbacks poll cli_signal_caught); a second one ends the program the usual way
 * (SA_RESETHAND). A signal the shell had ignored (a background job's SIGINT) stays
 * ignored. SIGXFSZ is ignored, so a file-size limit (a full disk, as the tests simulate)
 * makes the write fail with a message instead of killing reelsim with its temporary file
 * left behind. */
void cli_signals_install(cli_signals *saved);
void cli_signals_restore(const cli_signals *saved);

/* The signal caught (SIGINT or SIGTERM), or 0. Safe to call from any thread. */
int cli_signal_caught(void);

/* The exit status for a caught signal: 130 for SIGINT, 143 for SIGTERM. */
int cli_signal_exit_code(int sig);

#endif
