/* The nip contact tests' common set-up (validation/test_nip_contact.c, test_nip_reel.c): a
 * roll and drum described by a few numbers, the solver made from them, one solve. Needs
 * check.h included first. */
#ifndef RS_TESTS_NIP_SETUP_H
#define RS_TESTS_NIP_SETUP_H

#include <stdlib.h>

#include "nip/nip_contact.h"

typedef struct setup {
  double E_r, E_t, G, nu;   /* roll */
  double R, R0, Rd, Rd0;    /* roll and drum radii */
  double mu_roll, mu_drum;
  rs_winder_kind winder;
  double share;
  int M;
  double caliper, E_zd;     /* sheet */
  double E_drum;            /* isotropic drum, nu = 0.3 */
  double E_iso;             /* > 0: isotropic roll (nu = 0.3) instead of the paper roll */
  double E_sheet;           /* > 0: the sheet's E_md = E_cd instead of E_t */
} setup;

/* a paper roll (soft radially) on a steel drum, 100 um sheet */
static inline setup paper_roll(void)
{
  setup s = {3e7, 5e9, 3e7, 0.01, 0.5, 0.1, 0.3, 0.05, 0.19, 0.35, RS_WINDER_CENTER, 0.5, 64, 100e-6, 3e7,
             2.1e11, 0, 0};
  return s;
}

/* the roll's plane-strain constants */
static inline rs_ortho roll_of(const setup *s)
{
  rs_ortho ro;
  if (s->E_iso > 0) {
    CHECK(rs_ortho_isotropic(s->E_iso, 0.3, 1, &ro) == RS_OK);
  } else {
    rs_ortho_engineering e = {s->E_r, s->E_t, s->E_t, s->nu * s->E_r / s->E_t, s->nu * s->E_r / s->E_t, 0.3, s->G};
    CHECK(rs_ortho_from_engineering(&e, 1, &ro) == RS_OK);
  }
  return ro;
}

static inline rs_nip_contact *make(const setup *s)
{
  rs_nip_contact_config c = {0};
  CHECK(rs_ortho_isotropic(s->E_drum, 0.3, 1, &c.drum) == RS_OK);
  c.drum_radius = s->Rd;
  c.drum_core_radius = s->Rd0;
  double Es = s->E_sheet > 0 ? s->E_sheet : s->E_t;
  rs_sheet_constants k = {s->caliper, Es, s->E_zd, Es, s->nu, 0.3, s->nu, s->G, 1};
  CHECK(rs_sheet_from_constants(&k, &c.sheet) == RS_OK);
  c.mu_roll = s->mu_roll;
  c.mu_drum = s->mu_drum;
  c.winder = s->winder;
  c.torque_share = s->share;
  c.nodes = s->M;
  rs_nip_contact *nc = NULL;
  if (rs_nip_contact_create(&c, &nc) != RS_OK) {
    fprintf(stderr, "create: %s\n", rs_error_message());
    return NULL;
  }
  rs_ortho ro = roll_of(s);
  CHECK(rs_nip_contact_set_roll(nc, &ro, s->R, s->R0) == RS_OK);
  return nc;
}

static inline int solve(const setup *s, double P, double Ti, rs_nip_solution *out)
{
  rs_nip_contact *nc = make(s);
  if (!nc) return 0;
  rs_status st = rs_nip_contact_solve_load(nc, P, Ti, out);
  if (st) fprintf(stderr, "solve: %s\n", rs_error_message());
  rs_nip_contact_destroy(&nc);
  return st == RS_OK;
}

#endif
