/* See signals.h. */
#include "cli/signals.h"

#include <stdatomic.h>
#include <string.h>

#include "cli/cli.h"

/* Lock-free, so the handler may set it and every worker thread may read it. */
static atomic_int caught;

static void on_signal(int sig) { atomic_store(&caught, sig); }

void cli_signals_install(cli_signals *saved)
{
  struct sigaction sa, ign;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  atomic_store(&caught, 0);
  sigaction(SIGINT, &sa, &saved->old_int);
  sigaction(SIGTERM, &sa, &saved->old_term);
  sigaction(SIGHUP, &sa, &saved->old_hup);
  sigaction(SIGQUIT, &sa, &saved->old_quit);
  if (saved->old_int.sa_handler == SIG_IGN) sigaction(SIGINT, &saved->old_int, NULL);
  if (saved->old_term.sa_handler == SIG_IGN) sigaction(SIGTERM, &saved->old_term, NULL);
  /* nohup: a hangup the user asked to ignore stays ignored */
  if (saved->old_hup.sa_handler == SIG_IGN) sigaction(SIGHUP, &saved->old_hup, NULL);
  if (saved->old_quit.sa_handler == SIG_IGN) sigaction(SIGQUIT, &saved->old_quit, NULL);
  memset(&ign, 0, sizeof ign);
  ign.sa_handler = SIG_IGN;
  sigemptyset(&ign.sa_mask);
  sigaction(SIGXFSZ, &ign, &saved->old_xfsz);
}

void cli_signals_restore(const cli_signals *saved)
{
  sigaction(SIGINT, &saved->old_int, NULL);
  sigaction(SIGTERM, &saved->old_term, NULL);
  sigaction(SIGHUP, &saved->old_hup, NULL);
  sigaction(SIGQUIT, &saved->old_quit, NULL);
  sigaction(SIGXFSZ, &saved->old_xfsz, NULL);
}

int cli_signal_caught(void) { return atomic_load(&caught); }

int cli_signal_exit_code(int sig)
{
  if (sig == SIGHUP || sig == SIGQUIT) return 128 + sig;
  return sig == SIGTERM ? CLI_EXIT_TERMINATED : CLI_EXIT_INTERRUPTED;
}

const char *cli_signal_word(int sig)
{
  switch (sig) {
  case SIGTERM: return "terminated (SIGTERM)";
  case SIGHUP: return "terminated (SIGHUP)";
  case SIGQUIT: return "terminated (SIGQUIT)";
  default: return "interrupted";
  }
}
