/* The "storage" part of the run summary (docs/storage.md): one line per stage, then the
 * stage where each defect rule reads worst, with a WARNING where a rule flags risk there. */
#include <math.h>
#include <stdio.h>

#include "cli/cli.h"

/* stage s's defect report (NULL when not assessed) */
static const rs_defect_report *report(const rs_storage_result *sr, int s)
{
  return rs_storage_result_defects(sr, s);
}

static void stage_line(FILE *out, const rs_storage_result *sr, int s)
{
  char a[64], b[64], c[64];
  const int n = rs_storage_result_n_layers(sr);
  const double *r = rs_storage_result_sigma_r(sr, NULL) + (size_t)s * n;
  const double *t = rs_storage_result_sigma_theta(sr, NULL) + (size_t)s * n;
  const double *cp = rs_storage_result_core_pressure(sr, NULL);
  const double *hours = rs_storage_result_hours(sr, NULL);
  double peak = cp[s], hoop = INFINITY;
  for (int j = 0; j < n; ++j) {
    if (-r[j] > peak) peak = -r[j]; /* no libm in the program: plain comparisons */
    if (t[j] < hoop) hoop = t[j];
  }
  cli_fmt_stress(a, sizeof a, cp[s]);
  cli_fmt_stress(b, sizeof b, peak);
  cli_fmt_stress(c, sizeof c, hoop);
  fprintf(out, "  %5d %8.1f %7.1f %6.1f  %14s %14s %14s\n", s, hours[s],
          rs_storage_result_temperature(sr, NULL)[s], rs_storage_result_humidity(sr, NULL)[s], a, b,
          c);
}

static void worst_line(FILE *out, const char *rule, const rs_storage_result *sr, int s,
                       rs_defect_verdict v, const char *what)
{
  if (s < 0) {
    fprintf(out, "  %-18s not assessed\n", rule);
    return;
  }
  const double hours = rs_storage_result_hours(sr, NULL)[s];
  fprintf(out, "  %-18s worst at stage %d (%.1f h): %s\n", rule, s, hours, what);
  if (v == RS_DEFECT_RISK)
    fprintf(out, "  WARNING: %s at risk after storage stage %d (%.1f h, %.1f C, %.1f %% RH)\n",
            rule, s, hours, rs_storage_result_temperature(sr, NULL)[s],
            rs_storage_result_humidity(sr, NULL)[s]);
}

void cli_print_storage(FILE *out, const rs_storage_result *sr)
{
  char a[96], x[64];
  rs_storage_worst w;
  if (!sr) return;
  const int S = rs_storage_result_stages(sr), N = rs_storage_result_n_layers(sr);
  const int substeps = rs_storage_result_max_substeps(sr);
  const double *sigma_r = rs_storage_result_sigma_r(sr, NULL);
  fprintf(out, "storage:\n");
  fprintf(out, "  %d stage%s after winding, %.1f h; %ld elastic solves, at most %d sub-step%s a "
               "change, %.3f s\n",
          S - 1, S == 2 ? "" : "s", rs_storage_result_hours(sr, NULL)[S - 1],
          rs_storage_result_elastic_solves(sr), substeps, substeps == 1 ? "" : "s",
          rs_storage_result_wall_seconds(sr));
  fprintf(out, "  %5s %8s %7s %6s  %14s %14s %14s\n", "stage", "hours", "T (C)", "RH (%)",
          "core pressure", "peak pressure", "min hoop");
  for (int s = 0; s < S; ++s) stage_line(out, sr, s);
  /* an interface in radial tension: real layers would part there (docs/storage.md, Limits) */
  for (int s = 1; s < S; ++s) {
    int apart = 0;
    for (int j = 0; j < N - 1; ++j) apart += sigma_r[(size_t)s * N + j] > 0.0;
    if (apart > 0)
      fprintf(out, "  note: stage %d leaves %d interface%s in radial tension (sigma_r > 0): the "
                   "layers would part there\n", s, apart, apart == 1 ? "" : "s");
  }
  rs_storage_worst_stages(sr, &w);
  if (w.hoop >= 0) {
    cli_fmt_stress(x, sizeof x, report(sr, w.hoop)->hoop.min);
    snprintf(a, sizeof a, "least %s", x);
  }
  worst_line(out, "hoop stress", sr, w.hoop, RS_DEFECT_OK, a);
  if (w.starring >= 0) snprintf(a, sizeof a, "margin %.3g", report(sr, w.starring)->starring.margin_min);
  worst_line(out, "starring", sr, w.starring,
             w.starring >= 0 ? report(sr, w.starring)->starring.verdict : RS_DEFECT_NOT_ASSESSED, a);
  if (w.pressure >= 0) {
    cli_fmt_stress(x, sizeof x, report(sr, w.pressure)->pressure.max);
    if (report(sr, w.pressure)->pressure.verdict == RS_DEFECT_NOT_ASSESSED)
      snprintf(a, sizeof a, "%s (no material.pressure_limit)", x);
    else
      snprintf(a, sizeof a, "%s (%.3g of the limit)", x, report(sr, w.pressure)->pressure.ratio);
  }
  worst_line(out, "pressure", sr, w.pressure,
             w.pressure >= 0 ? report(sr, w.pressure)->pressure.verdict : RS_DEFECT_NOT_ASSESSED, a);
  if (w.slip >= 0) snprintf(a, sizeof a, "margin %.3g", report(sr, w.slip)->slip.margin_min);
  worst_line(out, "interlayer slip", sr, w.slip,
             w.slip >= 0 ? report(sr, w.slip)->slip.verdict : RS_DEFECT_NOT_ASSESSED, a);
  if (w.core >= 0) {
    cli_fmt_stress(x, sizeof x, report(sr, w.core)->core.pressure);
    if (report(sr, w.core)->core.verdict == RS_DEFECT_NOT_ASSESSED)
      snprintf(a, sizeof a, "%s (no core.rating)", x);
    else
      snprintf(a, sizeof a, "%s (%.3g of the rating)", x, report(sr, w.core)->core.ratio);
  }
  worst_line(out, "core pressure", sr, w.core, w.core >= 0 ? report(sr, w.core)->core.verdict : RS_DEFECT_NOT_ASSESSED,
             a);
}

/* compare's table of the runs after storage: the end of the last stage and the worst
 * over the stages (rs_storage_summarize), then the rules' verdicts where each reads worst. */
void cli_print_compare_storage(FILE *out, int n, const char (*names)[256],
                               const rs_storage_result *const *storage)
{
  int any = 0;
  for (int i = 0; i < n; ++i) any |= storage[i] != NULL;
  if (!any) return;
  fprintf(out, "\n%-24s %7s %10s %10s %10s %10s %10s\n", "after storage", "hours", "core P",
          "peak P", "min hoop", "max core P", "max peak P");
  fprintf(out, "%-24s %7s %10s %10s %10s %10s %10s\n", "", "h", "kPa", "kPa", "kPa", "kPa", "kPa");
  for (int i = 0; i < n; ++i) {
    if (!storage[i]) {
      fprintf(out, "%-24s -\n", names[i]);
      continue;
    }
    rs_storage_summary s;
    rs_storage_summarize(storage[i], &s);
    fprintf(out, "%-24s %7.1f %10.2f %10.2f %10.2f %10.2f %10.2f\n", names[i], s.hours,
            s.core_pressure / 1e3, s.peak_pressure / 1e3, s.min_hoop / 1e3,
            s.max_core_pressure / 1e3, s.max_peak_pressure / 1e3);
  }
  fprintf(out, "\n%-24s %-13s %-13s %-13s %-13s %s\n", "risk in storage", "hoop stress",
          "starring", "pressure", "slip", "core");
  for (int i = 0; i < n; ++i) {
    const rs_storage_result *sr = storage[i];
    if (!sr) continue;
    rs_storage_worst w;
    rs_storage_worst_stages(sr, &w);
      fprintf(out, "%-24s %-13s %-13s %-13s %-13s %s\n", names[i],
            rs_defect_verdict_name(w.hoop >= 0 ? report(sr, w.hoop)->hoop.verdict : RS_DEFECT_NOT_ASSESSED),
            rs_defect_verdict_name(w.starring >= 0 ? report(sr, w.starring)->starring.verdict : RS_DEFECT_NOT_ASSESSED),
            rs_defect_verdict_name(w.pressure >= 0 ? report(sr, w.pressure)->pressure.verdict : RS_DEFECT_NOT_ASSESSED),
            rs_defect_verdict_name(w.slip >= 0 ? report(sr, w.slip)->slip.verdict : RS_DEFECT_NOT_ASSESSED),
            rs_defect_verdict_name(w.core >= 0 ? report(sr, w.core)->core.verdict : RS_DEFECT_NOT_ASSESSED));
  }
}
