/* reelsim nip SCENE --radius R [--json] [--set key=value]...: solves the scene's contact
 * nip (nip.model: contact) once at roll radius R and reports it (docs/nip.md).
 * Exit 0 ok, 2 bad input, 3 solver failure. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "reelsim/nip.h"
#include "reelsim/scene.h"
#include "sweep/app_error.h"

static void json_array(const char *name, const double *v, int n)
{
  printf(",\"%s\":[", name);
  for (int i = 0; i < n; ++i) printf("%s%.17g", i ? "," : "", v[i]);
  printf("]");
}

static void json_bools(const char *name, const unsigned char *v, int n)
{
  printf(",\"%s\":[", name);
  for (int i = 0; i < n; ++i) printf("%s%s", i ? "," : "", v[i] ? "true" : "false");
  printf("]");
}

static const char *winder_name(rs_winder_kind w)
{
  return w == RS_WINDER_CENTER ? "center" : w == RS_WINDER_SURFACE ? "surface" : "center-surface";
}

/* The solution as one JSON object (docs/cli.md, "reelsim nip"). */
static void print_json(const rs_problem *pb, double R, const rs_nip_solution *sol)
{
  const int M = sol->M, E = M - 1;
  printf("{\"radius\":%.17g,\"winder\":\"%s\",\"a\":%.17g,\"load\":%.17g,\"Ti\":%.17g,\"T0\":%.17g,"
         "\"NIT\":%.17g,\"xi2\":%.17g,\"delta0\":%.17g,\"eps0\":%.17g,\"E_r\":%.17g,"
         "\"iterations\":%d,\"width_iterations\":%d,\"total_solves\":%d,"
         "\"condition_number\":%.17g,\"dissipation\":%.17g,\"nodes\":%d",
         R, winder_name(pb->nip.winder), sol->a, sol->load, sol->Ti, sol->T0, sol->T0 - sol->Ti,
         sol->xi2, sol->delta0, sol->eps0, sol->E_r, sol->iterations, sol->width_iterations,
         sol->total_solves, sol->condition_number, sol->dissipation, M);
  json_array("x", sol->x, M);
  json_array("pressure", sol->pressure, M);
  json_array("x_shear", sol->x_shear, E);
  json_array("shear_upper", sol->shear_upper, E);
  json_array("shear_lower", sol->shear_lower, E);
  json_bools("slip_upper", sol->slip_upper, E);
  json_bools("slip_lower", sol->slip_lower, E);
  printf("}\n");
}

/* The solution's figures, one a line. */
static void print_text(const rs_problem *pb, double R, const rs_nip_solution *sol)
{
  const int M = sol->M, E = M - 1;
  int su = 0, sl = 0;
  for (int e = 0; e < E; ++e) {
    su += sol->slip_upper[e];
    sl += sol->slip_lower[e];
  }
  printf("nip at roll radius %g m (%s winder, M = %d)\n", R, winder_name(pb->nip.winder), M);
  printf("  half-width a        %.6g mm\n", sol->a * 1e3);
  printf("  load P              %.6g N/m\n", sol->load);
  printf("  web tension Ti      %.6g N/m\n", sol->Ti);
  printf("  wound-on tension T0 %.6g N/m (NIT = %.6g N/m, mu_roll P = %.6g N/m)\n", sol->T0,
         sol->T0 - sol->Ti, pb->nip.mu_roll * sol->load);
  printf("  peak pressure       %.6g Pa\n", sol->pressure[M / 2]);
  printf("  roll E_r (secant)   %.6g Pa\n", sol->E_r);
  printf("  slip elements       roll %d / %d, drum %d / %d\n", su, E, sl, E);
  printf("  creep xi2           %.6g\n", sol->xi2);
  printf("  iterations          %d (half-widths %d, solves %d), condition number %.3g\n",
         sol->iterations, sol->width_iterations, sol->total_solves, sol->condition_number);
}

/* The scene's nip is one contact nip and R lies outside the core; else the exit status,
 * said. */
static int check_scene(const rs_problem *pb, const char *scene_path, double R)
{
  if (pb->winder.n_nips > 1 || pb->winder.type == RS_WINDER_TYPE_TWO_DRUM)
    /* each nip of a list has its own load (a drum's from the statics): one at a time */
    return cli_fail(CLI_EXIT_USAGE, "%s: nip: 'reelsim nip' solves one nip; this scene lists "
                    "several (docs/nip.md, \"Two-drum winders\"): give that nip as the scene's "
                    "only nip, with its load", scene_path);
  if (pb->nip.model != RS_NIP_CONTACT)
    return cli_fail(CLI_EXIT_USAGE, "%s: nip.model: 'reelsim nip' needs nip.model: contact", scene_path);
  if (!(R > pb->core.radius))
    return cli_fail(CLI_EXIT_USAGE, "nip: --radius %g m must exceed the core radius %g m", R,
                    pb->core.radius);
  return CLI_EXIT_OK;
}

int cli_nip(const cli_args *a)
{
  const char *scene_path = a->scene, *radius_text = a->radius;
  if (!radius_text) return cli_fail(CLI_EXIT_USAGE, "nip: need SCENE and --radius R (m)");
  char *end = NULL;
  double R = strtod(radius_text, &end);
  if (!end || *end || !(isfinite(R) && R > 0))
    return cli_fail(CLI_EXIT_USAGE, "nip: --radius must be a positive number of metres (got '%s')", radius_text);
  rs_scene *scene = NULL;
  rs_status st = rs_scene_load(scene_path, a->n_sets, a->sets, &scene);
  if (st) return cli_fail_status(st);
  cli_scene_warnings(scene);
  const rs_problem *pb = rs_scene_problem(scene);
  int code = check_scene(pb, scene_path, R);
  if (code != CLI_EXIT_OK) {
    rs_scene_destroy(&scene);
    return code;
  }
  rs_nip_contact *nc = NULL;
  rs_nip_solution sol = {0};
  rs_nip_state ns = {R, pb->core.radius, rs_recipe_eval(&pb->tension, R),
                     rs_recipe_eval(&pb->nip.load, R), 0.0, 0.0};
  ns.surface_modulus = rs_radial_modulus(&pb->material.radial, 0.0);
  st = rs_nip_contact_create_from_spec(&pb->nip, &pb->material, &nc);
  if (!st) st = rs_nip_contact_solve_state(nc, &ns, &sol);
  if (st) {
    app_error_wrap("%s", scene_path);
    code = cli_fail_status(st);
  } else if (a->json) {
    print_json(pb, R, &sol);
  } else {
    print_text(pb, R, &sol);
  }
  rs_nip_solution_free(&sol); /* a failed solve may have sized it already */
  rs_nip_contact_destroy(&nc);
  rs_scene_destroy(&scene);
  return code;
}
