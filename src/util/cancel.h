/* Cancelling long computations from inside (base layer, internal). A caller that can be
 * interrupted (the reel, through its progress callback) installs a poll for its thread;
 * loops deep inside a step that can take long (the cylinder series with many terms, the
 * contact iteration) call rs_cancel_requested(), which asks the poll at most every
 * RS_CANCEL_INTERVAL seconds and, once it said stop, says stop at once to every later
 * call (retries fail fast). Thread-local: runs in other threads are not affected. */
#ifndef RS_UTIL_CANCEL_H
#define RS_UTIL_CANCEL_H

#define RS_CANCEL_INTERVAL 0.05

typedef int (*rs_cancel_fn)(void *user);

typedef struct rs_cancel_scope {
  rs_cancel_fn fn;
  void *user;
  double last;
  int stop;
  struct rs_cancel_scope *outer;
} rs_cancel_scope;

/* Installs fn (NULL: nothing to ask) for this thread until rs_cancel_pop(scope). */
void rs_cancel_push(rs_cancel_scope *scope, rs_cancel_fn fn, void *user);
void rs_cancel_pop(rs_cancel_scope *scope);
/* Nonzero when this thread's computation should stop (RS_ERR_INTERRUPTED). */
int rs_cancel_requested(void);

#endif
