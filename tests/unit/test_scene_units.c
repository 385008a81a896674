/* Numbers with units in scenes (src/scene/units.c, UDUNITS-2) and the table of units, bounds
 * and plant ranges (src/scene/ranges.c). The conversions are checked against the units'
 * exact definitions (1 in = 0.0254 m, 1 lbf = 0.45359237 kg x 9.80665 m/s^2, degF), not
 * against UDUNITS itself. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reelsim/scene.h"
#include "scene/ranges.h"
#include "scene/scene_internal.h"

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

static const double lbf = 0.45359237 * 9.80665; /* N, exact by definition */

static void convert_exact(void)
{
  double v = 0.0;
  CHECK(rsi_ys_unit_convert(600, "m/min", "m/s", &v));
  CHECK_CLOSE(v, 10.0, 1e-15);
  CHECK(rsi_ys_unit_convert(2, "pli", "N/m", &v));
  CHECK_CLOSE(v, 2 * lbf / 0.0254, 1e-14);
  CHECK(rsi_ys_unit_convert(2, "lbf/in", "N/m", &v));
  CHECK_CLOSE(v, 2 * lbf / 0.0254, 1e-14);
  CHECK(rsi_ys_unit_convert(6, "in", "m", &v));
  CHECK_CLOSE(v, 0.1524, 1e-15);
  CHECK(rsi_ys_unit_convert(20, "um", "m", &v));
  CHECK_CLOSE(v, 20e-6, 1e-15);
  CHECK(rsi_ys_unit_convert(0.4, "kN/m", "N/m", &v));
  CHECK_CLOSE(v, 400.0, 1e-15);
  CHECK(rsi_ys_unit_convert(212, "degF", "degC", &v));
  CHECK_CLOSE(v, 100.0, 1e-13);
  CHECK(rsi_ys_unit_convert(2, "d", "h", &v));
  CHECK_CLOSE(v, 48.0, 1e-15);
  CHECK(rsi_ys_unit_convert(3.5, "GPa", "Pa", &v));
  CHECK_CLOSE(v, 3.5e9, 1e-15);
  CHECK(!rsi_ys_unit_convert(1, "kg", "m", &v));          /* another dimension */
  CHECK(!rsi_ys_unit_convert(1, "notaunit", "m", &v));    /* not a unit */
}

static void split(void)
{
  double v = 0.0;
  char unit[32];
  CHECK(rsi_ys_split_quantity("20 um", &v, unit, sizeof unit) && v == 20.0 && !strcmp(unit, "um"));
  CHECK(rsi_ys_split_quantity("600m/min ", &v, unit, sizeof unit) && v == 600.0 &&
        !strcmp(unit, "m/min"));
  CHECK(rsi_ys_split_quantity("2e-3 in", &v, unit, sizeof unit) && v == 2e-3 && !strcmp(unit, "in"));
  CHECK(!rsi_ys_split_quantity("350", &v, unit, sizeof unit));
  CHECK(!rsi_ys_split_quantity("abc", &v, unit, sizeof unit));
}

/* the schema's numbers, each with its entry in the table (and nothing in the table that
 * the schema does not have) */
static int walk(const ys_value *v, const char *path, int *found)
{
  int n = 0;
  if (v->type == YS_FLOAT) {
    const ys_range *r = rsi_ys_range_of(path);
    if (!r) printf("  no unit/bounds entry: %s\n", path);
    CHECK(r != NULL);
    ++*found;
    return 1;
  }
  if (v->type == YS_LIST) {
    if (v->entry->type == YS_FLOAT || (v->entry->type == YS_LIST && v->entry->entry->type == YS_FLOAT)) {
      const ys_range *r = rsi_ys_range_of(path);
      if (!r) printf("  no unit/bounds entry: %s\n", path);
      CHECK(r != NULL);
      ++*found;
      return 1;
    }
    return walk(v->entry, path, found);
  }
  if (v->type != YS_MAP) return 0;
  for (const ys_field *f = v->fields; f->key; ++f) {
    char sub[256];
    snprintf(sub, sizeof sub, "%s%s%s", path, path[0] ? "." : "", f->key);
    n += walk(f->value, sub, found);
  }
  return n;
}

static void every_number_has_bounds(void)
{
  int found = 0, n = 0;
  walk(&rsi_ys_scene_schema, "", &found);
  const ys_range *t = rsi_ys_ranges(&n);
  printf("%d numeric keys in the schema, %d entries in the table\n", found, n);
  CHECK(found == n);
  char buf[256];
  for (int i = 0; i < n; ++i) {
    if (strncmp(t[i].path, "storage.", 8) == 0) /* a list: its entries by index */
      snprintf(buf, sizeof buf, "storage[0].%s", t[i].path + 8);
    else
      snprintf(buf, sizeof buf, "%s", t[i].path);
    CHECK(rsi_ys_schema_at(buf) != NULL);
    CHECK(t[i].lo < t[i].hi);
    /* the plant range lies inside the hard bounds: no plant value is refused */
    if (!isnan(t[i].plo)) {
      if (!(t[i].lo <= t[i].plo && t[i].plo < t[i].phi && t[i].phi <= t[i].hi))
        printf("  plant range outside the bounds: %s\n", t[i].path);
      CHECK(t[i].lo <= t[i].plo && t[i].plo < t[i].phi && t[i].phi <= t[i].hi);
    }
    /* every likely slip unit converts to the key's unit */
    char unit[32], alt[32];
    const char *bar = strchr(t[i].unit, '|');
    snprintf(unit, sizeof unit, "%s", bar ? bar + 1 : t[i].unit);
    for (const char *p = t[i].alt; *p;) {
      size_t len = strcspn(p, " ");
      snprintf(alt, sizeof alt, "%.*s", (int)len, p);
      double v;
      if (!rsi_ys_unit_convert(1.0, alt, unit, &v)) printf("  %s: %s does not convert to %s\n", t[i].path, alt, unit);
      CHECK(rsi_ys_unit_convert(1.0, alt, unit, &v));
      p += len;
      while (*p == ' ') ++p;
    }
  }
}

/* docs/scenes.md lists each key's bounds and plant range in its table "Units, bounds and
 * plant ranges" */
static void bounds_documented(void)
{
  FILE *f = fopen(RS_ROOT_DIR "/docs/scenes.md", "rb");
  CHECK(f != NULL);
  if (!f) return;
  char *docs = calloc(1, 1 << 20);
  size_t len = fread(docs, 1, (1 << 20) - 1, f);
  fclose(f);
  docs[len] = '\0';
  int n = 0;
  const ys_range *t = rsi_ys_ranges(&n);
  for (int i = 0; i < n; ++i) {
    char pat[160];
    snprintf(pat, sizeof pat, "| `%s` |", t[i].path);
    if (!strstr(docs, pat)) printf("  bounds not in docs/scenes.md: %s\n", t[i].path);
    CHECK(strstr(docs, pat) != NULL);
  }
  free(docs);
}

static rs_scene *load(const char *text, int n_sets, const char *const *sets)
{
  rs_scene *s = NULL;
  rs_status st = rs_scene_load_text("units.yaml", text, strlen(text), n_sets, sets, &s);
  if (st != RS_OK) printf("load: %s\n", rs_error_message());
  return s;
}

static const char *plant =
    "material: {caliper: 20 um, E_theta: 4.5 GPa, density: 1.39 g/cm3, radial: {law: linear, E_r: 20 MPa}}\n"
    "core: {diameter: 6 in}\n"
    "winding: {final_diameter: 200 mm, tension: 2 lbf/in, speed: 600 m/min}\n"
    "nip: {model: friction, load: 0.4 kN/m, friction: {roll: 0.2}}\n";

static void plant_units(void)
{
  rs_scene *s = load(plant, 0, NULL);
  CHECK(s != NULL);
  if (!s) return;
  const rs_problem *p = rs_scene_problem(s);
  CHECK_CLOSE(p->material.caliper, 20e-6, 1e-15);
  CHECK_CLOSE(p->material.E_theta, 4.5e9, 1e-15);
  CHECK_CLOSE(p->material.density, 1390, 1e-15);
  CHECK_CLOSE(p->core.radius, 0.0762, 1e-15);
  CHECK_CLOSE(p->final_radius, 0.1, 1e-15);
  CHECK_CLOSE(rs_recipe_eval(&p->tension, 0.09), 2 * lbf / 0.0254, 1e-14);
  CHECK_CLOSE(rs_recipe_eval(&p->nip.load, 0.09), 400, 1e-15);
  CHECK(rs_scene_warning_count(s) == 0);
  CHECK(strstr(rs_scene_resolved_text(s), "# units: material.caliper: 20 um = 2e-05 m") != NULL);
  rs_scene_destroy(&s);
}

/* a bare number stays SI, to the bit */
static void bare_numbers(void)
{
  rs_scene *a = load("material: {caliper: 7.3e-5, E_theta: 3.5e9, radial: {law: linear, E_r: 2e7}}\n"
                     "core: {radius: 0.0762}\nwinding: {final_radius: 0.1, tension: 350}\n", 0, NULL);
  CHECK(a != NULL);
  if (!a) return;
  CHECK(rs_scene_problem(a)->material.caliper == 7.3e-5);
  CHECK(rs_recipe_eval(&rs_scene_problem(a)->tension, 0.09) == 350.0);
  CHECK(strstr(rs_scene_resolved_text(a), "# units:") == NULL);
  rs_scene_destroy(&a);
}

static const char *base =
    "material: {caliper: 70e-6, E_theta: 3.5e9, radial: {law: linear, E_r: 2e7}}\n"
    "core: {radius: 0.0762}\nwinding: {final_radius: 0.2, tension: 350}\n";

static int refused(const char *set, const char *want)
{
  rs_scene *s = NULL;
  rs_status st = rs_scene_load_text("units.yaml", base, strlen(base), 1, &set, &s);
  int ok = st == RS_ERR_INPUT && strstr(rs_error_message(), want) != NULL &&
           !strstr(rs_error_message(), "At t =");
  if (!ok) printf("--set %s: status %d, '%s' (wanted '%s')\n", set, (int)st, rs_error_message(), want);
  rs_scene_destroy(&s);
  return ok;
}

static void wrong_dimension(void)
{
  CHECK(refused("material.caliper=20 kg", "'20 kg' is not a length"));
  CHECK(refused("winding.tension=5 kN", "is not a force per width (expected a unit of a force per width: N/m"));
  CHECK(refused("material.E_theta=3 m/s", "is not a pressure"));
  CHECK(refused("material.caliper=20 zorks", "unknown unit 'zorks'"));
  CHECK(refused("material.nu_rtheta=0.3 m", "takes a plain number, without a unit"));
}

static void hard_bounds(void)
{
  CHECK(refused("material.caliper=20e-3", "above the plausible bound 0.01 m (1e-9 to 0.01 m): did you mean 20e-3 mm?"));
  CHECK(refused("material.E_theta=1e308", "above the plausible bound 1e13 Pa"));
  CHECK(refused("numerics.rtol=1e-320", "1e-320 is below the plausible bound 1e-12"));
  CHECK(refused("numerics.rtol=0.5", "above the plausible bound 0.1"));
  CHECK(refused("material.radial.E_r=1e-320", "below the plausible bound 1 Pa"));
}

static int warns(const char *set, const char *want)
{
  rs_scene *s = NULL;
  const char *sets[2] = {set, "nip.friction.roll=0.2"};
  int n = strncmp(set, "nip.", 4) == 0 ? 2 : 1;
  rs_status st = rs_scene_load_text("units.yaml", base, strlen(base), n, sets, &s);
  int ok = st == RS_OK && rs_scene_warning_count(s) == 1 && strstr(rs_scene_warning(s, 0), want);
  if (!ok) printf("--set %s: status %d, %d warnings, '%s' (wanted '%s')\n", set, (int)st,
                  rs_scene_warning_count(s), rs_scene_warning(s, 0), want);
  rs_scene_destroy(&s);
  return ok;
}

static void slip_warnings(void)
{
  CHECK(warns("winding.speed=600", "winding.speed 600 m/s: did you mean 600 m/min?"));
  CHECK(warns("core.radius=0.1524", "core.radius 0.1524 m: a diameter given as the radius"));
  CHECK(warns("winding.tension=0.12", "winding.tension 0.12 N/m: did you mean 0.12 kN/m?"));
  CHECK(warns("material.E_theta=3.5", "did you mean 3.5 GPa?"));
  CHECK(warns("winding.speed=600 m/s", "winding.speed 600 m/s: did you mean 600 m/min?"));
  /* inside the plant range, and zero: no warning */
  rs_scene *s = NULL;
  const char *ok[] = {"winding.speed=600 m/min", "winding.speed=0"};
  for (int i = 0; i < 2; ++i) {
    CHECK(rs_scene_load_text("units.yaml", base, strlen(base), 1, &ok[i], &s) == RS_OK);
    CHECK(rs_scene_warning_count(s) == 0);
    rs_scene_destroy(&s);
  }
  CHECK(rs_scene_warning_count(NULL) == 0 && strcmp(rs_scene_warning(NULL, 0), "") == 0);
}

static void core_forms(void)
{
  const char *id_wall[] = {"core.radius=null", "core.inner_diameter=3 in", "core.wall=12 mm"};
  rs_scene *s = NULL;
  CHECK(rs_scene_load_text("units.yaml", base, strlen(base), 3, id_wall, &s) == RS_OK);
  if (s) CHECK_CLOSE(rs_scene_problem(s)->core.radius, 0.0381 + 0.012, 1e-15);
  rs_scene_destroy(&s);
  /* a tube from its outside and wall: bore = radius - wall */
  const char *tube[] = {"core.wall=10 mm", "core.modulus=5e9", "core.poisson=0.3"};
  CHECK(rs_scene_load_text("units.yaml", base, strlen(base), 3, tube, &s) == RS_OK);
  if (s) {
    CHECK(rs_scene_problem(s)->core.kind == RS_CORE_TUBE);
    CHECK_CLOSE(rs_scene_problem(s)->core.bore, 0.0762 - 0.010, 1e-15);
  }
  rs_scene_destroy(&s);
  const char *tube_id[] = {"core.inner_diameter=0.1", "core.modulus=5e9", "core.poisson=0.3"};
  CHECK(rs_scene_load_text("units.yaml", base, strlen(base), 3, tube_id, &s) == RS_OK);
  if (s) CHECK_CLOSE(rs_scene_problem(s)->core.bore, 0.05, 1e-15);
  rs_scene_destroy(&s);
  CHECK(refused("core.inner_diameter=0.2", "must be < the core's outer diameter"));
  CHECK(refused("core.wall=0.1", "must be <= the core's outer radius"));
  const char *two[] = {"core.wall=0.01", "core.bore=0.05"};
  CHECK(rs_scene_load_text("units.yaml", base, strlen(base), 2, two, &s) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "not two") != NULL);
}

static const check_case cases[] = {
    {"convert_exact", convert_exact},
    {"split", split},
    {"every_number_has_bounds", every_number_has_bounds},
    {"bounds_documented", bounds_documented},
    {"plant_units", plant_units},
    {"bare_numbers", bare_numbers},
    {"wrong_dimension", wrong_dimension},
    {"hard_bounds", hard_bounds},
    {"slip_warnings", slip_warnings},
    {"core_forms", core_forms}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
