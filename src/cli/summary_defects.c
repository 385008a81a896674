/* The "defect risk" part of the run summary: one line per rule, a WARNING line where a
 * rule flags risk; hoop compression is an information line (rules in docs/defects.md). */
#include <math.h>
#include <stdio.h>

#include "cli/cli.h"

void cli_fmt_stress(char *buf, size_t size, double pa)
{
  if (fabs(pa) < 1e6)
    snprintf(buf, size, "%.2f kPa", pa / 1e3);
  else
    snprintf(buf, size, "%.3f MPa", pa / 1e6);
}

/* " at r = 80.1 .. 240.3 mm", " in 2 ranges: r = 80.1 .. 90.2, 95.0 .. 99.1 mm", or for
 * many (a ragged sign change) their extent; the file has them all. */
static void print_ranges(FILE *out, const rs_defect_range *rg, int n)
{
  enum { SHOWN = 3 };
  if (n == 1) {
    fprintf(out, " at r = %.1f .. %.1f mm", rg[0].r_first * 1e3, rg[0].r_last * 1e3);
  } else if (n <= SHOWN) {
    fprintf(out, " in %d ranges: r = ", n);
    for (int i = 0; i < n; ++i)
      fprintf(out, "%s%.1f .. %.1f", i ? ", " : "", rg[i].r_first * 1e3, rg[i].r_last * 1e3);
    fprintf(out, " mm");
  } else {
    fprintf(out, " in %d ranges between r = %.1f and %.1f mm (all in /defects)", n,
            rg[0].r_first * 1e3, rg[n - 1].r_last * 1e3);
  }
}

/* Hoop compression is information (the buckling line weighs it): never a WARNING. */
static void print_hoop(FILE *out, const rs_defect_report *rep)
{
  char a[64];
  if (rep->hoop.verdict == RS_DEFECT_NOT_ASSESSED) {
    fprintf(out, "  hoop stress        not assessed (no layers)\n");
    return;
  }
  cli_fmt_stress(a, sizeof a, rep->hoop.min);
  if (rep->hoop.verdict == RS_DEFECT_OK) {
    fprintf(out, "  hoop stress        no compression (least %s at r = %.1f mm)\n", a,
            rep->hoop.min_radius * 1e3);
    return;
  }
  fprintf(out, "  hoop stress        compression (sigma_theta < 0) in %d layer%s", rep->hoop.layers,
          rep->hoop.layers == 1 ? "" : "s");
  print_ranges(out, rep->hoop.ranges, rep->hoop.n_ranges);
  fprintf(out, "; least %s at r = %.1f mm\n", a, rep->hoop.min_radius * 1e3);
}

/* The zone behind a packet verdict: "zone r = 76.2 .. 97.5 mm (0.0 .. 21.3 mm = 0.0 .. 0.8 in
 * from the core), 288 layers slipping, mode m = 32" */
static void print_zone(FILE *out, const rs_defect_report *rep)
{
  const double in = 0.0254;
  fprintf(out, "zone r = %.1f .. %.1f mm (%.1f .. %.1f in from the core), %d layer%s %s, mode %d",
          rep->starring.zone_inner * 1e3, rep->starring.zone_outer * 1e3,
          rep->starring.zone_from_core / in, rep->starring.zone_to_core / in,
          rep->starring.zone_last - rep->starring.zone_first + 1,
          rep->starring.zone_last > rep->starring.zone_first ? "s" : "",
          rep->starring.bonded ? "bonded" : "slipping", rep->starring.mode);
}

static void print_starring(FILE *out, const rs_defect_report *rep)
{
  char a[64];
  switch (rep->starring.verdict) {
  case RS_DEFECT_NOT_ASSESSED:
    if (rep->hoop.verdict != RS_DEFECT_NOT_ASSESSED)
      fprintf(out, "  starring           not assessed (no E_theta or radial law)\n");
    return;
  case RS_DEFECT_OK:
    if (rep->starring.compressed == 0) {
      fprintf(out, "  starring           no hoop compression: ok\n");
      return;
    }
    break;
  default:
    break;
  }
  int risk = rep->starring.verdict == RS_DEFECT_RISK;
  if (risk) {
    fprintf(out, "  WARNING: starring risk in %d layer%s", rep->starring.layers,
            rep->starring.layers == 1 ? "" : "s");
    print_ranges(out, rep->starring.ranges, rep->starring.n_ranges);
    fprintf(out, ": ");
  } else {
    fprintf(out, "  starring           ");
  }
  double m = rep->starring.margin_min;
  if (rep->starring.criterion == RS_STARRING_STRENGTH) {
    cli_fmt_stress(a, sizeof a, rep->starring.min_sigma);
    fprintf(out, "hoop_strength margin %.*f (least sigma_theta %s at r = %.1f mm)", m >= 10.0 ? 0 : 2,
            m, a, rep->starring.strength_radius * 1e3);
  } else {
    fprintf(out, "packet margin N_cr/N = %.*f (N %.4g kN/m against %.4g kN/m; ", m >= 10.0 ? 0 : 2,
            m, rep->starring.force / 1e3, rep->starring.force_critical / 1e3);
    print_zone(out, rep);
    fprintf(out, ")");
  }
  fprintf(out, "%s\n", risk ? "" : ": ok");
}

static void print_pressure(FILE *out, const rs_defect_report *rep)
{
  char a[64], b[64];
  if (rep->pressure.verdict == RS_DEFECT_NOT_ASSESSED &&
      rep->hoop.verdict == RS_DEFECT_NOT_ASSESSED)
    return;
  cli_fmt_stress(a, sizeof a, rep->pressure.max);
  double r = rep->pressure.max_radius * 1e3;
  switch (rep->pressure.verdict) {
  case RS_DEFECT_NOT_ASSESSED:
    fprintf(
        out,
        "  pressure           peak %s at r = %.1f mm: not assessed (no material.pressure_limit)\n",
        a, r);
    return;
  case RS_DEFECT_OK:
    cli_fmt_stress(b, sizeof b, rep->pressure.limit);
    fprintf(out,
            "  pressure           peak %s at r = %.1f mm, %.2f of material.pressure_limit %s: ok\n",
            a, r, rep->pressure.ratio, b);
    return;
  case RS_DEFECT_RISK:
  case RS_DEFECT_PRESENT: /* not a verdict of these rules */
    cli_fmt_stress(b, sizeof b, rep->pressure.limit);
    fprintf(out,
            "  WARNING: pressure %s at r = %.1f mm exceeds material.pressure_limit %s (%.2f x): "
            "crushing/blocking risk\n",
            a, r, b, rep->pressure.ratio);
    return;
  }
}

/* "(center drive, T R 175 N m/m, inertia torque 2000 N m/m)" */
static void print_slip_load(FILE *out, const rs_defect_report *rep)
{
  double sh = rep->slip.core_share;
  if (sh == 1.0) fprintf(out, "center drive");
  else if (sh == 0.0) fprintf(out, "surface drive");
  else fprintf(out, "%.2f of the drive at the core", sh);
  fprintf(out, ", T R %.4g N m/m, inertia torque %.4g N m/m; from %d wrap%s below the surface",
          rep->slip.tension_torque, rep->slip.torque, rep->slip.capstan_layers,
          rep->slip.capstan_layers == 1 ? "" : "s");
}

static void print_slip(FILE *out, const rs_defect_report *rep)
{
  switch (rep->slip.verdict) {
  case RS_DEFECT_NOT_ASSESSED:
    fprintf(out, "  interlayer slip    not assessed (%s)\n",
            rep->slip.mu > 0.0 ? "no interface between layers" : "no material.friction_layer");
    return;
  case RS_DEFECT_OK:
    if (!isfinite(rep->slip.margin_min)) {
      fprintf(out, "  interlayer slip    no torque through the roll (");
      print_slip_load(out, rep);
      fprintf(out, "): ok\n");
      return;
    }
    fprintf(out, "  interlayer slip    friction torque capacity >= %.2f x the torque carried (%.4g "
                 "N m/m at r = %.1f mm; ",
            rep->slip.margin_min, rep->slip.margin_torque, rep->slip.margin_radius * 1e3);
    print_slip_load(out, rep);
    fprintf(out, "): ok\n");
    return;
  case RS_DEFECT_RISK:
  case RS_DEFECT_PRESENT: /* not a verdict of these rules */
    fprintf(out, "  WARNING: interlayer slip (cinching) risk at %d interface%s", rep->slip.layers,
            rep->slip.layers == 1 ? "" : "s");
    print_ranges(out, rep->slip.ranges, rep->slip.n_ranges);
    if (rep->slip.core_margin < 1.0)
      fprintf(out, "%s on the core (margin %.2f)", rep->slip.layers ? " and" : "",
              rep->slip.core_margin);
    fprintf(out, ": friction torque capacity down to %.2f x the torque carried (%.4g N m/m at r = "
                 "%.1f mm; ",
            rep->slip.margin_min, rep->slip.margin_torque, rep->slip.margin_radius * 1e3);
    print_slip_load(out, rep);
    fprintf(out, ")\n");
    return;
  }
}

static void print_core(FILE *out, const rs_defect_report *rep)
{
  char a[64], b[64];
  cli_fmt_stress(a, sizeof a, rep->core.pressure);
  cli_fmt_stress(b, sizeof b, rep->core.rating);
  switch (rep->core.verdict) {
  case RS_DEFECT_NOT_ASSESSED:
    fprintf(out, "  core               %s: not assessed (no core.rating)\n", a);
    return;
  case RS_DEFECT_OK:
    fprintf(out, "  core               %s, %.2f of core.rating %s: ok\n", a, rep->core.ratio, b);
    return;
  case RS_DEFECT_RISK:
  case RS_DEFECT_PRESENT: /* not a verdict of these rules */
    fprintf(out, "  WARNING: core pressure %s exceeds core.rating %s (%.2f x): core crush risk\n",
            a, b, rep->core.ratio);
    return;
  }
}

void cli_print_defects(FILE *out, const rs_defect_report *rep)
{
  fprintf(out, "defect risk (rules: docs/defects.md):\n");
  print_hoop(out, rep);
  print_starring(out, rep);
  print_pressure(out, rep);
  print_slip(out, rep);
  print_core(out, rep);
}
