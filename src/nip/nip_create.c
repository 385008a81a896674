/* The nip model a spec asks for: the one place that knows every model (above them all,
 * so the seam in nip.c depends on none of them). */
#include <stddef.h>

#include "reelsim/nip.h"
#include "nip/nip_contact.h"
#include "util/error.h"

rs_status rs_nip_create(const rs_nip_spec *spec, const rs_material *material, rs_nip **out)
{
  *out = NULL;
  switch (spec->model) {
  case RS_NIP_NONE: return RS_OK; /* no nip, no nip code */
  case RS_NIP_FRICTION: return rs_nip_friction_create(spec->mu_roll, out);
  case RS_NIP_CONTACT: return rs_nip_contact_nip_create(spec, material, out);
  }
  return RS_ERROR(RS_ERR_INPUT, "nip.model: unknown model %d", (int)spec->model);
}
