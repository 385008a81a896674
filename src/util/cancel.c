/* See cancel.h. */
#include "util/cancel.h"

#include <stddef.h>

#include "reelsim/clock.h"

static _Thread_local rs_cancel_scope *current;

void rs_cancel_push(rs_cancel_scope *scope, rs_cancel_fn fn, void *user)
{
  scope->fn = fn;
  scope->user = user;
  scope->last = rs_clock_wall();
  scope->stop = 0;
  scope->outer = current;
  current = scope;
}

void rs_cancel_pop(rs_cancel_scope *scope)
{
  if (current == scope) current = scope->outer;
}

int rs_cancel_requested(void)
{
  rs_cancel_scope *s = current;
  if (!s || !s->fn) return 0;
  if (s->stop) return 1;
  double now = rs_clock_wall();
  if (now - s->last < RS_CANCEL_INTERVAL) return 0;
  s->last = now;
  return s->stop = s->fn(s->user) != 0;
}
