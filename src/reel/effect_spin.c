/* The centrifugal load as a reel effect (effect.h; the model: spin.c, docs/roll-model.md,
 * "Centrifugal load"). Each layer's own rotation needs the hoop force rho t V^2, which is
 * not pressed on the roll beneath it: the roll is wound with T0 - rho t V^2, and a layer
 * whose T0 is not above it cannot stay on the roll. After winding, the spin part turns the
 * result into the roll at rest and at speed (rs_spin_wound). */
#include <stdlib.h>

#include "reel/effect.h"
#include "reel/spin.h"

typedef struct spin_effect {
  int stopped; /* a layer could not stay on the spinning roll (the run stopped there) */
} spin_effect;

static rs_status spin_setup(rs_reel_effect *e, rs_reel_state *s, rs_roll_params *params)
{
  (void)s;
  (void)params;
  e->content = calloc(1, sizeof(spin_effect));
  return e->content ? RS_OK : RS_ERROR(RS_ERR_MEMORY, "centrifugal load: out of memory");
}

/* carried = T0 - rho t V(r)^2 > 0 (N/m) */
static rs_status spin_layer(rs_reel_effect *e, const rs_reel_state *s, rs_reel_layer *L)
{
  spin_effect *sp = e->content;
  const rs_problem *pb = s->pb;
  const double V = rs_recipe_eval(&pb->speed, L->r);
  const double spin = pb->material.density * pb->material.caliper * V * V;
  L->carried = L->T0 - spin;
  if (!(L->carried > 0.0)) {
    sp->stopped = 1;
    return RS_ERROR(RS_ERR_SOLVER,
                    "centrifugal load: at r = %.6g m (layer %d of %d) the wound-on tension "
                    "%g N/m is not above rho t V^2 = %g N/m (V = %g m/s): the web cannot "
                    "stay on the spinning roll", L->r, L->j + 1, s->N, L->T0, spin, V);
  }
  return RS_OK;
}

/* The spin part, on the layers wound when the run succeeded or stopped here (with entrained
 * air it reads the films as entrained: res->air_film_entrained). */
static rs_status spin_collect(rs_reel_effect *e, const rs_reel_state *s, rs_status st)
{
  const spin_effect *sp = e->content;
  rs_reel_result *res = s->res;
  if ((st == RS_OK || sp->stopped) && res->n_layers > 0 && (!s->film || res->air_film_entrained))
    return rs_spin_wound(s->pb, res, 0);
  return RS_OK;
}

static void spin_destroy(rs_reel_effect *e)
{
  free(e->content);
  e->content = NULL;
}

const rs_reel_effect_ops rs_reel_spin_effect = {
    .name = "centrifugal",
    .setup = spin_setup,
    .wound = spin_layer,
    .collect = spin_collect,
    .destroy = spin_destroy,
};
