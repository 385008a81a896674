/* rs_storage_summarize (reelsim/storage.h): the figures of a stored roll that a decision
 * needs, the end of the last stage and the worst over the stages. */
#include <math.h>
#include <stddef.h>

#include "reelsim/storage.h"
#include "storage/storage_result.h"

void rs_storage_summarize(const rs_storage_result *sr, rs_storage_summary *sum)
{
  *sum = (rs_storage_summary){NAN, NAN, NAN, NAN, NAN, NAN, NAN};
  if (!sr || sr->n_stages < 1) return;
  const int n = sr->n_layers, last = sr->n_stages - 1;
  double max_core = -INFINITY, max_peak = -INFINITY, starring = NAN;
  for (int s = 0; s <= last; ++s) {
    const double *r = sr->sigma_r + (size_t)s * (size_t)n, *t = sr->sigma_theta + (size_t)s * (size_t)n;
    /* peak pressure as the winding's summary has it: the core pressure if larger */
    double peak = sr->core_pressure[s], hoop = INFINITY;
    for (int j = 0; j < n; ++j) {
      peak = fmax(peak, -r[j]);
      hoop = fmin(hoop, t[j]);
    }
    max_core = fmax(max_core, sr->core_pressure[s]);
    max_peak = fmax(max_peak, peak);
    const rs_defect_report *d = sr->defects ? sr->defects[s] : NULL;
    if (d && d->starring.verdict != RS_DEFECT_NOT_ASSESSED)
      starring = isnan(starring) ? d->starring.layers : fmax(starring, d->starring.layers);
    if (s == last) {
      sum->core_pressure = sr->core_pressure[s];
      sum->peak_pressure = peak;
      sum->min_hoop = n > 0 ? hoop : NAN;
    }
  }
  sum->max_core_pressure = max_core;
  sum->max_peak_pressure = max_peak;
  sum->starring_layers = starring;
  sum->hours = sr->hours[last];
}
