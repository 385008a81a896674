/* The /nip group: the radii where the nip solver ran, with T0, a, P and iterations there,
 * and the full distributions at the radii a scene asks for (docs/output.md). */
#include "output/h5_nip.h"

#include <stdio.h>
#include <stdlib.h>

#include "output/h5_util.h"
#include "reelsim/nip_contact.h"

/* One 1-D dataset of doubles, for the tables below. */
typedef struct nip_column {
  const char *name;
  const double *data;
  size_t n;
  const char *units, *description;
} nip_column;

static rs_status write_columns(hid_t g, const nip_column *cols, size_t count)
{
  rs_status st = RS_OK;
  for (size_t k = 0; st == RS_OK && k < count; ++k)
    st = rs_h5_write_1d(g, cols[k].name, cols[k].data, cols[k].n, cols[k].units,
                        cols[k].description);
  return st;
}

static rs_status write_flags(hid_t g, const char *name, const unsigned char *flags, size_t n,
                             const char *description)
{
  long long *v = malloc((n ? n : 1) * sizeof *v);
  if (!v) return RS_ERROR(RS_ERR_MEMORY, "out of memory for %s", name);
  for (size_t i = 0; i < n; ++i) v[i] = flags[i] != 0;
  rs_status st = rs_h5_write_1d_int64(g, name, v, n, "", description);
  free(v);
  return st;
}

static rs_status write_profile(hid_t parent, int i, double radius, const rs_nip_solution *s)
{
  char name[32];
  snprintf(name, sizeof name, "%d", i);
  hid_t g;
  rs_status st = rs_h5_group_create(parent, name, &g);
  if (st) return st;
  size_t M = (size_t)s->M, E = M - 1;
  const struct { const char *name; double v; } attrs[] = {
      {"roll_radius", radius}, {"T0", s->T0}, {"Ti", s->Ti}, {"a", s->a}, {"load", s->load},
      {"xi2", s->xi2}, {"delta0", s->delta0}, {"eps0", s->eps0}, {"E_r", s->E_r},
      {"condition_number", s->condition_number}};
  for (size_t k = 0; st == RS_OK && k < sizeof attrs / sizeof attrs[0]; ++k)
    st = rs_h5_attr_double(g, attrs[k].name, attrs[k].v);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "iterations", s->iterations);
  const nip_column cols[] = {
      {"x", s->x, M, "m", "nodes across the nip, in the direction of travel"},
      {"pressure", s->pressure, M, "Pa", "contact pressure at the nodes, compression positive"},
      {"x_shear", s->x_shear, E, "m", "element midpoints, where the shears live"},
      {"shear_upper", s->shear_upper, E, "Pa", "shear tau+ on the sheet's roll face"},
      {"shear_lower", s->shear_lower, E, "Pa", "shear tau- on the sheet's drum face"}};
  if (st == RS_OK) st = write_columns(g, cols, sizeof cols / sizeof cols[0]);
  if (st == RS_OK)
    st = write_flags(g, "slip_upper", s->slip_upper, E, "1 where the sheet slips on the roll, 0 where it sticks");
  if (st == RS_OK)
    st = write_flags(g, "slip_lower", s->slip_lower, E, "1 where the sheet slips on the drum, 0 where it sticks");
  H5Gclose(g);
  return st;
}

rs_status rs_h5_write_nip(hid_t loc, const rs_scene *scene, const rs_reel_result *res)
{
  if (rs_scene_problem(scene)->nip.model == RS_NIP_NONE) return RS_OK;
  size_t n = (size_t)res->n_nip;
  hid_t g;
  rs_status st = rs_h5_group_create(loc, "nip", &g);
  if (st) return st;
  const int adaptive = rs_scene_problem(scene)->nip.update == RS_NIP_UPDATE_ADAPTIVE;
  st = rs_h5_attr_string(g, "model", rs_scene_problem(scene)->nip.model == RS_NIP_CONTACT ? "contact" : "friction");
  if (st == RS_OK) st = rs_h5_attr_string(g, "update", adaptive ? "adaptive" : "every");
  if (st == RS_OK)
    st = adaptive ? rs_h5_attr_double(g, "T0_rtol", rs_scene_problem(scene)->nip.T0_rtol)
                  : rs_h5_attr_int64(g, "update_every", rs_scene_problem(scene)->nip.update_every);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "solves", res->nip_solves);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "rejected", res->nip_rejected);
  const rs_winder_spec *w = &rs_scene_problem(scene)->winder;
  if (st == RS_OK && w->n_nips > 0) { /* nip: as a list (docs/nip.md, "Two-drum winders") */
    st = rs_h5_attr_int64(g, "nips", w->n_nips);
    if (st == RS_OK)
      st = rs_h5_attr_string(g, "winder", w->type == RS_WINDER_TYPE_TWO_DRUM ? "two_drum"
                                          : w->type == RS_WINDER_TYPE_SURFACE ? "surface" : "center");
  }
  long long *it = malloc((n ? n : 1) * sizeof *it);
  if (!it && st == RS_OK) st = RS_ERROR(RS_ERR_MEMORY, "out of memory for the nip record");
  for (size_t i = 0; it && i < n; ++i) it[i] = res->nip_iterations[i];
  const nip_column cols[] = {
      {"radius", res->nip_radius, n, "m", "roll radius where the nip was solved (kept solves)"},
      {"wound_on_tension", res->nip_T0, n, "N/m", "wound-on tension T0 found there"},
      {"web_tension", res->nip_Ti, n, "N/m", "web tension Ti there (recipe)"},
      {"half_width", res->nip_a, n, "m", "contact half-width a (0: friction model)"},
      {"load", res->nip_solve_load, n, "N/m", "nip load P of the converged nip (eq. (21))"}};
  if (st == RS_OK) st = write_columns(g, cols, sizeof cols / sizeof cols[0]);
  if (st == RS_OK)
    st = rs_h5_write_1d_int64(g, "iterations", it, n, "", "stick/slip iterations of the solve");
  free(it);
  if (st == RS_OK && res->n_profiles > 0) {
    hid_t p = H5I_INVALID_HID;
    st = rs_h5_group_create(g, "profiles", &p);
    for (int i = 0; st == RS_OK && i < res->n_profiles; ++i)
      st = write_profile(p, i, res->profile_radius[i], &res->profiles[i]);
    if (p >= 0) H5Gclose(p);
  }
  H5Gclose(g);
  return st;
}
