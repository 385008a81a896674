/* `reelsim check`: the lines of a winder with several nips, and the nips' saturation
 * (docs/nip.md, "Two-drum winders"). */
#include <math.h>
#include <stdio.h>

#include "reel/winder.h"
#include "scene/scene_internal.h"

typedef char num_t[48];

static const char *g(num_t buf, double v)
{
  ys_fmt(buf, sizeof(num_t), v);
  return buf;
}

static const char *where(rs_nip_position p)
{
  switch (p) {
  case RS_NIP_AT_FRONT: return ", front drum";
  case RS_NIP_AT_REAR: return ", rear drum";
  case RS_NIP_AT_RIDER: return ", rider";
  case RS_NIP_AT_NONE: break;
  }
  return "";
}

/* the nips' NIT at radius R when all are friction nips (the sum of mu N, each capped);
 * NAN when a contact nip is among them or the loads cannot be had */
static double friction_nit(const rs_problem *p, double R, double cap, double *uncapped)
{
  const rs_winder_spec *w = &p->winder;
  double load[RS_MAX_NIPS], total, nit = 0.0;
  *uncapped = 0.0;
  if (rs_winder_nip_loads(w, p->material.density, R, p->core.radius, load, &total) != RS_OK)
    return NAN;
  for (int k = 0; k < w->n_nips; ++k) {
    if (w->nips[k].model != RS_NIP_FRICTION) return NAN;
    double n = w->nips[k].mu_roll * load[k];
    *uncapped += n;
    nit += cap > 0.0 && n > cap ? cap : n;
  }
  return nit;
}

static void print_list(FILE *out, const rs_problem *p)
{
  const rs_winder_spec *w = &p->winder;
  const double r0 = p->core.radius, r1 = p->final_radius;
  double l0[RS_MAX_NIPS], l1[RS_MAX_NIPS], t0, t1;
  num_t a, b, c, d;
  const int ok = rs_winder_nip_loads(w, p->material.density, r0, r0, l0, &t0) == RS_OK &&
                 rs_winder_nip_loads(w, p->material.density, r1, r0, l1, &t1) == RS_OK;
  if (w->type == RS_WINDER_TYPE_TWO_DRUM)
    fprintf(out, "  - winder: two drums, centres %s mm apart, share the roll's weight rho g pi "
                 "(R^2 - r_c^2) (%s N/m at the final radius, density %s kg/m^3) and the "
                 "rider's load along the contact normals; the core is not driven\n",
            g(a, w->drum_distance * 1e3), g(b, rs_winder_roll_weight(p->material.density, r1, r0)),
            g(c, p->material.density));
  else
    fprintf(out, "  - winder: %s, %d nips, each at its own load\n",
            w->type == RS_WINDER_TYPE_SURFACE ? "surface" : "center", w->n_nips);
  for (int k = 0; k < w->n_nips; ++k) {
    const rs_nip_spec *n = &w->nips[k];
    fprintf(out, "  - nip[%d]%s: ", k, where(w->position[k]));
    if (n->model == RS_NIP_FRICTION) fprintf(out, "friction (NIT = %s N)", g(a, n->mu_roll));
    else
      fprintf(out, "contact model (mu roll %s, mu drum %s, drum radius %s mm, %d nodes)",
              g(a, n->mu_roll), g(b, n->mu_drum), g(c, n->drum.radius * 1e3), n->nodes);
    const int drum = w->type == RS_WINDER_TYPE_TWO_DRUM && (w->position[k] == RS_NIP_AT_FRONT ||
                                                            w->position[k] == RS_NIP_AT_REAR);
    if (ok)
      fprintf(out, "; load %s%s N/m at the core -> %s N/m at the final radius",
              drum ? "from the statics, " : "", g(a, l0[k]), g(b, l1[k]));
    if (drum) fprintf(out, " (drum radius %s mm)", g(c, w->drum_radius[k] * 1e3));
    fprintf(out, "\n");
  }
  double u0, u1, n0 = friction_nit(p, r0, p->material.nit_saturation, &u0),
                 n1 = friction_nit(p, r1, p->material.nit_saturation, &u1);
  fprintf(out, "  - wound-on tension: T0 = T + the sum of the nips' NIT (each capped)");
  if (isfinite(n0) && isfinite(n1))
    fprintf(out, ": NIT %s N/m at the core -> %s N/m at the final radius (sum of mu N, the upper "
                 "bound: %s -> %s N/m)", g(a, n0), g(b, n1), g(c, u0), g(d, u1));
  fprintf(out, "\n");
  if (ok) fprintf(out, "  - nip load record (/layers/nip_load): the nips' total, %s -> %s N/m\n",
                  g(a, t0), g(b, t1));
}

int ys_print_nips(FILE *out, const rs_scene *s)
{
  if (s->problem.winder.n_nips == 0) return 0;
  print_list(out, &s->problem);
  return 1;
}

void ys_print_nip_saturation(FILE *out, const rs_scene *s)
{
  const rs_problem *p = &s->problem;
  num_t a;
  if (p->material.nit_saturation > 0.0 && p->nip.model != RS_NIP_NONE)
    fprintf(out, "  - nip saturation: each nip adds at most %s N/m of nip-induced tension "
                 "(material.nit_saturation; docs/nip.md, \"Two-drum winders\")\n",
            g(a, p->material.nit_saturation));
}
