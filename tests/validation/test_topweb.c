/* The TopWeb winding example (Rheologic's roll-winding case study): 3000 m of 100 um PET
 * wound at 150 N/m on a 150 mm core, no nip (cases/pet-topweb.yaml). Two published facts
 * to meet: the diameter from the length, 636 mm (the closed form
 * D = sqrt(D0^2 + 4 L t / pi)), and the hoop stress negative through most of the roll
 * with no wrinkle (starring) warning. */
#include <math.h>

#include "check.h"
#include "reel/result_internal.h"
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

/* Hoop compression in most of the roll, reported as information; the starring rule does
 * not fire: the compressed zone (bonded by friction) is far from buckling as a packet, and
 * even with every interface slipping (a friction used up by a speed change) its packet
 * margin stays over 1. */
static void hoop_compression_no_starring(void)
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
    CHECK_LOG("starring margin (bonded)", rep->starring.margin_min);
    CHECK_LOG("mode", rep->starring.mode);
    CHECK_LOG("zone from the core (m)", rep->starring.zone_from_core);
    CHECK_LOG("zone to (m)", rep->starring.zone_to_core);
    CHECK(rep->hoop.verdict == RS_DEFECT_PRESENT);
    CHECK(2 * rep->hoop.layers > res->n_layers); /* "through most of the roll" */
    CHECK(rep->starring.verdict == RS_DEFECT_OK && rep->starring.layers == 0);
    CHECK(rep->starring.compressed == rep->hoop.layers);
    CHECK(rep->starring.bonded == 1);
    CHECK_LT(1.0, rep->starring.margin_min);
  }
  rs_defect_report_destroy(&rep);
  lim.friction_layer = 1e-9; /* every interface slips under any torque */
  lim.accel_torque = 1.0;
  CHECK(rs_defects_assess(res, &lim, &rep) == RS_OK);
  if (rep) {
    CHECK_LOG("starring margin (slipping)", rep->starring.margin_min);
    CHECK_LOG("mode", rep->starring.mode);
    CHECK(rep->starring.bonded == 0);
    CHECK(rep->starring.verdict == RS_DEFECT_OK);
    CHECK_LT(1.0, rep->starring.margin_min);
  }
  rs_defect_report_destroy(&rep);
  rs_reel_result_destroy(&res);
  rs_scene_destroy(&sc);
}

static const check_case cases[] = {
    {"diameter", diameter},
    {"hoop_compression_no_starring", hoop_compression_no_starring},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
