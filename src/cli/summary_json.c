/* The run summary as JSON members (run --json, compare --json): the figures of the text
 * summary in SI units and the defect verdicts. Field by field in docs/cli.md, "JSON";
 * the names are a contract. */
#include "cli/summary_json.h"

#include <math.h> /* NAN: written as null */

#include "reelsim/scene.h"

static void defects(cli_json *j, const char *key, const rs_defect_report *d)
{
  cli_json_object(j, key);
  cli_json_object(j, "hoop");
  cli_json_string(j, "verdict", rs_defect_verdict_name(d->hoop.verdict));
  cli_json_int(j, "layers", d->hoop.layers);
  cli_json_number(j, "min", d->hoop.min);
  cli_json_number(j, "min_radius", d->hoop.min_radius);
  cli_json_end(j);

  cli_json_object(j, "starring");
  cli_json_string(j, "verdict", rs_defect_verdict_name(d->starring.verdict));
  cli_json_string(j, "criterion", rs_starring_criterion_name(d->starring.criterion));
  cli_json_int(j, "layers", d->starring.layers);
  int weighed = d->starring.verdict != RS_DEFECT_NOT_ASSESSED && d->starring.compressed > 0;
  cli_json_number(j, "margin_min", weighed ? d->starring.margin_min : NAN);
  cli_json_number(j, "margin_radius", weighed ? d->starring.margin_radius : NAN);
  cli_json_number(j, "strength_margin", weighed ? d->starring.strength_margin : NAN);
  cli_json_number(j, "packet_margin", weighed ? d->starring.packet_margin : NAN);
  cli_json_number(j, "zone_inner_radius", weighed ? d->starring.zone_inner : NAN);
  cli_json_number(j, "zone_outer_radius", weighed ? d->starring.zone_outer : NAN);
  cli_json_number(j, "zone_from_core", weighed ? d->starring.zone_from_core : NAN);
  cli_json_number(j, "zone_to_core", weighed ? d->starring.zone_to_core : NAN);
  cli_json_number(j, "hoop_force", weighed ? d->starring.force : NAN);
  cli_json_number(j, "critical_force", weighed ? d->starring.force_critical : NAN);
  cli_json_number(j, "mode", weighed ? d->starring.mode : NAN);
  if (weighed)
    cli_json_string(j, "interlayers", d->starring.bonded ? "bonded" : "slipping");
  else
    cli_json_null(j, "interlayers");
  cli_json_end(j);

  int assessed = d->pressure.verdict != RS_DEFECT_NOT_ASSESSED;
  cli_json_object(j, "pressure");
  cli_json_string(j, "verdict", rs_defect_verdict_name(d->pressure.verdict));
  cli_json_number(j, "max", d->pressure.max);
  cli_json_number(j, "max_radius", d->pressure.max_radius);
  cli_json_number(j, "limit", assessed ? d->pressure.limit : NAN);
  cli_json_number(j, "ratio", assessed ? d->pressure.ratio : NAN);
  cli_json_end(j);

  assessed = d->slip.verdict != RS_DEFECT_NOT_ASSESSED;
  cli_json_object(j, "slip");
  cli_json_string(j, "verdict", rs_defect_verdict_name(d->slip.verdict));
  cli_json_int(j, "layers", d->slip.layers);
  cli_json_number(j, "margin_min", assessed ? d->slip.margin_min : NAN);
  cli_json_number(j, "margin_radius", assessed ? d->slip.margin_radius : NAN);
  cli_json_number(j, "margin_torque", assessed ? d->slip.margin_torque : NAN);
  cli_json_number(j, "tension_torque", assessed ? d->slip.tension_torque : NAN);
  cli_json_number(j, "inertia_torque", assessed ? d->slip.torque : NAN);
  cli_json_number(j, "core_share", assessed ? d->slip.core_share : NAN);
  cli_json_number(j, "core_margin", assessed ? d->slip.core_margin : NAN);
  cli_json_number(j, "capstan_layers", assessed ? d->slip.capstan_layers : NAN);
  cli_json_end(j);

  assessed = d->core.verdict != RS_DEFECT_NOT_ASSESSED;
  cli_json_object(j, "core");
  cli_json_string(j, "verdict", rs_defect_verdict_name(d->core.verdict));
  cli_json_number(j, "pressure", d->core.pressure);
  cli_json_number(j, "rating", assessed ? d->core.rating : NAN);
  cli_json_number(j, "ratio", assessed ? d->core.ratio : NAN);
  cli_json_end(j);
  cli_json_end(j);
}

void cli_json_run_fields(cli_json *j, const rs_scene *scene, const rs_reel_result *res,
                         const rs_defect_report *d)
{
  rs_reel_summary s;
  rs_reel_sizes z;
  rs_reel_summarize(res, &s);
  rs_reel_sizes_of(res, rs_scene_problem(scene), &z);
  cli_json_string(j, "scene", rs_scene_path(scene));
  cli_json_string(j, "title", rs_scene_title(scene));
  cli_json_array(j, "warnings"); /* the scene's slip warnings, strings (docs/cli.md) */
  for (int i = 0; i < rs_scene_warning_count(scene); ++i)
    cli_json_string(j, NULL, rs_scene_warning(scene, i));
  cli_json_end(j);
  cli_json_int(j, "layers", s.layers);
  cli_json_number(j, "core_radius", rs_reel_result_core_radius(res));
  cli_json_number(j, "final_radius", s.final_radius);
  cli_json_number(j, "final_diameter", z.deformed_diameter);
  cli_json_number(j, "free_diameter", z.diameter);
  cli_json_number(j, "wound_length", z.wound_length);
  cli_json_number(j, "roll_mass", z.has_mass ? z.mass : NAN);
  if (z.has_air) {
    cli_json_object(j, "air");
    cli_json_number(j, "thickness", z.air_thickness);
    cli_json_number(j, "film_min", z.air_film_min);
    cli_json_number(j, "film_max", z.air_film_max);
    cli_json_number(j, "entrained_min", z.air_entrained_min);
    cli_json_number(j, "entrained_max", z.air_entrained_max);
    cli_json_end(j);
  } else {
    cli_json_null(j, "air");
  }
  cli_json_number(j, "core_pressure", s.core_pressure);
  cli_json_number(j, "peak_pressure", s.peak_pressure);
  cli_json_number(j, "peak_pressure_radius", s.peak_pressure_radius);
  cli_json_number(j, "min_hoop_stress", s.min_hoop);
  cli_json_number(j, "min_hoop_stress_radius", s.min_hoop_radius);
  cli_json_number(j, "wound_on_tension_min", s.wot_min);
  cli_json_number(j, "wound_on_tension_max", s.wot_max);
  cli_json_number(j, "solver_seconds", rs_reel_result_wall_seconds(res));
  cli_json_int(j, "increments", rs_reel_result_increments(res));
  cli_json_int(j, "cvode_steps", rs_reel_result_cvode_steps(res));
  if (d) defects(j, "defects", d);
  else cli_json_null(j, "defects");
  cli_json_lanes(j, scene, res);
}

void cli_json_storage(cli_json *j, const rs_storage_result *sr)
{
  if (!sr) {
    cli_json_null(j, "storage");
    return;
  }
  const int S = rs_storage_result_stages(sr);
  const struct {
    const char *key;
    const double *v;
  } rows[] = {{"hours", rs_storage_result_hours(sr, NULL)},
              {"temperature", rs_storage_result_temperature(sr, NULL)},
              {"humidity", rs_storage_result_humidity(sr, NULL)},
              {"core_pressure", rs_storage_result_core_pressure(sr, NULL)}};
  cli_json_object(j, "storage");
  cli_json_int(j, "stages", S - 1);
  for (size_t r = 0; r < sizeof rows / sizeof rows[0]; ++r) {
    cli_json_array(j, rows[r].key);
    for (int s = 0; s < S; ++s) cli_json_number(j, NULL, rows[r].v[s]);
    cli_json_end(j);
  }
  rs_storage_worst w;
  rs_storage_worst_stages(sr, &w);
  cli_json_object(j, "worst_stage");
  cli_json_int(j, "hoop", w.hoop);
  cli_json_int(j, "starring", w.starring);
  cli_json_int(j, "pressure", w.pressure);
  cli_json_int(j, "slip", w.slip);
  cli_json_int(j, "core", w.core);
  cli_json_end(j);
  cli_json_array(j, "defects");
  for (int s = 0; s < S; ++s) {
    const rs_defect_report *d = rs_storage_result_defects(sr, s);
    if (d) defects(j, NULL, d);
    else cli_json_null(j, NULL);
  }
  cli_json_end(j);
  cli_json_end(j);
}
