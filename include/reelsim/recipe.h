/* Winding recipes: web tension or nip load as a function of roll radius. */
#ifndef REELSIM_RECIPE_H
#define REELSIM_RECIPE_H

#include "reelsim/material.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

typedef enum rs_recipe_kind {
  RS_RECIPE_CONSTANT,   /* value = start */
  RS_RECIPE_LINEAR,     /* start at r0, end at r1, linear in r */
  RS_RECIPE_HYPERBOLIC, /* start * (1 - k (1 - r0/r)); k from `end` or given */
  RS_RECIPE_TORQUE,     /* constant torque: start * r0 / r */
  RS_RECIPE_TABLE       /* (r, value) points, piecewise linear, end values held */
} rs_recipe_kind;

typedef struct rs_recipe {
  rs_recipe_kind law;
  double start, end, k;  /* k: hyperbolic taper factor, NAN when derived from `end` */
  double r0, r1;        /* m: core radius and final radius (set when the scene resolves) */
  int n_points;
  double r[RS_TABLE_MAX];
  double value[RS_TABLE_MAX];
} rs_recipe;

/* The recipe's value at roll radius r (m); every law holds its end values outside
 * [r0, r1] (the last layer may lie up to half a caliper beyond r1). Units: the caller's. */
double rs_recipe_eval(const rs_recipe *rc, double r);

/* Smallest value the recipe takes on [r0, r1] (exact: each law is monotone or piecewise
 * linear). Used to reject tapers that make tension or load negative. */
double rs_recipe_min(const rs_recipe *rc);

/* Sets r0, r1 and derives k for a hyperbolic taper given by its end value. Checks the
 * table is strictly increasing in r. RS_ERR_INPUT on a malformed recipe. */
rs_status rs_recipe_prepare(rs_recipe *rc, double r0, double r1);

const char *rs_recipe_law_name(rs_recipe_kind law);

RS_END_DECLS
#endif
