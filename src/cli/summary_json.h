/* The run summary as members of a JSON object (summary_json.c, docs/cli.md "JSON"). */
#ifndef RS_CLI_SUMMARY_JSON_H
#define RS_CLI_SUMMARY_JSON_H

#include "cli/json.h"
#include "reelsim/defects.h"
#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/storage.h"

/* scene, title, the figures and the defect verdicts of one wound reel (d NULL: null) */
void cli_json_run_fields(cli_json *j, const rs_scene *scene, const rs_reel_result *res,
                         const rs_defect_report *d);
/* "storage": the stages after the winder (sr NULL: null): hours, temperature, humidity,
 * core pressure per stage (stage 0 the wound roll), the worst stage of each defect rule and
 * every stage's defect verdicts */
/* "lanes": count, ridge height, the hardest lane, the tension range, the slack lanes (null
 * without lanes; lanes_print.c) */
void cli_json_lanes(cli_json *j, const rs_scene *scene, const rs_reel_result *res);
void cli_json_storage(cli_json *j, const rs_storage_result *sr);

#endif
