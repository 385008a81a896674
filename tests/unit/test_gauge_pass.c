/* rs_reel_deformed_radius's strain pass (src/reel/gauge.c): the strains of the nodes are
 * formed in one vectorised pass when the output array is not the stresses', node by node
 * when it is (the caller's sigma_r overwritten in place); both must give the same radii
 * bit for bit, for each kind of law, with pressures at zero, in tension (a layer that
 * pulls: no strain) and beyond the table's last node, on a core that gives way.
 *   in_place_same   the two paths, several laws and roll sizes */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reelsim/reel.h"

static int compare(const rs_radial_law *law, int n)
{
  rs_problem pb;
  memset(&pb, 0, sizeof pb);
  pb.material.caliper = 70e-6;
  pb.material.E_theta = 4e9;
  pb.material.radial = *law;
  pb.core.kind = RS_CORE_ELASTIC;
  pb.core.radius = 0.0762;
  pb.core.stiffness = 1e9;
  CHECK(rs_radial_law_prepare(&pb.material.radial) == RS_OK);
  double *sr = malloc((size_t)n * sizeof *sr), *R = malloc((size_t)n * sizeof *R);
  double *inplace = malloc((size_t)n * sizeof *inplace);
  for (int j = 0; j < n; ++j) { /* compression rising inwards, a few in tension or zero */
    const double depth = (double)(n - j) / n;
    sr[j] = j % 17 == 5 ? 2e3 : j % 23 == 7 ? 0.0 : -2e6 * depth * depth;
  }
  sr[n - 1] = 0.0;
  memcpy(inplace, sr, (size_t)n * sizeof *sr);
  CHECK(rs_reel_deformed_radius(&pb, 2.2e6, sr, NULL, n, R) == RS_OK);
  CHECK(rs_reel_deformed_radius(&pb, 2.2e6, inplace, NULL, n, inplace) == RS_OK);
  int differ = 0;
  for (int j = 0; j < n; ++j) differ += memcmp(&R[j], &inplace[j], sizeof R[j]) != 0;
  /* compressed: below the free radius, above it less the core's give and every layer's
   * largest strain (2 MPa on the softest law here) */
  CHECK(R[n - 1] < pb.core.radius + n * 70e-6);
  CHECK(R[n - 1] > pb.core.radius * (1.0 - 2.2e6 / 1e9) + n * 70e-6 * (1.0 - 2.0));
  free(sr);
  free(R);
  free(inplace);
  return differ;
}

static void in_place_same(void)
{
  const rs_radial_law laws[] = {
      {.law = RS_RADIAL_PFEIFFER, .K1 = 5e3, .K2 = 60},
      {.law = RS_RADIAL_HAKIEL, .n_coef = 3, .C = {2e5, 2.0, 3e-5}},
      {.law = RS_RADIAL_LINEAR, .E_r = 5e6},
      {.law = RS_RADIAL_TABLE, .n_points = 3, .P = {0, 1e5, 1e6}, .E = {1e6, 3e6, 2e7}},
  };
  const int sizes[] = {1, 2, 5, 257, 6054};
  int differ = 0;
  for (size_t l = 0; l < sizeof laws / sizeof laws[0]; ++l)
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) differ += compare(&laws[l], sizes[s]);
  CHECK_LOG("radii that differ between the two paths", differ);
  CHECK(differ == 0);
}

static const check_case cases[] = {{"in_place_same", in_place_same}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
