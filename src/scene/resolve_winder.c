/* `nip:` as a list and the `winder` block into the problem (docs/nip.md, "Two-drum
 * winders"): each entry is resolved as the one `nip` mapping is (resolve.c), through a view
 * of the tree whose `nip` is that entry, so every key's checks and messages are the same
 * and name the entry ("nip[1].friction.roll"). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reel/winder.h"
#include "scene/scene_internal.h"

/* *view = root with its `nip` replaced by entry (view->kids is malloc'd; free it) */
static rs_status make_view(const yn *root, const yn *entry, yn *view)
{
  *view = *root;
  view->kids = malloc((size_t)root->n * sizeof *view->kids);
  if (!view->kids) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  for (int i = 0; i < root->n; ++i)
    view->kids[i] = strcmp(root->keys[i], "nip") == 0 ? (yn *)entry : root->kids[i];
  return RS_OK;
}

static int is_list(const yn *root)
{
  const yn *n = yn_get(root, "nip");
  return n && n->kind == YN_SEQ;
}

/* The winder block alone: type, and the keys only a two-drum winder uses. */
static rs_status resolve_block(const yn *root, rs_winder_spec *w, int list)
{
  w->type = (rs_winder_type)ys_enum(root, "winder.type");
  const int two = w->type == RS_WINDER_TYPE_TWO_DRUM;
  static const char *const drum_keys[] = {"winder.drum_distance", "winder.drum_radius"};
  for (int i = 0; i < 2; ++i)
    if (!two && ys_has(root, drum_keys[i]))
      return ys_fail(root, drum_keys[i], "only used with winder type two_drum");
  if (two && !list)
    return ys_fail(root, "winder.type", "a two-drum winder needs nip: as a list with a front "
                   "and a rear drum ({position: front, ...}, {position: rear, ...}) and "
                   "optionally a rider");
  if (!two) return RS_OK;
  w->drum_distance = ys_num(root, "winder.drum_distance");
  if (!ys_has(root, "winder.drum_distance"))
    return ys_fail(root, "winder.drum_distance",
                   "required by winder two_drum: the distance between the drums' centres (m)");
  if (!(w->drum_distance > 0.0))
    return ys_fail(root, "winder.drum_distance", "must be > 0 m (got %g)", w->drum_distance);
  if (ys_has(root, "winder.drum_radius") && !(ys_num(root, "winder.drum_radius") > 0.0))
    return ys_fail(root, "winder.drum_radius", "must be > 0 m (got %g)",
                   ys_num(root, "winder.drum_radius"));
  return RS_OK;
}

/* A front or rear drum's radius: its nip's drum.radius when it has a drum (the contact
 * model needs one), otherwise winder.drum_radius. */
static rs_status drum_radius(const yn *root, const yn *view, int i, double *R)
{
  char key[64];
  snprintf(key, sizeof key, "nip[%d].drum.radius", i);
  if (ys_has(view, "nip.drum.radius")) *R = ys_num(view, "nip.drum.radius");
  else if (ys_has(root, "winder.drum_radius")) *R = ys_num(root, "winder.drum_radius");
  else
    return ys_fail(root, "winder.drum_radius", "required by winder two_drum: the drums' radius "
                   "(m; %s is not given)", key);
  return RS_OK;
}

/* One entry of the list into w->nips[i]. */
static rs_status resolve_entry(const yn *root, rs_scene *s, int i, ys_nip_step one)
{
  rs_winder_spec *w = &s->problem.winder;
  const yn *entry = yn_get(root, "nip")->kids[i];
  yn view;
  rs_status st = make_view(root, entry, &view);
  if (st != RS_OK) return st;
  const rs_nip_position pos = (rs_nip_position)ys_enum(&view, "nip.position");
  const int drum = pos == RS_NIP_AT_FRONT || pos == RS_NIP_AT_REAR;
  if (ys_enum(&view, "nip.model") == RS_NIP_NONE)
    st = ys_fail(&view, "nip.model", "a nip of the list must be friction or contact");
  else if (drum && w->type != RS_WINDER_TYPE_TWO_DRUM)
    st = ys_fail(&view, "nip.position", "front and rear drums belong to a two-drum winder "
                 "(winder: two_drum)");
  if (st == RS_OK) st = one(&view, s, drum && w->type == RS_WINDER_TYPE_TWO_DRUM);
  if (st == RS_OK) {
    w->nips[i] = s->problem.nip;
    w->position[i] = pos;
    if (drum) st = drum_radius(root, &view, i, &w->drum_radius[i]);
  }
  free(view.kids);
  return st;
}

/* A two-drum winder: one front drum, one rear, the roll's weight known, and a roll that
 * rests on both drums from the core on. */
static rs_status check_two_drum(const yn *root, const rs_scene *s)
{
  const rs_winder_spec *w = &s->problem.winder;
  int front = -1, rear = -1;
  for (int i = 0; i < w->n_nips; ++i) {
    int *slot = w->position[i] == RS_NIP_AT_FRONT ? &front
                : w->position[i] == RS_NIP_AT_REAR ? &rear : NULL;
    if (slot && *slot >= 0) {
      char key[64];
      snprintf(key, sizeof key, "nip[%d].position", i);
      return ys_fail(root, key, "a two-drum winder has one %s drum (nip[%d] is one already)",
                     slot == &front ? "front" : "rear", *slot);
    }
    if (slot) *slot = i;
  }
  if (front < 0 || rear < 0)
    return ys_fail(root, "nip", "winder two_drum needs a nip with position: front and one with "
                   "position: rear (the drums)");
  if (!(s->problem.material.density > 0.0))
    return ys_fail(root, "material.density",
                   "required by winder two_drum: the drums carry the roll's weight, "
                   "rho g pi (R^2 - r_c^2) per width");
  double Nf, Nr;
  const double rc = s->problem.core.radius;
  if (rs_winder_drum_loads(rc, w->drum_radius[front], w->drum_radius[rear], w->drum_distance,
                           1.0, &Nf, &Nr, NULL) != RS_OK) {
    char why[512];
    snprintf(why, sizeof why, "%s", rs_error_message());
    return ys_fail(root, "winder.drum_distance", "%s (at the core, radius %g m)", why, rc);
  }
  return RS_OK;
}

/* The problem's `nip` for a list: the first nip's settings, and as its load the nips'
 * total against radius, at RS_TABLE_MAX radii from the core to the final radius (the
 * /layers/nip_load record; each nip's own load is computed where it is solved). */
static rs_status total_load(rs_scene *s)
{
  rs_problem *p = &s->problem;
  const rs_winder_spec *w = &p->winder;
  p->nip = w->nips[0];
  if (w->n_nips == 1 && w->type != RS_WINDER_TYPE_TWO_DRUM) return RS_OK; /* its own recipe */
  rs_recipe *rc = &p->nip.load;
  const double r0 = p->core.radius, r1 = p->final_radius;
  double load[RS_MAX_NIPS];
  memset(rc, 0, sizeof *rc);
  rc->law = RS_RECIPE_TABLE;
  rc->n_points = r1 > r0 ? RS_TABLE_MAX : 1;
  for (int i = 0; i < rc->n_points; ++i) {
    rc->r[i] = rc->n_points > 1 ? r0 + (r1 - r0) * i / (rc->n_points - 1) : r0;
    rs_status st = rs_winder_nip_loads(w, p->material.density, rc->r[i], r0, load, &rc->value[i]);
    if (st != RS_OK) return st;
  }
  return rs_recipe_prepare(rc, r0, r1);
}

rs_status ys_resolve_nips(const yn *root, rs_scene *s, ys_nip_step one)
{
  rs_winder_spec *w = &s->problem.winder;
  memset(w, 0, sizeof *w);
  const int list = is_list(root);
  rs_status st = resolve_block(root, w, list);
  if (st != RS_OK) return st;
  if (!list) {
    const int pos = ys_enum(root, "nip.position");
    if (pos == RS_NIP_AT_FRONT || pos == RS_NIP_AT_REAR)
      return ys_fail(root, "nip.position", "front and rear drums belong to a two-drum winder "
                     "(winder: two_drum, with nip: as a list)");
    return one(root, s, 0);
  }
  w->n_nips = yn_get(root, "nip")->n;
  for (int i = 0; i < w->n_nips; ++i)
    if ((st = resolve_entry(root, s, i, one)) != RS_OK) return st;
  if (w->type == RS_WINDER_TYPE_TWO_DRUM && (st = check_two_drum(root, s)) != RS_OK) return st;
  return total_load(s);
}

rs_status ys_check_nips_capacity(const yn *root, rs_scene *s, ys_capacity_step one)
{
  if (!is_list(root)) return one(root, s);
  rs_winder_spec *w = &s->problem.winder;
  const rs_nip_spec keep = s->problem.nip;
  rs_status st = RS_OK;
  for (int i = 0; st == RS_OK && i < w->n_nips; ++i) {
    const int by_winder = w->type == RS_WINDER_TYPE_TWO_DRUM &&
                          (w->position[i] == RS_NIP_AT_FRONT || w->position[i] == RS_NIP_AT_REAR);
    if (by_winder) continue; /* the contact nip checks a drum's load where it is solved */
    yn view;
    if ((st = make_view(root, yn_get(root, "nip")->kids[i], &view)) != RS_OK) break;
    s->problem.nip = w->nips[i];
    st = one(&view, s);
    free(view.kids);
  }
  s->problem.nip = keep;
  return st;
}
