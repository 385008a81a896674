/* compare's runs from its scenes and --variant options (compare_runs.h). */
#include "cli/compare_runs.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "cli/fail.h"

/* A word that starts a new override: KEY=... with KEY a scene key path. */
static int starts_set(const char *w)
{
  const char *eq = strchr(w, '=');
  if (!eq || eq == w || !(isalpha((unsigned char)w[0]) || w[0] == '_')) return 0;
  for (const char *p = w; p < eq; ++p)
    if (!isalnum((unsigned char)*p) && !strchr("_.[]", *p)) return 0;
  return 1;
}

/* Splits text (modified in place) into overrides: parts separated by ';', each split at
 * the spaces before a KEY=; words that do not start one join the one before ("title=Two
 * words"). Returns the count, or -1 with *bad the part that is not KEY=VALUE. */
static int split_sets(char *text, const char **out, const char **bad)
{
  int n = 0;
  for (char *part = text; part;) {
    char *semi = strchr(part, ';');
    if (semi) *semi = '\0';
    char *p = part;
    while (*p) {
      while (isspace((unsigned char)*p)) ++p;
      if (!*p) break;
      if (!starts_set(p)) {
        *bad = p;
        return -1;
      }
      char *start = p, *end = p;
      for (;;) { /* to the next word that starts an override, or the end */
        while (*end && !isspace((unsigned char)*end)) ++end;
        char *next = end;
        while (isspace((unsigned char)*next)) ++next;
        if (!*next || starts_set(next)) {
          p = next;
          break;
        }
        end = next;
      }
      *end = '\0';
      out[n++] = start;
      if (p == end) break;
    }
    part = semi ? semi + 1 : NULL;
  }
  return n;
}

static int name_ok(const char *name)
{
  if (!name[0]) return 0;
  for (const char *p = name; *p; ++p)
    if (!isalnum((unsigned char)*p) && *p != '_' && *p != '-') return 0;
  return 1;
}

/* One variant into run *run: "NAME: KEY=VALUE ..." or "NAME". */
static int make_variant(const char *given, char *text, int n_sets, const char *const *sets,
                        compare_run *run)
{
  char *colon = strchr(text, ':');
  char *rest = colon ? colon + 1 : text + strlen(text);
  if (colon) *colon = '\0';
  char *name = text, *e = name + strlen(name);
  while (isspace((unsigned char)*name)) ++name;
  while (e > name && isspace((unsigned char)e[-1])) *--e = '\0';
  if (!name_ok(name))
    return cli_fail(CLI_EXIT_USAGE, "compare: --variant '%s': the name before ':' must be letters, "
                                    "digits, '_' or '-' (e.g. --variant 'hyp30: winding.tension.end=84')",
                    given);
  run->sets = calloc((size_t)n_sets + strlen(rest) + 2, sizeof *run->sets);
  if (!run->sets) return cli_fail(CLI_EXIT_OTHER, "out of memory");
  const char *bad = NULL;
  int k = split_sets(rest, run->sets + n_sets, &bad);
  if (k < 0)
    return cli_fail(CLI_EXIT_USAGE, "compare: --variant '%s': '%s' is not KEY=VALUE (overrides are "
                                    "separated by spaces or ';')", given, bad);
  /* the --set overrides first: the variant's own win */
  memcpy(run->sets, sets, (size_t)n_sets * sizeof *sets);
  /* output.file=, the last of sets, stays last (it names the file the scene records) */
  if (n_sets > 0 && strncmp(sets[n_sets - 1], "output.file=", 12) == 0) {
    memmove(run->sets + n_sets - 1, run->sets + n_sets, (size_t)k * sizeof *run->sets);
    run->sets[n_sets - 1 + k] = sets[n_sets - 1];
  }
  run->n_sets = n_sets + k;
  run->name = name;
  run->variant = given;
  return -1;
}

int compare_runs_make(const cli_args *a, int n_sets, const char *const *sets, compare_runs *r)
{
  memset(r, 0, sizeof *r);
  r->run = calloc((size_t)a->n_scenes + (size_t)a->n_variants + 1, sizeof *r->run);
  r->texts = calloc((size_t)a->n_variants + 1, sizeof *r->texts);
  if (!r->run || !r->texts) return cli_fail(CLI_EXIT_OTHER, "out of memory");
  for (int v = 0; v < a->n_variants; ++v)
    if (a->variant_of[v] < 0)
      return cli_fail(CLI_EXIT_USAGE, "compare: --variant '%s' comes before any scene (give the "
                                      "scene it varies first)", a->variants[v]);
  for (int i = 0; i < a->n_scenes; ++i) {
    int has = 0;
    for (int v = 0; v < a->n_variants; ++v) {
      if (a->variant_of[v] != i) continue;
      has = 1;
      char *text = strdup(a->variants[v]);
      if (!text) return cli_fail(CLI_EXIT_OTHER, "out of memory");
      r->texts[r->n_texts++] = text;
      compare_run *run = &r->run[r->n++];
      run->scene = a->scenes[i];
      int code = make_variant(a->variants[v], text, n_sets, sets, run);
      if (code >= 0) return code;
    }
    if (has) continue;
    compare_run *run = &r->run[r->n++];
    run->scene = a->scenes[i];
    run->n_sets = n_sets;
    run->sets = calloc((size_t)n_sets + 1, sizeof *run->sets);
    if (!run->sets) return cli_fail(CLI_EXIT_OTHER, "out of memory");
    memcpy(run->sets, sets, (size_t)n_sets * sizeof *sets);
  }
  return -1;
}

void compare_runs_free(compare_runs *r)
{
  for (int i = 0; r->run && i < r->n; ++i) free(r->run[i].sets);
  for (int i = 0; r->texts && i < r->n_texts; ++i) free(r->texts[i]);
  free(r->run);
  free(r->texts);
  memset(r, 0, sizeof *r);
}
