/* The material from the checked tree: sheet constants and the radial modulus law. Errors
 * point into the model file the material came from (or the scene, when inline). */

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"

static const char *radial_keys(rs_radial_kind law)
{
  switch (law) {
  case RS_RADIAL_LINEAR: return "E_r";
  case RS_RADIAL_PFEIFFER: return "K1, K2";
  case RS_RADIAL_HAKIEL: return "C";
  case RS_RADIAL_TABLE: return "points";
  }
  return "";
}

static const char *radial_name(rs_radial_kind law)
{
  switch (law) {
  case RS_RADIAL_LINEAR: return "linear";
  case RS_RADIAL_PFEIFFER: return "pfeiffer";
  case RS_RADIAL_HAKIEL: return "hakiel";
  case RS_RADIAL_TABLE: return "table";
  }
  return "?";
}

static rs_status resolve_radial(const yn *root, rs_radial_law *law)
{
  char key[256], want[64];
  const yn *node = yn_get(root, "material.radial");
  rs_radial_kind kind = (rs_radial_kind)ys_enum(root, "material.radial.law");
  snprintf(want, sizeof want, "%s", radial_keys(kind));

  for (int i = 0; i < node->n; ++i) {
    const char *k = node->keys[i];
    if (strcmp(k, "law") == 0) continue;
    int used = 0;
    char list[64], *save = NULL;
    snprintf(list, sizeof list, "%s", want);
    for (char *t = strtok_r(list, ", ", &save); t; t = strtok_r(NULL, ", ", &save))
      used |= strcmp(t, k) == 0;
    if (!used) {
      snprintf(key, sizeof key, "material.radial.%s", k);
      return ys_fail(root, key, "not used by radial law %s (it takes: %s)", radial_name(kind),
                     want);
    }
  }
  {
    char list[64], *save = NULL;
    snprintf(list, sizeof list, "%s", want);
    for (char *t = strtok_r(list, ", ", &save); t; t = strtok_r(NULL, ", ", &save))
      if (!yn_map_get(node, t))
        return ys_fail(root, "material.radial", "radial law %s needs '%s' (it takes: %s)",
                       radial_name(kind), t, want);
  }

  memset(law, 0, sizeof *law);
  law->law = kind;
  law->E_r = ys_num(root, "material.radial.E_r");
  law->K1 = ys_num(root, "material.radial.K1");
  law->K2 = ys_num(root, "material.radial.K2");
  law->n_coef = ys_nums(root, "material.radial.C", law->C, RS_HAKIEL_MAX_COEF);
  law->n_points = ys_pairs(root, "material.radial.points", law->P, law->E, RS_TABLE_MAX);
  if (rs_radial_law_prepare(law) != RS_OK) {
    /* its messages open with the key they are about ("radial.K1 must be > 0 ..."):
     * find that key in the tree for the file and line */
    char msg[1024], tok[128];
    snprintf(msg, sizeof msg, "%s", rs_error_message());
    size_t n = 0;
    while (msg[n] && n < sizeof tok - 1 &&
           (isalnum((unsigned char)msg[n]) || strchr("_.[]", msg[n])))
      ++n;
    memcpy(tok, msg, n);
    tok[n] = '\0';
    const char *rest = msg + n;
    while (*rest == ':' || *rest == ' ') ++rest;
    snprintf(key, sizeof key, "material.%s", tok);
    /* "radial.points must be sorted ... (points[2].P ...)": point at the entry */
    const char *at = strstr(rest, "points[");
    int idx;
    if (strcmp(tok, "radial.points") == 0 && at && sscanf(at, "points[%d]", &idx) == 1)
      snprintf(key, sizeof key, "material.radial.points[%d]", idx);
    if (n == 0 || strncmp(tok, "radial", 6) != 0 || !yn_get(root, key))
      return ys_fail(root, "material.radial", "%s", msg);
    return ys_fail(root, key, "%s", rest);
  }
  return RS_OK;
}

rs_status ys_resolve_material(const yn *root, rs_material *m)
{
  const double caliper = ys_num(root, "material.caliper"), E_theta = ys_num(root, "material.E_theta"),
               nu_rtheta = ys_num(root, "material.nu_rtheta"),
               G_rtheta = ys_num(root, "material.G_rtheta"),
               density = ys_num(root, "material.density"),
               pressure_limit = ys_num(root, "material.pressure_limit"),
               friction_layer = ys_num(root, "material.friction_layer"),
               E_z = ys_num(root, "material.E_z"), E_cd = ys_num(root, "material.E_cd"),
               nu_md_cd = ys_num(root, "material.nu_md_cd");
  memset(m, 0, sizeof *m);
  snprintf(m->name, sizeof m->name, "%s", ys_str(root, "material.name"));
  if (!(caliper > 0.0))
    return ys_fail(root, "material.caliper", "must be > 0 m (got %g)", caliper);
  if (!(E_theta > 0.0))
    return ys_fail(root, "material.E_theta", "must be > 0 Pa (got %g)", E_theta);
  if (!(nu_rtheta > -1.0 && nu_rtheta < 1.0))
    return ys_fail(root, "material.nu_rtheta", "must lie in (-1, 1) (got %g)", nu_rtheta);
  if (ys_has(root, "material.G_rtheta") && !(G_rtheta > 0.0))
    return ys_fail(root, "material.G_rtheta", "must be > 0 Pa (got %g)", G_rtheta);
  if (ys_has(root, "material.density") && !(density > 0.0))
    return ys_fail(root, "material.density", "must be > 0 kg/m^3 (got %g)", density);
  if (ys_has(root, "material.pressure_limit") && !(pressure_limit > 0.0))
    return ys_fail(root, "material.pressure_limit",
                   "must be > 0 Pa (got %g; omit the key to skip the check)", pressure_limit);
  if (ys_has(root, "material.friction_layer") && !(friction_layer > 0.0))
    return ys_fail(root, "material.friction_layer",
                   "must be > 0 (got %g; omit the key to skip the check)", friction_layer);
  m->pressure_limit = pressure_limit;
  m->friction_layer = friction_layer;
  if (ys_has(root, "material.hoop_strength")) {
    const double hs = ys_num(root, "material.hoop_strength");
    if (!(hs > 0.0))
      return ys_fail(root, "material.hoop_strength",
                     "must be > 0 Pa (got %g; omit the key to skip the check)", hs);
    m->hoop_strength = hs;
  }
  if (ys_has(root, "material.nit_saturation")) {
    const double cap = ys_num(root, "material.nit_saturation");
    if (!(cap > 0.0))
      return ys_fail(root, "material.nit_saturation",
                     "must be > 0 N/m (got %g; omit the key for no cap)", cap);
    m->nit_saturation = cap;
  }
  /* the sheet in the contact nip (docs/nip.md): 0 = derived (E_z: the roll's nip E_r,
   * E_cd: E_theta); nu_md_cd defaults to 0.3, a typical in-plane Poisson ratio of paper */
  if (ys_has(root, "material.E_z") && !(E_z > 0.0))
    return ys_fail(root, "material.E_z", "must be > 0 Pa (got %g)", E_z);
  if (ys_has(root, "material.E_cd") && !(E_cd > 0.0))
    return ys_fail(root, "material.E_cd", "must be > 0 Pa (got %g)", E_cd);
  if (ys_has(root, "material.nu_md_cd") && !(nu_md_cd > -1.0 && nu_md_cd < 1.0))
    return ys_fail(root, "material.nu_md_cd", "must lie in (-1, 1) (got %g)", nu_md_cd);
  m->E_z = E_z;
  m->E_cd = E_cd;
  m->nu_md_cd = ys_has(root, "material.nu_md_cd") ? nu_md_cd : 0.3;
  m->caliper = caliper;
  m->E_theta = E_theta;
  m->nu_rtheta = nu_rtheta;
  m->G_rtheta = G_rtheta;
  m->density = density;
  if (ys_has(root, "material.roughness")) {
    const double sigma = ys_num(root, "material.roughness");
    if (!(sigma >= 0.0 && sigma < INFINITY))
      return ys_fail(root, "material.roughness", "must be >= 0 m (got %g)", sigma);
    m->roughness = sigma;
  }
  return resolve_radial(root, &m->radial);
}
