/* The reel's nip update policy: see nip_policy.h. */
#include "reel/nip_policy.h"

#include <math.h>

void rs_nip_policy_init(rs_nip_policy *p, const rs_nip_spec *spec, int layers_per_step,
                        int n_layers)
{
  p->kind = spec->update;
  p->every = spec->update_every > 0 ? spec->update_every : 1;
  p->rtol = spec->T0_rtol;
  p->min_step = layers_per_step;
  /* at least ~20 checks along a reel, so a late change in T0 is found without rewinding
   * a large part of it */
  p->max_step = n_layers / 20 > layers_per_step ? n_layers / 20 : layers_per_step;
  p->have = 0;
  p->r1 = p->n1 = p->r2 = p->n2 = 0.0;
  p->j2 = 0;
  p->step = p->kind == RS_NIP_UPDATE_EVERY ? p->every : layers_per_step;
  p->next = 0;
  p->last = n_layers > 0 ? (n_layers - 1) / layers_per_step * layers_per_step : 0;
  p->rejected = 0;
}

/* The next solve due `step` layers after `from`, and at the last increment at the latest
 * (adaptive): every interval of layers wound between solves is checked by the solve at its
 * end. */
static int policy_next(const rs_nip_policy *p, int from, int step)
{
  const int next = from + step;
  return p->kind == RS_NIP_UPDATE_ADAPTIVE && from < p->last && next > p->last ? p->last : next;
}

int rs_nip_policy_due(const rs_nip_policy *p, int layers)
{
  if (p->kind == RS_NIP_UPDATE_ADAPTIVE && p->have < 2) return 1;
  return p->have == 0 || layers >= p->next;
}

void rs_nip_policy_solve_at(rs_nip_policy *p, int layers)
{
  if (layers < p->next) p->next = layers;
}

double rs_nip_policy_predict(const rs_nip_policy *p, double r)
{
  if (p->have == 0) return 0.0;
  if (p->have == 1 || p->r2 == p->r1) return p->n2;
  return p->n2 + (p->n2 - p->n1) / (p->r2 - p->r1) * (r - p->r2);
}

/* Rounds a number of layers to whole increments, within [min_step, max_step]. */
static int policy_clamp(const rs_nip_policy *p, double layers)
{
  double lo = p->min_step, hi = p->max_step;
  if (layers < lo) layers = lo;
  if (layers > hi) layers = hi;
  int k = (int)(layers / p->min_step);
  return (k < 1 ? 1 : k) * p->min_step;
}

int rs_nip_policy_offer(rs_nip_policy *p, int layers, double r, double T0, double Ti)
{
  double nit = T0 - Ti;
  if (p->kind == RS_NIP_UPDATE_ADAPTIVE && p->have >= 2 && layers > p->j2) {
    double err = fabs(nit - rs_nip_policy_predict(p, r));
    double tol = p->rtol * fmax(fabs(T0), 1e-300);
    double factor = err > 0.0 ? 0.8 * sqrt(tol / err) : 2.0;
    if (factor > 2.0) factor = 2.0;
    if (err > tol && layers - p->j2 > p->min_step) {
      /* the prediction failed over this interval: wind it again, shorter */
      p->step = policy_clamp(p, (layers - p->j2) * (factor < 0.25 ? 0.25 : factor));
      p->next = policy_next(p, p->j2, p->step);
      p->rejected++;
      return 0;
    }
    p->step = policy_clamp(p, p->step * factor);
  } else if (p->kind == RS_NIP_UPDATE_ADAPTIVE && p->have >= 1) {
    p->step = policy_clamp(p, p->step); /* the second solve: keep the first interval */
  }
  p->r1 = p->r2;
  p->n1 = p->n2;
  p->r2 = r;
  p->n2 = nit;
  p->have++;
  p->j2 = layers;
  p->next = policy_next(p, layers, p->step);
  return 1;
}
