/* A scene: everything one simulated reel needs, resolved and checked.
 *
 * Loaded from YAML (libcyaml) by rs_scene_load; see docs/scenes.md for every key.
 * Plain data: the scene owns nothing but `resolved_text`, freed by rs_scene_destroy. */
#ifndef REELSIM_SCENE_H
#define REELSIM_SCENE_H

#include <stddef.h>
#include <stdio.h>

#include "reelsim/core.h"
#include "reelsim/material.h"
#include "reelsim/recipe.h"
#include "reelsim/roll.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

enum { RS_PATH_MAX = 4096, RS_MAX_PROFILES = 64 };

typedef enum rs_nip_model_kind {
  RS_NIP_NONE,     /* no nip section: T0 = web tension, no nip code runs */
  RS_NIP_FRICTION, /* T0 = T + mu_roll * N (Good, Wu & Fikes 1994) */
  RS_NIP_CONTACT   /* the seed paper's contact model (nip issue) */
} rs_nip_model_kind;

typedef enum rs_winder_kind {
  RS_WINDER_CENTER,         /* center-driven roll, undriven rider: M2 = 0 */
  RS_WINDER_SURFACE,        /* drum driven, roll undriven: M1 = 0 */
  RS_WINDER_CENTER_SURFACE  /* a share of the torque on each */
} rs_winder_kind;

/* The drum (surface winder) or rider roll: a cylinder on a rigid core. */
typedef struct rs_drum {
  double radius;       /* m */
  double core_radius;  /* m, rigid core; a cover is radius - core_radius */
  int orthotropic;     /* 0: isotropic E, nu; 1: E_r, E_theta, nu_rtheta, G_rtheta */
  double E, nu;
  double E_r, E_theta, nu_rtheta, G_rtheta;
} rs_drum;

typedef enum rs_nip_update_kind {
  RS_NIP_UPDATE_ADAPTIVE, /* solve where T0 changes, extrapolate within T0_rtol elsewhere */
  RS_NIP_UPDATE_EVERY     /* solve every update_every layers (1: every layer) */
} rs_nip_update_kind;

typedef struct rs_nip_spec {
  rs_nip_model_kind model;
  rs_recipe load;          /* N/m */
  double mu_roll;          /* sheet on roll (upper contact) */
  double mu_drum;          /* sheet on drum (lower contact) */
  rs_winder_kind winder;
  double torque_share;     /* center-surface: share of the drive torque on the roll */
  rs_drum drum;
  int nodes;               /* contact nodes M */
  int terms;               /* Fourier terms of the cylinder series; 0 = automatic */
  rs_nip_update_kind update;
  int update_every;        /* every: layers between nip solves */
  double T0_rtol;          /* adaptive: tolerance on T0, relative to T0 */
} rs_nip_spec;

typedef struct rs_numerics {
  int layers_per_step;     /* layers wound per increment */
  double rtol;             /* CVODE relative tolerance */
  double atol;             /* CVODE absolute tolerance (0: = rtol) */
  long max_steps;          /* CVODE steps per increment */
  rs_reuse reuse;          /* keep the deep part of an earlier integration (default) or not */
  rs_load_placement load_placement; /* where a new layer's load goes (default: beneath it) */
} rs_numerics;

typedef struct rs_output_spec {
  char file[RS_PATH_MAX];  /* HDF5 output; "" = none unless -o */
  int history_every;       /* layers between stored history stages; 0 = no history */
  int n_profiles;
  double nip_profiles_at[RS_MAX_PROFILES]; /* m */
} rs_output_spec;

typedef struct rs_scene {
  char path[RS_PATH_MAX];           /* the scene file as given */
  char title[512];
  char material_source[RS_PATH_MAX];/* models/ file the material came from, or "inline" */
  rs_material material;
  rs_core core;
  double final_radius;              /* m (from final_radius or web_length) */
  double web_length;                /* m (0 when final_radius was given) */
  int n_layers;                     /* round((final_radius - core radius) / caliper) */
  rs_recipe tension;                /* N/m */
  double accel_torque;              /* N m/m, winding.accel_torque (slip check); 0 = not given */
  rs_nip_spec nip;
  rs_numerics numerics;
  rs_output_spec output;
  char *resolved_text;              /* the resolved scene as YAML (owned) */
} rs_scene;

/* Loads and checks a scene. `sets` are "key.path=value" overrides applied to scalars
 * before checking (the CLI's --set). Errors: RS_ERR_INPUT with "FILE:LINE: key.path: why".
 * The caller owns *out (rs_scene_destroy). */
rs_status rs_scene_load(const char *path, int n_sets, const char *const *sets, rs_scene **out);
/* The same for a scene held in memory: text[0..len) (need not be NUL-terminated) is the
 * file's content and `name` stands for its path (messages, the directory models are
 * looked up in, the default title and output file name). */
rs_status rs_scene_load_text(const char *name, const char *text, size_t len, int n_sets,
                             const char *const *sets, rs_scene **out);
void rs_scene_destroy(rs_scene **scene);

/* Writes the human-readable list of active effects, one per line
 * ("  - core: elastic (E_c = 1e9 Pa), radius 76.2 mm", "  - nip: none (T0 = web tension)"). */
void rs_scene_print_effects(const rs_scene *scene, FILE *out);

RS_END_DECLS
#endif
