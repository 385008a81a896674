/* A winding problem: everything the reel needs to wind one roll, as plain data.
 *
 * The physics (material, core, tension recipe, nip) and the numerics, and what the reel
 * itself records (stress history, nip profiles). No file format: a scene (reelsim/scene.h)
 * resolves a YAML file into one, and a program may equally fill one in itself.
 *
 * A value struct on purpose, unlike the result: it is the input a program builds field by
 * field (tests/validation/test_taper.c winds one with no YAML), and the nip, material and
 * storage specs in it are handed on by address (rs_nip_contact_create_from_spec). */
#ifndef REELSIM_PROBLEM_H
#define REELSIM_PROBLEM_H

#include "reelsim/core.h"
#include "reelsim/material.h"
#include "reelsim/nip.h"
#include "reelsim/numerics.h"
#include "reelsim/recipe.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

enum { RS_MAX_PROFILES = 64, RS_STORAGE_MAX_STAGES = 256 };

typedef struct rs_numerics {
  int layers_per_step;     /* layers wound per increment */
  double rtol;             /* CVODE relative tolerance */
  double atol;             /* CVODE absolute tolerance (0: = rtol) */
  long max_steps;          /* CVODE steps per increment */
  rs_reuse reuse;          /* keep the deep part of an earlier integration (default) or not */
  rs_load_placement load_placement; /* where a new layer's load goes (default: beneath it) */
  rs_correction error_correction; /* (w, ln y) corrected for the integration's error (default) */
} rs_numerics;

/* What the reel records beside the final state. */
typedef struct rs_record_spec {
  int history_every;       /* layers between stored history stages; 0 = no history */
  int n_profiles;          /* contact distributions kept (contact nip only) */
  double nip_profiles_at[RS_MAX_PROFILES]; /* m, roll radii of those */
} rs_record_spec;

/* One storage stage (docs/storage.md): the roll is brought to temperature and humidity
 * (a uniform, instantaneous change from the previous stage's) and then held there for
 * `hours`. A scene's stage that omits either keeps the previous stage's value here. */
typedef struct rs_storage_stage {
  double hours;            /* h, >= 0 */
  double temperature;      /* C */
  double humidity;         /* % RH */
} rs_storage_stage;

/* After the winder: the state the roll is wound in and the stages it is stored through.
 * n_stages = 0: no storage (nothing of src/storage runs). */
typedef struct rs_storage_spec {
  double wind_temperature; /* C, winding.temperature (default 23) */
  double wind_humidity;    /* % RH, winding.humidity (default 50) */
  double core_alpha;       /* 1/K, core.alpha: the core's thermal expansion (0 if not given) */
  double core_beta;        /* 1/%RH, core.beta: its hygroscopic expansion (0 if not given) */
  int n_stages;
  rs_storage_stage stage[RS_STORAGE_MAX_STAGES];
} rs_storage_spec;

/* Entrained air (docs/roll-model.md, "Entrained air"): the scene's `air` block. on = 0:
 * no air, the roll winds exactly as without the block. */
typedef struct rs_air_spec {
  int on;                  /* 1: entrained air (needs the speed and a roughness) */
  double viscosity;        /* Pa s, air.viscosity (default 1.8e-5: air at 20 C) */
  double roughness;        /* m, combined RMS roughness of web and roll surfaces */
  double cutoff;           /* the film kept is max(0, h0 - cutoff roughness) (default 3) */
  double pressure;         /* Pa, absolute ambient pressure (default 101325) */
  double nip_radius;       /* m, the nip roller's radius (a problem with a nip) */
  int moving_surfaces;     /* U = moving_surfaces x V in the foil law: 2 (web and roll, default)
                              or 1 (one surface: TopWeb's convention) */
} rs_air_spec;

/* A winder with several nips (docs/nip.md, "Two-drum winders"): the scene's `nip:` as a
 * list and its `winder` block. n_nips = 0: the problem's one nip (`nip`) or none, wound
 * exactly as without this block. */
enum { RS_MAX_NIPS = 4 };
typedef enum rs_nip_position {
  RS_NIP_AT_NONE,  /* not given (a nip of a center or surface winder) */
  RS_NIP_AT_FRONT, /* the front drum of a two-drum winder */
  RS_NIP_AT_REAR,  /* the rear drum */
  RS_NIP_AT_RIDER  /* the rider roll on top of the roll */
} rs_nip_position;
typedef enum rs_winder_type {
  RS_WINDER_TYPE_CENTER,  /* the roll's weight on its shaft: every nip load as given */
  RS_WINDER_TYPE_SURFACE, /* likewise; the drive at the surface (documentation, checks) */
  RS_WINDER_TYPE_TWO_DRUM /* the roll rests on two drums that share its weight */
} rs_winder_type;
typedef struct rs_winder_spec {
  rs_winder_type type;
  int n_nips;                           /* 0: `nip` alone; else the list, in the scene's order */
  rs_nip_spec nips[RS_MAX_NIPS];        /* each nip's model, friction, drum and load */
  rs_nip_position position[RS_MAX_NIPS];
  double drum_radius[RS_MAX_NIPS];      /* m, two_drum: the drum of a front/rear nip */
  double drum_distance;                 /* m, two_drum: the drums' centre distance */
} rs_winder_spec;
/* Lanes across the width (docs/lanes.md): the web split into `count` lanes (0: none, the
 * reel winds one radial line exactly as without the block), each its own roll on the shared
 * core with its caliper, coupled layer by layer through the one sheet entering. */
enum { RS_LANES_MAX = 256 };
typedef enum rs_lanes_nip {
  RS_LANES_NIP_UNIFORM = 0, /* each lane the mean line load */
  RS_LANES_NIP_ROLLER = 1   /* a rigid lay-on roller resting on the lanes' radius profile */
} rs_lanes_nip;
typedef struct rs_lanes_spec {
  int count;                      /* lanes; 0: no lanes */
  rs_lanes_nip nip;
  double x[RS_LANES_MAX];         /* m, each lane's centre across the width */
  double width[RS_LANES_MAX];     /* m, each lane's width (> 0) */
  double caliper[RS_LANES_MAX];   /* factor on material.caliper (> 0) */
  double tension[RS_LANES_MAX];   /* factor on the entry tension (> 0; 1: uniform) */
} rs_lanes_spec;

typedef struct rs_problem {
  rs_material material;
  rs_core core;
  double final_radius;     /* m */
  int n_layers;            /* round((final_radius - core radius) / caliper) */
  rs_recipe tension;       /* N/m, web tension against radius */
  double accel_torque;     /* N m/m, torque during speed changes (slip check); 0 = not given */
  rs_nip_spec nip;         /* model RS_NIP_NONE: T0 = web tension */
  rs_numerics numerics;
  rs_record_spec record;
  rs_storage_spec storage; /* stages after winding (n_stages = 0: none) */
  /* Winding at speed (docs/roll-model.md, "Centrifugal load"): centrifugal = 0 winds as
   * at rest, whatever the speed; 1 takes rho t V^2 off each layer's contact load and adds
   * the spin field of the last layer's speed (rs_reel_result.at_speed_*). */
  rs_recipe speed;         /* m/s against roll radius, winding.speed (zeroed: 0) */
  int centrifugal;         /* 1: centrifugal load on (needs material.density) */
  /* Entrained air: each layer's film widens the roll, so the reel decides the number of
   * layers as it winds: up to n_layers, until the outer radius reaches final_radius or,
   * when web_length > 0, until that much web is wound. */
  rs_air_spec air;
  double web_length;       /* m, the roll's size as a length (0: final_radius) */
  double acceleration;     /* m/s^2 at the roll's surface in a speed change (cinching); 0 = not
                              given (winding.accel_torque is the alternative) */
  double core_friction;    /* static web-on-core friction, core.friction (cinching at the core);
                              0 = not given */
  /* Several nips (nip: as a list) and the winder that carries the roll. With a list, `nip`
   * holds the first nip's settings (update policy, model) and, as its load, the nips'
   * total against radius (the /layers/nip_load record). */
  rs_winder_spec winder;
  rs_lanes_spec lanes;     /* lanes across the width (count 0: none) */
} rs_problem;

RS_END_DECLS
#endif
