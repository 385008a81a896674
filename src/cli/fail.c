/* See fail.h. */
#include "cli/fail.h"
#include "sweep/app_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static int verbose;

void cli_fail_verbose(int on) { verbose = on; }

int cli_fail_is_verbose(void) { return verbose; }

int cli_fail(int code, const char *fmt, ...)
{
  va_list ap;
  fputs("reelsim: ", stderr);
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
  return code;
}

/* Bad input may hold several errors, one a line (a scene's): each gets its own
 * "reelsim: " line. */
static void print_lines(const char *msg)
{
  for (;;) {
    const char *nl = strchr(msg, '\n');
    if (!nl) {
      cli_fail(0, "%s", msg);
      return;
    }
    cli_fail(0, "%.*s", (int)(nl - msg), msg);
    msg = nl + 1;
  }
}

int cli_fail_status(rs_status st)
{
  int code = rs_status_exit_code(st);
  if (st == RS_ERR_INPUT) print_lines(app_error_message());
  else if (st == RS_ERR_SOLVER) cli_fail(code, "solver failure: %s", app_error_message());
  else cli_fail(code, "%s: %s", rs_status_name(st), app_error_message());
  if (verbose && st != RS_ERR_INPUT && app_error_where()[0])
    fprintf(stderr, "reelsim:   (at %s)\n", app_error_where());
  return code;
}
