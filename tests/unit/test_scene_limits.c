/* Hostile YAML is refused while it is read (docs/scenes.md, "Limits"): alias expansion,
 * nesting depth, keys per mapping, values and bytes per file. Each input here would cost
 * minutes or gigabytes without its bound (the billion-laughs file expands to 4.3e7
 * values; 500,000 nesting levels take libyaml's document loader minutes), so a case
 * passes within ctest's time limit only when the bound works. Aliases within the limits
 * still load. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reelsim/scene.h"

static const char scene_head[] = "material: {caliper: 1.0e-4, E_theta: 4.0e9, "
                                 "radial: {law: linear, E_r: 2.0e7}}\n"
                                 "core: {radius: 0.05}\n";

/* Loads text as "hostile.yaml": must be an input error whose message holds `want`. */
static void refused(const char *text, size_t len, const char *want)
{
  rs_scene *s = (rs_scene *)1;
  rs_status st = rs_scene_load_text("hostile.yaml", text, len, 0, NULL, &s);
  CHECK(st == RS_ERR_INPUT);
  CHECK(rs_status_exit_code(st) == 2);
  CHECK(s == NULL);
  const char *msg = rs_error_message();
  printf("  %.200s\n", msg);
  CHECK(strstr(msg, want) != NULL);
}

/* The billion laughs: 8 levels of 9 aliases of the level below. */
static void aliases_bounded(void)
{
  char text[2048];
  size_t len = (size_t)snprintf(text, sizeof text, "a0: &a0 [x, x, x, x, x, x, x, x, x]\n");
  for (int i = 1; i <= 8; ++i) {
    len += (size_t)snprintf(text + len, sizeof text - len, "a%d: &a%d [", i, i);
    for (int j = 0; j < 9; ++j)
      len += (size_t)snprintf(text + len, sizeof text - len, "%s*a%d", j ? ", " : "", i - 1);
    len += (size_t)snprintf(text + len, sizeof text - len, "]\n");
  }
  /* a3 holds 820 values, so the 13th copy of it on line 5 passes 10,000 */
  refused(text, len, "hostile.yaml:5: too many alias expansions (limit 10000 values copied");
}

/* An alias that sits inside its own anchor would be a cycle. */
static void alias_cycle(void)
{
  static const char text[] = "x: &a [1, *a]\n";
  refused(text, strlen(text), "hostile.yaml:1: x[1]: alias *a names no complete anchor");
}

/* `head` and n levels of `open` (never closed: the parser must stop long before) */
static void deep(const char *head, const char *open, int n, const char *want)
{
  size_t h = strlen(head), w = strlen(open), len = h + (size_t)n * w;
  char *text = malloc(len + 1);
  CHECK(text != NULL);
  if (!text) return;
  memcpy(text, head, h);
  for (int i = 0; i < n; ++i) memcpy(text + h + (size_t)i * w, open, w);
  text[len] = '\0';
  refused(text, len, want);
  free(text);
}

static void nesting_bounded(void)
{
  deep("x: ", "[", 500000, "hostile.yaml:1: nesting deeper than 64 levels");
  deep("x: ", "{a: ", 200000, "hostile.yaml:1: nesting deeper than 64 levels");
  deep("x:\n", "- ", 400000, "hostile.yaml:2: nesting deeper than 64 levels");
  /* 64 levels below the top are allowed, the 65th is not (64 unclosed lists read on to
   * the end of the text) */
  deep("x: ", "[", 64, "YAML syntax error");
  deep("x: ", "[", 65, "nesting deeper than 64 levels");
}

/* An alias that would carry a deep value below the limit. */
static void nesting_through_alias(void)
{
  char text[1024];
  size_t len = (size_t)snprintf(text, sizeof text, "a: &d ");
  for (int i = 0; i < 40; ++i) len += (size_t)snprintf(text + len, sizeof text - len, "[");
  for (int i = 0; i < 40; ++i) len += (size_t)snprintf(text + len, sizeof text - len, "]");
  len += (size_t)snprintf(text + len, sizeof text - len, "\nb:\n  c:\n    d: ");
  for (int i = 0; i < 30; ++i) len += (size_t)snprintf(text + len, sizeof text - len, "[");
  len += (size_t)snprintf(text + len, sizeof text - len, "*d");
  for (int i = 0; i < 30; ++i) len += (size_t)snprintf(text + len, sizeof text - len, "]");
  len += (size_t)snprintf(text + len, sizeof text - len, "\n");
  refused(text, len, "hostile.yaml:4: nesting deeper than 64 levels");
}

static void size_bounded(void)
{
  size_t len = (1u << 20) + 1;
  char *text = malloc(len);
  CHECK(text != NULL);
  if (!text) return;
  memset(text, ' ', len);
  memcpy(text, "a: 1", 4);
  refused(text, len, "hostile.yaml: larger than 1048576 bytes (the limit for scene files)");
  free(text);
}

static void values_bounded(void)
{
  enum { N = 25000 };
  char *text = malloc(4 * N + 16);
  CHECK(text != NULL);
  if (!text) return;
  size_t len = (size_t)sprintf(text, "x:\n");
  for (int i = 0; i < N; ++i) len += (size_t)sprintf(text + len, "- 1\n");
  refused(text, len, "hostile.yaml:20000: more than 20000 values in one file");
  free(text);
}

static void keys_bounded(void)
{
  enum { N = 50000 };
  char *text = malloc(16 * (size_t)N + 16);
  CHECK(text != NULL);
  if (!text) return;
  size_t len = (size_t)sprintf(text, "x:\n");
  for (int i = 0; i < N; ++i) len += (size_t)sprintf(text + len, "  k%d: 1\n", i);
  refused(text, len, "hostile.yaml:258: x: more than 256 keys in one mapping");
  free(text);
}

/* Aliases within the limits are ordinary YAML: a shared tension table loads, and an error
 * inside the copy is reported at the copy's path. */
static void aliases_within_limits(void)
{
  char text[1024];
  rs_scene *s = NULL;
  size_t len = (size_t)snprintf(text, sizeof text,
                                "%swinding:\n  final_radius: 0.07\n"
                                "  tension: {law: table, table: &t [[0.05, 300], [0.07, 250]]}\n"
                                "nip:\n  model: friction\n  friction: {roll: 0.2}\n"
                                "  load: {table: *t}\n",
                                scene_head);
  rs_status st = rs_scene_load_text("shared.yaml", text, len, 0, NULL, &s);
  if (st != RS_OK) printf("  %s\n", rs_error_message());
  CHECK(st == RS_OK);
  if (s) {
    CHECK(rs_scene_problem(s)->nip.load.n_points == 2);
    CHECK(rs_scene_problem(s)->nip.load.value[1] == 250.0);
    CHECK(rs_scene_problem(s)->tension.value[0] == 300.0);
  }
  rs_scene_destroy(&s);
  len = (size_t)snprintf(text, sizeof text,
                         "%swinding:\n  final_radius: 0.07\n  tension: &t {law: constant, value: 3}\n"
                         "nip:\n  model: friction\n  friction: {roll: 0.2}\n  load: *t\n"
                         "numerics: {rtol: &r abc}\n",
                         scene_head);
  refused(text, len, "hostile.yaml:10: numerics.rtol: not a number (got 'abc')");
}

/* The largest scene the schema allows (three tables at their 256 rows, a radial table among
 * them) stays well inside every limit. */
static void largest_scene_loads(void)
{
  size_t cap = 1 << 16, len = 0;
  char *text = malloc(cap);
  CHECK(text != NULL);
  if (!text) return;
  static const char *const heads[3] = {
      "material:\n  caliper: 7.0e-5\n  E_theta: 3.5e9\n  radial:\n    law: table\n    points:\n",
      "core: {radius: 0.0762}\nwinding:\n  final_radius: 0.5\n  tension:\n    law: table\n"
      "    table:\n",
      "nip:\n  model: friction\n  friction: {roll: 0.2}\n  load:\n    table:\n"};
  for (int t = 0; t < 3; ++t) {
    len += (size_t)snprintf(text + len, cap - len, "%s", heads[t]);
    for (int i = 0; i < 256; ++i)
      len += (size_t)snprintf(text + len, cap - len, "      - [%.4f, %g]\n", 0.08 + 0.001 * i,
                              1e5 + 1e3 * i);
  }
  CHECK(len < cap - 1);
  rs_scene *s = NULL;
  rs_status st = rs_scene_load_text("largest.yaml", text, len, 0, NULL, &s);
  if (st != RS_OK) printf("  %s\n", rs_error_message());
  CHECK(st == RS_OK);
  if (s) {
    const rs_problem *p = rs_scene_problem(s);
    CHECK(p->material.radial.n_points == 256);
    CHECK(p->tension.n_points == 256);
    CHECK(p->nip.load.n_points == 256);
    printf("  %zu bytes, loads\n", len);
  }
  rs_scene_destroy(&s);
  free(text);
}

static const check_case cases[] = {
    {"aliases_bounded", aliases_bounded},
    {"alias_cycle", alias_cycle},
    {"nesting_bounded", nesting_bounded},
    {"nesting_through_alias", nesting_through_alias},
    {"size_bounded", size_bounded},
    {"values_bounded", values_bounded},
    {"keys_bounded", keys_bounded},
    {"aliases_within_limits", aliases_within_limits},
    {"largest_scene_loads", largest_scene_loads},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
