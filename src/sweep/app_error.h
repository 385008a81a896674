/* The applications' own error record (the CLI's and the recipe search's). The library's
 * setter is private (an application cannot write the library's record, so what it reads
 * there is the library's own word); an application records its own failures here, per
 * thread, with the same where and why.
 *
 * app_error_message(), app_error_where(), app_error_status() read what a program prints:
 * the application's record when it was written after the library's last change, else the
 * library's (rs_error_message()...). app_error_wrap prefixes context to whichever that is. */
#ifndef RS_SWEEP_APP_ERROR_H
#define RS_SWEEP_APP_ERROR_H

#include "reelsim/status.h"

rs_status app_error_set(rs_status st, const char *func, const char *file, int line,
                        const char *fmt, ...) __attribute__((format(printf, 5, 6)));
#define APP_ERROR(st, ...) app_error_set((st), __func__, __FILE__, __LINE__, __VA_ARGS__)

rs_status app_error_wrap(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
rs_status app_error_status(void);
const char *app_error_message(void);
const char *app_error_where(void);
void app_error_clear(void); /* both records */

#endif
