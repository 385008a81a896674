/* Entrained air: the film a web carries into the roll and how the trapped air answers the
 * roll's pressure (docs/roll-model.md, "Entrained air"). Closed forms, no state. */
#include <math.h>

#include "reelsim/material.h"

/* Knox & Sweeney (1971): a tensioned web wrapping a roll is a foil bearing whose constant
 * film (Blok & van Rossum 1953; Eshel & Elrod 1965) is h0 = 0.643 R (6 mu U / T)^(2/3),
 * with U the sum of the surface speeds in Reynolds' equation. */
double rs_air_foil_film(double R, double U, double T, double mu)
{
  if (!(U > 0.0) || !(mu > 0.0)) return 0.0;
  return 0.643 * R * cbrt(pow(6.0 * mu * U / T, 2.0));
}

/* Martin (1916): rigid cylinders, an isoviscous Newtonian film, full Sommerfeld pressure,
 * h_min = 4.9 mu u R_eq / w (Hamrock, Fundamentals of Fluid Film Lubrication, 1994). */
double rs_air_nip_film(double R_roll, double R_nip, double u, double w, double mu)
{
  if (!(u > 0.0) || !(mu > 0.0)) return 0.0;
  if (!(w > 0.0)) return INFINITY; /* an unloaded nip holds no air back */
  const double Req = R_roll * R_nip / (R_roll + R_nip);
  return 4.9 * mu * u * Req / w;
}

double rs_air_surviving_film(double h0, double sigma, double k)
{
  const double cut = k * sigma;
  return h0 > cut ? h0 - cut : 0.0;
}

double rs_air_compressed_film(double h, double P, double p_a)
{
  return h * p_a / (p_a + (P > 0.0 ? P : 0.0));
}

double rs_air_series_modulus(double E_r, double t, double h, double P, double p_a)
{
  if (!(h > 0.0)) return E_r;
  const double q = p_a + (P > 0.0 ? P : 0.0);
  return t / (t / E_r + h * p_a / (q * q));
}
