/* The hard bounds and slip warnings over the resolved tree (ranges.h): a value beyond its
 * key's bounds is refused with the unit slip that would explain it, one outside the range
 * plants use is kept as a warning in the scene. The table is ranges.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/ranges.h"
#include "scene/scene_internal.h"

static int within(double v, double lo, double hi) { return !(v < lo) && !(v > hi); }

/* "did you mean 600 m/min?": the first likely unit in which the number as written lands
 * inside the plant range (or, without one, inside the bounds); "a unit slip?" when none
 * does. A radius of a diameter's size gets that hint instead. */
static void slip_hint(const ys_range *r, const char *path, const char *unit, double v,
                      const char *num, char *out, size_t size)
{
  char alt[64];
  double lo = isnan(r->plo) ? r->lo : r->plo, hi = isnan(r->phi) ? r->hi : r->phi, si;
  size_t n = strlen(path);
  snprintf(out, size, "a unit slip?");
  if (n >= 6 && strcmp(path + n - 6, "radius") == 0 && !within(v, lo, hi) &&
      within(0.5 * v, lo, hi)) {
    if (strcmp(path, "core.radius") == 0)
      snprintf(out, size, "a diameter given as the radius (core.diameter: %s)?", num);
    else
      snprintf(out, size, "a diameter given as the radius?");
    return;
  }
  for (const char *p = r->alt; *p;) {
    size_t len = strcspn(p, " ");
    snprintf(alt, sizeof alt, "%.*s", (int)len, p);
    p += len;
    while (*p == ' ') ++p;
    if (rsi_ys_unit_convert(v, alt, unit, &si) && within(si, lo, hi)) {
      snprintf(out, size, "did you mean %s %s?", num, alt);
      return;
    }
  }
}

static rs_status check_node(yn *node, const char *path, int column, void *ctx)
{
  rs_scene *scene = ctx;
  const ys_range *r = rsi_ys_range_of(path);
  double v;
  /* a pair's first column is the radius the recipe or law is tabulated at: checked by its law */
  if (!r || column == 0 || !rsi_ys_parse_double(node->text, &v)) return RS_OK;
  char unit[32], hint[160], num[64], lo[64], hi[64], where[512];
  rsi_ys_column_unit(r->unit, column, unit, sizeof unit);
  const char *sp = unit[0] ? " " : "";
  /* the number as written (a value given with a unit is shown in the key's unit) */
  snprintf(num, sizeof num, "%s", node->text);
  if (!within(v, r->lo, r->hi)) {
    slip_hint(r, path, unit, v, num, hint, sizeof hint);
    rsi_ys_fmt(lo, sizeof lo, r->lo);
    rsi_ys_fmt(hi, sizeof hi, r->hi);
    return rsi_ys_note(rsi_yn_error(node, "%s%s%s is %s the plausible bound %s%s%s (%s to %s%s%s): %s", num, sp,
                    unit, v < r->lo ? "below" : "above", v < r->lo ? lo : hi, sp, unit, lo, hi,
                    sp, unit, hint));
  }
  /* zero is never a slip of units */
  if (v == 0.0 || isnan(r->plo) || within(v, r->plo, r->phi)) return RS_OK;
  slip_hint(r, path, unit, v, num, hint, sizeof hint);
  rsi_ys_fmt(lo, sizeof lo, r->plo);
  rsi_ys_fmt(hi, sizeof hi, r->phi);
  rsi_yn_where(node, where, sizeof where);
  /* the path as written ("storage[1].hours"), unless the value came from a model file,
   * whose paths are its own ("caliper") */
  const char *shown = path;
  size_t top = strcspn(path, ".");
  if (node->path && strncmp(node->path, path, top) == 0) shown = node->path;
  char msg[1200];
  snprintf(msg, sizeof msg, "%s: %s %s%s%s: %s (plants use %s to %s%s%s)", where, shown, num, sp,
           unit, hint, lo, hi, sp, unit);
  if (scene->n_warnings < RS_SCENE_MAX_WARNINGS) { /* cut to fit */
    char *w = scene->warnings[scene->n_warnings++];
    size_t n = strlen(msg) < sizeof scene->warnings[0] ? strlen(msg) : sizeof scene->warnings[0] - 1;
    memcpy(w, msg, n);
    w[n] = '\0';
  }
  return RS_OK;
}

rs_status rsi_ys_check_ranges(const yn *root, rs_scene *scene)
{
  /* the walk takes a mutable tree for the unit conversion; this check changes nothing */
  return rsi_ys_each_number((yn *)root, check_node, scene);
}
