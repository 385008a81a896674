/* The nip as a reel effect (effect.h): a thin wrapper over the nip model (rs_nip) and its
 * update policy (nip_policy.h). At an increment's start the nip is solved when the policy
 * says so (or a profile is asked for there); an adaptive solve whose check fails rewinds
 * the roll to the previous solve. Each layer gets T0 = Ti + the predicted nip-induced
 * tension. The kept solves and the profiles go into the result's nip record. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reel/effect.h"
#include "reel/nip_policy.h"
#include "reel/winder.h"
#include "reelsim/nip.h"
#include "nip/nip_contact.h"
#include "util/error.h"

typedef struct nip_effect {
  rs_nip *nip;
  rs_nip_policy pol;
  rs_roll_state *snap;  /* adaptive: the roll at the latest accepted solve */
  int cap;              /* entries the result's nip record holds */
  int solved;           /* the nip was solved at this increment's start */
  int n_prof, next_prof;
  double prof_r[RS_MAX_PROFILES]; /* m, the profiles' radii, increasing */
} nip_effect;

static int compare_doubles(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static rs_status nip_setup(rs_reel_effect *e, rs_reel_state *s, rs_roll_params *params)
{
  const rs_problem *pb = s->pb;
  rs_reel_result *res = s->res;
  (void)params;
  nip_effect *n = calloc(1, sizeof *n);
  if (!n) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the nip");
  e->content = n;
  rs_status st = rs_winder_nip_create(pb, &n->nip);
  if (st) return st;
  rs_nip_policy_init(&n->pol, &pb->nip, s->per_step, s->N);
  if (pb->nip.update == RS_NIP_UPDATE_ADAPTIVE && (st = rs_roll_state_create(&n->snap))) return st;
  if (pb->nip.model == RS_NIP_CONTACT && pb->record.n_profiles > 0) {
    n->n_prof = pb->record.n_profiles;
    memcpy(n->prof_r, pb->record.nip_profiles_at, (size_t)n->n_prof * sizeof(double));
    qsort(n->prof_r, (size_t)n->n_prof, sizeof(double), compare_doubles);
    res->profiles = calloc((size_t)n->n_prof, sizeof *res->profiles);
    res->profile_radius = calloc((size_t)n->n_prof, sizeof(double));
    if (!res->profiles || !res->profile_radius)
      return RS_ERROR(RS_ERR_MEMORY, "cannot allocate %d nip profiles", n->n_prof);
  }
  return RS_OK;
}

/* Appends one kept nip solve to the result's record. */
static rs_status nip_record(rs_reel_result *res, int *cap, double r, double T0, double Ti,
                            const rs_nip_report *rep)
{
  if (res->n_nip == *cap) {
    int c = *cap ? 2 * *cap : 64;
    double **d[] = {&res->nip_radius, &res->nip_T0, &res->nip_Ti, &res->nip_a, &res->nip_solve_load};
    for (int i = 0; i < 5; ++i) {
      double *g = realloc(*d[i], (size_t)c * sizeof(double));
      if (!g) return RS_ERROR(RS_ERR_MEMORY, "cannot grow the nip record to %d solves", c);
      *d[i] = g;
    }
    int *it = realloc(res->nip_iterations, (size_t)c * sizeof(int));
    if (!it) return RS_ERROR(RS_ERR_MEMORY, "cannot grow the nip record to %d solves", c);
    res->nip_iterations = it;
    *cap = c;
  }
  int k = res->n_nip++;
  res->nip_radius[k] = r;
  res->nip_T0[k] = T0;
  res->nip_Ti[k] = Ti;
  res->nip_a[k] = rep->a;
  res->nip_solve_load[k] = rep->load;
  res->nip_iterations[k] = rep->iterations;
  return RS_OK;
}

/* The nip solved for the layer `at` about to go on (at.R: the roll's outer radius, at.r: the
 * layer's): *T0 >= 0, and *Ti the web tension it was solved with. The web tension is the
 * layer's, Ti(R + t): with Ti(R) the layer's T0 was Ti(R + t) + (T0 - Ti)(R), off the nip's
 * T0 by t dTi/dr, and where T0 -> 0 under a taper (center-surface winder, mu_roll = 0:
 * T0 = share Ti exactly) that made it negative and stopped the run as "slack"
 * (tests/hard/test_hard_nip.c). */
static rs_status nip_solve(nip_effect *n, const rs_reel_state *s, const rs_reel_layer *at,
                           double *T0, double *Ti)
{
  const rs_problem *pb = s->pb;
  const int layers = rs_roll_layers(s->roll), first = at->j;
  rs_nip_state ns = {.roll_radius = at->R,
                     .core_radius = pb->core.radius,
                     .web_tension = rs_reel_web_tension(s, at->r),
                     .nip_load = rs_reel_nip_load(s, at->R),
                     .surface_modulus = rs_roll_surface_modulus(s->roll),
                     .surface_pressure = layers > 0 ? -rs_roll_layer_sigma_r(s->roll, layers - 1) : 0.0};
  rs_status st;
  *T0 = 0.0;
  *Ti = ns.web_tension;
  s->res->nip_solves++;
  if ((st = rs_nip_wound_on_tension(n->nip, &ns, T0))) {
    rs_error_wrap("nip model '%s' at roll radius %.6g m (layer %d of %d)", rs_nip_name(n->nip),
                  at->R, first + 1, s->N);
    if (st == RS_ERR_INPUT && layers > 0) {
      /* the recipe turned impossible part-way (e.g. a tension the drum cannot carry beyond
       * some radius): the scene was sound at the start and the finished layers stand, so
       * this is the run failing there (exit 3, --keep-partial), not a scene to reject
       * (exit 2, nothing wound) */
      char why[1024];
      snprintf(why, sizeof why, "%s", rs_error_message());
      st = RS_ERROR(RS_ERR_SOLVER, "cannot wind past layer %d: %s", layers, why);
    }
    return st;
  }
  if (!(*T0 >= 0.0) || !isfinite(*T0))
    return RS_ERROR(RS_ERR_SOLVER,
                    "wound-on tension %g N/m at roll radius %.6g m (layer %d of %d) is %s: the "
                    "web would go slack on the roll",
                    *T0, at->R, first + 1, s->N, isfinite(*T0) ? "negative" : "not finite");
  return RS_OK;
}

/* Solves the nip when due or when a profile is asked for at this radius; a solve whose
 * check fails puts the roll back to the previous solve (step->rewind). */
static rs_status nip_begin(rs_reel_effect *e, rs_reel_state *s, rs_reel_step *step)
{
  nip_effect *n = e->content;
  rs_reel_result *res = s->res;
  rs_reel_layer at = {.j = step->first};
  rs_status st;
  n->solved = 0;
  rs_reel_place(s, &at);
  const int want_profile = n->next_prof < n->n_prof && at.R >= n->prof_r[n->next_prof];
  if (!rs_nip_policy_due(&n->pol, step->first) && !want_profile) return RS_OK;
  double T0, Ti;
  if ((st = nip_solve(n, s, &at, &T0, &Ti))) return st;
  if (!rs_nip_policy_offer(&n->pol, step->first, at.R, T0, Ti)) {
    /* the wound-on tension moved more than predicted: wind that stretch again */
    res->nip_rejected++;
    if ((st = rs_roll_restore(s->roll, n->snap))) return st;
    step->rewind = n->pol.j2;
    return RS_OK;
  }
  rs_nip_report rep;
  rs_nip_get_report(n->nip, &rep);
  if ((st = nip_record(res, &n->cap, at.R, T0, Ti, &rep))) return st;
  const rs_nip_solution *sol = want_profile ? rs_nip_last_solution(n->nip) : NULL;
  if (sol) {
    if ((st = rs_nip_solution_copy(&res->profiles[res->n_profiles], sol))) return st;
    res->profile_radius[res->n_profiles++] = at.R;
  }
  while (want_profile && n->next_prof < n->n_prof && n->prof_r[n->next_prof] <= at.R) ++n->next_prof;
  if (n->snap && (st = rs_roll_save(s->roll, n->snap))) return st;
  n->solved = 1;
  return RS_OK;
}

/* T0 = Ti + NIT, the nip's part as solved or predicted at the radius the layer goes on at
 * (the roll's outer radius then, computed as rs_roll_outer_radius does, so that at a solve
 * the prediction is the solve's NIT bit for bit; r - caliper differs by an ulp, which the
 * slope of NIT turns into 1e-13 N/m). */
static rs_status nip_tension(rs_reel_effect *e, const rs_reel_state *s, rs_reel_step *step,
                             rs_reel_layer *L)
{
  nip_effect *n = e->content;
  (void)s;
  double T0 = L->Ti + rs_nip_policy_predict(&n->pol, L->R);
  /* T0 = 0 exactly (a taper to 0 on a center-surface winder with mu_roll = 0, where T0 =
   * share Ti; mu_roll = 0 on a surface winder) comes out of Ti + NIT with a round-off of
   * ~1e-13 N/m either way: below the nip's accuracy (load_rtol 1e-9) of the tensions it is
   * made of, it is 0, not a slack web (tests/hard/test_hard_nip.c) */
  if (T0 < 0.0 && T0 >= -1e-9 * (fabs(L->Ti) + fabs(n->pol.n1) + fabs(n->pol.n2))) T0 = 0.0;
  L->T0 = T0;
  /* A negative PREDICTED T0 is not yet a slack web: the linear prediction of NIT overshoots
   * where NIT has a kink (a tension table's kink when T0 does not follow Ti), and the
   * adaptive check would only see it at the next solve. Solve here instead; a solve's own
   * T0 < 0 stops the run. Terminates: the solve is due at once, and after it layer `first`
   * gets the solve's T0 (>= 0) or the policy rewinds with a shorter interval. */
  if (!(T0 >= 0.0) && isfinite(T0) && L->b == 0 && !n->solved) {
    rs_nip_policy_solve_at(&n->pol, step->first);
    step->again = 1;
  }
  return RS_OK;
}

static void nip_destroy(rs_reel_effect *e)
{
  nip_effect *n = e->content;
  if (n) {
    rs_roll_state_destroy(&n->snap);
    rs_nip_destroy(&n->nip);
  }
  free(n);
  e->content = NULL;
}

const rs_reel_effect_ops rs_reel_nip_effect = {
    .name = "nip",
    .setup = nip_setup,
    .begin = nip_begin,
    .tension = nip_tension,
    .destroy = nip_destroy,
};
