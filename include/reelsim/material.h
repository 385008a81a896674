/* Web materials: the radial (stack) modulus laws and the sheet constants.
 * Physics free of I/O; the scene loader fills these structs from models/ YAML. */
#ifndef REELSIM_MATERIAL_H
#define REELSIM_MATERIAL_H

#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

enum { RS_TABLE_MAX = 256, RS_HAKIEL_MAX_COEF = 5, RS_NAME_MAX = 128, RS_PRONY_MAX = 16 };

typedef enum rs_radial_kind {
  RS_RADIAL_LINEAR,   /* E_r constant */
  RS_RADIAL_PFEIFFER, /* P = K1 (exp(K2 eps) - 1)  =>  E_r = K2 (P + K1) */
  RS_RADIAL_HAKIEL,   /* E_r = C0 + C1 P + C2 P^2 + C3 P^3 (+ C4 P^4) */
  RS_RADIAL_TABLE     /* measured (P, E_r) points, monotone cubic (Fritsch-Carlson) */
} rs_radial_kind;

typedef struct rs_radial_law {
  rs_radial_kind law;
  double E_r;                       /* linear: Pa */
  double K1, K2;                    /* pfeiffer: Pa, dimensionless */
  double C[RS_HAKIEL_MAX_COEF];     /* hakiel: Pa, 1, 1/Pa, 1/Pa^2, 1/Pa^3 */
  int n_coef;
  int n_points;                     /* table */
  double P[RS_TABLE_MAX];           /* Pa, strictly increasing, P[0] >= 0 */
  double E[RS_TABLE_MAX];           /* Pa, > 0 */
  double slope[RS_TABLE_MAX];       /* dE/dP at the points, set by rs_radial_law_prepare */
} rs_radial_law;

/* Checks the law (positive moduli, sorted table) and precomputes what evaluation needs
 * (table slopes). Returns RS_ERR_INPUT with a message naming the offending value. */
rs_status rs_radial_law_prepare(rs_radial_law *law);

/* Tangent radial modulus E_r(P) in Pa at interlayer pressure P >= 0 (Pa, compression
 * positive). Table: monotone cubic between points, the end values held outside them. */
double rs_radial_modulus(const rs_radial_law *law, double P);
/* The same at n pressures: E[i] = E_r(P[i]) (one dispatch on the law for the whole array,
 * so that the loops vectorise; the roll engine evaluates every layer at every increment). */
void rs_radial_modulus_n(const rs_radial_law *law, const double *P, double *E, int n);
/* The same at the pressures of n radial stresses sigma (Pa, compression negative), with the
 * check a stack needs: P[i] = -sigma[i], E[i] = E_r(P[i]), in one pass over the arrays for
 * the linear, Pfeiffer and quadratic laws. Returns the first i whose E[i] is not positive
 * and finite (the law outside its range), or -1 when all are. */
int rs_radial_modulus_stress_n(const rs_radial_law *law, const double *sigma, double *P, double *E,
                               int n);

/* The stack's strain at pressure P >= 0 (compression positive) loaded from zero,
 * eps(P) = integral over [0, P] of dp / E_r(p) (dimensionless; 0 for P <= 0): what a stack
 * test measures and what compresses a layer of the roll at pressure P. For Pfeiffer's law
 * it is ln(1 + P/K1)/K2. */
double rs_radial_strain(const rs_radial_law *law, double P);
/* eps(b) - eps(a) for 0 <= a <= b: Gauss-Legendre (8 points) on [a, b], split at a table's
 * points; accurate where 1/E_r varies little over [a, b] (a tabulation's step). */
double rs_radial_strain_step(const rs_radial_law *law, double a, double b);
/* d[i] = rs_radial_strain_step(law, P[i], P[i + 1]) for i = 0..n-1, the same numbers, the
 * moduli of all the steps' Gauss points formed in one rs_radial_modulus_n (a tabulation of
 * eps at n + 1 pressures) */
void rs_radial_strain_steps(const rs_radial_law *law, const double *P, int n, double *d);

/* A Prony series of the web's relaxation (storage creep, docs/storage.md): term i relaxes
 * the fraction w_i of a modulus with relaxation time tau_i,
 *   E(t) = E (1 - sum_i w_i (1 - exp(-t / tau_i))),
 * for the hoop modulus E_theta (w_theta) and for the stack law (w_radial). */
typedef struct rs_prony {
  int n;                          /* terms; 0 = no viscoelastic data */
  double tau[RS_PRONY_MAX];       /* h, > 0 */
  double w_theta[RS_PRONY_MAX];   /* >= 0, sum < 1 */
  double w_radial[RS_PRONY_MAX];  /* >= 0, sum < 1 */
} rs_prony;

typedef struct rs_material {
  char name[RS_NAME_MAX];
  double caliper;    /* m: the sheet thickness 2h of the seed paper */
  double E_theta;    /* Pa: hoop (machine-direction) modulus */
  double nu_rtheta;  /* Poisson ratio in the Hakiel core condition */
  rs_radial_law radial;
  double G_rtheta;   /* Pa: in-plane shear modulus (nip model); 0 = not given */
  /* The sheet and the roll in the nip (contact model, docs/nip.md); 0 = not given: */
  double E_z;        /* Pa: thickness (ZD) modulus of one sheet; 0 = the roll's nip E_r */
  double E_cd;       /* Pa: cross-direction modulus (plane strain); 0 = E_theta */
  double nu_md_cd;   /* MD stress -> CD strain Poisson ratio (plane strain); the scene's
                        default is 0.3, a value given here is used as is (0 is 0) */
  double density;    /* kg/m^3; 0 = not given */
  double pressure_limit; /* Pa: crushing/blocking pressure (defect check); 0 = not given */
  double friction_layer; /* web-on-web friction coefficient (slip check); 0 = not given */
  /* Free strains of the web in storage (docs/storage.md): eps* = alpha dT + beta dH. */
  int has_thermal;       /* material.thermal given */
  double alpha_r, alpha_theta; /* 1/K: thermal expansion through the stack and along the web */
  int has_hygroscopic;   /* material.hygroscopic given */
  double beta_r, beta_theta;   /* 1/%RH: hygroscopic expansion, likewise */
  rs_prony viscoelastic; /* material.viscoelastic (n = 0: not given) */
  double roughness;      /* m: RMS roughness of the web's two faces combined (entrained air,
                            the default of air.roughness); 0 = not given */
  double hoop_strength;  /* Pa: machine-direction compressive strength (starring); 0 = not
                            given */
  double nit_saturation; /* N/m: the most nip-induced tension one nip adds (measured WIT
                            levels off with nip load; docs/nip.md, "Two-drum winders");
                            0 = not given (no cap) */
} rs_material;

/* Entrained air (docs/roll-model.md, "Entrained air"). The film a web wrapping a roll of
 * radius R carries in (Knox & Sweeney 1971, the foil bearing of Blok & van Rossum 1953):
 *     h0 = 0.643 R (6 mu U / T)^(2/3)                                  (m)
 * mu the air's viscosity (Pa s), T the web tension (N/m), U the sum of the two surfaces'
 * speeds (m/s; 2V when web and roll both move at V). */
double rs_air_foil_film(double R, double U, double T, double mu);
/* The film a loaded nip lets through: the rigid-isoviscous minimum film of a cylinder
 * rolling on a cylinder (Martin 1916; Hamrock 1994, "rigid-isoviscous" regime),
 *     h_min = 4.9 mu u R_eq / w,    1/R_eq = 1/R_roll + 1/R_nip       (m)
 * u the mean speed of the surfaces (m/s), w the nip load (N/m). */
double rs_air_nip_film(double R_roll, double R_nip, double u, double w, double mu);
/* The film that stays in the roll once the web lies on the asperities: what exceeds k
 * combined RMS roughnesses (sigma, m), max(0, h0 - k sigma); the air below escapes
 * through the valleys (k = 3: Ducotey & Good 1999's full-separation height). */
double rs_air_surviving_film(double h0, double sigma, double k);
/* A film h (at the ambient pressure p_a, Pa absolute) under the radial pressure P (Pa,
 * gauge, compression positive; P < 0 counts as 0): the trapped air an isothermal ideal
 * gas, h p_a / (p_a + P). */
double rs_air_compressed_film(double h, double P, double p_a);
/* The stack and the film under one layer in series, as the roll's stress solve sees it
 * (layer pitch t): t / E = t / E_r + h p_a / (p_a + P)^2, the film's tangent compliance
 * -dh/dP. h = 0 returns E_r itself. */
double rs_air_series_modulus(double E_r, double t, double h, double P, double p_a);

RS_END_DECLS
#endif
