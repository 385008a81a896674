/* The lazy deep part of the roll engine (src/roll/roll_lazy.c): below the lazy frontier a
 * node's stress is its stored value plus a common scale times the reference's shape.
 *   layer_reads_match_full  rs_roll_layer_sigma_r and rs_roll_core_pressure, read while
 *                           the deep part is lazy, equal the full profile bit for bit once
 *                           it is applied (rs_roll_sigma_r), at several stages of a roll
 *   matches_reuse_none      with the deep solution reused as it was integrated (the
 *                           first-order reuse) and kept lazy, the stresses of a 1500-layer
 *                           roll agree with integrating every increment from the core,
 *                           within the reuse's error bound (1e-5 x T0/s a layer), for both
 *                           load placements: the lazy scale carries the hoop stress of
 *                           Hakiel's placement too (the corrected reuse, whose error is
 *                           smaller than either's: test_roll_profile.vs_tight_reference)
 *   reads_change_nothing    reading the full profiles every 100 layers leaves the winding
 *                           bit for bit as it was (the readers get copies; the lazy state is
 *                           untouched: history stages and entrained air read every so often)
 *   flat_then_steep         a table law flat below its first point and steep above it (ln E_r
 *                           not concave: a node frozen on the flat part would see no drift
 *                           coming): within rtol of reuse: none (was 5e-3 off)
 *   very_soft_web           g ~ 700, g t / r ~ 7: nodes wound after the lazy scale started
 *                           are not frozen (stored = true - C e_j cancelled: 90 % off); the
 *                           profile within the reuse's own error of reuse: none
 *   restore_to_empty        rewinding to an empty roll and winding again (a heap overflow
 *                           once) gives the fresh roll's stresses within the reuse error */
#include <math.h>
#include <string.h>

#include "check.h"
#include "roll_helpers.h"

enum { N = 1500 };

static rs_roll *newsprint(rs_reuse reuse, rs_load_placement placement)
{
  rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, N);
  p.rtol = 1e-5 / RS_ACCURACY_PER_RTOL; /* the reuse held to 1e-5 */
  p.reuse = reuse;
  p.placement = placement;
  rs_roll *roll = NULL;
  CHECK(rs_roll_create(&p, &roll) == RS_OK);
  return roll;
}

static int wind_to(rs_roll *roll, int n)
{
  const double T = 682.5;
  while (rs_roll_layers(roll) < n)
    if (rs_roll_add_layers(roll, 1, &T) != RS_OK) return 0;
  return 1;
}

static void layer_reads_match_full(void)
{
  rs_roll *roll = newsprint(RS_REUSE_ON, RS_LOAD_BENEATH);
  if (!roll) return;
  static double lazy[N];
  for (int n = 500; n <= N; n += 500) {
    CHECK(wind_to(roll, n));
    const double core = rs_roll_core_pressure(roll);
    for (int j = 0; j < n; ++j) lazy[j] = rs_roll_layer_sigma_r(roll, j);
    const double *full = rs_roll_sigma_r(roll);
    CHECK(memcmp(lazy, full, (size_t)n * sizeof(double)) == 0);
    CHECK(core == rs_roll_core_pressure(roll));
  }
  CHECK(isnan(rs_roll_layer_sigma_r(roll, -1)) && isnan(rs_roll_layer_sigma_r(roll, N)));
  rs_roll_destroy(&roll);
}

/* max over layers of |a - b| / (T0 / s_j) and the core pressure's relative difference */
static void compare_rolls(rs_load_placement placement, double tol)
{
  rs_roll *a = newsprint(RS_REUSE_FIRST_ORDER, placement), *b = newsprint(RS_REUSE_OFF, placement);
  if (!a || !b) return;
  CHECK(wind_to(a, N) && wind_to(b, N));
  const double *sa = rs_roll_sigma_r(a), *sb = rs_roll_sigma_r(b);
  const double *ha = rs_roll_sigma_theta(a), *hb = rs_roll_sigma_theta(b);
  double dr = 0.0, dh = 0.0;
  for (int j = 0; j < N; ++j) {
    const double unit = 682.5 / rs_roll_layer_radius(a, j);
    dr = fmax(dr, fabs(sa[j] - sb[j]) / unit);
    dh = fmax(dh, fabs(ha[j] - hb[j]) * 70e-6 / 682.5);
  }
  CHECK_CLOSE(rs_roll_core_pressure(a), rs_roll_core_pressure(b), tol);
  CHECK(dr < tol * 100); /* summed over the increments: the core pressure is ~100 T0/s */
  CHECK(dh < 3 * tol); /* the hoop stress: see test_roll.reuse_vs_from_core */
  rs_roll_stats st;
  rs_roll_get_stats(a, &st);
  CHECK(st.full_integrations < N / 2); /* the deep part was reused */
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

static void matches_reuse_none(void)
{
  compare_rolls(RS_LOAD_BENEATH, 2e-5);
  compare_rolls(RS_LOAD_HAKIEL, 2e-5);
}

static void reads_change_nothing(void)
{
  rs_roll *a = newsprint(RS_REUSE_ON, RS_LOAD_BENEATH), *b = newsprint(RS_REUSE_ON, RS_LOAD_BENEATH);
  if (!a || !b) return;
  for (int n = 100; n <= N; n += 100) {
    CHECK(wind_to(a, n) && wind_to(b, n));
    (void)rs_roll_sigma_r(b); /* b read every 100 layers, a never */
    (void)rs_roll_sigma_theta(b);
  }
  CHECK(rs_roll_core_pressure(a) == rs_roll_core_pressure(b));
  CHECK(memcmp(rs_roll_sigma_r(a), rs_roll_sigma_r(b), N * sizeof(double)) == 0);
  CHECK(memcmp(rs_roll_sigma_theta(a), rs_roll_sigma_theta(b), N * sizeof(double)) == 0);
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

/* the largest |a - b| over the core and every layer, over the largest |b| */
static double profile_difference(const rs_roll *a, const rs_roll *b, int n)
{
  double d = fabs(rs_roll_core_pressure(a) - rs_roll_core_pressure(b));
  double m = fabs(rs_roll_core_pressure(b));
  const double *sa = rs_roll_sigma_r(a), *sb = rs_roll_sigma_r(b);
  for (int j = 0; j < n; ++j) {
    d = fmax(d, fabs(sa[j] - sb[j]));
    m = fmax(m, fabs(sb[j]));
  }
  return d / m;
}

static void flat_then_steep(void)
{
  const int n = 1000;
  rs_roll *r[2] = {NULL, NULL};
  for (int v = 0; v < 2; ++v) {
    rs_roll_params p = pfeiffer_params(0.0762, 70e-6, 3.5e9, 5e3, 60, 1e9, n);
    p.radial.law = RS_RADIAL_TABLE;
    p.radial.n_points = 4;
    const double P[] = {3e5, 3.06e5, 4.5e5, 9e5}, E[] = {3e6, 3.01e6, 3e7, 6e7};
    memcpy(p.radial.P, P, sizeof P);
    memcpy(p.radial.E, E, sizeof E);
    CHECK(rs_radial_law_prepare(&p.radial) == RS_OK);
    p.rtol = 3e-5 / RS_ACCURACY_PER_RTOL; /* the reuse held to 3e-5 */
    p.reuse = v ? RS_REUSE_OFF : RS_REUSE_ON;
    CHECK(rs_roll_create(&p, &r[v]) == RS_OK);
    if (!r[v] || !wind_to(r[v], n)) goto out;
  }
  CHECK_LOG("profile difference, reuse against none", profile_difference(r[0], r[1], n));
  CHECK_LT(profile_difference(r[0], r[1], n), 1e-4);
out:
  rs_roll_destroy(&r[0]);
  rs_roll_destroy(&r[1]);
}

static void very_soft_web(void)
{
  const int n = 900;
  const double T = 100.0;
  rs_roll *r[2] = {NULL, NULL};
  for (int v = 0; v < 2; ++v) {
    rs_roll_params p = pfeiffer_params(0.01, 1e-4, 4.9e9, 1e4, 1, INFINITY, n);
    p.rtol = 3e-5 / RS_ACCURACY_PER_RTOL; /* the reuse held to 3e-5 */
    p.reuse = v ? RS_REUSE_OFF : RS_REUSE_ON;
    CHECK(rs_roll_create(&p, &r[v]) == RS_OK);
    if (!r[v]) goto out;
    for (int k = 0; k < n; ++k) CHECK(rs_roll_add_layers(r[v], 1, &T) == RS_OK);
  }
  CHECK_LOG("profile difference, reuse against none", profile_difference(r[0], r[1], n));
  CHECK_LT(profile_difference(r[0], r[1], n), 2e-2); /* the reuse's own error here: 7.8e-3 */
out:
  rs_roll_destroy(&r[0]);
  rs_roll_destroy(&r[1]);
}

static void restore_to_empty(void)
{
  rs_roll *a = newsprint(RS_REUSE_ON, RS_LOAD_BENEATH), *b = newsprint(RS_REUSE_ON, RS_LOAD_BENEATH);
  rs_roll_state *st = NULL;
  CHECK(rs_roll_state_create(&st) == RS_OK);
  if (!a || !b || !st) goto out;
  CHECK(rs_roll_save(a, st) == RS_OK); /* the empty roll */
  CHECK(wind_to(a, N));
  CHECK(rs_roll_restore(a, st) == RS_OK);
  CHECK(rs_roll_layers(a) == 0);
  CHECK(wind_to(a, N) && wind_to(b, N));
  CHECK_LT(profile_difference(a, b, N), 2e-5);
out:
  rs_roll_state_destroy(&st);
  rs_roll_destroy(&a);
  rs_roll_destroy(&b);
}

static const check_case cases[] = {{"layer_reads_match_full", layer_reads_match_full},
                                   {"matches_reuse_none", matches_reuse_none},
                                   {"reads_change_nothing", reads_change_nothing},
                                   {"flat_then_steep", flat_then_steep},
                                   {"very_soft_web", very_soft_web},
                                   {"restore_to_empty", restore_to_empty}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
