/* The accuracy study's plan, errors and convergence orders: see include/reelsim/study.h
 * and docs/accuracy.md. No I/O, no winding. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reel/result_internal.h"
#include "reelsim/study.h"
#include "util/error.h"

const char *rs_study_figure_name(rs_study_figure f)
{
  static const char *const names[RS_N_FIGURES] = {"core_pressure", "peak_pressure", "sigma_r",
                                                  "sigma_theta", "T0_final", "max"};
  return f >= 0 && f < RS_N_FIGURES ? names[f] : "?";
}

const char *rs_study_knob_name(rs_study_knob k)
{
  static const char *const names[RS_N_KNOBS] = {
      "reference", "reference2", "default", "rtol",          "layers_per_step", "nodes",
      "terms",     "T0_rtol",    "update_every", "history_every", "grid"};
  return k >= 0 && k < RS_N_KNOBS ? names[k] : "?";
}

/* ---- errors ----------------------------------------------------------------------------- */

static double rel(double x, double ref)
{
  if (x == ref) return 0.0; /* also 0 = 0 */
  return fabs(x - ref) / fabs(ref);
}

rs_status rs_study_errors(const rs_reel_result *run, const rs_reel_result *ref, double caliper,
                          double *err)
{
  const int n = ref->n_layers;
  if (run->n_layers != n || n < 1)
    return RS_ERROR(RS_ERR_INPUT, "a run wound %d layers, the reference %d: not the same reel",
                    run->n_layers, n);
  for (int j = 0; j < n; ++j)
    if (run->radius[j] != ref->radius[j])
      return RS_ERROR(RS_ERR_INPUT, "layer %d is at r = %.9g m in a run, %.9g m in the reference",
                      j + 1, run->radius[j], ref->radius[j]);
  rs_reel_summary a, b;
  rs_reel_summarize(run, &a);
  rs_reel_summarize(ref, &b);
  err[RS_FIG_CORE] = rel(a.core_pressure, b.core_pressure);
  err[RS_FIG_PEAK] = rel(a.peak_pressure, b.peak_pressure);
  double er = 0.0, et = 0.0;
  for (int j = 0; j < n; ++j) {
    er = fmax(er, rel(run->sigma_r[j], ref->sigma_r[j]));
    const double hoop_scale = fabs(ref->wound_on_tension[j]) / caliper;
    const double d = fabs(run->sigma_theta[j] - ref->sigma_theta[j]);
    et = fmax(et, d == 0.0 ? 0.0 : d / hoop_scale);
  }
  err[RS_FIG_SIGMA_R] = er;
  err[RS_FIG_SIGMA_THETA] = et;
  err[RS_FIG_T0] = rel(run->wound_on_tension[n - 1], ref->wound_on_tension[n - 1]);
  double mx = 0.0;
  for (int f = 0; f < RS_FIG_MAX; ++f) mx = isnan(err[f]) || isnan(mx) ? NAN : fmax(mx, err[f]);
  err[RS_FIG_MAX] = mx;
  return RS_OK;
}

static int same(const double *a, const double *b, int n)
{
  return n == 0 || memcmp(a, b, (size_t)n * sizeof *a) == 0;
}

int rs_study_identical(const rs_reel_result *a, const rs_reel_result *b)
{
  const int n = a->n_layers;
  return n == b->n_layers && a->core_pressure == b->core_pressure && same(a->radius, b->radius, n) &&
         same(a->wound_on_tension, b->wound_on_tension, n) && same(a->sigma_r, b->sigma_r, n) &&
         same(a->sigma_theta, b->sigma_theta, n);
}

/* ---- settings ----------------------------------------------------------------------------- */

void rs_study_defaults(int has_nip, int contact, rs_study_setting *s)
{
  memset(s, 0, sizeof *s);
  s->rtol = 1e-3; /* src/scene/schema.c */
  s->layers_per_step = 1;
  if (has_nip) s->T0_rtol = 1e-4; /* adaptive (src/scene/defaults.c) */
  if (contact) {
    s->nodes = 96; /* docs/accuracy.md: 64 lost 0.1 % of the core pressure once G_rtheta is real */
    s->terms = 256;
  }
}

int rs_study_coarser_or_equal(const rs_study_setting *a, const rs_study_setting *b)
{
  if (a->rtol < b->rtol || a->layers_per_step < b->layers_per_step || a->nodes > b->nodes ||
      a->terms > b->terms || a->history_every < b->history_every)
    return 0;
  /* the nip update policy: every 1 is the finest there is */
  if (b->update_every == 1) return 1;
  if (b->update_every > 1) return a->update_every >= b->update_every;
  return a->update_every == 0 && a->T0_rtol >= b->T0_rtol; /* b adaptive (or no nip) */
}

int rs_study_setting_sets(const rs_study_setting *s, int has_nip, int contact,
                          char sets[RS_STUDY_MAX_SETS][RS_STUDY_SET_LEN])
{
  int n = 0;
  snprintf(sets[n++], RS_STUDY_SET_LEN, "numerics.rtol=%.17g", s->rtol);
  snprintf(sets[n++], RS_STUDY_SET_LEN, "numerics.layers_per_step=%d", s->layers_per_step);
  snprintf(sets[n++], RS_STUDY_SET_LEN, "output.history_every=%d", s->history_every);
  if (has_nip) {
    if (s->update_every > 0) {
      snprintf(sets[n++], RS_STUDY_SET_LEN, "nip.update=every");
      snprintf(sets[n++], RS_STUDY_SET_LEN, "nip.update_every=%d", s->update_every);
    } else {
      snprintf(sets[n++], RS_STUDY_SET_LEN, "nip.update=adaptive");
      snprintf(sets[n++], RS_STUDY_SET_LEN, "nip.T0_rtol=%.17g", s->T0_rtol);
    }
  }
  if (contact) {
    snprintf(sets[n++], RS_STUDY_SET_LEN, "nip.nodes=%d", s->nodes);
    snprintf(sets[n++], RS_STUDY_SET_LEN, "nip.terms=%d", s->terms);
  }
  return n;
}

/* ---- the plan ------------------------------------------------------------------------------ */

/* The reference: every layer wound and solved (layers_per_step 1, the nip at every
 * layer: the model itself, no approximation of it), CVODE three decades tighter than the
 * default, 4/3 of the default's nip nodes and twice its series terms. The second
 * reference tightens what can be tightened: rtol by another decade, nodes to 5/3 and
 * terms to four times the default's. The nip's part is bounded by cost: with a solve at
 * every layer (6,000-9,000 of them for the story scenes) a solve at 160 nodes and 1024
 * terms costs ~5x the default's, and one at 192 nodes and 4096 terms ~20x. */
static void reference(int has_nip, int contact, int second, rs_study_setting *s)
{
  rs_study_defaults(has_nip, contact, s);
  s->rtol = second ? 1e-10 : 1e-9;
  if (has_nip) {
    s->update_every = 1;
    s->T0_rtol = 0.0;
  }
  if (contact) {
    s->nodes = second ? 160 : 128;
    s->terms = second ? 1024 : 512;
  }
}

typedef struct plan_builder {
  rs_study_plan *plan;
  int cap;
  rs_status st;
} plan_builder;

static void add(plan_builder *b, rs_study_knob knob, double level, const rs_study_setting *s,
                const char *label)
{
  if (b->st) return;
  rs_study_plan *p = b->plan;
  if (p->n_runs == b->cap) {
    int cap = b->cap ? 2 * b->cap : 32;
    rs_study_run *r = realloc(p->runs, (size_t)cap * sizeof *r);
    if (!r) {
      b->st = RS_ERROR(RS_ERR_MEMORY, "cannot plan %d study runs", cap);
      return;
    }
    p->runs = r;
    b->cap = cap;
  }
  rs_study_run *run = &p->runs[p->n_runs++];
  memset(run, 0, sizeof *run);
  snprintf(run->label, sizeof run->label, "%s", label);
  run->knob = knob;
  run->level = level;
  run->set = *s;
  run->n_sets = rs_study_setting_sets(s, p->has_nip, p->contact, run->sets);
}

static void sweep_double(plan_builder *b, rs_study_knob knob, const rs_study_setting *base,
                         const double *levels, int n, const char *name)
{
  char label[64];
  for (int i = 0; i < n; ++i) {
    rs_study_setting s = *base;
    if (knob == RS_KNOB_RTOL) s.rtol = levels[i];
    else {
      s.update_every = 0;
      s.T0_rtol = levels[i];
    }
    snprintf(label, sizeof label, "%s=%g", name, levels[i]);
    add(b, knob, levels[i], &s, label);
  }
}

static void sweep_int(plan_builder *b, rs_study_knob knob, const rs_study_setting *base,
                      const int *levels, int n, int max_level, const char *name)
{
  char label[64];
  for (int i = 0; i < n; ++i) {
    if (levels[i] > max_level) continue;
    rs_study_setting s = *base;
    switch (knob) {
    case RS_KNOB_LAYERS: s.layers_per_step = levels[i]; break;
    case RS_KNOB_NODES: s.nodes = levels[i]; break;
    case RS_KNOB_TERMS: s.terms = levels[i]; break;
    case RS_KNOB_EVERY:
      s.update_every = levels[i];
      s.T0_rtol = 0.0;
      break;
    default: s.history_every = levels[i]; break;
    }
    snprintf(label, sizeof label, "%s=%d", name, levels[i]);
    add(b, knob, levels[i], &s, label);
  }
}

rs_status rs_study_plan_create(const rs_scene *scene, int quick, rs_study_plan **out)
{
  *out = NULL;
  rs_study_plan *p = calloc(1, sizeof *p);
  if (!p) return RS_ERROR(RS_ERR_MEMORY, "cannot plan a study");
  p->has_nip = rs_scene_problem(scene)->nip.model != RS_NIP_NONE;
  p->contact = rs_scene_problem(scene)->nip.model == RS_NIP_CONTACT;
  p->quick = quick != 0;
  const int N = rs_scene_problem(scene)->n_layers;
  plan_builder b = {p, 0, RS_OK};
  rs_study_setting s, def;
  reference(p->has_nip, p->contact, 0, &s);
  add(&b, RS_KNOB_REFERENCE, 0, &s, "reference");
  reference(p->has_nip, p->contact, 1, &s);
  add(&b, RS_KNOB_REFERENCE2, 0, &s, "reference2");
  rs_study_defaults(p->has_nip, p->contact, &def);
  add(&b, RS_KNOB_DEFAULT, 0, &def, "default");

  /* one knob at a time, from the defaults; the default level itself is the default run */
  static const double rtol_full[] = {1e-2, 3e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8},
                      rtol_quick[] = {1e-4, 1e-5, 1e-7};
  static const int m_full[] = {2, 5, 10, 20, 50}, m_quick[] = {2, 10, 50};
  static const int M_full[] = {16, 32, 48, 64}, M_quick[] = {32, 64};
  static const int terms_full[] = {16, 32, 64, 128}, terms_quick[] = {16, 64};
  static const double T0_full[] = {1e-1, 1e-2, 3e-3, 1e-3, 1e-5}, T0_quick[] = {1e-2, 1e-3, 1e-5};
  static const int every_full[] = {1000, 300, 100, 30, 10}, every_quick[] = {300, 100, 10};
  static const int hist_full[] = {1000, 100, 10}, hist_quick[] = {100};
#define LEVELS(a) (quick ? a##_quick : a##_full), (quick ? (int)(sizeof a##_quick / sizeof *a##_quick) : (int)(sizeof a##_full / sizeof *a##_full))
  sweep_double(&b, RS_KNOB_RTOL, &def, LEVELS(rtol), "rtol");
  sweep_int(&b, RS_KNOB_LAYERS, &def, LEVELS(m), N / 2, "layers_per_step");
  if (p->contact) {
    sweep_int(&b, RS_KNOB_NODES, &def, LEVELS(M), 1 << 20, "nodes");
    sweep_int(&b, RS_KNOB_TERMS, &def, LEVELS(terms), 1 << 30, "terms");
  }
  if (p->has_nip) {
    sweep_double(&b, RS_KNOB_T0_RTOL, &def, LEVELS(T0), "T0_rtol");
    sweep_int(&b, RS_KNOB_EVERY, &def, LEVELS(every), N / 2, "update_every");
  }
  sweep_int(&b, RS_KNOB_HISTORY, &def, LEVELS(hist), N, "history_every");
#undef LEVELS

  /* a small grid of the knobs that cost the most time: rtol x layers per step (x the nip
   * update tolerance: the default's and ten times it) */
  const double g_rtol[] = {def.rtol, 0.1 * def.rtol};
  static const int g_m[] = {2, 5, 10};
  const int n_m = quick ? 2 : 3, n_T0 = p->has_nip ? 2 : 1;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < n_m; ++j)
      for (int k = 0; k < n_T0; ++k) {
        if (g_m[j] > N / 2) continue;
        rs_study_setting g = def;
        g.rtol = g_rtol[i];
        g.layers_per_step = g_m[j];
        char label[64];
        if (k == 1) {
          g.T0_rtol = 10 * def.T0_rtol;
          snprintf(label, sizeof label, "grid rtol=%g m=%d T0_rtol=%g", g.rtol, g.layers_per_step,
                   g.T0_rtol);
        } else {
          snprintf(label, sizeof label, "grid rtol=%g m=%d", g.rtol, g.layers_per_step);
        }
        add(&b, RS_KNOB_GRID, 0, &g, label);
      }
  if (b.st) {
    rs_study_plan_destroy(&p);
    return b.st;
  }
  *out = p;
  return RS_OK;
}

void rs_study_plan_destroy(rs_study_plan **plan)
{
  if (!plan || !*plan) return;
  free((*plan)->runs);
  free(*plan);
  *plan = NULL;
}

/* ---- convergence order ------------------------------------------------------------------ */

double rs_study_order(int n, const double *x, const double *error, double floor)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int k = 0;
  for (int i = 0; i < n; ++i) {
    if (!(x[i] > 0) || !isfinite(x[i]) || !(error[i] > floor) || !isfinite(error[i])) continue;
    const double lx = log(x[i]), ly = log(error[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
    ++k;
  }
  if (k < 2) return NAN;
  const double den = k * sxx - sx * sx;
  return den > 0 ? (k * sxy - sx * sy) / den : NAN;
}

/* ---- a finished study --------------------------------------------------------------------- */

void rs_study_report_free(rs_study_report *rep)
{
  if (!rep) return;
  free(rep->rows);
  rep->rows = NULL;
}

/* The x of a knob's level in error ~ x^p (the default run sits at the default level). */
static double knob_x(rs_study_knob k, const rs_study_setting *s)
{
  switch (k) {
  case RS_KNOB_RTOL: return s->rtol;
  case RS_KNOB_LAYERS: return s->layers_per_step - 1.0; /* exact at m = 1 */
  case RS_KNOB_NODES: return s->nodes > 0 ? 1.0 / s->nodes : NAN;
  case RS_KNOB_TERMS: return s->terms > 0 ? 1.0 / s->terms : NAN;
  case RS_KNOB_T0_RTOL: return s->update_every == 0 ? s->T0_rtol : NAN;
  case RS_KNOB_EVERY: return s->update_every > 0 ? s->update_every : NAN;
  default: return NAN;
  }
}

static void knob_orders(const rs_study_plan *plan, rs_study_report *rep)
{
  const int n = plan->n_runs;
  double *x = malloc((size_t)(n + 1) * sizeof *x), *e = malloc((size_t)(n + 1) * sizeof *e);
  for (int k = 0; k < RS_N_KNOBS; ++k)
    for (int f = 0; f < 2; ++f) {
      rs_study_knob_order *o = &rep->order[k][f];
      o->order = NAN;
      o->points = 0;
      o->floor = NAN;
      if (!x || !e || k == RS_KNOB_REFERENCE || k == RS_KNOB_REFERENCE2 || k == RS_KNOB_DEFAULT ||
          k == RS_KNOB_HISTORY || k == RS_KNOB_GRID)
        continue;
      const rs_study_figure fig = f == 0 ? RS_FIG_CORE : RS_FIG_MAX;
      int m = 0;
      for (int i = 0; i < n; ++i) {
        const rs_study_run *r = &plan->runs[i];
        if (r->knob != (rs_study_knob)k && r->knob != RS_KNOB_DEFAULT) continue;
        x[m] = knob_x((rs_study_knob)k, &r->set);
        e[m] = rep->rows[i].err[fig];
        if (isfinite(x[m])) ++m;
      }
      if (m < 2) continue;
      double least = INFINITY;
      for (int i = 0; i < m; ++i) least = fmin(least, e[i]);
      o->floor = fmax(3.0 * least, 3.0 * rep->uncertainty[fig]);
      for (int i = 0; i < m; ++i) o->points += e[i] > o->floor && x[i] > 0;
      double p = rs_study_order(m, x, e, o->floor);
      /* nodes and terms: x = 1/M, so the slope is the order in M already */
      o->order = p;
    }
  free(x);
  free(e);
}

/* x to three significant digits: errors that agree that far are the same error to a user,
 * and a difference in the twelfth digit must not put a slower run on the front. */
static double round3(double x)
{
  if (!(x > 0) || !isfinite(x)) return x;
  const double q = pow(10.0, floor(log10(x)) - 2.0);
  return round(x / q) * q;
}

/* Row i of the report from run i's result (NULL: a run that failed, NaN figures, not on
 * the front), against the reference `ref` and the defaults `def`; its time and front error
 * into t[i] and ef[i] (NaN for the references: they are not candidates). */
static rs_status analyze_row(const rs_study_plan *plan, const rs_reel_result *res, int i,
                             const rs_reel_result *ref, const rs_reel_result *def,
                             double caliper, double *t, double *ef, rs_study_report *rep)
{
  rs_study_row *row = &rep->rows[i];
  const int is_ref = plan->runs[i].knob == RS_KNOB_REFERENCE || plan->runs[i].knob == RS_KNOB_REFERENCE2;
  if (!res) {
    row->core_pressure = row->peak_pressure = row->T0_final = row->err_front = NAN;
    for (int f = 0; f < RS_N_FIGURES; ++f) row->err[f] = NAN;
    t[i] = ef[i] = NAN;
    return RS_OK;
  }
  rs_reel_summary sum;
  rs_reel_summarize(res, &sum);
  row->cvode_steps = res->cvode_steps;
  row->nip_solves = res->nip_solves;
  row->core_pressure = sum.core_pressure;
  row->peak_pressure = sum.peak_pressure;
  row->T0_final = res->n_layers > 0 ? res->wound_on_tension[res->n_layers - 1] : NAN;
  rs_status st = rs_study_errors(res, ref, caliper, row->err);
  if (st) {
    rs_error_wrap("study run '%s'", plan->runs[i].label);
    return st;
  }
  row->err_front = round3(fmax(row->err[RS_FIG_MAX], rep->uncertainty[RS_FIG_MAX]));
  row->identical_to_default = rs_study_identical(res, def);
  t[i] = is_ref ? NAN : row->cpu_seconds;
  ef[i] = is_ref ? NAN : row->err_front;
  if (!is_ref && row->err[RS_FIG_MAX] > 0 &&
      (rep->smallest_run < 0 || row->err[RS_FIG_MAX] < rep->smallest_error)) {
    rep->smallest_error = row->err[RS_FIG_MAX];
    rep->smallest_run = i;
  }
  return RS_OK;
}

/* The defaults' time: the least of the runs that did exactly the defaults' work (run 2 and
 * those identical to it), with their spread; t[2] becomes it. */
static void default_timing(rs_study_report *rep, int n, double *t)
{
  rep->default_cpu = t[2];
  rep->default_timings = 1;
  double most = t[2];
  for (int i = 3; i < n; ++i)
    if (rep->rows[i].identical_to_default && isfinite(t[i])) {
      rep->default_timings++;
      if (t[i] < rep->default_cpu) rep->default_cpu = t[i];
      if (t[i] > most) most = t[i];
    }
  rep->default_spread = rep->default_cpu > 0.0 ? (most - rep->default_cpu) / rep->default_cpu : 0.0;
  t[2] = rep->default_cpu;
}

rs_status rs_study_analyze(const rs_study_plan *plan, const rs_reel_result *const *results,
                           const double *wall, const double *cpu, double caliper,
                           rs_study_report *rep)
{
  memset(rep, 0, sizeof *rep);
  const int n = plan->n_runs;
  if (n < 3) return RS_ERROR(RS_ERR_INTERNAL, "a study needs its two references and the defaults");
  rep->plan = plan;
  rep->time_noise = 0.1;
  rep->smallest_run = -1;
  rep->rows = calloc((size_t)n, sizeof *rep->rows);
  double *t = malloc((size_t)n * sizeof *t), *ef = malloc((size_t)n * sizeof *ef);
  int *on = malloc((size_t)n * sizeof *on);
  rs_status st = RS_OK;
  if (!rep->rows || !t || !ef || !on) {
    st = RS_ERROR(RS_ERR_MEMORY, "cannot analyse %d study runs", n);
    goto done;
  }
  for (int i = 0; i < 3; ++i)
    if (!results[i]) {
      st = RS_ERROR(RS_ERR_INTERNAL, "the study's run '%s' has no result", plan->runs[i].label);
      goto done;
    }
  rep->n_layers = results[0]->n_layers;
  if ((st = rs_study_errors(results[0], results[1], caliper, rep->uncertainty))) goto done;
  for (int i = 0; i < n && st == RS_OK; ++i) {
    rep->rows[i].wall_seconds = wall[i];
    rep->rows[i].cpu_seconds = cpu[i];
    st = analyze_row(plan, results[i], i, results[0], results[2], caliper, t, ef, rep);
  }
  if (st) goto done;
  default_timing(rep, n, t);
  rep->n_front = rs_pareto_front(n, t, ef, on);
  for (int i = 0; i < n; ++i) rep->rows[i].on_front = on[i];
  rep->default_on_front = rs_pareto_within(n, t, ef, on, 2, rep->time_noise, 0.0);
  knob_orders(plan, rep);
done:
  free(t);
  free(ef);
  free(on);
  if (st) rs_study_report_free(rep);
  return st;
}
