/* Clocks for timing runs (base layer).
 *
 * rs_clock_wall: seconds of the monotonic clock (CLOCK_MONOTONIC) from an arbitrary origin,
 * for intervals only: it does not jump when the system time is set.
 * rs_clock_thread_cpu: CPU seconds the calling thread has used (CLOCK_THREAD_CPUTIME_ID);
 * on a shared machine it leaves out other programs' turns on the core.
 * Both return 0 if the clock cannot be read (POSIX guarantees CLOCK_MONOTONIC where it is
 * defined; a zero interval is the harmless failure). */
#ifndef REELSIM_CLOCK_H
#define REELSIM_CLOCK_H

#include "reelsim/export.h"
RS_BEGIN_DECLS

double rs_clock_wall(void);
double rs_clock_thread_cpu(void);

RS_END_DECLS
#endif
