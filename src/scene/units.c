/* Numbers written with a unit ("20 um", "600 m/min", "2 pli", "6 in"), converted with
 * UDUNITS-2 into the key's scene unit (ranges.c) before the schema checks: the loader's
 * later steps and the physics see SI numbers only.
 *
 * The unit system (Debian's XML database, udunits2.xml, or UDUNITS2_XML_PATH) is read once
 * per process, and only when a value carries a unit (a few ms); it is freed when the
 * library is unloaded or the process exits. UDUNITS is not thread-safe: one lock guards
 * the system and every call into it. Its messages would go to stderr: silenced
 * (ut_ignore), the loader reports its own. */
#include <ctype.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <udunits2.h>

#include "scene/ranges.h"
#include "scene/scene_internal.h"
#include "util/error.h"

static pthread_mutex_t units_lock = PTHREAD_MUTEX_INITIALIZER;
static ut_system *units_sys;
static int units_tried;

/* pli (pounds per linear inch, the plant's unit of tension and nip load) is not in the
 * database: 1 pli = 1 lbf/in = 175.13 N/m. */
static void add_pli(ut_system *sys)
{
  ut_unit *u = ut_parse(sys, "lbf/in", UT_ASCII);
  if (u) {
    ut_map_name_to_unit("pli", UT_ASCII, u);
    ut_map_symbol_to_unit("pli", UT_ASCII, u);
  }
  ut_free(u);
}

/* the system, read on first use (called with the lock held); NULL if it cannot be read */
static ut_system *units_system(void)
{
  if (!units_tried) {
    units_tried = 1;
    ut_set_error_message_handler(ut_ignore);
    units_sys = ut_read_xml(NULL);
    if (units_sys) add_pli(units_sys);
  }
  return units_sys;
}

__attribute__((destructor)) static void units_free(void)
{
  if (units_sys) ut_free_system(units_sys);
  units_sys = NULL;
}

/* A unit's text as units are written: letters (UTF-8 symbols such as µ and ° too),
 * digits, blanks and the operators . / * ^ - ( ). Anything else is no unit and never
 * reaches UDUNITS' parser, which loses a few bytes on some malformed text (its lexer's
 * copy of an identifier; tests/fuzz/lsan-udunits.supp). */
static int plain_unit_text(const char *u)
{
  for (const unsigned char *p = (const unsigned char *)u; *p; ++p)
    if (!(isalnum(*p) || *p >= 0x80 || strchr(" ./*^-()", *p))) return 0;
  return 1;
}

/* 1: converted; 0: a unit not known; -1: both known but of different dimensions;
 * -2: the database could not be read */
static int convert_locked(double v, const char *from, const char *to, double *out)
{
  if (!plain_unit_text(from) || !plain_unit_text(to)) return 0;
  ut_system *sys = units_system();
  if (!sys) return -2;
  ut_unit *a = ut_parse(sys, from, UT_UTF8), *b = ut_parse(sys, to, UT_UTF8);
  int r = 0;
  if (a && b) {
    r = -1;
    if (ut_are_convertible(a, b)) {
      cv_converter *cv = ut_get_converter(a, b);
      if (cv) {
        *out = cv_convert_double(cv, v);
        r = 1;
      }
      cv_free(cv);
    }
  }
  ut_free(a);
  ut_free(b);
  return r;
}

static int convert(double v, const char *from, const char *to, double *out)
{
  pthread_mutex_lock(&units_lock);
  int r = convert_locked(v, from, to, out);
  pthread_mutex_unlock(&units_lock);
  return r;
}

int rsi_ys_unit_convert(double v, const char *from, const char *to, double *out)
{
  return convert(v, from, to, out) == 1;
}

int rsi_ys_split_quantity(const char *text, double *v, char *unit, size_t size)
{
  char *end;
  double x = strtod(text, &end);
  if (end == text) return 0;
  while (*end == ' ' || *end == '\t') ++end;
  size_t n = strlen(end);
  while (n > 0 && (end[n - 1] == ' ' || end[n - 1] == '\t')) --n;
  if (n == 0 || n >= size) return 0;
  memcpy(unit, end, n);
  unit[n] = '\0';
  *v = x;
  return 1;
}

/* What a scene unit measures, and units it could be written in, for messages. */
static void describe(const char *unit, const char **what, const char **examples)
{
  static const struct {
    const char *unit, *what, *examples;
  } d[] = {{"m", "a length", "mm, um, in, ft"},
           {"Pa", "a pressure or modulus", "kPa, MPa, GPa, psi"},
           {"N/m", "a force per width", "kN/m, N/mm, pli, lbf/in"},
           {"m/s", "a speed", "m/min, ft/min, km/h"},
           {"kg/m3", "a density", "g/cm3"},
           {"m/s2", "an acceleration", "ft/s2, g"},
           {"h", "a time", "min, s, d"},
           {"degC", "a temperature", "degF, K"},
           {"1/K", "an expansion per degree", "1/degC"},
           {"N", "a torque per width", "N.m/m, lbf.ft/ft"},
           {"Pa.s", "a viscosity", "mPa.s"}};
  for (size_t i = 0; i < sizeof d / sizeof d[0]; ++i)
    if (strcmp(d[i].unit, unit) == 0) {
      *what = d[i].what;
      *examples = d[i].examples;
      return;
    }
  *what = "a quantity";
  *examples = unit;
}

/* the errors of the load in progress on this thread, held until rsi_ys_units_note_errors */
static _Thread_local struct {
  int n;
  char text[YS_MAX_ERRORS][640];
} held;

static rs_status hold(rs_status st)
{
  if (st == RS_ERR_INPUT && held.n < YS_MAX_ERRORS)
    snprintf(held.text[held.n++], sizeof held.text[0], "%s", rs_error_message());
  return st;
}

void rsi_ys_units_note_errors(void)
{
  for (int i = 0; i < held.n; ++i) rsi_ys_note(RS_ERROR(RS_ERR_INPUT, "%s", held.text[i]));
  held.n = 0;
}

static rs_status convert_node(yn *node, const char *path, int column, void *ctx)
{
  rs_scene *scene = ctx;
  double v, si = 0.0;
  char unit[64], key_unit[32], text[64];
  if (node->quoted || rsi_yn_is_empty(node) || rsi_ys_parse_double(node->text, &v)) return RS_OK;
  if (!rsi_ys_split_quantity(node->text, &v, unit, sizeof unit)) return RS_OK; /* typecheck says why */
  const ys_range *r = rsi_ys_range_of(path);
  rsi_ys_column_unit(r ? r->unit : "", column, key_unit, sizeof key_unit);
  rs_status st = RS_OK;
  if (!key_unit[0]) {
    st = rsi_yn_error(node, "takes a plain number, without a unit (got '%s')", node->text);
  } else {
    const char *what, *examples;
    describe(key_unit, &what, &examples);
    int c = convert(v, unit, key_unit, &si);
    if (c == -2)
      st = rsi_yn_error(node, "'%s': the units database (udunits2.xml) cannot be read; give the "
                          "value in %s", node->text, key_unit);
    else if (c == 0)
      st = rsi_yn_error(node, "unknown unit '%s' in '%s' (expected %s: %s or e.g. %s)", unit,
                    node->text, what, key_unit, examples);
    else if (c < 0)
      st = rsi_yn_error(node, "'%s' is not %s (expected a unit of %s: %s or e.g. %s)", node->text,
                    what, what, key_unit, examples);
    else if (!isfinite(si))
      st = rsi_yn_error(node, "must be a finite number (got '%s')", node->text);
  }
  /* a bad value has been reported: a number stands in for it so that the schema checks do
   * not report it again (the load stops after them) */
  if (st != RS_OK) si = 0.0;
  hold(st);
  /* 15 digits: "20 um" reads as 2e-05, as if written so (the conversion's last bit is noise) */
  snprintf(text, sizeof text, "%.15g", si);
  if (st == RS_OK && scene) { /* for the resolved scene's header: what each unit became */
    size_t len = strlen(scene->units_text);
    snprintf(scene->units_text + len, sizeof scene->units_text - len, "# units: %s: %s = %s %s\n",
             node->path ? node->path : path, node->text, text, key_unit);
  }
  char *copy = malloc(strlen(text) + 1);
  if (!copy) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  strcpy(copy, text);
  free(node->text);
  node->text = copy;
  return st;
}

rs_status rsi_ys_convert_units(yn *root, rs_scene *scene)
{
  held.n = 0;
  return rsi_ys_each_number(root, convert_node, scene);
}
