/* Recording an error (private to the library: an application reads the record through
 * reelsim/status.h and cannot write it, so what it reads is the library's own word; the
 * applications keep their own record, src/sweep/app_error.h). */
#ifndef RS_UTIL_ERROR_H
#define RS_UTIL_ERROR_H

#include "reelsim/status.h"

/* Records an error and returns st. Use through RS_ERROR so the location is filled in.
 * The message is printf-formatted; a previous record is overwritten. */
rs_status rs_error_set(rs_status st, const char *func, const char *file, int line,
                       const char *fmt, ...) __attribute__((format(printf, 5, 6)));

#define RS_ERROR(st, ...) rs_error_set((st), __func__, __FILE__, __LINE__, __VA_ARGS__)

#endif
