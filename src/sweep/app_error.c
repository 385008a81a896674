/* The applications' error record (app_error.h). It is current while the library's record
 * is as it was when the application wrote its own: a fingerprint (FNV-1a of the library's
 * status, message and where) taken then tells whether the library has written since. */
#include "sweep/app_error.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

enum { APP_MSG_LEN = 8192, APP_WHERE_LEN = 256 };

static _Thread_local rs_status app_status = RS_OK;
static _Thread_local char app_msg[APP_MSG_LEN], app_where[APP_WHERE_LEN];
static _Thread_local uint64_t library_then;

static uint64_t fnv(uint64_t h, const char *s)
{
  for (; *s; ++s) h = (h ^ (unsigned char)*s) * 1099511628211u;
  return (h ^ 0xffu) * 1099511628211u; /* a separator between the strings */
}

static uint64_t library_now(void)
{
  uint64_t h = 14695981039346656037u ^ (uint64_t)rs_error_status();
  return fnv(fnv(h, rs_error_message()), rs_error_where());
}

static int app_current(void) { return app_status != RS_OK && library_now() == library_then; }

rs_status app_error_set(rs_status st, const char *func, const char *file, int line,
                        const char *fmt, ...)
{
  va_list ap;
  const char *base = strrchr(file, '/');
  app_status = st;
  snprintf(app_where, sizeof app_where, "%s (%s:%d)", func, base ? base + 1 : file, line);
  va_start(ap, fmt);
  vsnprintf(app_msg, sizeof app_msg, fmt, ap);
  va_end(ap);
  library_then = library_now();
  return st;
}

rs_status app_error_wrap(const char *fmt, ...)
{
  char prefix[APP_MSG_LEN], old[APP_MSG_LEN];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(prefix, sizeof prefix, fmt, ap);
  va_end(ap);
  if (!app_current()) return rs_error_wrap("%s", prefix);
  memcpy(old, app_msg, sizeof old);
  /* Truncation is fine here: the message is for people, and the head carries the context. */
  size_t n = strlen(prefix);
  if (n > APP_MSG_LEN - 3) n = APP_MSG_LEN - 3;
  memcpy(app_msg, prefix, n);
  memcpy(app_msg + n, ": ", 2);
  size_t m = strlen(old);
  if (m > APP_MSG_LEN - 3 - n) m = APP_MSG_LEN - 3 - n;
  memcpy(app_msg + n + 2, old, m);
  app_msg[n + 2 + m] = '\0';
  return app_status;
}

rs_status app_error_status(void) { return app_current() ? app_status : rs_error_status(); }
const char *app_error_message(void) { return app_current() ? app_msg : rs_error_message(); }
const char *app_error_where(void) { return app_current() ? app_where : rs_error_where(); }

void app_error_clear(void)
{
  app_status = RS_OK;
  app_msg[0] = app_where[0] = '\0';
  rs_error_clear();
}
