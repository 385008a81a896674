/* Signals for the commands that wind reels (run, compare, study, sweep, optimize) and for
 * plot: one handler, so each stops the same way on SIGINT and SIGTERM, and on SIGHUP (a
 * closed terminal) and SIGQUIT as on SIGTERM. */
#ifndef RS_CLI_SIGNALS_H
#define RS_CLI_SIGNALS_H

#include <signal.h>

typedef struct cli_signals {
  struct sigaction old_int, old_term, old_xfsz, old_hup, old_quit;
} cli_signals;

/* The first SIGINT, SIGTERM, SIGHUP or SIGQUIT asks the winding to stop after its current increment (the
 * progress callbacks poll cli_signal_caught); a second one ends the program the usual way
 * (SA_RESETHAND). A signal the shell had ignored (a background job's SIGINT) stays
 * ignored. SIGXFSZ is ignored, so a file-size limit (a full disk, as the tests simulate)
 * makes the write fail with a message instead of killing reelsim with its temporary file
 * left behind. */
void cli_signals_install(cli_signals *saved);
void cli_signals_restore(const cli_signals *saved);

/* The signal caught (SIGINT, SIGTERM, SIGHUP or SIGQUIT), or 0. Safe from any thread. */
int cli_signal_caught(void);

/* The exit status for a caught signal: 128 + the signal (130 SIGINT, 143 SIGTERM, 129
 * SIGHUP, 131 SIGQUIT). */
int cli_signal_exit_code(int sig);
/* What the signal did, for messages: "interrupted" (SIGINT), "terminated (SIGTERM)", ... */
const char *cli_signal_word(int sig);

#endif
