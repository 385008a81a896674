/* The recipe search's shared pieces: --vary parsing and checking, a run's figures. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reel/result_internal.h"
#include "reelsim/defects.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "sweep/figures.h"
#include "sweep/app_error.h"
#include "sweep/vary.h"

#define SMALL RS_TEST_SCENES "/small.yaml"

/* LO:HI:N: N values from LO to HI, the ends exact, the spacing even. */
static void grid_values(void)
{
  sweep_vary v;
  CHECK(sweep_vary_parse("winding.tension=100:300:5", SWEEP_VARY_GRID, &v) == RS_OK);
  CHECK(strcmp(v.key, "winding.tension") == 0);
  CHECK(v.kind == SWEEP_GRID && v.n == 5 && !sweep_vary_is_words(&v));
  double want[] = {100, 150, 200, 250, 300};
  for (int i = 0; i < 5; ++i) CHECK_CLOSE(v.values[i], want[i], 1e-15);
  CHECK(v.values[4] == 300.0);
  sweep_vary_clear(&v);
  CHECK(sweep_vary_parse("winding.tension=0.1:0.1:1", SWEEP_VARY_GRID, &v) == RS_OK);
  CHECK(v.n == 1 && v.values[0] == 0.1);
  sweep_vary_clear(&v);
}

/* V1,V2,...: numbers when every item is one, words otherwise; LO:HI for optimize. */
static void lists_and_ranges(void)
{
  sweep_vary v;
  CHECK(sweep_vary_parse("core.radius=0.05,0.04,0.06", SWEEP_VARY_LIST, &v) == RS_OK);
  CHECK(v.kind == SWEEP_LIST && v.n == 3 && !sweep_vary_is_words(&v));
  CHECK(v.values[1] == 0.04 && v.lo == 0.04 && v.hi == 0.06);
  sweep_vary_clear(&v);
  CHECK(sweep_vary_parse("material=newsprint,pet-film", SWEEP_VARY_LIST, &v) == RS_OK);
  CHECK(sweep_vary_is_words(&v) && v.n == 2);
  CHECK(strcmp(v.words[0], "newsprint") == 0 && strcmp(v.words[1], "pet-film") == 0);
  char buf[256];
  CHECK(sweep_vary_set_text(&v, 1, buf, sizeof buf) == RS_OK);
  CHECK(strcmp(buf, "material=pet-film") == 0);
  CHECK(sweep_vary_set_text(&v, 2, buf, sizeof buf) == RS_ERR_INPUT);
  sweep_vary_clear(&v);
  CHECK(sweep_vary_parse("winding.tension=100:300", SWEEP_VARY_RANGE, &v) == RS_OK);
  CHECK(v.kind == SWEEP_RANGE && v.lo == 100 && v.hi == 300 && v.values == NULL);
  CHECK(sweep_vary_set_text(&v, 0.1 + 0.2, buf, sizeof buf) == RS_OK);
  CHECK(strtod(strchr(buf, '=') + 1, NULL) == 0.1 + 0.2); /* %.17g round-trips */
  sweep_vary_clear(&v);
}

/* Each malformed argument is refused naming itself and what is wrong. */
static void refusals(void)
{
  static const struct {
    const char *arg;
    unsigned allowed;
    const char *why;
  } bad[] = {
      {"winding.tension", SWEEP_VARY_GRID | SWEEP_VARY_LIST, "expected KEY="},
      {"=1:2:3", SWEEP_VARY_GRID, "no KEY"},
      {"k=", SWEEP_VARY_GRID, "no value"},
      {"k=3:1:4", SWEEP_VARY_GRID, "LO > HI"},
      {"k=1:3:0", SWEEP_VARY_GRID, "N must be >= 1"},
      {"k=1:3:-2", SWEEP_VARY_GRID, "N must be >= 1"},
      {"k=1:3:2.5", SWEEP_VARY_GRID, "N is not a whole number"},
      {"k=a:3:2", SWEEP_VARY_GRID, "LO is not"},
      {"k=1:inf:2", SWEEP_VARY_GRID, "HI is not"},
      {"k=1:2:3:4", SWEEP_VARY_GRID, "three parts"},
      {"k=1:3", SWEEP_VARY_GRID | SWEEP_VARY_LIST, "expected LO:HI:N"},
      {"k=1:3:4", SWEEP_VARY_RANGE, "expected LO:HI"},
      {"k=1,2", SWEEP_VARY_RANGE, "not a list"},
      {"k=1,,2", SWEEP_VARY_LIST, "empty item"},
      {"k=1,2:3", SWEEP_VARY_LIST | SWEEP_VARY_GRID, "not both"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    sweep_vary v;
    rs_status st = sweep_vary_parse(bad[i].arg, bad[i].allowed, &v);
    CHECK(st == RS_ERR_INPUT);
    const char *msg = app_error_message();
    int ok = strstr(msg, bad[i].arg) && strstr(msg, bad[i].why) && strncmp(msg, "--vary ", 7) == 0;
    if (!ok) fprintf(stderr, "  %s: got '%s'\n", bad[i].arg, msg);
    CHECK(ok);
    sweep_vary_clear(&v);
  }
}

/* The scene decides what a key takes: an unknown key and a refused value name the
 * argument; the scene's own errors are its own. */
static void checked_against_scene(void)
{
  sweep_vary v;
  CHECK(sweep_vary_parse("winding.tension=100:300:3", SWEEP_VARY_GRID, &v) == RS_OK);
  CHECK(sweep_vary_check(SMALL, 0, NULL, &v) == RS_OK);
  sweep_vary_clear(&v);
  CHECK(sweep_vary_parse("winding.tensoin=100:300:3", SWEEP_VARY_GRID, &v) == RS_OK);
  CHECK(sweep_vary_check(SMALL, 0, NULL, &v) == RS_ERR_INPUT);
  CHECK(strncmp(app_error_message(), "--vary winding.tensoin=100:300:3: ", 34) == 0);
  CHECK(strstr(app_error_message(), "tensoin") != NULL);
  sweep_vary_clear(&v);
  /* a final radius below the core's: refused at HI's end only */
  CHECK(sweep_vary_parse("winding.final_radius=0.01,0.06", SWEEP_VARY_LIST, &v) == RS_OK);
  CHECK(sweep_vary_check(SMALL, 0, NULL, &v) == RS_ERR_INPUT);
  CHECK(strncmp(app_error_message(), "--vary winding.final_radius=0.01,0.06: ", 38) == 0);
  sweep_vary_clear(&v);
  CHECK(sweep_vary_parse("material.radial.law=linear,nonsense", SWEEP_VARY_LIST, &v) == RS_OK);
  CHECK(sweep_vary_check(SMALL, 0, NULL, &v) == RS_ERR_INPUT);
  CHECK(strstr(app_error_message(), "--vary material.radial.law=linear,nonsense") != NULL);
  sweep_vary_clear(&v);
  /* a bad --set is the scene's error, not the --vary argument's */
  const char *sets[] = {"numerics.rtol=abc"};
  CHECK(sweep_vary_parse("winding.tension=100:300:3", SWEEP_VARY_GRID, &v) == RS_OK);
  CHECK(sweep_vary_check(SMALL, 1, sets, &v) == RS_ERR_INPUT);
  CHECK(strstr(app_error_message(), "--vary") == NULL);
  sweep_vary_clear(&v);
}

/* The figures of small.yaml (a linear law on a rigid core) are the summary's, and a
 * failed run has NaN figures but its status and time. */
static void figures_of_a_run(void)
{
  rs_scene *scene = NULL;
  CHECK(rs_scene_load(SMALL, 0, NULL, &scene) == RS_OK);
  rs_reel_result *res = NULL;
  CHECK(rs_scene_wind(scene, NULL, &res) == RS_OK);
  double fig[SWEEP_N_FIGURES];
  CHECK(sweep_figures_compute(rs_scene_problem(scene), res, RS_OK, 0.5, fig) == RS_OK);
  rs_reel_summary sum;
  rs_reel_summarize(res, &sum);
  CHECK(fig[SWEEP_FIG_CORE_PRESSURE] == sum.core_pressure && sum.core_pressure > 0);
  CHECK(fig[SWEEP_FIG_PEAK_PRESSURE] == sum.peak_pressure);
  CHECK(fig[SWEEP_FIG_MIN_SIGMA_THETA] == sum.min_hoop);
  CHECK(fig[SWEEP_FIG_FINAL_RADIUS] == sum.final_radius);
  CHECK(fig[SWEEP_FIG_LAYERS] == res->n_layers && res->n_layers == 200);
  CHECK(fig[SWEEP_FIG_WALL_SECONDS] == 0.5 && fig[SWEEP_FIG_STATUS] == 0);
  /* starring: the count of layers at risk from rs_defects_assess; none here */
  rs_defect_limits lim;
  rs_defect_limits_from_problem(rs_scene_problem(scene), &lim);
  rs_defect_report *rep = NULL;
  CHECK(rs_defects_assess(res, &lim, &rep) == RS_OK);
  CHECK(fig[SWEEP_FIG_STARRING_LAYERS] == rep->starring.layers && rep->starring.layers == 0);
  CHECK(isnan(fig[SWEEP_FIG_SLIP_MARGIN])); /* no material.friction_layer */
  rs_defect_report_destroy(&rep);
  /* Five layers pressed beyond a hoop strength of 1 MPa, three in compression below it:
   * five at risk; with a friction coefficient the slip margin is the report's. */
  const double crit = 1.0e6;
  rs_problem pb = *rs_scene_problem(scene);
  pb.material.hoop_strength = crit;
  pb.material.friction_layer = 0.3;
  for (int i = 10; i < 15; ++i) res->sigma_theta[i] = -1.2 * crit;
  for (int i = 20; i < 23; ++i) res->sigma_theta[i] = -0.8 * crit;
  CHECK(sweep_figures_compute(&pb, res, RS_OK, 0.5, fig) == RS_OK);
  CHECK(fig[SWEEP_FIG_STARRING_LAYERS] == 5);
  rs_defect_limits_from_problem(&pb, &lim);
  CHECK(rs_defects_assess(res, &lim, &rep) == RS_OK);
  CHECK(fig[SWEEP_FIG_SLIP_MARGIN] == rep->slip.margin_min && rep->slip.margin_min > 0.0);
  rs_defect_report_destroy(&rep);
  CHECK_CLOSE(fig[SWEEP_FIG_MIN_SIGMA_THETA], -1.2 * crit, 1e-15);
  CHECK(sweep_figures_compute(NULL, NULL, RS_ERR_SOLVER, 0.25, fig) == RS_OK);
  CHECK(isnan(fig[SWEEP_FIG_CORE_PRESSURE]) && isnan(fig[SWEEP_FIG_LAYERS]));
  CHECK(fig[SWEEP_FIG_STATUS] == 3 && fig[SWEEP_FIG_WALL_SECONDS] == 0.25);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&scene);
}

/* The table of names: every figure found by its name, unknown ones not. */
static void figure_names(void)
{
  for (int i = 0; i < SWEEP_N_FIGURES; ++i) CHECK(sweep_figure_find(sweep_figures[i].name) == i);
  CHECK(sweep_figure_find("core_presure") == -1);
  CHECK(sweep_figure_find("starring_layers") == SWEEP_FIG_STARRING_LAYERS);
  CHECK(sweep_figure_find("slip_margin") == SWEEP_FIG_SLIP_MARGIN);
  CHECK(sweep_figure_find("buckling_layers") == SWEEP_FIG_STARRING_LAYERS); /* the old name */
  char names[512];
  sweep_figure_names(names, sizeof names);
  CHECK(strncmp(names, "core_pressure, peak_pressure, ", 30) == 0);
  CHECK(strstr(names, "status") != NULL);
}

/* The applications' record (sweep/app_error.h): an application's error is read back while
 * the library's record is unchanged, the library's once it writes again; a wrap prefixes
 * whichever is current; clearing clears both. */
static void app_error_record(void)
{
  app_error_clear();
  CHECK(app_error_status() == RS_OK && app_error_message()[0] == '\0');
  CHECK(APP_ERROR(RS_ERR_INPUT, "--vary x: bad") == RS_ERR_INPUT);
  CHECK(app_error_status() == RS_ERR_INPUT && strcmp(app_error_message(), "--vary x: bad") == 0);
  CHECK(strstr(app_error_where(), "app_error_record (test_vary.c:") == app_error_where());
  CHECK(rs_error_message()[0] == '\0'); /* the library's record is its own */
  CHECK(app_error_wrap("sweep") == RS_ERR_INPUT);
  CHECK(strcmp(app_error_message(), "sweep: --vary x: bad") == 0);
  sweep_vary v; /* the library writes: its word is current */
  CHECK(sweep_vary_parse("winding.tension=100:300:3", SWEEP_VARY_GRID, &v) == RS_OK);
  const char *sets[] = {"numerics.rtol=abc"};
  CHECK(sweep_vary_check(SMALL, 1, sets, &v) == RS_ERR_INPUT);
  CHECK(strcmp(app_error_message(), rs_error_message()) == 0 && rs_error_message()[0]);
  sweep_vary_clear(&v);
  app_error_clear();
  CHECK(app_error_status() == RS_OK && rs_error_status() == RS_OK);
}

static const check_case cases[] = {
    {"app_error_record", app_error_record},
    {"grid_values", grid_values},
    {"lists_and_ranges", lists_and_ranges},
    {"refusals", refusals},
    {"checked_against_scene", checked_against_scene},
    {"figures_of_a_run", figures_of_a_run},
    {"figure_names", figure_names},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
