/* --vary KEY=LO:HI:N | KEY=LO:HI | KEY=V1,V2,...: parsing and checking (vary.h). */
#include "sweep/vary.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reelsim/scene.h"
#include "sweep/app_error.h"

/* The whole of s[0..len) is a finite number. */
static int parse_number(const char *s, size_t len, double *x)
{
  char buf[64];
  if (len == 0 || len >= sizeof buf) return 0;
  memcpy(buf, s, len);
  buf[len] = '\0';
  char *end;
  errno = 0;
  *x = strtod(buf, &end);
  return *end == '\0' && errno != ERANGE && isfinite(*x);
}

static rs_status bad(const sweep_vary *v, const char *why)
{
  return APP_ERROR(RS_ERR_INPUT, "--vary %s: %s", v->arg, why);
}

void sweep_vary_clear(sweep_vary *v)
{
  if (!v) return;
  free(v->values);
  free(v->words);
  free(v->words_text);
  v->values = NULL;
  v->words = NULL;
  v->words_text = NULL;
}

int sweep_vary_is_words(const sweep_vary *v) { return v->words != NULL; }

static rs_status parse_range(sweep_vary *v, const char *s, unsigned allowed)
{
  const char *c1 = strchr(s, ':'), *c2 = strchr(c1 + 1, ':');
  if (c2 && strchr(c2 + 1, ':')) return bad(v, "expected LO:HI:N (three parts at most)");
  if (!parse_number(s, (size_t)(c1 - s), &v->lo))
    return bad(v, "LO is not a finite number");
  const char *hi_end = c2 ? c2 : s + strlen(s);
  if (!parse_number(c1 + 1, (size_t)(hi_end - c1 - 1), &v->hi))
    return bad(v, "HI is not a finite number");
  if (v->lo > v->hi) return bad(v, "LO > HI");
  if (!c2) {
    if (!(allowed & SWEEP_VARY_RANGE))
      return bad(v, "expected LO:HI:N (a count of values) or a list V1,V2,...");
    v->kind = SWEEP_RANGE;
    v->n = 0;
    return RS_OK;
  }
  if (!(allowed & SWEEP_VARY_GRID))
    return bad(v, "expected LO:HI (a range, without a count)");
  char *end;
  errno = 0;
  long n = strtol(c2 + 1, &end, 10);
  if (c2[1] == '\0' || *end || errno == ERANGE) return bad(v, "N is not a whole number");
  if (n < 1) return bad(v, "N must be >= 1");
  if (n > 1000000) return bad(v, "N must be <= 1000000");
  v->kind = SWEEP_GRID;
  v->n = (int)n;
  v->values = malloc((size_t)n * sizeof *v->values);
  if (!v->values) return APP_ERROR(RS_ERR_MEMORY, "out of memory");
  for (int i = 0; i < v->n; ++i)
    v->values[i] = v->n == 1 ? v->lo
                 : i == v->n - 1 ? v->hi
                                 : v->lo + (v->hi - v->lo) * ((double)i / (double)(v->n - 1));
  return RS_OK;
}

static rs_status parse_list(sweep_vary *v, const char *s)
{
  int n = 1;
  for (const char *p = s; *p; ++p) n += *p == ',';
  v->kind = SWEEP_LIST;
  v->n = n;
  v->values = malloc((size_t)n * sizeof *v->values);
  v->words = malloc((size_t)n * sizeof *v->words);
  v->words_text = strdup(s);
  if (!v->values || !v->words || !v->words_text) return APP_ERROR(RS_ERR_MEMORY, "out of memory");
  int numeric = 1;
  char *p = v->words_text;
  for (int i = 0; i < n; ++i) {
    char *comma = strchr(p, ',');
    if (comma) *comma = '\0';
    if (!*p) return bad(v, "an empty item in the list");
    v->words[i] = p;
    numeric = numeric && parse_number(p, strlen(p), &v->values[i]);
    p = comma ? comma + 1 : p + strlen(p);
  }
  if (numeric) {
    free(v->words);
    free(v->words_text);
    v->words = NULL;
    v->words_text = NULL;
    v->lo = v->hi = v->values[0];
    for (int i = 1; i < n; ++i) {
      v->lo = fmin(v->lo, v->values[i]);
      v->hi = fmax(v->hi, v->values[i]);
    }
  } else {
    free(v->values);
    v->values = NULL;
    v->lo = 0;
    v->hi = n - 1;
  }
  return RS_OK;
}

rs_status sweep_vary_parse(const char *arg, unsigned allowed, sweep_vary *v)
{
  memset(v, 0, sizeof *v);
  v->arg = arg ? arg : "";
  const char *eq = arg ? strchr(arg, '=') : NULL;
  if (!eq) return bad(v, "expected KEY=LO:HI:N or KEY=V1,V2,...");
  size_t klen = (size_t)(eq - arg);
  if (klen == 0) return bad(v, "no KEY before '='");
  if (klen >= sizeof v->key) return bad(v, "KEY is too long");
  memcpy(v->key, arg, klen);
  v->key[klen] = '\0';
  const char *s = eq + 1;
  if (!*s) return bad(v, "no value after '='");
  if (strchr(s, ':')) {
    if (strchr(s, ',')) return bad(v, "either LO:HI:N or a list V1,V2,..., not both");
    return parse_range(v, s, allowed);
  }
  if (!(allowed & SWEEP_VARY_LIST)) return bad(v, "expected LO:HI (a range), not a list");
  return parse_list(v, s);
}

rs_status sweep_vary_set_text(const sweep_vary *v, double x, char *buf, size_t size)
{
  int len;
  if (v->words) {
    if (!(x >= 0 && x < v->n) || x != floor(x))
      return APP_ERROR(RS_ERR_INPUT, "--vary %s: no item %g", v->arg, x);
    len = snprintf(buf, size, "%s=%s", v->key, v->words[(int)x]);
  } else {
    len = snprintf(buf, size, "%s=%.17g", v->key, x);
  }
  if (len < 0 || (size_t)len >= size)
    return APP_ERROR(RS_ERR_INPUT, "--vary %s: the value is too long", v->arg);
  return RS_OK;
}

/* Loads the scene with sets + "KEY=value" at point x. */
static rs_status check_at(const char *path, int n_sets, const char *const *sets,
                          const sweep_vary *v, double x, const char **all)
{
  char text[SWEEP_KEY_MAX + 512];
  rs_status st = sweep_vary_set_text(v, x, text, sizeof text);
  if (st != RS_OK) return st;
  for (int i = 0; i < n_sets; ++i) all[i] = sets[i];
  all[n_sets] = text;
  rs_scene *scene = NULL;
  st = rs_scene_load(path, n_sets + 1, all, &scene);
  rs_scene_destroy(&scene);
  return st;
}

rs_status sweep_vary_check(const char *scene_path, int n_sets, const char *const *sets,
                           const sweep_vary *v)
{
  return sweep_vary_check_stoppable(scene_path, n_sets, sets, v, NULL);
}

rs_status sweep_vary_check_stoppable(const char *scene_path, int n_sets, const char *const *sets,
                                     const sweep_vary *v, rs_reel_progress_fn stop)
{
  /* the scene as given first: its own error is not the --vary argument's */
  rs_scene *scene = NULL;
  rs_status st = rs_scene_load(scene_path, n_sets, sets, &scene);
  rs_scene_destroy(&scene);
  if (st != RS_OK) return st;
  const char **all = malloc(((size_t)n_sets + 1) * sizeof *all);
  if (!all) return APP_ERROR(RS_ERR_MEMORY, "out of memory");
  int n = v->kind == SWEEP_RANGE ? 2 : v->n;
  for (int i = 0; i < n && st == RS_OK; ++i) {
    if (stop && stop(NULL, 0, 0)) {
      free(all);
      return APP_ERROR(RS_ERR_INTERRUPTED, "--vary %s: stopped while checking value %d of %d",
                      v->arg, i + 1, n);
    }
    double x = v->kind == SWEEP_RANGE ? (i == 0 ? v->lo : v->hi)
             : v->words              ? (double)i
                                     : v->values[i];
    st = check_at(scene_path, n_sets, sets, v, x, all);
  }
  free(all);
  if (st == RS_ERR_INPUT) return app_error_wrap("--vary %s", v->arg);
  return st;
}
