/* The fused one-layer increment (src/roll/roll_layer.c) and w kept as each step's quintic
 * (roll->w_lazy, roll_integrate.c) are the two-step path (rsi_roll_block_increment then
 * rsi_roll_commit, w stored node by node) operation for operation: a roll wound through
 * rs_roll_add_layers and a twin wound by the same steps spelled out with the fused path
 * and the kept quintics switched off must hold the same stresses bit for bit.
 *
 *   fused_is_two_step   1500 one-layer increments (the load beneath each layer: the fused
 *                       path runs for ~all of them once the reused start is 256 nodes
 *                       deep), then two-layer blocks and one-layer increments in turn,
 *                       and a rewind (rs_roll_save / rs_roll_restore) mid-run: sigma_r,
 *                       sigma_theta and the core pressure equal at every 50 layers.
 *                       Not vacuous: the fused path took most increments (a start 256
 *                       nodes or more below the top, the deep part from the shape) and
 *                       steps kept w as their quintics.
 *   quadratic_air       the same with Hakiel's quadratic E_r(P) (the other one-pass branch
 *                       of rs_radial_modulus_stress_n) and an entrained air film under
 *                       every layer (rsi_roll_air_series in the predictor's modulus).
 *   nonfinite_same      an increment whose stresses overflow above the reused start (a web
 *                       stiffer across than along, g < 1, so the decays grow down the roll,
 *                       and a tension near the largest double) fails as the two-step path
 *                       does: the same error, naming the same node, and the stresses left
 *                       bit for bit as they were (the deep part, c x the reference's
 *                       shape, overflowed unchecked: 653 layers and the core became
 *                       infinite and the increment returned RS_OK).
 *   nonfinite_hakiel    the same with Hakiel's placement (the two-step path, and the hoop
 *                       stresses' shape).
 *   lg2_series          ln g^2 at a node formed from a neighbour's by the atanh series
 *                       (roll_lg2, chained up the roll through thousands of nodes) equals
 *                       log(E_theta / E_r) there: at every node formed in the epoch, every
 *                       97 layers of a 5000-layer roll, within 2e-14 (measured 1.8e-15;
 *                       the series cut at z^5 is off by 2.2e-13), on the lazy path.
 *   lg2_range           the same for ln g^2 formed in one pass over a short integration's
 *                       nodes (rsi_roll_lg2_range, rs_log_positive): within 4e-15.
 *   lg2_range_same_roll the pass and the lazy path wind the same 1970-layer roll: sigma_r
 *                       within rtol of the largest (measured 0.22 rtol: rounding moves
 *                       some of CVODE's steps; they are not bit for bit). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "roll/roll_internal.h"
#include "roll_helpers.h"

enum { N = 1500, MORE = 200 };

enum { CAP = N + 2 * MORE + 70 };
static double film[CAP + 1];

static rs_roll *newsprint(int quadratic_air)
{
  rs_roll_params p = quadratic_air ? hakiel_params(0.0762, 70e-6, 3.5e9, 2e6, 60.0, 1e-6, 1e9, CAP)
                                    : pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, CAP);
  if (quadratic_air) {
    for (int j = 0; j <= CAP; ++j) film[j] = 0.5e-6;
    p.air_film = film;
    p.air_pressure = 101325.0;
  }
  p.rtol = 1e-6;
  p.atol = 0.0;
  p.placement = RS_LOAD_BENEATH;
  rs_roll *roll = NULL;
  CHECK(rs_roll_create(&p, &roll) == RS_OK);
  return roll;
}

/* rs_roll_add_layers for one layer, with rsi_roll_block_increment + rsi_roll_commit in place of
 * rsi_roll_add_one and w stored at every node (w_lazy off) */
static rs_status add_two_step(rs_roll *roll, double T0)
{
  const int k_old = roll->n, k = k_old + 1, top = k - roll->shift;
  roll->lazy.ok = roll->lazy.allowed;
  roll->w_lazy = 0;
  roll->prof.on = roll->lazy.ok && roll->shift && roll->p.reuse == RS_REUSE_ON;
  rs_status st = rsi_roll_set_modulus_stress(roll, top);
  if (st == RS_OK) st = rsi_roll_integrate(roll, top);
  if (st == RS_OK) {
    rsi_roll_block_increment(roll, k_old, 1, &T0, NULL);
    st = rsi_roll_commit(roll, 1, &T0);
  }
  rsi_roll_start_release(roll, st);
  if (st) return st;
  roll->n = k;
  roll->stats.increments++;
  return RS_OK;
}

static int same(rs_roll *a, rs_roll *b)
{
  const int n = rs_roll_layers(a);
  if (n != rs_roll_layers(b)) return 0;
  if (rs_roll_core_pressure(a) != rs_roll_core_pressure(b)) return 0;
  if (n == 0) return 1;
  return memcmp(rs_roll_sigma_r(a), rs_roll_sigma_r(b), (size_t)n * sizeof(double)) == 0 &&
         memcmp(rs_roll_sigma_theta(a), rs_roll_sigma_theta(b), (size_t)n * sizeof(double)) == 0;
}

/* winds both: a by the library, b by the two-step path; returns the number of increments
 * of a that ran the fused path (deep part read from the shape, a start >= 256 below) */
static int wind_both(rs_roll *a, rs_roll *b, int layers, double T, int *mismatch)
{
  int fused = 0;
  for (int i = 0; i < layers; ++i) {
    const double Ti = T * (1.0 + 0.3 * sin(0.01 * (rs_roll_layers(a) + i)));
    const int n = rs_roll_layers(a);
    if (rs_roll_add_layers(a, 1, &Ti) != RS_OK || add_two_step(b, Ti) != RS_OK) {
      CHECK(0);
      return fused;
    }
    if (a->ref.start >= 1 && n - a->ref.start >= 256 && a->deep_lo == a->ref.start) ++fused;
    if ((rs_roll_layers(a) % 50 == 0) && !same(a, b)) ++*mismatch;
  }
  return fused;
}

static void run(int quadratic_air)
{
  rs_roll *a = newsprint(quadratic_air), *b = newsprint(quadratic_air);
  rs_roll_state *sa = NULL, *sb = NULL;
  CHECK(rs_roll_state_create(&sa) == RS_OK && rs_roll_state_create(&sb) == RS_OK);
  if (!a || !b || !sa || !sb) return;
  int mismatch = 0;
  int fused_runs = wind_both(a, b, N, 400.0, &mismatch);
  const long kept_steps = a->wstep_n;
  CHECK(mismatch == 0);
  CHECK(same(a, b));
  /* blocks of two (the two-step path in both, w node by node) between one-layer increments */
  for (int i = 0; i < 20; ++i) {
    const double T2[2] = {420.0, 430.0};
    CHECK(rs_roll_add_layers(a, 2, T2) == RS_OK);
    CHECK(rs_roll_add_layers(b, 2, T2) == RS_OK);
    fused_runs += wind_both(a, b, 3, 410.0, &mismatch);
  }
  CHECK(mismatch == 0);
  CHECK(same(a, b));
  /* a rewind mid-run: the detour's integrations (and the quintics they kept) do not apply */
  CHECK(rs_roll_save(a, sa) == RS_OK && rs_roll_save(b, sb) == RS_OK);
  fused_runs += wind_both(a, b, MORE, 600.0, &mismatch);
  CHECK(rs_roll_restore(a, sa) == RS_OK && rs_roll_restore(b, sb) == RS_OK);
  CHECK(same(a, b));
  fused_runs += wind_both(a, b, MORE, 380.0, &mismatch);
  CHECK(mismatch == 0);
  CHECK(same(a, b));
  printf("fused increments %d, steps kept as quintics %ld\n", fused_runs, kept_steps);
  CHECK(fused_runs > N / 2);
  CHECK(kept_steps > 10);
  rs_roll_state_destroy(&sa);
  rs_roll_state_destroy(&sb);
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

/* ln g^2 as the interpolation reads it against log(E_theta / E_r), at the nodes formed in
 * the roll's latest epoch, every 97 layers of a 5000-layer roll: formed one by one when a
 * step first looks (range = 0: the lazy path, roll_lg2) or all in one pass before the
 * integration (the default for a span of up to RS_LG2_RANGE_MAX nodes, rsi_roll_lg2_range) */
static void lg2_check(int range, double tol)
{
  enum { M = 5000 };
  /* K1 small: E_r ~ 60 P, so near the top the modulus changes by 1/m a layer m layers
   * down, and every ratio the series takes (|z| up to 0.015) occurs */
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 50, 60, 1e9, M);
  p.rtol = 1e-6;
  p.atol = 0.0;
  rs_roll *r = NULL;
  CHECK(rs_roll_create(&p, &r) == RS_OK);
  if (!r) return;
  if (!range) r->ode.lg2_range_max = 0;
  double worst = 0.0;
  long samples = 0;
  for (int i = 0; i < M; ++i) {
    const double T = 500.0 * (1.0 + 0.3 * sin(0.003 * i));
    if (rs_roll_add_layers(r, 1, &T) != RS_OK) {
      CHECK(0);
      break;
    }
    if (i % 97 != 0 && i != M - 1) continue;
    for (int j = 0; j < r->ode.nodes_in_use; ++j) {
      const int in_range = r->ode.lg2_range_epoch == r->ode.epoch && j >= r->ode.lg2_lo && j <= r->ode.lg2_hi;
      if (range ? in_range : r->ode.lg2_epoch[j] == r->ode.epoch) {
        const double d = fabs(r->ode.lg2[j] - log(r->p.E_theta / r->ode.Er[j]));
        worst = d > worst ? d : worst;
        ++samples;
      }
    }
  }
  CHECK_LOG("nodes compared", (double)samples);
  CHECK_LOG("worst |ln g^2 - log(E_theta/E_r)|", worst);
  CHECK(samples > 10000);
  CHECK_LT(worst, tol);
  rs_roll_destroy(&r);
}

static void lg2_series(void)
{
  lg2_check(0, 2e-14);
}

/* ln g^2 is within 2 ulp of ~8 (the largest here) of log()'s (rs_log_positive is within
 * one ulp of it: tests/unit/test_log_vec.c) */
static void lg2_range(void)
{
  lg2_check(1, 4e-15);
}

/* The pass and the lazy path wind the same roll: only rounding tells them apart, but that
 * is enough to move some of CVODE's steps, and each integration's own error (held to
 * rtol) then differs: the stresses agree within rtol of the largest (measured 2.2e-7 at
 * rtol 1e-6), not bit for bit */
static void lg2_range_same_roll(void)
{
  rs_roll *a = newsprint(0), *b = newsprint(0);
  if (!a || !b) return;
  b->ode.lg2_range_max = 0;
  int passes = 0; /* increments of roll a whose integration took the pass */
  for (int i = 0; i < CAP; ++i) {
    const double T = 500.0 * (1.0 + 0.3 * sin(0.003 * i));
    if (rs_roll_add_layers(a, 1, &T) != RS_OK || rs_roll_add_layers(b, 1, &T) != RS_OK) {
      CHECK(0);
      break;
    }
    passes += a->ode.lg2_range_epoch == a->ode.epoch;
  }
  CHECK(b->ode.lg2_range_epoch == 0); /* roll b never took it */
  const int n = rs_roll_layers(a);
  const double *sa = rs_roll_sigma_r(a), *sb = rs_roll_sigma_r(b);
  double big = 0.0, diff = 0.0;
  for (int j = 0; j < n; ++j) {
    big = fmax(big, fabs(sb[j]));
    diff = fmax(diff, fabs(sa[j] - sb[j]));
  }
  CHECK_LOG("layers", (double)n);
  CHECK_LOG("increments that took the pass", (double)passes);
  CHECK(passes > n / 2);
  CHECK_LOG("max |sigma_r difference| / max |sigma_r|", diff / big);
  CHECK(n == rs_roll_layers(b) && n > 1000);
  CHECK_LT(diff / big, 1e-6); /* rtol */
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

static void nonfinite_case(rs_load_placement placement)
{
  enum { M = 1000 };
  /* E_r = 20 E_theta (g ~ 0.22): the decays grow down the roll, to ~8 at the core; a
   * linear law never drifts, so each increment starts just below the top and the deep
   * part is c x the shape, lazy */
  rs_roll_params p = linear_params(0.0762, 1e-3, 1e9, 2e10, 1e9, M + 2);
  p.rtol = 1e-6;
  p.atol = 0.0;
  p.placement = placement;
  rs_roll *a = NULL, *b = NULL;
  CHECK(rs_roll_create(&p, &a) == RS_OK && rs_roll_create(&p, &b) == RS_OK);
  if (!a || !b) return;
  int mismatch = 0;
  const int fused = wind_both(a, b, M, 500.0, &mismatch);
  CHECK(mismatch == 0);
  (void)fused;
  printf("  start %d deep_lo %d lazy_top %d\n", a->ref.start, a->deep_lo, a->lazy.top);
  CHECK(a->lazy.top > M / 2 && a->deep_lo > M / 2); /* the deep part lazy, below the start */
  static double sr[M], sth[M];
  memcpy(sr, rs_roll_sigma_r(a), sizeof sr);
  memcpy(sth, rs_roll_sigma_theta(a), sizeof sth);
  const double core = rs_roll_core_pressure(a);
  const double T = 1.5e308; /* T0/s finite, T0/s e_j not where e_j > 1.2 */
  char msg_a[512] = "", msg_b[512] = "";
  CHECK(rs_roll_add_layers(a, 1, &T) == RS_ERR_SOLVER);
  snprintf(msg_a, sizeof msg_a, "%s", rs_error_message());
  CHECK(add_two_step(b, T) == RS_ERR_SOLVER);
  snprintf(msg_b, sizeof msg_b, "%s", rs_error_message());
  printf("  library:  %s\n  two-step: %s\n", msg_a, msg_b);
  CHECK(strstr(msg_a, "non-finite stress increment at the core") != NULL);
  CHECK(strcmp(msg_a, msg_b) == 0);
  CHECK(rs_roll_layers(a) == M);
  CHECK(memcmp(rs_roll_sigma_r(a), sr, sizeof sr) == 0);
  CHECK(memcmp(rs_roll_sigma_theta(a), sth, sizeof sth) == 0);
  CHECK(rs_roll_core_pressure(a) == core);
  const double T1 = 500.0; /* and the roll winds on */
  CHECK(rs_roll_add_layers(a, 1, &T1) == RS_OK);
  CHECK(isfinite(rs_roll_core_pressure(a)) && rs_roll_core_pressure(a) > core);
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

static void nonfinite_same(void) { nonfinite_case(RS_LOAD_BENEATH); }
static void nonfinite_hakiel(void) { nonfinite_case(RS_LOAD_HAKIEL); }

static void fused_is_two_step(void) { run(0); }
static void quadratic_air(void) { run(1); }

static const check_case cases[] = {{"fused_is_two_step", fused_is_two_step},
                                   {"quadratic_air", quadratic_air},
                                   {"nonfinite_same", nonfinite_same},
                                   {"nonfinite_hakiel", nonfinite_hakiel},
                                   {"lg2_series", lg2_series},
                                   {"lg2_range", lg2_range},
                                   {"lg2_range_same_roll", lg2_range_same_roll}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
