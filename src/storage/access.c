/* The storage result's accessors (reelsim/storage.h): one per array, named after it, as
 * the reel result's (src/reel/result_access.c); what a foreign-function interface (Python's
 * ctypes) calls instead of mirroring the struct's layout. */
#include <stddef.h>

#include "reelsim/storage.h"
#include "storage/storage_result.h"

int rs_storage_result_stages(const rs_storage_result *sr) { return sr ? sr->n_stages : 0; }
int rs_storage_result_n_layers(const rs_storage_result *sr) { return sr ? sr->n_layers : 0; }
long rs_storage_result_elastic_solves(const rs_storage_result *sr) { return sr ? sr->elastic_solves : 0; }
int rs_storage_result_max_substeps(const rs_storage_result *sr) { return sr ? sr->max_substeps : 0; }
double rs_storage_result_wall_seconds(const rs_storage_result *sr) { return sr ? sr->wall_seconds : 0.0; }

/* an array of `count` values: the field and its length, or NULL and 0 for NULL or a result
 * without it */
#define RS_STORAGE_ARRAY(field, count)                                            \
  const double *rs_storage_result_##field(const rs_storage_result *sr, int *n)   \
  {                                                                               \
    const int len = sr && sr->field ? (count) : 0;                                \
    if (n) *n = len > 0 ? len : 0;                                                \
    return len > 0 ? sr->field : NULL;                                            \
  }

RS_STORAGE_ARRAY(hours, sr->n_stages)
RS_STORAGE_ARRAY(temperature, sr->n_stages)
RS_STORAGE_ARRAY(humidity, sr->n_stages)
RS_STORAGE_ARRAY(core_pressure, sr->n_stages)
RS_STORAGE_ARRAY(sigma_r, sr->n_stages * sr->n_layers)
RS_STORAGE_ARRAY(sigma_theta, sr->n_stages * sr->n_layers)

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
