/* Sweep files (rs_output_write_sweep, rs_output_write_sweep_csv; docs/output.md). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output/h5_layout.h"
#include "output/h5_util.h"
#include "reelsim/output.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/shortest.h"

static rs_status check_sweep(const rs_output_sweep *sw)
{
  if (!sw || sw->n_keys < 1 || sw->n_runs < 1 || !sw->keys || !sw->values ||
      (sw->n_figures > 0 && (!sw->figures || !sw->figure_names)))
    return RS_ERROR(RS_ERR_INTERNAL, "an empty or incomplete sweep to write");
  return RS_OK;
}

/* "newsprint,pet-film": a word-valued key's words, malloc'd. */
static char *join_words(int n, const char *const *words)
{
  size_t len = 1;
  for (int i = 0; i < n; ++i) len += strlen(words[i]) + 1;
  char *s = malloc(len);
  if (!s) return NULL;
  s[0] = '\0';
  for (int i = 0; i < n; ++i) {
    if (i) strcat(s, ",");
    strcat(s, words[i]);
  }
  return s;
}

static rs_status write_values(hid_t g, const rs_output_sweep *sw)
{
  hsize_t dims[2] = {(hsize_t)sw->n_runs, (hsize_t)sw->n_keys};
  hid_t space = H5Screate_simple(2, dims, NULL), dcpl = -1;
  hid_t ds = space < 0 || rs_h5_dcpl_checked(space, sizeof(double), &dcpl) != RS_OK
                 ? -1
                 : H5Dcreate2(g, "values", H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl,
                              H5P_DEFAULT);
  if (dcpl >= 0) H5Pclose(dcpl);
  rs_status st = RS_OK;
  if (ds < 0 || H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, sw->values) < 0) {
    char detail[512];
    rs_h5_error_detail(detail, sizeof detail);
    st = RS_ERROR(RS_ERR_IO, "cannot write /sweep/values: %s", detail);
  }
  if (st == RS_OK)
    st = rs_h5_attr_string(ds, "description",
                           "R x K: run i's value of key j (/sweep/parameters); for a key of "
                           "words, the index of its word in the attribute words:<key>");
  for (int k = 0; st == RS_OK && k < sw->n_keys; ++k) {
    if (!sw->n_words || sw->n_words[k] <= 0) continue;
    char name[256], *joined = join_words(sw->n_words[k], sw->words[k]);
    if (!joined) {
      st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
      break;
    }
    snprintf(name, sizeof name, "words:%s", sw->keys[k]);
    st = rs_h5_attr_string(ds, name, joined);
    free(joined);
  }
  if (ds >= 0) H5Dclose(ds);
  if (space >= 0) H5Sclose(space);
  return st;
}

static rs_status write_profiles(hid_t g, const rs_output_sweep *sw)
{
  hid_t pg = -1;
  rs_status st = rs_h5_group_create(g, "profiles", &pg);
  for (int i = 0; st == RS_OK && i < sw->n_runs; ++i) {
    const rs_output_profile *p = &sw->profiles[i];
    char name[32];
    hid_t rg;
    snprintf(name, sizeof name, "%d", i);
    if ((st = rs_h5_group_create(pg, name, &rg)) != RS_OK) break;
    size_t n = p->n > 0 ? (size_t)p->n : 0;
    st = rs_h5_write_1d(rg, "radius", p->radius, n, "m", "outer radius of each layer");
    if (st == RS_OK)
      st = rs_h5_write_1d(rg, "sigma_r", p->sigma_r, n, "Pa", "final radial stress per layer");
    if (st == RS_OK)
      st = rs_h5_write_1d(rg, "sigma_theta", p->sigma_theta, n, "Pa",
                          "final hoop stress per layer");
    H5Gclose(rg);
  }
  if (pg >= 0) H5Gclose(pg);
  return st;
}

static rs_status build_sweep(hid_t file, const void *ctx)
{
  const rs_output_sweep *sw = ctx;
  hid_t g, fg = -1;
  rs_status st = rs_h5_group_create(file, "sweep", &g);
  if (st != RS_OK) return st;
  st = rs_h5_attr_string(g, "scene_file", sw->scene_path ? sw->scene_path : "");
  if (st == RS_OK && sw->scene_text) st = rs_h5_attr_string(g, "scene", sw->scene_text);
  if (st == RS_OK) st = rs_h5_attr_string(g, "sample", sw->sample ? sw->sample : "grid");
  if (st == RS_OK) st = rs_h5_attr_int64(g, "seed", sw->seed);
  if (st == RS_OK) st = rs_h5_attr_int64(g, "runs", sw->n_runs);
  if (st == RS_OK)
    st = rs_h5_write_1d_strings(g, "parameters", sw->keys, (size_t)sw->n_keys,
                                "the scene keys varied, in the order of /sweep/values' columns");
  if (st == RS_OK) st = write_values(g, sw);
  if (st == RS_OK) st = rs_h5_group_create(g, "figures", &fg);
  for (int f = 0; st == RS_OK && f < sw->n_figures; ++f)
    st = rs_h5_write_1d(fg, sw->figure_names[f], sw->figures + (size_t)f * (size_t)sw->n_runs,
                        (size_t)sw->n_runs, sw->figure_units ? sw->figure_units[f] : "",
                        sw->figure_help ? sw->figure_help[f] : "");
  if (fg >= 0) H5Gclose(fg);
  if (st == RS_OK && sw->profiles) st = write_profiles(g, sw);
  H5Gclose(g);
  return st;
}

rs_status rs_output_write_sweep(const char *path, const rs_output_sweep *sw)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no output file name given");
  rs_status st = check_sweep(sw);
  if (st != RS_OK) return st;
  return rs_h5_write_staged(path, build_sweep, sw);
}

/* ---- CSV ------------------------------------------------------------------------------- */

typedef struct buf {
  char *s;
  size_t len, cap;
  int failed;
} buf;

static void put(buf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(buf *b, const char *fmt, ...)
{
  if (b->failed) return;
  for (;;) {
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(b->s + b->len, b->cap - b->len, fmt, ap);
    va_end(ap);
    if (n < 0) {
      b->failed = 1;
      return;
    }
    if ((size_t)n < b->cap - b->len) {
      b->len += (size_t)n;
      return;
    }
    size_t cap = 2 * b->cap + (size_t)n + 1;
    char *s = realloc(b->s, cap);
    if (!s) {
      b->failed = 1;
      return;
    }
    b->s = s;
    b->cap = cap;
  }
}

rs_status rs_output_write_sweep_csv(const char *path, const rs_output_sweep *sw)
{
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no CSV file name given");
  rs_status st = check_sweep(sw);
  if (st == RS_OK) st = rs_atomic_file_check_target(path);
  if (st != RS_OK) return st;
  buf b = {malloc(4096), 0, 4096, 0};
  if (!b.s) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  b.s[0] = '\0';
  for (int k = 0; k < sw->n_keys; ++k) put(&b, "%s%s", k ? "," : "", sw->keys[k]);
  for (int f = 0; f < sw->n_figures; ++f) put(&b, ",%s", sw->figure_names[f]);
  put(&b, "\n");
  char num[RS_SHORTEST_SIZE];
  for (int i = 0; i < sw->n_runs; ++i) {
    for (int k = 0; k < sw->n_keys; ++k) {
      double v = sw->values[(size_t)i * (size_t)sw->n_keys + (size_t)k];
      int w = sw->n_words && sw->n_words[k] > 0;
      if (w && v >= 0 && v < sw->n_words[k]) put(&b, "%s%s", k ? "," : "", sw->words[k][(int)v]);
      else put(&b, "%s%s", k ? "," : "", rs_shortest(num, v));
    }
    for (int f = 0; f < sw->n_figures; ++f) {
      double v = sw->figures[(size_t)f * (size_t)sw->n_runs + (size_t)i];
      if (isfinite(v)) put(&b, ",%s", rs_shortest(num, v));
      else put(&b, ",");
    }
    put(&b, "\n");
  }
  if (b.failed) st = RS_ERROR(RS_ERR_MEMORY, "out of memory writing '%s'", path);
  else st = rs_atomic_file_write(path, b.s, b.len);
  free(b.s);
  return st;
}
