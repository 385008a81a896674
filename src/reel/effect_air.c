/* Entrained air as a reel effect (effect.h; the model: reel_air.c, docs/roll-model.md,
 * "Entrained air"). The reel's radii are the real ones, t + h_j(P_j) a layer: the outer
 * radius with the films compressed as the roll presses them now at each increment's start,
 * then t + h a layer as each goes on; the film a layer brings; the reel's end where the
 * roll reaches its size; after winding, the films as entrained and as the final pressures
 * compress them. */
#include <math.h>
#include <stdlib.h>

#include "reel/effect.h"
#include "reel/reel_air.h"
#include "util/error.h"

typedef struct air_effect {
  rs_reel_air air;
  double R;    /* m, the roll's outer radius with its films, as the layers go on */
  double film; /* m, the film under the layer going on */
} air_effect;

static rs_status air_setup(rs_reel_effect *e, rs_reel_state *s, rs_roll_params *params)
{
  air_effect *a = calloc(1, sizeof *a);
  if (!a) return RS_ERROR(RS_ERR_MEMORY, "entrained air: out of memory");
  e->content = a;
  rs_status st = rs_reel_air_create(&a->air, s->N);
  if (st) return st;
  params->air_film = a->air.film;
  params->air_pressure = s->pb->air.pressure;
  params->air_radius = a->air.node;
  s->film = a->air.film;
  return RS_OK;
}

static rs_status air_begin(rs_reel_effect *e, rs_reel_state *s, rs_reel_step *step)
{
  air_effect *a = e->content;
  a->R = rs_reel_air_begin(&a->air, s->pb, s->roll, step->first);
  return RS_OK;
}

static void air_place(const rs_reel_effect *e, const rs_reel_state *s, rs_reel_layer *L)
{
  const air_effect *a = e->content;
  L->R = a->R;
  L->r = a->R + s->pb->material.caliper;
}

/* The film this layer brings; the layer nearest the roll's size is the last. */
static rs_status air_tension(rs_reel_effect *e, const rs_reel_state *s, rs_reel_step *step,
                             rs_reel_layer *L)
{
  air_effect *a = e->content;
  const rs_problem *pb = s->pb;
  const double film = rs_reel_air_film(pb, L->R, L->Ti, rs_recipe_eval(&pb->speed, L->r), L->load);
  /* a slack web (Ti = 0, no nip) floats on an unbounded film: past the roll's size (a
   * recipe at its end) that is the end, before it the run cannot go on */
  if (rs_reel_air_stop(&a->air, pb, L->j, L->R, isfinite(film) ? film : 0.0)) {
    step->m = L->b;
    step->end = 1;
    return RS_OK;
  }
  if (!isfinite(film))
    return RS_ERROR(RS_ERR_SOLVER,
                    "entrained air: the film under layer %d of %d (r = %.6g m, web tension "
                    "%g N/m) is not finite: a slack web floats on the air it carries",
                    L->j + 1, s->N, L->R, L->Ti);
  a->film = film;
  return RS_OK;
}

static rs_status air_wound(rs_reel_effect *e, const rs_reel_state *s, rs_reel_layer *L)
{
  air_effect *a = e->content;
  const double t = s->pb->material.caliper;
  rs_reel_air_wound(&a->air, L->j, a->R, a->film, t);
  a->R += a->film + t;
  L->radius = a->R;
  return RS_OK;
}

/* res->air_film_entrained (before the spin part, which reads it) */
static rs_status air_collect(rs_reel_effect *e, const rs_reel_state *s, rs_status st)
{
  const air_effect *a = e->content;
  (void)st;
  return s->res->n_layers > 0 ? rs_reel_air_entrained(&a->air, s->res) : RS_OK;
}

/* the radii with the films compressed by the final pressures; the history's last stage,
 * the final state, at that radius */
static rs_status air_finish(rs_reel_effect *e, const rs_reel_state *s, rs_status st)
{
  const air_effect *a = e->content;
  rs_reel_result *res = s->res;
  (void)st;
  if (!res->air_film_entrained) return RS_OK;
  rs_status ast = rs_reel_air_finish(&a->air, s->pb, res);
  if (res->n_stages > 0 && res->stage_layers[res->n_stages - 1] == res->n_layers)
    res->stage_radius[res->n_stages - 1] = res->radius[res->n_layers - 1];
  return ast;
}

static void air_destroy(rs_reel_effect *e)
{
  air_effect *a = e->content;
  if (a) rs_reel_air_free(&a->air);
  free(a);
  e->content = NULL;
}

const rs_reel_effect_ops rs_reel_air_effect = {
    .name = "air",
    .setup = air_setup,
    .begin = air_begin,
    .place = air_place,
    .tension = air_tension,
    .wound = air_wound,
    .collect = air_collect,
    .finish = air_finish,
    .destroy = air_destroy,
};

/* For a driver that winds several reels as one sheet (the lanes, lanes.c): whether the next
 * layer (s->first) at web tension Ti and nip load w ends this reel at its size, found as
 * air_tension finds it (the radius begin gives, the film, rs_reel_air_stop); 0 without
 * air. */
int rs_reel_air_ends(const rs_reel_state *s, double Ti, double w)
{
  for (int k = 0; k < s->n_effects; ++k) {
    if (s->effects[k].ops != &rs_reel_air_effect) continue;
    air_effect *a = s->effects[k].content;
    const rs_problem *pb = s->pb;
    const double R = rs_reel_air_begin(&a->air, pb, s->roll, s->first);
    const double V = rs_recipe_eval(&pb->speed, R + pb->material.caliper);
    const double film = rs_reel_air_film(pb, R, Ti, V, w);
    return rs_reel_air_stop(&a->air, pb, s->first, R, isfinite(film) ? film : 0.0);
  }
  return 0;
}
