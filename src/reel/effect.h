/* The reel loop and its effects (internal to src/reel/; docs/architecture.md, "The reel
 * loop").
 *
 * The loop (src/reel/reel.c; one increment: reel_step.c) winds one roll increment by
 * increment through named phases:
 *
 *   set up     the effects' setup (in list order), then the roll
 *   per increment of m layers (layers_per_step, fewer at the end):
 *     begin    each effect's `begin`: the outer radius with the air films; the nip solved
 *              when due (it may wind a stretch again: step.rewind)
 *     per layer j:
 *       place    where the layer goes on (an effect's `place`, else the roll's radii)
 *       tension  the tension phase: the web tension Ti and the nip load w of the layer
 *                (the recipes Ti(r), w(r); a driver's `web` effect, e.g. a lane's share
 *                of the web's tension and of the roller's load); T0 = Ti
 *       effects  each effect's `tension` (the air film, which may end the reel; the nip's T0,
 *                which may ask to solve first: step.again), then the check T0 >= 0, then
 *                each effect's `wound` (the air's records, the centrifugal part of the load)
 *       records  radius, Ti, w, T0 into the result
 *     increment  the roll winds the m layers (rs_roll_add_layers)
 *     records    each effect's `after_increment` (the history, the wound radius)
 *   finish     the roll's state into the result, each effect's `collect` (list order: the
 *              history's last stage, the films as entrained, the spin part), each effect's
 *              `finish` (the films compressed by the final pressures, then the gauges), the
 *              check that every stress is finite
 *
 * An effect is an ops table and its content, as SUNDIALS' vectors and solvers: the loop
 * calls an op when it is not NULL, and a problem without the effect has no entry in the
 * list, so none of its code runs. Each effect's content is written by its own file only
 * (effect_history.c, effect_air.c, effect_nip.c, effect_spin.c, effect_gauge.c: the list's
 * order); the loop's state below is written by the loop, except where an op's comment says
 * what it may set. */
#ifndef RS_REEL_EFFECT_H
#define RS_REEL_EFFECT_H

#include "reelsim/problem.h"
#include "reel/result_internal.h"
#include "reelsim/reel.h"
#include "roll/roll.h"
#include "reelsim/status.h"

/* at most this many effects in one loop (history, air, nip, centrifugal, gauge and a
 * driver's own) */
#define RS_REEL_MAX_EFFECTS 8

typedef struct rs_reel_effect rs_reel_effect;
typedef struct rs_reel_state rs_reel_state;

/* One increment: layers first .. first + m - 1 go on. */
typedef struct rs_reel_step {
  int first;      /* layers on the roll when the increment begins */
  int m;          /* layers it winds; a `tension` op that ends the reel at layer b sets m = b */
  int end;        /* set with m: the reel is finished after this increment (the roll's size) */
  int again;      /* a `tension` op: plan the increment again, nothing wound (the nip solves) */
  int rewind;     /* a `begin` op: >= 0 wind again from this many layers (the roll is back
                     there); the loop tells every effect's `rewind` */
} rs_reel_step;

/* One layer as it goes on. */
typedef struct rs_reel_layer {
  int j, b;       /* the layer (0-based) and its place in the increment */
  double R;       /* m, the radius it goes on at (the roll's outer radius beneath it) */
  double r;       /* m, its outer radius (the recipes are taken there) */
  double Ti;      /* N/m, web tension from the recipe */
  double load;    /* N/m, nip load from the recipe (0 without a nip) */
  double T0;      /* N/m, wound-on tension: Ti, or what the nip makes of it */
  double radius;  /* m, the radius recorded for it (r; the air effect's films added) */
  double carried; /* N/m, what the roll is given: T0 less what the layer's spin needs */
} rs_reel_layer;

typedef struct rs_reel_effect_ops {
  const char *name;
  /* before the roll exists: allocates e->content, may fill the roll's parameters (the air's
   * films) and s->film */
  rs_status (*setup)(rs_reel_effect *e, rs_reel_state *s, rs_roll_params *params);
  /* at each increment's start (list order); may set step->rewind */
  rs_status (*begin)(rs_reel_effect *e, rs_reel_state *s, rs_reel_step *step);
  /* where layer L->j goes on: sets L->R and L->r (one effect at most has it) */
  void (*place)(const rs_reel_effect *e, const rs_reel_state *s, rs_reel_layer *L);
  /* the layer's T0 (L->Ti, L->load given; a driver's own tension sets Ti and T0); may set
   * step->m = L->b and step->end, or step->again: the ops after it are then not called for
   * this layer */
  rs_status (*tension)(rs_reel_effect *e, const rs_reel_state *s, rs_reel_step *step,
                       rs_reel_layer *L);
  /* the layer is accepted at L->T0 (>= 0): may set L->radius and L->carried */
  rs_status (*wound)(rs_reel_effect *e, const rs_reel_state *s, rs_reel_layer *L);
  /* after the roll wound the increment (s->first layers now) */
  rs_status (*after_increment)(rs_reel_effect *e, const rs_reel_state *s);
  /* the roll went back to `layers` layers: drop what was recorded beyond */
  void (*rewind)(rs_reel_effect *e, const rs_reel_state *s, int layers);
  /* after the loop, the roll's state copied into s->res; st: the run's status so far */
  rs_status (*collect)(rs_reel_effect *e, const rs_reel_state *s, rs_status st);
  /* the tension phase (one effect at most has them, a driver's: the lanes' coupling): the
   * web tension (N/m) of a layer whose outer radius is r, and the nip load (N/m) at radius
   * r; both read by the loop and by the nip effect when it solves (rs_reel_web_tension,
   * rs_reel_nip_load). Without them, the problem's recipes. */
  double (*web_tension)(const rs_reel_effect *e, const rs_reel_state *s, double r);
  double (*nip_load)(const rs_reel_effect *e, const rs_reel_state *s, double r);
  /* after every collect */
  rs_status (*finish)(rs_reel_effect *e, const rs_reel_state *s, rs_status st);
  /* frees e->content (also after a failed setup) */
  void (*destroy)(rs_reel_effect *e);
} rs_reel_effect_ops;

struct rs_reel_effect {
  const rs_reel_effect_ops *ops;
  void *content;
};

/* The winding state of one roll: what the loop steps. Effects read it. */
struct rs_reel_state {
  const rs_problem *pb;
  int N, per_step;        /* layers of the reel, layers per increment */
  int first;              /* layers on the roll */
  int done;               /* the reel is finished (every layer, or the roll's size) */
  double t_start;         /* s, wall clock at the start */
  rs_reel_result *res;    /* filled as the loop goes */
  rs_roll *roll;
  double *block;          /* [min(per_step, N)] N/m, the loads of one increment */
  const double *film;     /* [N + 1] m, the air films entrained (the air effect's), or NULL */
  int n_effects;
  rs_reel_effect effects[RS_REEL_MAX_EFFECTS];
  const rs_reel_effect *placer; /* the effect with `place`, or NULL */
  const rs_reel_effect *web;    /* the effect with `web_tension` and `nip_load`, or NULL */
};

/* Where layer L->j goes on: the placing effect's radii (the air films), else the roll's. */
static inline void rs_reel_place(const rs_reel_state *s, rs_reel_layer *L)
{
  if (s->placer) {
    s->placer->ops->place(s->placer, s, L);
    return;
  }
  L->R = rs_roll_layer_radius(s->roll, L->j - 1);
  L->r = rs_roll_layer_radius(s->roll, L->j);
}

/* The tension phase: the web tension of a layer whose outer radius is r (the web effect's,
 * else the tension recipe at r) and the nip load at radius r (the web effect's, else the
 * load recipe at r). */
static inline double rs_reel_web_tension(const rs_reel_state *s, double r)
{
  if (s->web) return s->web->ops->web_tension(s->web, s, r);
  return rs_recipe_eval(&s->pb->tension, r);
}

static inline double rs_reel_nip_load(const rs_reel_state *s, double r)
{
  if (s->web) return s->web->ops->nip_load(s->web, s, r);
  return rs_recipe_eval(&s->pb->nip.load, r);
}

/* The effects (each in its own file). */
extern const rs_reel_effect_ops rs_reel_history_effect; /* effect_history.c */
extern const rs_reel_effect_ops rs_reel_air_effect;     /* effect_air.c */
/* whether the next layer at web tension Ti and nip load w ends the reel at its size (its
 * air films; 0 without air): a driver of several reels ends them together (lanes.c) */
int rs_reel_air_ends(const rs_reel_state *s, double Ti, double w);
extern const rs_reel_effect_ops rs_reel_nip_effect;     /* effect_nip.c */
extern const rs_reel_effect_ops rs_reel_spin_effect;    /* effect_spin.c */
extern const rs_reel_effect_ops rs_reel_gauge_effect;   /* effect_gauge.c */

/* The loop's phases, for a driver that steps several rolls (reel.c).
 * create: the effects set up and the roll created: first `extra` (n_extra of them, e.g. a
 *   lanes driver's tension; content given by the caller or made by its setup op; its
 *   destroy op, if any, called with the state's), then the problem's. On failure *out (if
 *   not NULL) still holds the state for finish.
 * step: one increment (or a rewind, or a re-plan); s->done once the reel is finished.
 * finish: the result (*res, the caller's; NULL when it could not be allocated) with the
 *   run's status st merged. */
rs_status rs_reel_state_create(const rs_problem *pb, const rs_reel_effect *extra, int n_extra,
                               rs_reel_state **out);
rs_status rs_reel_state_step(rs_reel_state *s);
rs_status rs_reel_state_finish(rs_reel_state *s, rs_status st, rs_reel_result **res);
void rs_reel_state_destroy(rs_reel_state **s);

#endif
