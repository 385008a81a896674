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

/* Strings as every reelsim file has them: variable-length UTF-8. */
static int attr_string(hid_t obj, const char *name, const char *value)
{
  hid_t t = H5Tcopy(H5T_C_S1), sp = H5Screate(H5S_SCALAR);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
  int bad = a < 0 || H5Awrite(a, t, &value) < 0;
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

/* A dataset of `rank` (1 or 2) dims; dims of 0 make an empty one. */
static int dataset(hid_t loc, const char *name, hid_t type, int rank, const hsize_t *dims,
                   const void *data)
{
  hid_t sp = H5Screate_simple(rank, dims, NULL);
  hid_t d = H5Dcreate2(loc, name, type, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  int empty = dims[0] == 0 || (rank > 1 && dims[1] == 0);
  int bad = d < 0 || (!empty && H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0);
  if (d >= 0) H5Dclose(d);
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
  /* the keys, as variable-length strings */
  hid_t vs = H5Tcopy(H5T_C_S1);
  H5Tset_size(vs, H5T_VARIABLE);
  H5Tset_cset(vs, H5T_CSET_UTF8);
  const char **keys = malloc((size_t)(K ? K : 1) * sizeof *keys);
  double *lo = malloc((size_t)(K ? K : 1) * sizeof *lo), *hi = malloc((size_t)(K ? K : 1) * sizeof *hi);
  double *col = malloc((size_t)(E ? E : 1) * sizeof *col);
  if (!keys || !lo || !hi || !col) bad = -1;
  for (int k = 0; !bad && k < K; ++k) {
    keys[k] = p->vars[k].key;
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
    if (f == OPT_MISFIT && !p->target) continue;
    for (int i = 0; i < E; ++i) col[i] = h->figures[(size_t)i * OPT_N_FIGURES + (size_t)f];
    bad = dataset(fg, opt_figure_name(f), H5T_NATIVE_DOUBLE, 1, de, col);
  }
  if (fg >= 0) H5Gclose(fg);
  int best = h->best;
  hid_t sc = H5Screate(H5S_SCALAR);
  hid_t bd = bad ? -1 : H5Dcreate2(g, "best", H5T_NATIVE_INT, sc, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (bd < 0 || H5Dwrite(bd, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, &best) < 0) bad = 1;
  if (bd >= 0) H5Dclose(bd);
  H5Sclose(sc);

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

/* The file is built in memory (HDF5's core driver, no backing store) and its image goes
 * through the atomic writer (reelsim/output.h): never a predictable temporary name, never
 * through a symlink, flushed and renamed whole. */
int opt_history_write(const char *path, const opt_problem *p, const opt_history *h, char *why,
                      size_t size)
{
  H5E_auto2_t func;
  void *data;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  hid_t file = -1;
  if (fapl >= 0 && H5Pset_fapl_core(fapl, (size_t)1 << 20, 0) >= 0)
    file = H5Fcreate("reelsim-optimize-history", H5F_ACC_EXCL, H5P_DEFAULT, fapl);
  if (fapl >= 0) H5Pclose(fapl);
  int bad = file < 0 || write_all(file, p, h) != 0 || H5Fflush(file, H5F_SCOPE_GLOBAL) < 0;
  ssize_t n = bad ? -1 : H5Fget_file_image(file, NULL, 0);
  void *image = n > 0 ? malloc((size_t)n) : NULL;
  if (!image || H5Fget_file_image(file, image, (size_t)n) != n) bad = 1;
  if (file >= 0 && H5Fclose(file) < 0) bad = 1;
  H5Eset_auto2(H5E_DEFAULT, func, data);
  if (bad) snprintf(why, size, "%s: cannot build the history file", path);
  else if (rs_output_write_file(path, image, (size_t)n) != RS_OK) {
    snprintf(why, size, "%s", rs_error_message());
    bad = 1;
  }
  free(image);
  return bad ? -1 : 0;
}
