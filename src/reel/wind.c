/* rs_reel_wind (reel.h): the driver of one roll through the loop's phases (reel.c,
 * reel_step.c), or of the lanes across the width (lanes.c) when the problem has them. In a
 * file of its own so that the lanes driver, which steps the phases, and the phases do not
 * call each other (scripts/check-layers.sh: no cycle between object files). */
#include <stddef.h>

#include "reel/effect.h"
#include "reel/lanes.h"
#include "util/cancel.h"
#include "reelsim/reel.h"
#include "reel/result_internal.h"
#include "util/error.h"

/* ---- the driver -------------------------------------------------------------------------- */

/* The progress callback asked from inside long steps too (util/cancel.h): a nip solve with
 * many series terms or nodes stops within RS_CANCEL_INTERVAL of a Ctrl-C, not at its end. */
typedef struct reel_cancel {
  const rs_reel_options *opts;
  int done, N;
} reel_cancel;

static int reel_cancel_poll(void *user)
{
  const reel_cancel *c = user;
  return c->opts->progress(c->opts->user, c->done, c->N);
}

/* set up; increments until the reel is finished, the progress after each that wound layers;
 * finish */
rs_status rs_reel_wind(const rs_problem *pb, const rs_reel_options *opts, rs_reel_result **out)
{
  if (!out) return RS_ERROR(RS_ERR_INTERNAL, "rs_reel_wind: out is NULL");
  *out = NULL;
  if (!pb) return RS_ERROR(RS_ERR_INTERNAL, "rs_reel_wind: no problem");
  if (pb->lanes.count > 0) return rs_lanes_wind(pb, opts, out); /* lanes across the width */
  rs_reel_state *s = NULL;
  rs_status st = rs_reel_state_create(pb, NULL, 0, &s);
  if (!s) return st;
  rs_cancel_scope scope = {0};
  reel_cancel cancel = {opts, 0, s->N};
  rs_cancel_push(&scope, opts && opts->progress ? reel_cancel_poll : NULL, &cancel);
  while (st == RS_OK && !s->done) {
    const int before = s->first;
    if ((st = rs_reel_state_step(s)) || s->first <= before) continue;
    cancel.done = s->first;
    if (opts && opts->progress && opts->progress(opts->user, s->first, s->N))
      st = RS_ERROR(RS_ERR_INTERRUPTED, "interrupted after layer %d of %d", s->first, s->N);
  }
  rs_cancel_pop(&scope);
  st = rs_reel_state_finish(s, st, out);
  rs_reel_state_destroy(&s);
  return st;
}
