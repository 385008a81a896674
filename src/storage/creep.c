/* Viscoelastic creep over a storage hold (issue 16's creep part: the Prony series of
 * material.viscoelastic). Until it is implemented a material with viscoelastic data is
 * refused rather than held elastically without saying so. */
#include <stdlib.h>

#include "storage/storage_internal.h"

rs_status rs_storage_creep_create(const rs_storage_roll *roll, rs_storage_creep **out)
{
  *out = NULL;
  if (roll->problem->material.viscoelastic.n == 0) return RS_OK;
  return RS_ERROR(RS_ERR_INPUT, "material.viscoelastic: creep in storage is not implemented yet");
}

rs_status rs_storage_creep_hold(rs_storage_creep *creep, rs_storage_roll *roll, double hours)
{
  (void)creep, (void)roll, (void)hours;
  return RS_OK;
}

void rs_storage_creep_destroy(rs_storage_creep **creep)
{
  if (creep) *creep = NULL;
}
