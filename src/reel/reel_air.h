/* Entrained air in the reel (docs/roll-model.md, "Entrained air"): the film each layer
 * brings, the roll's outer radius with the films, where the reel stops, the final radii. */
#ifndef REELSIM_REEL_AIR_H
#define REELSIM_REEL_AIR_H

#include "reelsim/problem.h"
#include "reelsim/reel.h"
#include "roll/roll.h"
#include "reelsim/status.h"

typedef struct rs_reel_air {
  double *film;     /* [N + 1] m, the film under layer j (node j), as it survived; the roll
                       reads it (rs_roll_params.air_film) */
  double *length;   /* [N] m, web wound once layer j is on, at the radii it went on at */
  double *node;     /* [N + 1] m, the roll's node j (outer face of layer j) at its radius as
                       the layer went on, films included; the roll reads it
                       (rs_roll_params.air_radius) */
  double radius;    /* m, the roll's outer radius with its films (rs_reel_air_begin) */
} rs_reel_air;

rs_status rs_reel_air_create(rs_reel_air *air, int N);
void rs_reel_air_free(rs_reel_air *air);

/* The film (m) a layer brings onto a roll of outer radius R (m) at web tension Ti (N/m),
 * web speed V (m/s) and nip load w (N/m; the problem's nip only): the foil bearing, or
 * what the nip lets through if less, less the roughness cut-off. */
double rs_reel_air_film(const rs_problem *pb, double R, double Ti, double V, double w);

/* The outer radius of the roll of n layers, each film compressed by the roll's pressure on
 * it now (m); kept in air->radius. */
double rs_reel_air_begin(rs_reel_air *air, const rs_problem *pb, const rs_roll *roll, int n);

/* 1 when layer j (0-based), going on at outer radius R with film h, would overshoot the
 * problem's size (final_radius, or web_length when given): the layer nearest the size is
 * the last one. Layer 0 always goes on. */
int rs_reel_air_stop(const rs_reel_air *air, const rs_problem *pb, int j, double R, double h);

/* Records layer j's film and web length (R: the roll's radius beneath it). */
void rs_reel_air_wound(rs_reel_air *air, int j, double R, double h, double t);

/* res->air_film_entrained from the films (before the spin part, which reads it). */
rs_status rs_reel_air_entrained(const rs_reel_air *air, rs_reel_result *res);

/* After winding (the final stresses in res): res->radius with the films compressed by the
 * final pressures, res->air_film, res->air_film_entrained, res->air_wound_length. */
rs_status rs_reel_air_finish(const rs_reel_air *air, const rs_problem *pb, rs_reel_result *res);

#endif
