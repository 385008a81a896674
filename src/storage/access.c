/* Results by name for a foreign-function interface (Python's ctypes), which reads these
 * instead of mirroring the structs' layout: the storage stages and the defect verdicts
 * (reelsim/storage.h). */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "reelsim/storage.h"

int rs_storage_result_stages(const rs_storage_result *sr) { return sr ? sr->n_stages : 0; }

const double *rs_storage_result_array(const rs_storage_result *sr, const char *name, int *n)
{
  if (n) *n = 0;
  if (!sr || !name) return NULL;
  const struct {
    const char *name;
    const double *v;
    int count;
  } a[] = {
      {"hours", sr->hours, sr->n_stages},
      {"temperature", sr->temperature, sr->n_stages},
      {"humidity", sr->humidity, sr->n_stages},
      {"core_pressure", sr->core_pressure, sr->n_stages},
      {"sigma_r", sr->sigma_r, sr->n_stages * sr->n_layers},
      {"sigma_theta", sr->sigma_theta, sr->n_stages * sr->n_layers},
  };
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i)
    if (strcmp(name, a[i].name) == 0) {
      if (n) *n = a[i].v ? a[i].count : 0;
      return a[i].v;
    }
  return NULL;
}

const rs_defect_report *rs_storage_result_defects(const rs_storage_result *sr, int s)
{
  if (!sr || !sr->defects || s < 0 || s >= sr->n_stages) return NULL;
  return sr->defects[s];
}

rs_status rs_defects_of_problem(const rs_problem *problem, const rs_reel_result *res,
                                rs_defect_report **out)
{
  rs_defect_limits lim;
  rs_defect_limits_from_problem(problem, &lim);
  return rs_defects_assess(res, &lim, out);
}
