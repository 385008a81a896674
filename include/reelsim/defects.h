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

/* What the rules compare against; 0 (NULL) means "not given". */
typedef struct rs_defect_limits {
  double pressure_limit; /* Pa, material: pressure the web stands without crushing/blocking */
  double core_rating;    /* Pa, core: external pressure the core is rated for */
  double accel_torque;   /* N m/m, torque on the roll during speed changes, per unit width */
  double friction_layer; /* web-on-web friction coefficient */
  /* The web, for the hoop buckling rule (not assessed without both): */
  double E_theta;              /* Pa, hoop (machine-direction) modulus */
  const rs_radial_law *radial; /* the stack's radial modulus law E_r(P), prepared */
} rs_defect_limits;

/* The problem's optional figures (a scene's keys material.pressure_limit, core.rating,
 * winding.accel_torque, material.friction_layer) and its material's E_theta and radial law
 * (lim->radial points into the problem, which must outlive the assessment). */
void rs_defect_limits_from_problem(const rs_problem *problem, rs_defect_limits *lim);

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
  struct {                   /* hoop buckling (starring): -sigma_theta > sigma_cr(E_r(P)) */
    rs_defect_verdict verdict;
    int layers;              /* layers at risk */
    int n_ranges;
    rs_defect_range *ranges; /* where, innermost first */
    int compressed;          /* layers in hoop compression (those the rule weighs) */
    double margin_min;       /* least sigma_cr / (-sigma_theta) over them (when compressed > 0) */
    double margin_radius;    /* m, that layer's outer radius */
    double margin_critical;  /* Pa, sigma_cr there */
    double margin_sigma;     /* Pa, sigma_theta there (negative) */
  } buckling;
  struct {                   /* greatest pressure on the web against material.pressure_limit */
    rs_defect_verdict verdict;
    double max, max_radius;  /* Pa (compression positive), m */
    double limit, ratio;     /* Pa, max / limit (0 when not assessed) */
  } pressure;
  struct {                   /* interlayer slip: friction torque capacity < applied torque */
    rs_defect_verdict verdict;
    double torque, mu;       /* N m/m, web-on-web friction */
    int layers;              /* interfaces at risk */
    int n_ranges;
    rs_defect_range *ranges; /* layers whose outer interface is at risk */
    double margin_min;       /* least capacity / torque over the interfaces */
    double margin_radius;    /* m, where */
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
