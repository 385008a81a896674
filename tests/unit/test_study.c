/* The accuracy study's library module (src/study/): the Pareto front on handcrafted points,
 * the run plan (every run coarser than the reference, skipped knobs, scenes that load),
 * the error measures on results built by hand, and the convergence-order fit. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/study.h"

static int front_of(int n, const double *t, const double *e, int *on)
{
  int k = rs_pareto_front(n, t, e, on);
  int count = 0;
  for (int i = 0; i < n; ++i) count += on[i];
  CHECK(k == count);
  return k;
}

static void pareto_handcrafted(void)
{
  int on[8];
  /* no points */
  CHECK(rs_pareto_front(0, NULL, NULL, on) == 0);
  /* one point */
  {
    const double t[] = {2.0}, e[] = {1e-3};
    CHECK(front_of(1, t, e, on) == 1 && on[0]);
  }
  /* a staircase: (3, 4) is dominated by (2, 3), (5, 1) by (4, 1) */
  {
    const double t[] = {1, 2, 3, 4, 5}, e[] = {5, 3, 4, 1, 1};
    CHECK(front_of(5, t, e, on) == 3);
    CHECK(on[0] && on[1] && !on[2] && on[3] && !on[4]);
  }
  /* ties: equal time, the smaller error wins; equal error, the shorter time wins */
  {
    const double t[] = {1, 1, 2}, e[] = {2, 3, 2};
    CHECK(front_of(3, t, e, on) == 1);
    CHECK(on[0] && !on[1] && !on[2]);
  }
  /* duplicates: neither dominates the other, both stay (and so does a point that is better
   * in one coordinate) */
  {
    const double t[] = {1, 1, 2, 0.5}, e[] = {1, 1, 0.5, 3};
    CHECK(front_of(4, t, e, on) == 4);
  }
  /* a duplicate of a dominated point is dominated too */
  {
    const double t[] = {1, 2, 2}, e[] = {1, 2, 2};
    CHECK(front_of(3, t, e, on) == 1 && on[0] && !on[1] && !on[2]);
  }
  /* all dominated but one */
  {
    const double t[] = {3, 1, 2, 1.5, 4, 1}, e[] = {3, 0.5, 2, 1, 4, 0.5 + 1e-12};
    CHECK(front_of(6, t, e, on) == 1);
    CHECK(on[1]);
  }
  /* NaN and infinite points are never on the front and dominate nothing */
  {
    const double t[] = {NAN, 1, 0.1, INFINITY}, e[] = {0, 1, NAN, 0};
    CHECK(front_of(4, t, e, on) == 1 && on[1]);
  }
  /* within the noise: (2.02, 1.01) is dominated by (2, 1) but within 2% of it */
  {
    const double t[] = {2, 2.02, 3}, e[] = {1, 1.01, 2};
    CHECK(front_of(3, t, e, on) == 1);
    CHECK(rs_pareto_within(3, t, e, on, 0, 0.0, 0.0));
    CHECK(!rs_pareto_within(3, t, e, on, 1, 0.0, 0.0));
    CHECK(rs_pareto_within(3, t, e, on, 1, 0.02, 0.02));
    CHECK(!rs_pareto_within(3, t, e, on, 2, 0.02, 0.02));
  }
}

static rs_scene *load(const char *name)
{
  char path[1024];
  snprintf(path, sizeof path, "%s/cli/scenes/%s", RS_TESTS_DIR, name);
  rs_scene *sc = NULL;
  rs_status st = rs_scene_load(path, 0, NULL, &sc);
  CHECK(st == RS_OK);
  if (st) fprintf(stderr, "%s\n", rs_error_message());
  return sc;
}

/* Every run is the scene with overrides: each must load, be coarser or equal to the
 * reference in every knob, and knobs the scene does not use must not appear. */
static void check_plan(const char *scene_name, int quick, int want_nip, int want_contact)
{
  rs_scene *sc = load(scene_name);
  if (!sc) return;
  rs_study_plan *plan = NULL;
  CHECK(rs_study_plan_create(sc, quick, &plan) == RS_OK);
  if (!plan) return;
  CHECK(plan->has_nip == want_nip && plan->contact == want_contact);
  CHECK(plan->runs[0].knob == RS_KNOB_REFERENCE && plan->runs[1].knob == RS_KNOB_REFERENCE2 &&
        plan->runs[2].knob == RS_KNOB_DEFAULT);
  const rs_study_setting *ref = &plan->runs[0].set;
  CHECK(rs_study_coarser_or_equal(ref, &plan->runs[1].set)); /* reference2 is tighter */
  int per_knob[RS_N_KNOBS] = {0};
  for (int i = 0; i < plan->n_runs; ++i) {
    const rs_study_run *r = &plan->runs[i];
    per_knob[r->knob]++;
    if (r->knob != RS_KNOB_REFERENCE) /* the second reference is tighter on purpose */
      CHECK(rs_study_coarser_or_equal(&r->set, ref) == (r->knob != RS_KNOB_REFERENCE2));
    const char *sets[RS_STUDY_MAX_SETS];
    for (int k = 0; k < r->n_sets; ++k) {
      sets[k] = r->sets[k];
      if (!want_nip) CHECK(strncmp(r->sets[k], "nip.", 4) != 0);
    }
    rs_scene *s = NULL;
    rs_status st = rs_scene_load(rs_scene_path(sc), r->n_sets, sets, &s);
    CHECK(st == RS_OK);
    if (st) fprintf(stderr, "run %s: %s\n", r->label, rs_error_message());
    if (s) {
      CHECK_CLOSE(rs_scene_problem(s)->numerics.rtol, r->set.rtol, 0.0);
      CHECK(rs_scene_problem(s)->numerics.layers_per_step == r->set.layers_per_step);
      CHECK(rs_scene_problem(s)->record.history_every == r->set.history_every);
      if (want_contact) CHECK(rs_scene_problem(s)->nip.nodes == r->set.nodes && rs_scene_problem(s)->nip.terms == r->set.terms);
      if (want_nip)
        CHECK(r->set.update_every > 0 ? rs_scene_problem(s)->nip.update == RS_NIP_UPDATE_EVERY &&
                                            rs_scene_problem(s)->nip.update_every == r->set.update_every
                                      : rs_scene_problem(s)->nip.update == RS_NIP_UPDATE_ADAPTIVE &&
                                            rs_scene_problem(s)->nip.T0_rtol == r->set.T0_rtol);
    }
    rs_scene_destroy(&s);
  }
  CHECK(per_knob[RS_KNOB_REFERENCE] == 1 && per_knob[RS_KNOB_DEFAULT] == 1);
  CHECK(per_knob[RS_KNOB_RTOL] >= 2 && per_knob[RS_KNOB_LAYERS] >= 2);
  CHECK(per_knob[RS_KNOB_HISTORY] >= 1 && per_knob[RS_KNOB_GRID] >= 2);
  CHECK((per_knob[RS_KNOB_NODES] > 0) == want_contact);
  CHECK((per_knob[RS_KNOB_TERMS] > 0) == want_contact);
  CHECK((per_knob[RS_KNOB_T0_RTOL] > 0) == want_nip);
  CHECK((per_knob[RS_KNOB_EVERY] > 0) == want_nip);
  printf("  %s%s: %d runs\n", scene_name, quick ? " (quick)" : "", plan->n_runs);
  rs_study_plan_destroy(&plan);
  rs_study_plan_destroy(&plan); /* NULL is fine */
  rs_scene_destroy(&sc);
}

static void plan_no_nip(void)
{
  check_plan("small.yaml", 0, 0, 0);
  check_plan("small.yaml", 1, 0, 0);
}

static void plan_contact_nip(void)
{
  check_plan("nip-surface.yaml", 0, 1, 1);
  check_plan("nip-surface.yaml", 1, 1, 1);
}

static void coarser_or_equal(void)
{
  rs_study_setting ref, d;
  rs_study_defaults(1, 1, &d);
  ref = d;
  ref.update_every = 1;
  ref.T0_rtol = 0;
  CHECK(rs_study_coarser_or_equal(&d, &ref));  /* adaptive is coarser than every layer */
  CHECK(!rs_study_coarser_or_equal(&ref, &d)); /* and not the other way */
  rs_study_setting e = d;
  e.update_every = 10;
  e.T0_rtol = 0;
  CHECK(!rs_study_coarser_or_equal(&e, &d)); /* every 10 and adaptive: not comparable */
  CHECK(!rs_study_coarser_or_equal(&d, &e));
  rs_study_setting f = d;
  f.nodes = 128;
  CHECK(!rs_study_coarser_or_equal(&f, &d)); /* more nodes is finer */
  f = d;
  f.rtol = 1e-7;
  CHECK(!rs_study_coarser_or_equal(&f, &d));
  CHECK(rs_study_coarser_or_equal(&d, &f));
}

/* Two hand-made results of three layers, with known differences. */
static void errors_by_hand(void)
{
  double r[3] = {0.101, 0.102, 0.103}, T0a[3] = {100, 100, 100}, T0b[3] = {100, 100, 101};
  double sra[3] = {-3000, -2000, -1000}, srb[3] = {-3000, -2100, -1000};
  double sta[3] = {1e6, -5e5, 1e6}, stb[3] = {1e6, -5e5 + 2e4, 1e6};
  rs_reel_result a = {0}, b = {0};
  a.n_layers = b.n_layers = 3;
  a.radius = b.radius = r;
  a.wound_on_tension = T0a;
  b.wound_on_tension = T0b;
  a.web_tension = b.web_tension = T0a;
  a.sigma_r = sra;
  b.sigma_r = srb;
  a.sigma_theta = sta;
  b.sigma_theta = stb;
  a.core_pressure = 4000;
  b.core_pressure = 4040;
  a.core_radius = b.core_radius = 0.1;
  double err[RS_N_FIGURES];
  CHECK(rs_study_errors(&b, &a, 1e-4, err) == RS_OK);
  CHECK_CLOSE(err[RS_FIG_CORE], 0.01, 1e-12);       /* 40 / 4000 */
  CHECK_CLOSE(err[RS_FIG_PEAK], 0.01, 1e-12);       /* the core carries the peak */
  CHECK_CLOSE(err[RS_FIG_SIGMA_R], 0.05, 1e-12);    /* 100 / 2000 */
  CHECK_CLOSE(err[RS_FIG_SIGMA_THETA], 0.02, 1e-12); /* 2e4 / (100 N/m / 1e-4 m) */
  CHECK_CLOSE(err[RS_FIG_T0], 0.01, 1e-12);
  CHECK_CLOSE(err[RS_FIG_MAX], 0.05, 1e-12);
  CHECK(rs_study_errors(&a, &a, 1e-4, err) == RS_OK);
  for (int f = 0; f < RS_N_FIGURES; ++f) CHECK(err[f] == 0.0);
  CHECK(rs_study_identical(&a, &a));
  CHECK(!rs_study_identical(&a, &b));
  b.n_layers = 2;
  CHECK(rs_study_errors(&b, &a, 1e-4, err) == RS_ERR_INPUT);
  CHECK(strcmp(rs_study_figure_name(RS_FIG_SIGMA_THETA), "sigma_theta") == 0);
  CHECK(strcmp(rs_study_knob_name(RS_KNOB_LAYERS), "layers_per_step") == 0);
}

/* The defaults' time on the front is the least of the timings of the runs that did their
 * work: a twin (same answer, bit for bit) that happened to run faster must not let a run
 * that is more accurate and only a little faster push the defaults off the front; without
 * the twin that run does. */
static void default_time_least(void)
{
  double r[3] = {0.101, 0.102, 0.103}, T0[3] = {100, 100, 100};
  double sr_ref[3] = {-3000, -2000, -1000}, sr_def[3] = {-3003, -2002, -1001};
  double st[3] = {1e6, -5e5, 1e6};
  rs_reel_result ref = {0}, def = {0}, twin = {0}, better = {0};
  rs_reel_result *all[] = {&ref, &def, &twin, &better};
  for (int i = 0; i < 4; ++i) {
    all[i]->n_layers = 3;
    all[i]->radius = r;
    all[i]->wound_on_tension = all[i]->web_tension = T0;
    all[i]->sigma_theta = st;
    all[i]->core_radius = 0.1;
  }
  ref.sigma_r = better.sigma_r = sr_ref;
  ref.core_pressure = better.core_pressure = 4000;
  def.sigma_r = twin.sigma_r = sr_def;
  def.core_pressure = twin.core_pressure = 4004;
  rs_study_run runs[5] = {{.label = "reference", .knob = RS_KNOB_REFERENCE},
                          {.label = "reference2", .knob = RS_KNOB_REFERENCE2},
                          {.label = "default", .knob = RS_KNOB_DEFAULT},
                          {.label = "history_every=100", .knob = RS_KNOB_HISTORY},
                          {.label = "rtol=1e-06", .knob = RS_KNOB_RTOL}};
  rs_study_plan plan = {.n_runs = 5, .runs = runs};
  const rs_reel_result *res[5] = {&ref, &ref, &def, &twin, &better};
  /* the defaults measured at 1.0 s, their twin at 0.8 s, an exact run at 0.85 s */
  const double cpu[5] = {10, 20, 1.0, 0.8, 0.85};
  rs_study_report rep;
  CHECK(rs_study_analyze(&plan, res, cpu, cpu, 1e-4, &rep) == RS_OK);
  CHECK_LOG("defaults' time on the front (s)", rep.default_cpu);
  CHECK(rep.default_cpu == 0.8);
  CHECK(rep.default_timings == 2);
  CHECK_CLOSE(rep.default_spread, 0.25, 1e-12);
  CHECK(rep.rows[3].identical_to_default && !rep.rows[4].identical_to_default);
  CHECK(rep.default_on_front);
  CHECK(rep.rows[4].on_front); /* more accurate, slower than 0.8 s: on the front too */
  CHECK(rep.rows[2].cpu_seconds == 1.0); /* the table keeps the run's own measurement */
  rs_study_report_free(&rep);
  /* without the twin the exact run, 15 % faster than the defaults' only timing, dominates
   * them beyond the 10 % noise margin */
  rs_study_run runs2[4] = {runs[0], runs[1], runs[2], runs[4]};
  plan.runs = runs2;
  plan.n_runs = 4;
  const rs_reel_result *res2[4] = {&ref, &ref, &def, &better};
  const double cpu2[4] = {10, 20, 1.0, 0.85};
  CHECK(rs_study_analyze(&plan, res2, cpu2, cpu2, 1e-4, &rep) == RS_OK);
  CHECK(rep.default_cpu == 1.0 && rep.default_timings == 1);
  CHECK(!rep.default_on_front);
  rs_study_report_free(&rep);
}

static void order_fit(void)
{
  const double x[] = {1e-3, 1e-4, 1e-5, 1e-6}, e[] = {3e-2, 3e-4, 3e-6, 1e-9};
  /* e = 3e4 x^2 except the last point, which sits at a floor of 1e-8 */
  double p = rs_study_order(4, x, e, 1e-8);
  CHECK_LOG("order (floor excludes the last point)", p);
  CHECK_CLOSE(p, 2.0, 1e-12);
  CHECK(isnan(rs_study_order(4, x, e, 1e-3))); /* one point left */
  const double m[] = {2, 4, 8}, em[] = {0.1, 0.05, 0.025};
  CHECK_CLOSE(rs_study_order(3, m, em, 0.0), -1.0, 1e-12);
}

static const check_case cases[] = {
    {"pareto_handcrafted", pareto_handcrafted},
    {"plan_no_nip", plan_no_nip},
    {"plan_contact_nip", plan_contact_nip},
    {"coarser_or_equal", coarser_or_equal},
    {"errors_by_hand", errors_by_hand},
    {"order_fit", order_fit},
    {"default_time_least", default_time_least},
};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
