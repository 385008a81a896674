/* A winder with several nips: the two-drum statics and the nip set (see winder.h and
 * docs/nip.md, "Two-drum winders"). */
#include "reel/winder.h"

#include <math.h>
#include <stdlib.h>

static const double pi = 3.14159265358979323846;

double rs_winder_roll_weight(double density, double R, double r_c)
{
  return density * RS_GRAVITY * pi * (R * R - r_c * r_c);
}

rs_status rs_winder_drum_loads(double R, double Rf, double Rr, double c, double V,
                               double *N_front, double *N_rear, double *angle_deg)
{
  /* drum centres at (-c/2, 0) (front) and (c/2, 0); the roll's centre (x, y) at distances
   * Lf = R + Rf and Lr = R + Rr from them */
  const double Lf = R + Rf, Lr = R + Rr;
  if (!(c > 0.0) || !(Lf + Lr > c))
    return RS_ERROR(RS_ERR_INPUT,
                    "winder: a roll of radius %g m falls between drums of radii %g and %g m "
                    "whose centres are %g m apart (it rests on both only when 2R + Rf + Rr > c)",
                    R, Rf, Rr, c);
  const double x = (Lf * Lf - Lr * Lr) / (2.0 * c);
  if (!(fabs(x) < c / 2.0))
    return RS_ERROR(RS_ERR_INPUT,
                    "winder: a roll of radius %g m on drums of radii %g and %g m, %g m apart, "
                    "has its centre outside the drums' (it would roll off the larger drum)",
                    R, Rf, Rr, c);
  const double dxf = x + c / 2.0, dxr = x - c / 2.0, y = sqrt(Lf * Lf - dxf * dxf);
  const double nfx = dxf / Lf, nfy = y / Lf, nrx = dxr / Lr, nry = y / Lr;
  /* [nfx nrx; nfy nry] (Nf, Nr) = (0, V) */
  const double det = nfx * nry - nrx * nfy;
  *N_front = -nrx * V / det;
  *N_rear = nfx * V / det;
  if (angle_deg) *angle_deg = atan2(nfx, nfy) * 180.0 / pi;
  return RS_OK;
}

rs_status rs_winder_nip_loads(const rs_winder_spec *w, double density, double R, double r_c,
                              double *load, double *total)
{
  double rider = 0.0, Rf = 0.0, Rr = 0.0;
  int front = -1, rear = -1;
  *total = 0.0;
  for (int k = 0; k < w->n_nips; ++k) {
    load[k] = 0.0;
    if (w->type == RS_WINDER_TYPE_TWO_DRUM && w->position[k] == RS_NIP_AT_FRONT) {
      front = k;
      Rf = w->drum_radius[k];
    } else if (w->type == RS_WINDER_TYPE_TWO_DRUM && w->position[k] == RS_NIP_AT_REAR) {
      rear = k;
      Rr = w->drum_radius[k];
    } else {
      load[k] = rs_recipe_eval(&w->nips[k].load, R);
      if (w->position[k] == RS_NIP_AT_RIDER) rider += load[k];
    }
  }
  if (front >= 0 && rear >= 0) {
    const double V = rs_winder_roll_weight(density, R, r_c) + rider;
    rs_status st = rs_winder_drum_loads(R, Rf, Rr, w->drum_distance, V, &load[front],
                                        &load[rear], NULL);
    if (st) return st;
  }
  for (int k = 0; k < w->n_nips; ++k) *total += load[k];
  return RS_OK;
}

/* ---- the nip set --------------------------------------------------------------------- */
typedef struct nip_set {
  rs_winder_spec w;
  double density, cap; /* kg/m^3; N/m, 0 = no cap */
  rs_nip *sub[RS_MAX_NIPS];
  double load[RS_MAX_NIPS], total;
  rs_nip_report rep;
} nip_set;

static const char *position_name(rs_nip_position p)
{
  switch (p) {
  case RS_NIP_AT_FRONT: return " (front drum)";
  case RS_NIP_AT_REAR: return " (rear drum)";
  case RS_NIP_AT_RIDER: return " (rider)";
  case RS_NIP_AT_NONE: break;
  }
  return "";
}

/* T0 = Ti + sum_k min(T0_k - Ti, S): each nip solved at its own load with the web
 * tension Ti; its nip-induced tension capped at the saturation S (when given). */
static rs_status set_wot(void *ctx, const rs_nip_state *st, double *T0)
{
  nip_set *s = ctx;
  rs_status e = rs_winder_nip_loads(&s->w, s->density, st->roll_radius, st->core_radius,
                                    s->load, &s->total);
  if (e) return e;
  double nit = 0.0;
  s->rep.a = 0.0;
  s->rep.iterations = 0;
  for (int k = 0; k < s->w.n_nips; ++k) {
    rs_nip_state ns = *st;
    double T0k = 0.0;
    ns.nip_load = s->load[k];
    if ((e = rs_nip_wound_on_tension(s->sub[k], &ns, &T0k)))
      return rs_error_wrap("nip[%d]%s, load %g N/m", k, position_name(s->w.position[k]),
                           s->load[k]);
    double nk = T0k - st->web_tension;
    if (s->cap > 0.0 && nk > s->cap) nk = s->cap;
    nit += nk;
    rs_nip_report r;
    rs_nip_get_report(s->sub[k], &r);
    if (k == 0) s->rep.a = r.a;
    s->rep.iterations += r.iterations;
  }
  s->rep.load = s->total;
  *T0 = st->web_tension + nit;
  return RS_OK;
}

static void set_destroy(void *ctx)
{
  nip_set *s = ctx;
  for (int k = 0; k < RS_MAX_NIPS; ++k) rs_nip_destroy(&s->sub[k]);
  free(s);
}

static void set_report(void *ctx, rs_nip_report *rep) { *rep = ((const nip_set *)ctx)->rep; }

/* the first contact nip's solution (the profiles the reel keeps) */
static const struct rs_nip_solution *set_solution(void *ctx)
{
  const nip_set *s = ctx;
  for (int k = 0; k < s->w.n_nips; ++k) {
    const struct rs_nip_solution *sol = rs_nip_last_solution(s->sub[k]);
    if (sol) return sol;
  }
  return NULL;
}

static const rs_nip_ops set_ops = {.name = "nip set",
                                   .wound_on_tension = set_wot,
                                   .destroy = set_destroy,
                                   .report = set_report,
                                   .solution = set_solution};

rs_status rs_winder_nip_create(const rs_problem *pb, rs_nip **out)
{
  const rs_winder_spec *w = &pb->winder;
  const double cap = pb->material.nit_saturation;
  *out = NULL;
  /* the one nip as it always was: no list (or a list of one), no cap, no drums */
  if (w->n_nips <= 1 && !(cap > 0.0) && w->type != RS_WINDER_TYPE_TWO_DRUM)
    return rs_nip_create(w->n_nips == 1 ? &w->nips[0] : &pb->nip, &pb->material, out);
  if (w->n_nips == 0 && pb->nip.model == RS_NIP_NONE) return RS_OK;
  nip_set *s = calloc(1, sizeof *s);
  if (!s) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the nip set");
  s->w = *w;
  if (w->n_nips == 0) { /* the one nip, capped */
    s->w.n_nips = 1;
    s->w.nips[0] = pb->nip;
    s->w.position[0] = RS_NIP_AT_NONE;
  }
  s->density = pb->material.density;
  s->cap = cap > 0.0 ? cap : 0.0;
  for (int k = 0; k < s->w.n_nips; ++k) {
    rs_status st = rs_nip_create(&s->w.nips[k], &pb->material, &s->sub[k]);
    if (st) {
      const char *where = position_name(s->w.position[k]);
      set_destroy(s);
      return rs_error_wrap("nip[%d]%s", k, where);
    }
  }
  return rs_nip_wrap(&set_ops, s, out);
}
