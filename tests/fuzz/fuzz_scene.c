/* libFuzzer target for the scene loader (rs_scene_load_text).
 *
 * The input is a scene file. Lines at its top of the form "#set key.path=value" (YAML
 * comments, so the text stays a scene) are also passed as --set overrides, up to 8, so
 * the override code is fuzzed too. The property checked, for every input:
 *   - the loader returns RS_OK with a scene, or RS_ERR_INPUT with a non-empty message
 *     and no scene (any other status, a crash, a leak or a sanitizer report is a bug);
 *   - a loaded scene's resolved text loads again (docs/scenes.md: "It is itself a valid
 *     scene") to the same scene (the typed values compared), and is then a fixed point:
 *     loading the second resolved text resolves to the same body (the first round may
 *     change only how a string is quoted: 'a' becomes "a").
 * A failure aborts, which libFuzzer reports with the input that caused it.
 * tests/fuzz/replay.c runs the same function over the kept inputs in the normal build. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/scene.h"
#include "scene/scene_type.h" /* the fields: these tests look inside */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { FUZZ_MAX_SETS = 8, FUZZ_SET_LEN = 256 };

static void fuzz_fail(const char *what, rs_status st)
{
  fprintf(stderr, "fuzz_scene: %s (status %s, message '%s', at %s)\n", what, rs_status_name(st),
          rs_error_message(), rs_error_where());
  abort();
}

/* "#set a.b=c" lines at the top of the input -> sets[] (copies, NUL-terminated). */
static int read_sets(const char *text, size_t size, char buf[][FUZZ_SET_LEN])
{
  int n = 0;
  size_t pos = 0;
  while (n < FUZZ_MAX_SETS && size - pos > 5 && memcmp(text + pos, "#set ", 5) == 0) {
    size_t start = pos + 5, end = start;
    while (end < size && text[end] != '\n') ++end;
    size_t len = end - start;
    if (len >= FUZZ_SET_LEN || memchr(text + start, '\0', len)) break;
    memcpy(buf[n], text + start, len);
    buf[n++][len] = '\0';
    pos = end < size ? end + 1 : end;
  }
  return n;
}

/* The resolved text after its comment header (the header lists the --sets). */
static const char *body_of(const char *resolved)
{
  const char *p = resolved;
  while (*p == '#') {
    const char *nl = strchr(p, '\n');
    if (!nl) return p + strlen(p);
    p = nl + 1;
  }
  return p;
}

/* The typed scene, field by field where a reload may legitimately differ (the material's
 * source after inlining), bytes where it may not. */
static int same_scene(const rs_scene *a, const rs_scene *b)
{
  return strcmp(a->title, b->title) == 0 && strcmp(a->problem.material.name, b->problem.material.name) == 0 &&
         a->problem.material.caliper == b->problem.material.caliper && a->problem.material.E_theta == b->problem.material.E_theta &&
         a->problem.material.nu_rtheta == b->problem.material.nu_rtheta &&
         a->problem.material.G_rtheta == b->problem.material.G_rtheta &&
         a->problem.material.density == b->problem.material.density &&
         memcmp(&a->problem.material.radial, &b->problem.material.radial, sizeof a->problem.material.radial) == 0 &&
         memcmp(&a->problem.core, &b->problem.core, sizeof a->problem.core) == 0 && a->problem.final_radius == b->problem.final_radius &&
         a->problem.n_layers == b->problem.n_layers &&
         memcmp(&a->problem.tension, &b->problem.tension, sizeof a->problem.tension) == 0 &&
         memcmp(&a->problem.nip, &b->problem.nip, sizeof a->problem.nip) == 0 &&
         a->problem.material.nit_saturation == b->problem.material.nit_saturation &&
         memcmp(&a->problem.winder, &b->problem.winder, sizeof a->problem.winder) == 0 &&
         memcmp(&a->problem.numerics, &b->problem.numerics, sizeof a->problem.numerics) == 0 &&
         memcmp(&a->problem.record, &b->problem.record, sizeof a->problem.record) == 0 &&
         memcmp(&a->output, &b->output, sizeof a->output) == 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static char setbuf[FUZZ_MAX_SETS][FUZZ_SET_LEN];
  const char *sets[FUZZ_MAX_SETS];
  const char *text = (const char *)data;
  int n_sets = read_sets(text, size, setbuf);
  for (int i = 0; i < n_sets; ++i) sets[i] = setbuf[i];

  rs_scene *scene = (rs_scene *)(uintptr_t)1; /* must be set to NULL on failure */
  rs_error_clear();
  rs_status st = rs_scene_load_text("fuzz.yaml", text, size, n_sets, sets, &scene);
  if (st != RS_OK) {
    if (st != RS_ERR_INPUT) fuzz_fail("a failure other than RS_ERR_INPUT", st);
    if (!rs_error_message()[0]) fuzz_fail("an input error without a message", st);
    if (scene) fuzz_fail("a failed load left a scene behind", st);
    return 0;
  }
  if (!scene || !scene->resolved_text) fuzz_fail("RS_OK without a scene", st);
  if (scene->problem.n_layers < 1) fuzz_fail("a scene with no layers was accepted", st);

  rs_scene *again = NULL, *third = NULL;
  const char *resolved = scene->resolved_text;
  st = rs_scene_load_text("fuzz.yaml", resolved, strlen(resolved), 0, NULL, &again);
  if (st != RS_OK) {
    fprintf(stderr, "fuzz_scene: resolved text:\n%s\n", resolved);
    fuzz_fail("the resolved scene does not load again", st);
  }
  if (!same_scene(scene, again)) {
    fprintf(stderr, "fuzz_scene: first:\n%s\nsecond:\n%s\n", resolved, again->resolved_text);
    fuzz_fail("the resolved scene loads to another scene", st);
  }
  resolved = again->resolved_text;
  st = rs_scene_load_text("fuzz.yaml", resolved, strlen(resolved), 0, NULL, &third);
  if (st != RS_OK) fuzz_fail("the resolved scene does not load a second time", st);
  if (strcmp(body_of(third->resolved_text), body_of(resolved)) != 0) {
    fprintf(stderr, "fuzz_scene: second:\n%s\nthird:\n%s\n", resolved, third->resolved_text);
    fuzz_fail("the resolved scene is not a fixed point", st);
  }
  rs_scene_destroy(&third);
  rs_scene_destroy(&again);
  rs_scene_destroy(&scene);
  return 0;
}
