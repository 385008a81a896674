/* reelsim status codes and the error record.
 *
 * Every library function that can fail returns an rs_status. On failure it has
 * recorded where (function, source file, line) and why (a message) in a per-thread
 * error record, read with rs_error_message() / rs_error_where(). Only the library writes
 * the record (its setter is private), so what a program reads there is the library's own
 * word. The library never prints and never exits; the CLI maps statuses to exit codes
 * (rs_status_exit_code). */
#ifndef REELSIM_STATUS_H
#define REELSIM_STATUS_H

#include "reelsim/export.h"
RS_BEGIN_DECLS

typedef enum rs_status {
  RS_OK = 0,
  RS_ERR_INPUT,       /* bad input: scene, model, argument (CLI exit 2) */
  RS_ERR_SOLVER,      /* a solver could not converge or produce a finite answer (exit 3) */
  RS_ERR_IO,          /* file system or HDF5 failure (exit 1) */
  RS_ERR_MEMORY,      /* allocation failed (exit 1) */
  RS_ERR_INTERRUPTED, /* the run was interrupted (SIGINT) (exit 1) */
  RS_ERR_INTERNAL     /* a bug: an invariant did not hold (exit 1) */
} rs_status;

/* Prefixes the current message with more context ("while winding layer 12: ...").
 * Returns the recorded status, so a caller can `return rs_error_wrap(...)`. */
rs_status rs_error_wrap(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

rs_status rs_error_status(void);     /* RS_OK when no error is recorded */
const char *rs_error_message(void);  /* "" when none */
const char *rs_error_where(void);    /* "function (file:line)" or "" */
void rs_error_clear(void);

const char *rs_status_name(rs_status st);
int rs_status_exit_code(rs_status st); /* 0, 2 (input), 3 (solver), 1 (other) */

RS_END_DECLS
#endif
