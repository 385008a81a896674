/* The roll build-up engine (private to the library: the reel winds a roll, applications
 * wind a problem, reelsim/reel.h): Hakiel-type accretion integrated with SUNDIALS CVODE.
 *
 * Plane stress, axisymmetric, cylindrically orthotropic roll on a core (Hakiel 1987).
 * Each call to rs_roll_add_layers winds m layers of caliper t at wound-on tensions T0
 * (N/m); each layer k adds the stress increment ds(r) that solves
 *     r^2 ds'' + 3 r ds' - (g^2 - 1) ds = 0,  g^2 = E_theta / E_r(P)
 * with the core condition r_c ds'(r_c) = (E_theta/E_c + nu - 1) ds(r_c) and, by default,
 * ds(s_{k-1}) = -T0/s_{k-1} on the roll beneath the layer (RS_LOAD_BENEATH), or Hakiel's
 * ds(s_k) = -T0/s_k at its outer radius (RS_LOAD_HAKIEL).
 * E_r is the tangent radial modulus at the pressure before the increment (frozen).
 * See docs/roll-model.md for the scale-free (Riccati) formulation that never overflows. */
#ifndef RS_ROLL_ROLL_H
#define RS_ROLL_ROLL_H

#include "reelsim/material.h"
#include "reelsim/numerics.h"
#include "reelsim/status.h"


typedef struct rs_roll rs_roll;

/* The accuracy rtol stands for, as a share of it. The error correction leaves each
 * integration within a few hundredths of rtol, a tenth at most (docs/roll-model.md); what
 * it does not see is held to RS_ACCURACY_PER_RTOL x rtol directly: the deep reuse (whose
 * error, of one sign, adds up to ~1.3x that over a reel: the two are then of a size,
 * measured on six scenes and the 100,633-layer film, docs/accuracy.md) and the storage
 * stages' stepped changes and creep integration (docs/storage.md) */
#define RS_ACCURACY_PER_RTOL 0.02

typedef struct rs_roll_params {
  double core_radius;      /* m */
  double core_stiffness;   /* Pa, effective E_c; INFINITY for a rigid core */
  double caliper;          /* m */
  double E_theta;          /* Pa */
  double nu_rtheta;
  rs_radial_law radial;    /* must have been through rs_radial_law_prepare */
  int max_layers;          /* capacity */
  double rtol;             /* CVODE relative tolerance on (w, ln y) */
  double atol;             /* CVODE absolute tolerance; <= 0: rtol */
  long max_steps;          /* CVODE internal steps per increment; <= 0: 100000 */
  rs_reuse reuse;          /* 0 = RS_REUSE_ON */
  rs_load_placement placement; /* 0 = RS_LOAD_BENEATH */
  rs_correction correction; /* 0 = RS_CORRECTION_ON */
  /* Entrained air (docs/roll-model.md, "Entrained air"): air_film[j] (m) is the film under
   * layer j, at node j (its inner face), entrained at the ambient pressure air_pressure (Pa,
   * absolute); the stack law and the film in series, rs_air_series_modulus. Read at every
   * increment: the caller fills entry j before winding layer j (max_layers + 1 entries).
   * NULL: no air, the stack law alone. */
  const double *air_film;
  double air_pressure;
  /* The roll's nodes at their real radii (docs/roll-model.md, "Entrained air"):
   * air_radius[j] (m) is node j's radius with the films beneath it (the outer face of layer
   * j; node 0 the core, r_c), read once, when the increment that creates node j is wound
   * (the caller fills it before). Used with air_film and the load beneath each layer, from
   * the first node with a film beneath it; NULL, or no film yet: r_c + j t. */
  const double *air_radius;
} rs_roll_params;

typedef struct rs_roll_stats {
  long increments;         /* calls to rs_roll_add_layers */
  long cvode_steps;        /* internal CVODE steps, all increments */
  long rhs_evals;
  long jac_evals;
  long full_integrations;  /* increments integrated from the core (the rest reused the
                              deep part of the last of these) */
} rs_roll_stats;

rs_status rs_roll_create(const rs_roll_params *params, rs_roll **out);
void rs_roll_destroy(rs_roll **roll); /* accepts NULL and *roll == NULL */

/* Winds m >= 1 layers in one increment; T0[i] >= 0 (N/m) is the wound-on tension of
 * the i-th of them, innermost first; each layer's load where params.placement puts it. */
rs_status rs_roll_add_layers(rs_roll *roll, int m, const double *T0);

int rs_roll_layers(const rs_roll *roll);
double rs_roll_outer_radius(const rs_roll *roll);          /* m */
double rs_roll_layer_radius(const rs_roll *roll, int j);   /* outer radius of layer j (0-based) */
/* Per layer j = 0..n-1 (layer j+1 in the notes), evaluated at its outer radius; Pa,
 * tension positive. The arrays stay owned by the roll and hold until the next
 * rs_roll_add_layers or rs_roll_restore (the engine may fill them afresh at each read).
 * FILLS CACHES: these two readers take const but write the roll's caches (the lazy deep
 * part brought up to date, the hoop stresses from equilibrium), so two threads must not
 * read one roll at once; a roll belongs to one thread, for reading as for winding. */
const double *rs_roll_sigma_r(const rs_roll *roll);
const double *rs_roll_sigma_theta(const rs_roll *roll);
/* sigma_r of layer j alone (NaN outside 0..n-1): the engine keeps its deep part lazy
 * (docs/roll-model.md), which rs_roll_sigma_r brings up to date over the whole roll */
double rs_roll_layer_sigma_r(const rs_roll *roll, int j);
double rs_roll_core_pressure(const rs_roll *roll);         /* Pa, compression positive */
/* Tangent radial modulus E_r (Pa) at the outermost loaded interface: under the outermost
 * layer (RS_LOAD_BENEATH; the core for one layer), at its outer face (RS_LOAD_HAKIEL); with
 * air films, the film there in series. */
double rs_roll_surface_modulus(const rs_roll *roll);
void rs_roll_get_stats(const rs_roll *roll, rs_roll_stats *stats);

/* A saved state of the roll, to wind again from (the reel's adaptive nip policy rewinds
 * when a predicted wound-on tension proves wrong). Owned by the caller; a state can be
 * saved into again and again (its arrays grow as needed). */
typedef struct rs_roll_state rs_roll_state;
rs_status rs_roll_state_create(rs_roll_state **out);
void rs_roll_state_destroy(rs_roll_state **state); /* accepts NULL and *state == NULL */
rs_status rs_roll_save(const rs_roll *roll, rs_roll_state *state);
/* Restores a state saved from this roll (same parameters). */
rs_status rs_roll_restore(rs_roll *roll, const rs_roll_state *state);

#endif
