/* The TopWeb winding example (Rheologic's roll-winding case study): 3000 m of 100 um PET
 * wound at 150 N/m on a 150 mm core, no nip (cases/pet-topweb.yaml). Two published facts
 * to meet: the diameter from the length, 636 mm (the closed form
 * D = sqrt(D0^2 + 4 L t / pi)), and the hoop stress negative through most of the roll
 * with no wrinkle (buckling) warning. */
#include <math.h>

#include "check.h"
#include "reelsim/defects.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "scene/scene_type.h" /* the scene's web length: this test looks inside */

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

static const double pi = 3.14159265358979323846;

static rs_reel_result *wind(rs_scene **sc)
{
  rs_reel_result *res = NULL;
  *sc = NULL;
  CHECK(rs_scene_load(RS_ROOT_DIR "/cases/pet-topweb.yaml", 0, NULL, sc) == RS_OK);
  if (!*sc) return NULL;
  CHECK(rs_scene_wind(*sc, NULL, &res) == RS_OK);
  return res;
}

/* reelsim winds whole turns: N = round((R - r_c) / t) layers of the closed form's R, so
 * its diameter 2 (r_c + N t) is within one caliper (0.1 mm) of the closed form. */
static void diameter(void)
{
  rs_scene *sc;
  rs_reel_result *res = wind(&sc);
  if (!res) return;
  const double D0 = 0.150, L = 3000.0, t = 100e-6;
  double D_closed = sqrt(D0 * D0 + 4.0 * L * t / pi);
  double D = 2.0 * res->radius[res->n_layers - 1];
  CHECK_LOG("layers", res->n_layers);
  CHECK_LOG("reelsim diameter (m)", D);
  CHECK_LOG("closed-form diameter (m)", D_closed);
  CHECK(sc->problem.material.caliper == t && sc->problem.core.radius == 0.5 * D0 && sc->web_length == L);
  CHECK(res->n_layers == (int)lround((0.5 * D_closed - 0.5 * D0) / t));
  CHECK_ABS(D, D_closed, t);
  CHECK_ABS(D, 0.636, 0.5e-3); /* TopWeb's 636 mm, as rounded there */
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

/* Hoop compression in most of the roll, reported as information; the buckling rule does
 * not fire: the compression is a small fraction of T0/t and far below the critical stress
 * sqrt(E_theta E_r / 3) of a layer on the stack. */
static void hoop_compression_no_buckling(void)
{
  rs_scene *sc;
  rs_reel_result *res = wind(&sc);
  if (!res) return;
  rs_defect_limits lim;
  rs_defect_limits_from_problem(rs_scene_problem(sc), &lim);
  rs_defect_report *rep = NULL;
  CHECK(rs_defects_assess(res, &lim, &rep) == RS_OK);
  if (rep) {
    double T0_t = 150.0 / sc->problem.material.caliper; /* 1.5 MPa */
    CHECK_LOG("layers in hoop compression", rep->hoop.layers);
    CHECK_LOG("of layers", res->n_layers);
    CHECK_LOG("least sigma_theta / (T0/t)", rep->hoop.min / T0_t);
    CHECK_LOG("least buckling margin", rep->buckling.margin_min);
    CHECK_LOG("at r (m)", rep->buckling.margin_radius);
    CHECK_LOG("critical stress there (Pa)", rep->buckling.margin_critical);
    CHECK(rep->hoop.verdict == RS_DEFECT_PRESENT);
    CHECK(2 * rep->hoop.layers > res->n_layers); /* "through most of the roll" */
    CHECK(rep->buckling.verdict == RS_DEFECT_OK && rep->buckling.layers == 0);
    CHECK(rep->buckling.compressed == rep->hoop.layers);
    CHECK_LT(1.0, rep->buckling.margin_min);
  }
  rs_defect_report_destroy(&rep);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

static const check_case cases[] = {
    {"diameter", diameter},
    {"hoop_compression_no_buckling", hoop_compression_no_buckling},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
