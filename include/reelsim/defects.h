/* Defect-risk indicators of a wound reel: simple, documented rules applied to the final
 * stress profile (docs/defects.md gives each rule, its formula, units and rationale).
 * They flag where a roll is prone to a defect; they do not model the defect itself.
 * Pure computation on a result: no I/O. */
#ifndef REELSIM_DEFECTS_H
#define REELSIM_DEFECTS_H

#include "reelsim/material.h"
#include "reelsim/problem.h"
#include "reelsim/reel.h"
#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

typedef enum rs_defect_verdict {
  RS_DEFECT_NOT_ASSESSED, /* the rule lacks an input it needs (a limit not given, no layers) */
  RS_DEFECT_OK,
  RS_DEFECT_RISK,
  RS_DEFECT_PRESENT       /* information, not a risk: the condition occurs (hoop compression) */
} rs_defect_verdict;

/* "not assessed", "ok", "risk", "present" */
const char *rs_defect_verdict_name(rs_defect_verdict v);

/* Which criterion decided the starring verdict (the least margin). */
typedef enum rs_starring_criterion {
  RS_STARRING_NONE,     /* not assessed, or no hoop compression */
  RS_STARRING_STRENGTH, /* -sigma_theta against material.hoop_strength */
  RS_STARRING_PACKET    /* the compressive zone buckling as a ring packet on a foundation */
} rs_starring_criterion;

/* "none", "hoop_strength", "packet_buckling" */
const char *rs_starring_criterion_name(rs_starring_criterion c);

/* What the rules compare against; 0 (NULL) means "not given". */
typedef struct rs_defect_limits {
  double pressure_limit; /* Pa, material: pressure the web stands without crushing/blocking */
  double core_rating;    /* Pa, core: external pressure the core is rated for */
  double accel_torque;   /* N m/m, torque that speeds up or stops the roll, per unit width */
  double friction_layer; /* static web-on-web friction coefficient */
  /* The web and the core, for the starring rule (not assessed without E_theta and radial): */
  double E_theta;              /* Pa, hoop (machine-direction) modulus */
  const rs_radial_law *radial; /* the stack's radial modulus law E_r(P), prepared */
  double caliper;              /* m, the web's thickness t (0: one layer's pitch from radii) */
  double hoop_strength;        /* Pa, machine-direction compressive strength; 0 = not given */
  double core_stiffness;       /* Pa, E_c of u_c = r_c sigma_r / E_c; INFINITY or 0 = rigid */
  /* Cinching (docs/defects.md, section 4): */
  double acceleration;   /* m/s^2 at the roll's surface (winding.acceleration); 0 = not given */
  double density;        /* kg/m^3, the web's (needed with acceleration) */
  double core_share;     /* share of the drive torque entering at the core: 1 center winding
                            or unwinding on a core brake, 0 surface winding, torque_share for
                            center-surface (rs_defect_core_share) */
  double core_friction;  /* static web-on-core friction coefficient (core.friction); 0 = not
                            given: the core interface is not assessed */
} rs_defect_limits;

/* The problem's optional figures (a scene's keys material.pressure_limit, core.rating,
 * winding.accel_torque / acceleration, material.friction_layer, material.hoop_strength,
 * core.friction) and its material's E_theta, caliper, density and radial law and the
 * winder's core share (lim->radial points into the problem, which must outlive the
 * assessment). */
void rs_defect_limits_from_problem(const rs_problem *problem, rs_defect_limits *lim);

/* Share of the drive torque that enters the roll at its core, from the winder: 1 for center
 * winding (and a scene without a nip), 0 for surface winding (the drum drives the roll's
 * surface), nip.torque_share for center-surface. A new winder kind adds its case here. */
double rs_defect_core_share(const rs_problem *problem);

/* Consecutive layers first..last (0-based, inclusive) flagged by a rule, and the outer
 * radii of those two layers (m). */
typedef struct rs_defect_range {
  int first, last;
  double r_first, r_last;
} rs_defect_range;

typedef struct rs_defect_report {
  struct {                   /* hoop compression, sigma_theta < 0: information, not a risk */
    rs_defect_verdict verdict; /* PRESENT, OK (none) or NOT_ASSESSED (no layers) */
    int layers;              /* layers in hoop compression */
    int n_ranges;
    rs_defect_range *ranges; /* where, innermost first */
    double min, min_radius;  /* Pa, least sigma_theta; m, its layer's outer radius */
  } hoop;
  struct {                   /* starring (docs/defects.md, section 2) */
    rs_defect_verdict verdict;
    rs_starring_criterion criterion; /* the criterion with the least margin (decides) */
    int layers;              /* layers at risk (over the strength or in a zone that buckles) */
    int n_ranges;
    rs_defect_range *ranges; /* where, innermost first */
    int compressed;          /* layers in hoop compression (those the rule weighs) */
    int zones;               /* compressive zones (runs of compressed layers) weighed */
    double margin_min;       /* least margin of both criteria (when compressed > 0) */
    double margin_radius;    /* m, where: the layer (strength) or the zone's mid radius */
    /* (a) the strength: least hoop_strength / (-sigma_theta) (NaN when not given) */
    double strength_margin, strength_radius;
    /* (b, c) the zone with the least packet margin N_cr / N: */
    double packet_margin;    /* N_cr / N (NaN: no zone) */
    int zone_first, zone_last; /* its layers (0-based) */
    double zone_inner, zone_outer; /* m, r_a (the first layer's inner radius) and r_b */
    double zone_from_core, zone_to_core; /* m, r_a - r_c and r_b - r_c (practice: 2-20 in) */
    double force;            /* N/m, N = -sum of sigma_theta t over the zone */
    double force_critical;   /* N/m, N_cr */
    double foundation;       /* Pa/m, k beneath the zone */
    double stiffness;        /* N m, D of the packet */
    int mode;                /* m of N_cr: few arms starring, many spoking */
    int bonded;              /* 1: the layers stay bonded (friction holds), 0: they slip */
    double min_sigma, min_sigma_radius; /* Pa, m: least sigma_theta (as hoop.min) */
  } starring;
  struct {                   /* greatest pressure on the web against material.pressure_limit */
    rs_defect_verdict verdict;
    double max, max_radius;  /* Pa (compression positive), m */
    double limit, ratio;     /* Pa, max / limit (0 when not assessed) */
  } pressure;
  struct {                   /* interlayer slip (cinching): capacity < torque carried */
    rs_defect_verdict verdict;
    double torque, mu;       /* N m/m, the inertia torque I |alpha| of the whole roll (from
                                accel_torque or the acceleration); web-on-web friction */
    double tension_torque;   /* N m/m, T R: web tension at the end times the outer radius */
    double core_share;       /* the winder's share of the drive at the core (limits) */
    double alpha;            /* 1/s^2, |alpha| (0 when only accel_torque is given) */
    int layers;              /* interfaces at risk */
    int n_ranges;
    rs_defect_range *ranges; /* layers whose outer interface is at risk */
    double margin_min;       /* least capacity / torque carried over the interfaces */
    double margin_radius;    /* m, where */
    double margin_torque;    /* N m/m, the torque that interface carries */
    double core_margin;      /* the web-on-core interface's (NaN: not assessed) */
    int capstan_layers;      /* k_c: the outermost wraps that take the surface torque by
                                capstan friction; the check starts under them */
  } slip;
  struct {                   /* core pressure against core.rating */
    rs_defect_verdict verdict;
    double pressure, rating, ratio; /* Pa, Pa, pressure / rating (0 when not assessed) */
  } core;
} rs_defect_report;

/* Applies every rule to the result's final state. The caller owns *out
 * (rs_defect_report_destroy). */
rs_status rs_defects_assess(const rs_reel_result *res, const rs_defect_limits *lim,
                            rs_defect_report **out);
void rs_defect_report_destroy(rs_defect_report **rep);

/* A report's figure by name, for bindings (python/reelsim): "starring.layers",
 * "starring.margin_min", "starring.margin_radius", "starring.packet_margin",
 * "starring.strength_margin", "starring.mode", "starring.zone_from_core",
 * "starring.zone_to_core", "slip.layers", "slip.margin_min", "slip.margin_radius",
 * "slip.capstan_layers", "hoop_compression.layers", "hoop_compression.min_sigma_theta",
 * "hoop_compression.min_sigma_theta_radius", "pressure.max_pressure",
 * "pressure.max_pressure_radius", "pressure.limit", "pressure.ratio", "core.core_pressure",
 * "core.rating", "core.ratio"; NaN for an unknown name or one not assessed. */
double rs_defect_report_value(const rs_defect_report *rep, const char *name);
/* "starring.verdict", "starring.criterion", "starring.interlayers", "slip.verdict",
 * "hoop_compression.verdict", "pressure.verdict", "core.verdict"; ""
 * for an unknown name. */
const char *rs_defect_report_text(const rs_defect_report *rep, const char *name);

/* Critical hoop force (N/m, positive) of a ring packet of bending stiffness D (N m, per unit
 * width) and radius R (m) on an elastic foundation of modulus k (Pa/m):
 *     N_cr = min over m >= 2 of [ D (m^2 - 1) / R^2 + k R^2 / (m^2 - 1) ]
 * (Brush & Almroth 1975, ring on a Winkler foundation, inextensional modes); *mode gets m.
 * Tends to 2 sqrt(k D) when the optimum m is large. 0 when D, k or R is not positive. */
double rs_defect_ring_critical_force(double D, double k, double R, int *mode);

/* The wound stack as rings on springs (docs/defects.md, section 2 (b)): n rings (a layer,
 * or a packet of bonded layers), ring j of bending stiffness D[j] (N m per unit width) at
 * mid radius rho[j] carrying the hoop force N[j] (N/m, compression positive), joined to the
 * ring beneath (j = 0: the core) by a radial spring k[j] (Pa/m) at radius r_spring[j]. */
typedef struct rs_ring_stack {
  int n;
  const double *D, *rho, *N, *k, *r_spring;
} rs_ring_stack;

/* The least load factor lambda (> 0) at which the stack with hoop forces lambda N[j]
 * buckles in some mode cos(m theta), m >= 2 (*mode), its mode's largest deflection at layer
 * *peak; 1e12 when none below that, NaN when out of memory. One ring on one spring:
 * lambda N = rs_defect_ring_critical_force(D, k, R). */
double rs_defect_ring_stack_critical(const rs_ring_stack *s, int *mode, int *peak);

/* Torque (N m/m) the interface at radius r carries in a speed change of a roll of outer
 * radius R on a core of radius r_c: s T R + |s - f_in| M_acc, f_in = (r^4 - r_c^4) /
 * (R^4 - r_c^4) the share of the roll's inertia inside r, s the drive's core share,
 * T R the tension's torque and M_acc = I |alpha| the torque of the whole roll's inertia
 * (the worse sign of alpha). */
double rs_defect_interface_torque(double s, double TR, double M_acc, double r, double r_c,
                                  double R);

/* Critical compressive hoop stress (Pa, positive) of one layer on the stack's elastic
 * foundation: a strip of the web (bending stiffness D = E_theta t^3 / 12 per unit width)
 * on a Winkler foundation of modulus k buckles at the axial load N_cr = 2 sqrt(k D)
 * (Hetenyi 1946; Timoshenko & Gere 1961, sec. 2.10); with the interface beneath it as the
 * foundation, k = E_r / t, the caliper cancels:  sigma_cr = N_cr / t = sqrt(E_theta E_r / 3).
 * 0 when either modulus is not positive. */
double rs_defect_critical_hoop_stress(double E_theta, double E_r);

/* Friction torque (N m/m) an interface at radius r (m) under pressure P (Pa) transmits
 * before the layers slip:  M_f = mu P (2 pi r) r  (no capacity when P <= 0). */
double rs_defect_slip_capacity(double mu, double P, double r);

RS_END_DECLS
#endif
