/* A lane's deformed outer radius layer by layer (src/reel/lanes_radius.c) against the
 * contract's full-stack sum (rs_reel_deformed_radius on the roll's current state) at every
 * layer of a reel: the core's displacement, the calipers and the radial compression of the
 * whole stack. The tension a lane winds at is not smooth (a slack stretch at T = 0, steps
 * up and down), as a lane's share is not: 0 over 30-36 % of the layers, 1.5x over 36-60 %.
 * Tolerances: 3e-4 of the compression at any layer, 5e-5 (newsprint) and 1e-4 (a linear
 * stack) over the reel's second half, where the tension is steady again (lanes_radius.h:
 * the deep part carried between full sums); the work (layers summed) at most a tenth
 * (newsprint's 6054 layers) and a quarter (2000 layers) of a full sum at every layer. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "reel/effect.h"
#include "reel/lanes_radius.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"

#ifndef RS_TESTS_DIR
#error "RS_TESTS_DIR must name tests/"
#endif

/* the web tension of the layer being wound: the recipe's, `low` times it over a stretch (0:
 * slack), 1.5x beyond it (the tension phase of effect.h, as the lanes' coupling sets it) */
static double web_tension(const rs_reel_effect *e, const rs_reel_state *s, double r)
{
  const double low = *(const double *)e->content;
  const double T = rs_recipe_eval(&s->pb->tension, r), k = (double)s->first / s->N;
  return k > 0.3 && k < 0.36 ? low * T : k >= 0.36 && k < 0.6 ? 1.5 * T : T;
}

static double nip_load(const rs_reel_effect *e, const rs_reel_state *s, double r)
{
  (void)e;
  return rs_recipe_eval(&s->pb->nip.load, r);
}

static const rs_reel_effect_ops varying = {
    .name = "varying", .web_tension = web_tension, .nip_load = nip_load};

/* winds the scene, comparing at every layer; worst relative to the compression */
static void against_full_sum(const char *scene, int n_sets, const char **sets, double low,
                             double tol, double tol_late, double share)
{
  rs_scene *sc = NULL;
  CHECK(rs_scene_load(scene, n_sets, sets, &sc) == RS_OK);
  if (!sc) return;
  const rs_problem *pb = rs_scene_problem(sc);
  const int N = pb->n_layers;
  rs_reel_state *s = NULL;
  const rs_reel_effect e = {&varying, &low};
  rs_lane_radius g;
  double *full = malloc((size_t)N * sizeof(double)), worst = 0.0, worst_abs = 0.0, comp_end = 0.0, worst_late = 0.0;
  CHECK(rs_lane_radius_init(&g, N) == RS_OK);
  CHECK(rs_reel_state_create(pb, &e, 1, &s) == RS_OK);
  while (s && !s->done) {
    CHECK(rs_reel_state_step(s) == RS_OK);
    const int k = rs_roll_layers(s->roll);
    double R = 0.0;
    CHECK(rs_lane_radius_update(&g, pb, s->roll, s->film, s->res->wound_on_tension, &R) == RS_OK);
    CHECK(rs_reel_deformed_radius(pb, rs_roll_core_pressure(s->roll), rs_roll_sigma_r(s->roll),
                                  s->film, k, full) == RS_OK);
    const double comp = pb->core.radius + k * pb->material.caliper - full[k - 1];
    const double err = fabs(R - full[k - 1]);
    worst_abs = fmax(worst_abs, err);
    /* relative to the compression (with air films, the films' net: negative) */
    if (comp != 0.0) worst = fmax(worst, err / fabs(comp));
    if (k > N / 2 && comp != 0.0) worst_late = fmax(worst_late, err / fabs(comp));
    comp_end = comp;
  }
  const double work = (double)g.top_layers + (double)g.full_nodes;
  long nodes_full = 0;
  for (int k = 1; k <= N; ++k) nodes_full += k;
  printf("  %d layers: %ld full sums, %.4g layers summed in all against %ld (every layer)\n", N,
         g.full_sums, work, nodes_full);
  printf("  compression at the end %.17g m; worst error %.17g m, %.17g of the compression\n",
         comp_end, worst_abs, worst);
  printf("  worst error over the second half %.17g of the compression\n", worst_late);
  CHECK(worst < tol);
  CHECK(worst_late < tol_late);
  CHECK(work < share * (double)nodes_full);
  rs_reel_state_destroy(&s);
  rs_lane_radius_free(&g);
  free(full);
  rs_scene_destroy(&sc);
}

/* the newsprint reel of cases/newsprint-rider.yaml (Pfeiffer's law, 6054 layers, an
 * elastic core; the friction rider solved at every layer) */
static void newsprint_reel(void)
{
  const char *sets[] = {"nip.update=every", "nip.update_every=1"};
  against_full_sum(RS_TESTS_DIR "/../cases/newsprint-rider.yaml", 2, sets, 0.0, 3e-4, 5e-5, 0.1);
}

/* a linear stack (E_r 20 MPa, E_theta 4 GPa), 2000 layers on a rigid core, no nip */
static void linear_stack(void)
{
  const char *sets[] = {"winding.final_radius=0.25"};
  against_full_sum(RS_TESTS_DIR "/cli/scenes/small.yaml", 1, sets, 0.0, 3e-4, 1e-4, 0.25);
}

/* entrained air (cases/pet-topweb-air.yaml, Hakiel's law, 3000 m of 100 um PET at 50
 * m/min, no nip): the films under the layers, compressed by the pressure at their nodes, in
 * the radius (the stretch at half the tension, not slack: a slack web without a nip floats
 * on an unbounded film) */
static void entrained_air(void)
{
  against_full_sum(RS_TESTS_DIR "/../cases/pet-topweb-air.yaml", 0, NULL, 0.5, 3e-4, 1e-4, 0.25);
}

static const check_case cases[] = {{"newsprint_reel", newsprint_reel},
                                   {"linear_stack", linear_stack},
                                   {"entrained_air", entrained_air}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
