/* See fail.h. */
#include "cli/fail.h"

#include <stdarg.h>
#include <stdio.h>

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

int cli_fail_status(rs_status st)
{
  int code = rs_status_exit_code(st);
  if (st == RS_ERR_INPUT) return cli_fail(code, "%s", rs_error_message());
  if (st == RS_ERR_SOLVER)
    return cli_fail(code, "solver failure: %s\nreelsim:   (at %s)", rs_error_message(),
                    rs_error_where());
  return cli_fail(code, "%s: %s\nreelsim:   (at %s)", rs_status_name(st), rs_error_message(),
                  rs_error_where());
}
