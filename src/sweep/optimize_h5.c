/* The optimisation's history file (docs/output.md, "/optimize"): every evaluation, the
 * best one and the settings. Built in memory and written by the atomic writer, so it is
 * whole or absent. */
#define _POSIX_C_SOURCE 200809L /* gmtime_r */
#include "sweep/optimize.h"

#include <hdf5.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "reelsim/output.h"
#include "reelsim/version.h"
#include "sweep/app_error.h"

/* Strings as every reelsim file has them: fixed-length UTF-8, NUL-padded (inside the
 * checksummed object header; docs/output.md, "Checksums"). */
static hid_t fixed_string(size_t len)
{
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, len ? len : 1);
  H5Tset_cset(t, H5T_CSET_UTF8);
  H5Tset_strpad(t, H5T_STR_NULLPAD);
  return t;
}

static int attr_string(hid_t obj, const char *name, const char *value)
{
  hid_t t = fixed_string(strlen(value)), sp = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
  int bad = a < 0 || H5Awrite(a, t, value) < 0;
  if (a >= 0) H5Aclose(a);
  H5Sclose(sp);
  H5Tclose(t);
  return bad ? -1 : 0;
}

static int attr_number(hid_t obj, const char *name, hid_t type, const void *value)
{
  hid_t sp = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(obj, name, type, sp, H5P_DEFAULT, H5P_DEFAULT);
  int bad = a < 0 || H5Awrite(a, type, value) < 0;
  if (a >= 0) H5Aclose(a);
  H5Sclose(sp);
  return bad ? -1 : 0;
}

/* A dataset of `rank` (0, 1 or 2) dims; dims of 0 make an empty one. Chunked (whole rows,
 * up to 32768 values a chunk) with the Fletcher-32 checksum; a scalar or empty one compact
 * (in the checksummed object header). */
static int dataset(hid_t loc, const char *name, hid_t type, int rank, const hsize_t *dims,
                   const void *data)
{
  hid_t sp = rank ? H5Screate_simple(rank, dims, NULL) : H5Screate(H5S_SCALAR);
  int empty = rank && (dims[0] == 0 || (rank > 1 && dims[1] == 0));
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  if (rank == 0 || empty) {
    H5Pset_layout(dcpl, H5D_COMPACT);
  } else {
    hsize_t chunk[2] = {dims[0], rank > 1 ? dims[1] : 1};
    hsize_t row = rank > 1 ? dims[1] : 1, rows = 32768 / row ? 32768 / row : 1;
    if (chunk[0] > rows) chunk[0] = rows;
    H5Pset_chunk(dcpl, rank, chunk);
    H5Pset_fletcher32(dcpl);
  }
  hid_t d = H5Dcreate2(loc, name, type, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  int bad = d < 0 || (!empty && H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0);
  if (d >= 0) H5Dclose(d);
  H5Pclose(dcpl);
  H5Sclose(sp);
  return bad ? -1 : 0;
}

static const char *quantity_name(const opt_problem *p, int q)
{
  return q < OPT_N_FIGURES ? opt_figure_name(q) : p->vars[q - OPT_N_FIGURES].key;
}

/* The root attributes that make it a reelsim file (docs/output.md): program, version,
 * created, scene_file. */
static int write_root(hid_t file, const opt_problem *p)
{
  char created[32] = "";
  time_t now = time(NULL);
  struct tm utc;
  if (gmtime_r(&now, &utc)) strftime(created, sizeof created, "%Y-%m-%dT%H:%M:%SZ", &utc);
  int bad = attr_string(file, "program", "reelsim");
  bad = bad || attr_string(file, "version", RS_VERSION_STRING);
  bad = bad || attr_string(file, "created", created);
  bad = bad || attr_string(file, "scene_file", p->scene);
  return bad ? -1 : 0;
}

static int write_all(hid_t file, const opt_problem *p, const opt_history *h)
{
  int bad = 0, K = p->n_vars, E = h->n;
  if (write_root(file, p) != 0) return -1;
  hid_t g = H5Gcreate2(file, "/optimize", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) return -1;
  /* the keys, as fixed-length strings as wide as the longest */
  size_t width = 1;
  for (int k = 0; k < K; ++k)
    if (strlen(p->vars[k].key) > width) width = strlen(p->vars[k].key);
  hid_t vs = fixed_string(width);
  char *keys = calloc((size_t)(K ? K : 1), width);
  double *lo = malloc((size_t)(K ? K : 1) * sizeof *lo), *hi = malloc((size_t)(K ? K : 1) * sizeof *hi);
  double *col = malloc((size_t)(E ? E : 1) * sizeof *col);
  if (!keys || !lo || !hi || !col) bad = -1;
  for (int k = 0; !bad && k < K; ++k) {
    memcpy(keys + (size_t)k * width, p->vars[k].key, strlen(p->vars[k].key));
    lo[k] = p->vars[k].lo;
    hi[k] = p->vars[k].hi;
  }
  hsize_t dk[1] = {(hsize_t)K}, dv[2] = {(hsize_t)E, (hsize_t)K}, de[1] = {(hsize_t)E};
  bad = bad || dataset(g, "parameters", vs, 1, dk, keys);
  bad = bad || dataset(g, "lower", H5T_NATIVE_DOUBLE, 1, dk, lo);
  bad = bad || dataset(g, "upper", H5T_NATIVE_DOUBLE, 1, dk, hi);
  bad = bad || dataset(g, "values", H5T_NATIVE_DOUBLE, 2, dv, h->values);
  bad = bad || dataset(g, "phase", H5T_NATIVE_INT, 1, de, h->phase);
  hid_t fg = bad ? -1 : H5Gcreate2(g, "figures", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (fg < 0) bad = 1;
  for (int f = 0; !bad && f < OPT_N_FIGURES; ++f) {
    if (!opt_figure_recorded(p, h, f)) continue;
    for (int i = 0; i < E; ++i) col[i] = h->figures[(size_t)i * OPT_N_FIGURES + (size_t)f];
    bad = dataset(fg, opt_figure_name(f), H5T_NATIVE_DOUBLE, 1, de, col);
  }
  if (fg >= 0) H5Gclose(fg);
  int best = h->best;
  bad = bad || dataset(g, "best", H5T_NATIVE_INT, 0, NULL, &best);

  /* the settings, as attributes of /optimize */
  char cons[4096] = "";
  size_t used = 0;
  for (int j = 0; j < p->n_cons && used < sizeof cons; ++j)
    used += (size_t)snprintf(cons + used, sizeof cons - used, "%s%s %s %.17g", j ? "\n" : "",
                             quantity_name(p, p->cons[j].quantity), p->cons[j].ge ? ">=" : "<=",
                             p->cons[j].bound);
  int n_start = h->n_start, nc = p->n_cons;
  bad = bad || attr_string(g, "scene", p->scene);
  bad = bad || attr_string(g, "objective", quantity_name(p, p->objective));
  bad = bad || attr_string(g, "sense", p->maximize ? "maximize" : "minimize");
  bad = bad || attr_string(g, "constraints", cons);
  bad = bad || attr_number(g, "n_constraints", H5T_NATIVE_INT, &nc);
  bad = bad || attr_string(g, "algorithm", "latin hypercube start, then NLOPT_LN_COBYLA");
  bad = bad || attr_number(g, "n_start", H5T_NATIVE_INT, &n_start);
  bad = bad || attr_number(g, "xtol_rel", H5T_NATIVE_DOUBLE, &p->settings.xtol_rel);
  bad = bad || attr_number(g, "xtol_abs", H5T_NATIVE_DOUBLE, &p->settings.xtol_abs);
  bad = bad || attr_number(g, "ftol_rel", H5T_NATIVE_DOUBLE, &p->settings.ftol_rel);
  int maxeval = p->settings.maxeval > 0 ? p->settings.maxeval : 30 * K + 30;
  bad = bad || attr_number(g, "maxeval", H5T_NATIVE_INT, &maxeval);
  bad = bad || attr_string(g, "nlopt_result", opt_result_text(h));
  if (p->n_sets) {
    char sets[4096] = "";
    used = 0;
    for (int j = 0; j < p->n_sets && used < sizeof sets; ++j)
      used += (size_t)snprintf(sets + used, sizeof sets - used, "%s%s", j ? "\n" : "", p->sets[j]);
    bad = bad || attr_string(g, "sets", sets);
  }
  H5Tclose(vs);
  free(keys);
  free(lo);
  free(hi);
  free(col);
  H5Gclose(g);
  return bad ? -1 : 0;
}

struct history_fill {
  const opt_problem *p;
  const opt_history *h;
};

static int fill_history(int64_t file, void *user)
{
  const struct history_fill *f = user;
  return write_all((hid_t)file, f->p, f->h);
}

/* The file goes through rs_output_write_h5 (reelsim/output.h): built in memory with
 * checksummed metadata, never a predictable temporary name, never through a symlink,
 * flushed and renamed whole. */
int opt_history_write(const char *path, const opt_problem *p, const opt_history *h, char *why,
                      size_t size)
{
  struct history_fill f = {p, h};
  if (rs_output_write_h5(path, fill_history, &f) == RS_OK) return 0;
  snprintf(why, size, "%s", app_error_message());
  return -1;
}
