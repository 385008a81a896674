/* /defects: one subgroup per defect-risk rule, its verdict and figures as attributes
 * (units in docs/output.md) and the flagged layer ranges as datasets. */
#include "output/h5_defects.h"

#include <math.h>
#include <stdlib.h>

#include "output/h5_util.h"
#include "reelsim/defects.h"
#include "util/error.h"

/* The flagged ranges: layer indices (0-based, as in /layers) and outer radii. */
static rs_status write_ranges(hid_t g, const rs_defect_range *ranges, int n)
{
  size_t k = (size_t)(n > 0 ? n : 1);
  long long *first = malloc(k * sizeof *first), *last = malloc(k * sizeof *last);
  double *r0 = malloc(k * sizeof *r0), *r1 = malloc(k * sizeof *r1);
  rs_status st = RS_OK;
  if (!first || !last || !r0 || !r1) {
    st = RS_ERROR(RS_ERR_MEMORY, "out of memory for %d defect ranges", n);
  } else {
    for (int i = 0; i < n; ++i) {
      first[i] = ranges[i].first;
      last[i] = ranges[i].last;
      r0[i] = ranges[i].r_first;
      r1[i] = ranges[i].r_last;
    }
    st = rs_h5_write_1d_int64(g, "range_first_layer", first, (size_t)n, "",
                              "first layer of each flagged range (0-based index into /layers)");
    if (st == RS_OK)
      st = rs_h5_write_1d_int64(g, "range_last_layer", last, (size_t)n, "",
                                "last layer of each flagged range (0-based, inclusive)");
    if (st == RS_OK)
      st = rs_h5_write_1d(g, "range_inner_radius", r0, (size_t)n, "m",
                          "outer radius of the first layer of each flagged range");
    if (st == RS_OK)
      st = rs_h5_write_1d(g, "range_outer_radius", r1, (size_t)n, "m",
                          "outer radius of the last layer of each flagged range");
  }
  free(first);
  free(last);
  free(r0);
  free(r1);
  return st;
}

/* Opens the rule's group /defects/<name> with its verdict and rule; *g is open on success. */
static rs_status rule_group(hid_t parent, const char *name, rs_defect_verdict verdict,
                            const char *rule, hid_t *g)
{
  rs_status st = rs_h5_group_create(parent, name, g);
  if (st != RS_OK) return st;
  st = rs_h5_attr_string(*g, "verdict", rs_defect_verdict_name(verdict));
  if (st == RS_OK) st = rs_h5_attr_string(*g, "rule", rule);
  if (st != RS_OK) H5Gclose(*g);
  return st;
}

static rs_status write_hoop(hid_t parent, const rs_defect_report *rep)
{
  hid_t g;
  rs_status st = rule_group(parent, "hoop_compression", rep->hoop.verdict,
                            "information, not a risk: present where sigma_theta < 0 (the "
                            "starring rule is /defects/starring)",
                            &g);
  if (st != RS_OK) return st;
  if (rep->hoop.verdict != RS_DEFECT_NOT_ASSESSED) {
    st = rs_h5_attr_int64(g, "layers", rep->hoop.layers);
    if (st == RS_OK) st = rs_h5_attr_double(g, "min_sigma_theta", rep->hoop.min);
    if (st == RS_OK) st = rs_h5_attr_double(g, "min_sigma_theta_radius", rep->hoop.min_radius);
    if (st == RS_OK) st = write_ranges(g, rep->hoop.ranges, rep->hoop.n_ranges);
  }
  H5Gclose(g);
  return st;
}

/* The zone the starring rule found least safe, as attributes (docs/output.md). */
static rs_status write_zone(hid_t g, const rs_defect_report *rep)
{
  const struct { const char *name; double v; } f[] = {
      {"packet_margin", rep->starring.packet_margin},
      {"zone_inner_radius", rep->starring.zone_inner},
      {"zone_outer_radius", rep->starring.zone_outer},
      {"zone_from_core", rep->starring.zone_from_core},
      {"zone_to_core", rep->starring.zone_to_core},
      {"hoop_force", rep->starring.force},
      {"critical_force", rep->starring.force_critical},
      {"foundation", rep->starring.foundation},
      {"bending_stiffness", rep->starring.stiffness},
  };
  rs_status st = RS_OK;
  for (size_t i = 0; st == RS_OK && i < sizeof f / sizeof f[0]; ++i)
    st = rs_h5_attr_double(g, f[i].name, f[i].v);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "mode", rep->starring.mode);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "zone_layers",
                                         rep->starring.zone_last - rep->starring.zone_first + 1);
  if (st == RS_OK)
    st = rs_h5_attr_string(g, "interlayers", rep->starring.bonded ? "bonded" : "slipping");
  return st;
}

static rs_status write_starring(hid_t parent, const rs_defect_report *rep)
{
  hid_t g;
  rs_status st = rule_group(parent, "starring", rep->starring.verdict,
                            "risk where -sigma_theta > material.hoop_strength or where a "
                            "compressive zone's hoop force exceeds its ring-packet critical force "
                            "min_m D (m^2-1)/R^2 + k R^2/(m^2-1) (docs/defects.md)",
                            &g);
  if (st != RS_OK) return st;
  if (rep->starring.verdict != RS_DEFECT_NOT_ASSESSED) {
    st = rs_h5_attr_string(g, "criterion", rs_starring_criterion_name(rep->starring.criterion));
    if (st == RS_OK) st = rs_h5_attr_int64(g, "layers", rep->starring.layers);
    if (st == RS_OK) st = rs_h5_attr_int64(g, "compressed_layers", rep->starring.compressed);
    if (st == RS_OK) st = rs_h5_attr_int64(g, "zones", rep->starring.zones);
    if (st == RS_OK && rep->starring.compressed > 0) {
      st = rs_h5_attr_double(g, "min_margin", rep->starring.margin_min);
      if (st == RS_OK) st = rs_h5_attr_double(g, "min_margin_radius", rep->starring.margin_radius);
      if (st == RS_OK) st = write_zone(g, rep);
      if (st == RS_OK && isfinite(rep->starring.strength_margin))
        st = rs_h5_attr_double(g, "strength_margin", rep->starring.strength_margin);
    }
    if (st == RS_OK) st = write_ranges(g, rep->starring.ranges, rep->starring.n_ranges);
  }
  H5Gclose(g);
  return st;
}

static rs_status write_pressure(hid_t parent, const rs_defect_report *rep)
{
  hid_t g;
  rs_status st = rule_group(parent, "pressure", rep->pressure.verdict,
                            "risk where the greatest pressure on the web > "
                            "material.pressure_limit",
                            &g);
  if (st != RS_OK) return st;
  st = rs_h5_attr_double(g, "max_pressure", rep->pressure.max);
  if (st == RS_OK) st = rs_h5_attr_double(g, "max_pressure_radius", rep->pressure.max_radius);
  if (st == RS_OK && rep->pressure.verdict != RS_DEFECT_NOT_ASSESSED) {
    st = rs_h5_attr_double(g, "limit", rep->pressure.limit);
    if (st == RS_OK) st = rs_h5_attr_double(g, "ratio", rep->pressure.ratio);
  }
  H5Gclose(g);
  return st;
}

static rs_status write_slip(hid_t parent, const rs_defect_report *rep)
{
  hid_t g;
  rs_status st = rule_group(parent, "interlayer_slip", rep->slip.verdict,
                            "risk where mu P 2 pi r^2 < the torque the interface carries, "
                            "s T R + |s - f_in| I alpha (docs/defects.md)", &g);
  if (st != RS_OK) return st;
  if (rep->slip.verdict != RS_DEFECT_NOT_ASSESSED) {
    st = rs_h5_attr_double(g, "accel_torque", rep->slip.torque);
    if (st == RS_OK) st = rs_h5_attr_double(g, "tension_torque", rep->slip.tension_torque);
    if (st == RS_OK) st = rs_h5_attr_double(g, "core_share", rep->slip.core_share);
    if (st == RS_OK) st = rs_h5_attr_double(g, "alpha", rep->slip.alpha);
    if (st == RS_OK) st = rs_h5_attr_double(g, "min_margin_torque", rep->slip.margin_torque);
    if (st == RS_OK) st = rs_h5_attr_int64(g, "capstan_layers", rep->slip.capstan_layers);
    if (st == RS_OK && isfinite(rep->slip.core_margin))
      st = rs_h5_attr_double(g, "core_margin", rep->slip.core_margin);
    if (st == RS_OK) st = rs_h5_attr_double(g, "friction_layer", rep->slip.mu);
    if (st == RS_OK) st = rs_h5_attr_int64(g, "layers", rep->slip.layers);
    if (st == RS_OK) st = rs_h5_attr_double(g, "min_margin", rep->slip.margin_min);
    if (st == RS_OK) st = rs_h5_attr_double(g, "min_margin_radius", rep->slip.margin_radius);
    if (st == RS_OK) st = write_ranges(g, rep->slip.ranges, rep->slip.n_ranges);
  }
  H5Gclose(g);
  return st;
}

static rs_status write_core(hid_t parent, const rs_defect_report *rep)
{
  hid_t g;
  rs_status st = rule_group(parent, "core", rep->core.verdict,
                            "risk where core pressure > core.rating", &g);
  if (st != RS_OK) return st;
  st = rs_h5_attr_double(g, "core_pressure", rep->core.pressure);
  if (st == RS_OK && rep->core.verdict != RS_DEFECT_NOT_ASSESSED) {
    st = rs_h5_attr_double(g, "rating", rep->core.rating);
    if (st == RS_OK) st = rs_h5_attr_double(g, "ratio", rep->core.ratio);
  }
  H5Gclose(g);
  return st;
}

rs_status rs_h5_write_defects(hid_t file, const rs_scene *scene, const rs_reel_result *res,
                              const rs_defect_report *given)
{
  rs_defect_limits lim;
  rs_defect_report *own = NULL;
  const rs_defect_report *rep = given;
  rs_status st = RS_OK;
  if (!rep) { /* assessed here unless the caller has the report */
    rs_defect_limits_from_problem(rs_scene_problem(scene), &lim);
    if ((st = rs_defects_assess(res, &lim, &own)) != RS_OK) return st;
    rep = own;
  }
  hid_t g;
  st = rs_h5_group_create(file, "defects", &g);
  if (st == RS_OK) {
    st = rs_h5_attr_string(g, "rules", "docs/defects.md");
    if (st == RS_OK) st = write_hoop(g, rep);
    if (st == RS_OK) st = write_starring(g, rep);
    if (st == RS_OK) st = write_pressure(g, rep);
    if (st == RS_OK) st = write_slip(g, rep);
    if (st == RS_OK) st = write_core(g, rep);
    H5Gclose(g);
  }
  rs_defect_report_destroy(&own);
  return st;
}
