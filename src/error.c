/* The per-thread error record behind include/reelsim/status.h. Per thread, because
 * `reelsim compare` winds several reels at once. */
#include "reelsim/status.h"
#include "util/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

enum { RS_MSG_LEN = 8192, RS_WHERE_LEN = 256 }; /* room for a scene's errors, one a line */

static _Thread_local rs_status rs_err_status = RS_OK;
static _Thread_local char rs_err_msg[RS_MSG_LEN];
static _Thread_local char rs_err_where[RS_WHERE_LEN];

rs_status rs_error_set(rs_status st, const char *func, const char *file, int line,
                       const char *fmt, ...)
{
  va_list ap;
  const char *base = strrchr(file, '/');
  rs_err_status = st;
  snprintf(rs_err_where, sizeof rs_err_where, "%s (%s:%d)", func, base ? base + 1 : file, line);
  va_start(ap, fmt);
  vsnprintf(rs_err_msg, sizeof rs_err_msg, fmt, ap);
  va_end(ap);
  return st;
}

rs_status rs_error_wrap(const char *fmt, ...)
{
  char prefix[RS_MSG_LEN], old[RS_MSG_LEN];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(prefix, sizeof prefix, fmt, ap);
  va_end(ap);
  memcpy(old, rs_err_msg, sizeof old);
  /* Truncation is fine here: the message is for people, and the head carries the context. */
  size_t n = strlen(prefix);
  if (n > RS_MSG_LEN - 3) n = RS_MSG_LEN - 3;
  memcpy(rs_err_msg, prefix, n);
  memcpy(rs_err_msg + n, ": ", 2);
  size_t m = strlen(old);
  if (m > RS_MSG_LEN - 3 - n) m = RS_MSG_LEN - 3 - n;
  memcpy(rs_err_msg + n + 2, old, m);
  rs_err_msg[n + 2 + m] = '\0';
  return rs_err_status;
}

rs_status rs_error_status(void) { return rs_err_status; }
const char *rs_error_message(void) { return rs_err_msg; }
const char *rs_error_where(void) { return rs_err_where; }

void rs_error_clear(void)
{
  rs_err_status = RS_OK;
  rs_err_msg[0] = '\0';
  rs_err_where[0] = '\0';
}

const char *rs_status_name(rs_status st)
{
  switch (st) {
  case RS_OK: return "ok";
  case RS_ERR_INPUT: return "bad input";
  case RS_ERR_SOLVER: return "solver failure";
  case RS_ERR_IO: return "i/o error";
  case RS_ERR_MEMORY: return "out of memory";
  case RS_ERR_INTERRUPTED: return "interrupted";
  case RS_ERR_INTERNAL: return "internal error";
  }
  return "unknown status";
}

int rs_status_exit_code(rs_status st)
{
  switch (st) {
  case RS_OK: return 0;
  case RS_ERR_INPUT: return 2;
  case RS_ERR_SOLVER: return 3;
  default: return 1;
  }
}
