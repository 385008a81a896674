/* Copying a converged nip (the reel keeps the distributions at the radii a scene asks for). */
#include <stdlib.h>
#include <string.h>

#include "nip/contact_internal.h"
#include "nip/nip_contact.h"

rs_status rs_nip_solution_copy(rs_nip_solution *dst, const rs_nip_solution *src)
{
  rs_status st = rs_nipc_solution_reserve(dst, src->M);
  if (st) return st;
  /* keep dst's arrays, take every figure of src */
  rs_nip_solution keep = *dst;
  *dst = *src;
  dst->capacity = keep.capacity;
  dst->x = keep.x;
  dst->pressure = keep.pressure;
  dst->x_shear = keep.x_shear;
  dst->shear_upper = keep.shear_upper;
  dst->shear_lower = keep.shear_lower;
  dst->slip_rate_upper = keep.slip_rate_upper;
  dst->slip_rate_lower = keep.slip_rate_lower;
  dst->slip_upper = keep.slip_upper;
  dst->slip_lower = keep.slip_lower;
  size_t M = (size_t)src->M, E = M > 0 ? M - 1 : 0, d = sizeof(double);
  memcpy(dst->x, src->x, M * d);
  memcpy(dst->pressure, src->pressure, M * d);
  memcpy(dst->x_shear, src->x_shear, E * d);
  memcpy(dst->shear_upper, src->shear_upper, E * d);
  memcpy(dst->shear_lower, src->shear_lower, E * d);
  memcpy(dst->slip_rate_upper, src->slip_rate_upper, E * d);
  memcpy(dst->slip_rate_lower, src->slip_rate_lower, E * d);
  memcpy(dst->slip_upper, src->slip_upper, E);
  memcpy(dst->slip_lower, src->slip_lower, E);
  return RS_OK;
}
