/* The lanes in the run's summary (docs/lanes.md, "Outputs"): a block of figures, the three
 * defect lines (hard band, baggy lane, ridge height) and the --json "lanes" object. */
#include <math.h>
#include <stdio.h>

#include "cli/cli.h"
#include "cli/summary_json.h"
#include "reelsim/scene.h"

static int lanes_summary(const rs_scene *scene, const rs_reel_result *res, rs_lanes_summary *s)
{
  return rs_lanes_summarize(res, rs_scene_problem(scene)->material.pressure_limit, s);
}

void cli_print_lanes(FILE *out, const rs_scene *scene, const rs_reel_result *res)
{
  rs_lanes_summary s;
  char a[64];
  if (!lanes_summary(scene, res, &s)) return;
  const double *x = rs_lanes_result_x(res, NULL, NULL);
  const double *w = rs_lanes_result_width(res, NULL, NULL);
  const double t = rs_scene_problem(scene)->material.caliper;
  fprintf(out, "lanes (%d across %.4g m; docs/lanes.md):\n", s.count,
          x[s.count - 1] + 0.5 * w[s.count - 1] - (x[0] - 0.5 * w[0]));
  cli_fmt_stress(a, sizeof a, s.hardest_pressure);
  fprintf(out, "  hardest lane       x = %.4g m: peak pressure %s\n", s.hardest_x, a);
  fprintf(out, "  web tension        %.1f .. %.1f N/m across the lanes\n", s.tension_min,
          s.tension_max);
  fprintf(out, "  ridge height       %.3f mm (%.1f calipers; the highest lane at x = %.4g m)\n",
          s.ridge_height * 1e3, s.ridge_height / t, s.ridge_x);
  if (s.pressure_limit > 0.0)
    fprintf(out, "  hard band          %d lane%s over the pressure limit%s\n", s.hard_lanes,
            s.hard_lanes == 1 ? "" : "s", s.hard_lanes ? ": risk" : ": ok");
  else
    fprintf(out, "  hard band          not assessed (no material.pressure_limit)\n");
  if (!s.slack_lanes) {
    fprintf(out, "  baggy lane         no lane went slack: ok\n");
    return;
  }
  fprintf(out, "  baggy lane         %d lane%s went slack while winding (baggy web, wrinkles "
          "when unwound): risk\n", s.slack_lanes, s.slack_lanes == 1 ? "" : "s");
  for (int i = 0, shown = 0; i < s.count && shown < 8; ++i)
    if (!isnan(s.slack_from[i]))
      fprintf(out, "    x = %.4g m from r = %.1f mm\n", x[i], s.slack_from[i] * 1e3), ++shown;
}

void cli_json_lanes(cli_json *j, const rs_scene *scene, const rs_reel_result *res)
{
  rs_lanes_summary s;
  if (!lanes_summary(scene, res, &s)) {
    cli_json_null(j, "lanes");
    return;
  }
  const double *x = rs_lanes_result_x(res, NULL, NULL);
  cli_json_object(j, "lanes");
  cli_json_int(j, "count", s.count);
  cli_json_number(j, "ridge_height", s.ridge_height);
  cli_json_number(j, "ridge_x", s.ridge_x);
  cli_json_object(j, "hardest");
  cli_json_number(j, "x", s.hardest_x);
  cli_json_number(j, "peak_pressure", s.hardest_pressure);
  cli_json_end(j);
  cli_json_number(j, "max_lane_pressure", s.hardest_pressure);
  cli_json_int(j, "slack_lanes", s.slack_lanes);
  cli_json_number(j, "tension_min", s.tension_min);
  cli_json_number(j, "tension_max", s.tension_max);
  cli_json_int(j, "hard_lanes", s.hard_lanes);
  cli_json_number(j, "pressure_limit", s.pressure_limit > 0.0 ? s.pressure_limit : NAN);
  cli_json_array(j, "slack");
  for (int i = 0; i < s.count; ++i)
    if (!isnan(s.slack_from[i])) {
      cli_json_object(j, NULL);
      cli_json_number(j, "x", x[i]);
      cli_json_number(j, "from_radius", s.slack_from[i]);
      cli_json_end(j);
    }
  cli_json_end(j);
  cli_json_end(j);
}

void cli_print_compare_lanes(FILE *out, int n, const char (*names)[256],
                             const rs_scene *const *scenes, const rs_reel_job *jobs)
{
  rs_lanes_summary s;
  int any = 0;
  for (int i = 0; i < n; ++i)
    any |= jobs[i].status == RS_OK && lanes_summary(scenes[i], jobs[i].result, &s);
  if (!any) return;
  fprintf(out, "\n%-24s %6s %12s %17s %11s\n", "lanes", "count", "ridge height",
          "max lane pressure", "slack lanes");
  fprintf(out, "%-24s %6s %12s %17s %11s\n", "", "", "mm", "kPa", "");
  for (int i = 0; i < n; ++i) {
    if (jobs[i].status != RS_OK || !lanes_summary(scenes[i], jobs[i].result, &s)) {
      fprintf(out, "%-24s -\n", names[i]);
      continue;
    }
    fprintf(out, "%-24s %6d %12.3f %17.2f %11d\n", names[i], s.count, s.ridge_height * 1e3,
            s.hardest_pressure / 1e3, s.slack_lanes);
  }
}
