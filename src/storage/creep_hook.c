/* The storage driver's creep hook (storage_internal.h): the wound roll held through a
 * stage with the material's Prony series (creep.c; docs/storage.md, "Creep"). */
#include <math.h>
#include <stdlib.h>

#include "storage/creep.h"
#include "storage/storage_internal.h"
#include "util/error.h"
#include "storage/storage_result.h"

struct rs_storage_creep {
  rs_creep *c;
};

rs_status rs_storage_creep_create(const rs_storage_roll *roll, rs_storage_creep **out)
{
  *out = NULL;
  const rs_problem *pb = roll->problem;
  const rs_prony *v = &pb->material.viscoelastic;
  if (v->n == 0) return RS_OK;
  rs_creep_params p = {0};
  p.n_layers = roll->n;
  p.core_radius = roll->s[0];
  p.caliper = pb->material.caliper;
  p.E_theta = pb->material.E_theta;
  p.nu_rtheta = pb->material.nu_rtheta;
  p.radial = &pb->material.radial;
  p.core_stiffness = roll->E_c_inv > 0.0 ? 1.0 / roll->E_c_inv : INFINITY;
  p.n_terms = v->n;
  for (int i = 0; i < v->n && i < RS_CREEP_MAX_TERMS; ++i) {
    p.tau[i] = v->tau[i];
    p.w_theta[i] = v->w_theta[i];
    p.w_radial[i] = v->w_radial[i];
  }
  /* no error correction here: its local tolerance a quarter of the reuse's, so that the
   * global error the steps add up to stays within ~rtol/50 of the core pressure (measured on
   * cases/newsprint-storage-creep.yaml: at RS_ACCURACY_PER_RTOL x rtol it was 3.7x that;
   * docs/storage.md) */
  p.rtol = 0.25 * RS_ACCURACY_PER_RTOL * pb->numerics.rtol;
  p.max_steps = pb->numerics.max_steps > 0 ? pb->numerics.max_steps : 100000;
  rs_storage_creep *sc = calloc(1, sizeof *sc);
  if (!sc) return RS_ERROR(RS_ERR_MEMORY, "cannot allocate the creep solver");
  rs_status st = rs_creep_create(&p, &sc->c);
  if (st != RS_OK) {
    free(sc);
    return st;
  }
  *out = sc;
  return RS_OK;
}

/* The roll's faces: sr[0] = -core pressure, sr[1..n] at the layers' outer radii */
rs_status rs_storage_creep_hold(rs_storage_creep *creep, rs_storage_roll *roll, double hours)
{
  double core_p = -roll->sr[0];
  rs_status st = rs_creep_hold(creep->c, hours, &core_p, roll->sr + 1, roll->st);
  if (st == RS_OK) roll->sr[0] = -core_p;
  return st;
}

void rs_storage_creep_destroy(rs_storage_creep **creep)
{
  if (!creep || !*creep) return;
  rs_creep_destroy(&(*creep)->c);
  free(*creep);
  *creep = NULL;
}
