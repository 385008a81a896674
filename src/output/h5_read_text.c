/* Reading reelsim files back, the text and the names (reelsim/reader.h): string datasets,
 * attributes, the children of a group. HDF5's error printing is off for every call, as in
 * h5_read.c. */
#include "reelsim/reader.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>

#include "output/h5_read_check.h"
#include "output/h5_read_internal.h"
#include "output/h5_util.h"
#include "util/error.h"

/* Strings of type `type` read from an attribute (attr >= 0) or a dataset into out[n]. */
static rs_status read_string_values(const rs_reader *r, const char *what, hid_t attr, hid_t dset,
                                    size_t n, char **out)
{
  hid_t ftype = attr >= 0 ? H5Aget_type(attr) : H5Dget_type(dset);
  if (ftype < 0 || H5Tget_class(ftype) != H5T_STRING) {
    if (ftype >= 0) H5Tclose(ftype);
    return RS_ERROR(RS_ERR_INPUT, "%s: %s is not a string", r->path, what);
  }
  rs_status st = RS_OK;
  hid_t mtype = H5Tcopy(H5T_C_S1);
  if (H5Tis_variable_str(ftype) > 0) {
    char **v = calloc(n ? n : 1, sizeof *v);
    H5Tset_size(mtype, H5T_VARIABLE);
    H5Tset_cset(mtype, H5Tget_cset(ftype));
    herr_t e = !v ? -1
               : attr >= 0 ? H5Aread(attr, mtype, v)
                           : H5Dread(dset, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    if (e < 0) st = RS_ERROR(RS_ERR_INPUT, "%s: cannot read %s (damaged)", r->path, what);
    for (size_t i = 0; st == RS_OK && i < n; ++i)
      if (!(out[i] = rsi_reader_dup(v[i] ? v[i] : ""))) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
    if (e >= 0 && v) {
      /* the library allocated each string: let it free them */
      hid_t space = attr >= 0 ? H5Aget_space(attr) : H5Dget_space(dset);
      H5Dvlen_reclaim(mtype, space, H5P_DEFAULT, v);
      H5Sclose(space);
    }
    free(v);
  } else {
    size_t len = H5Tget_size(ftype);
    char *buf = malloc(n * (len + 1) + 1);
    H5Tset_size(mtype, len + 1);
    H5Tset_strpad(mtype, H5T_STR_NULLTERM);
    H5Tset_cset(mtype, H5Tget_cset(ftype)); /* HDF5 converts no character sets */
    herr_t e = !buf ? -1
               : attr >= 0 ? H5Aread(attr, mtype, buf)
                           : H5Dread(dset, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
    if (e < 0) st = RS_ERROR(RS_ERR_INPUT, "%s: cannot read %s (damaged)", r->path, what);
    for (size_t i = 0; st == RS_OK && i < n; ++i)
      if (!(out[i] = rsi_reader_dup(buf + i * (len + 1)))) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
    free(buf);
  }
  H5Tclose(mtype);
  H5Tclose(ftype);
  return st;
}

rs_status rs_reader_read_strings(const rs_reader *r, const char *path, char ***strings,
                                 size_t *n)
{
  hid_t d;
  int rank;
  hsize_t dims[2];
  char what[600];
  *strings = NULL;
  *n = 0;
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  rs_status st = rsi_reader_open_dataset(r, path, 1, &d, &rank, dims);
  if (st == RS_OK && (st = rs_h5_check_dataset(&r->bounds, path, d, 1)) != RS_OK) H5Dclose(d);
  if (st == RS_OK) {
    size_t k = (size_t)dims[0];
    *strings = calloc(k ? k : 1, sizeof **strings);
    snprintf(what, sizeof what, "'%s'", path);
    st = *strings ? read_string_values(r, what, -1, d, k, *strings)
                  : RS_ERROR(RS_ERR_MEMORY, "out of memory");
    if (st != RS_OK) rs_reader_free_strings(strings, k);
    else *n = k;
    H5Dclose(d);
  }
  rs_h5_quiet_end(&q);
  return st;
}

/* ---- attributes ----------------------------------------------------------------------- */

static rs_status open_attr(const rs_reader *r, const char *path, const char *name, hid_t *attr)
{
  const char *p = h5path(path);
  *attr = -1;
  int there = rsi_reader_exists_quiet(r->file, p);
  if (there < 0) return rs_h5_walk_error(&r->bounds, p, there);
  if (!there) return RS_ERROR(RS_ERR_INPUT, "%s: no object '%s'", r->path, p);
  htri_t has = H5Aexists_by_name(r->file, p, name, H5P_DEFAULT);
  if (has == 0) return RS_ERROR(RS_ERR_INPUT, "%s: '%s' has no attribute '%s'", r->path, p, name);
  *attr = has < 0 ? -1 : H5Aopen_by_name(r->file, p, name, H5P_DEFAULT, H5P_DEFAULT);
  if (*attr < 0)
    return RS_ERROR(RS_ERR_INPUT, "%s: cannot open attribute '%s' of '%s' (damaged)", r->path,
                    name, p);
  return RS_OK;
}

rs_status rs_reader_attr_string(const rs_reader *r, const char *path, const char *name,
                                char **value)
{
  hid_t a;
  char what[600];
  *value = NULL;
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  rs_status st = open_attr(r, path, name, &a);
  if (st == RS_OK) {
    snprintf(what, sizeof what, "attribute '%s' of '%s'", name, h5path(path));
    st = rs_h5_check_attr(&r->bounds, what, a, 1);
    if (st == RS_OK) st = read_string_values(r, what, a, -1, 1, value);
    H5Aclose(a);
  }
  rs_h5_quiet_end(&q);
  return st;
}

static rs_status attr_number(const rs_reader *r, const char *path, const char *name,
                             hid_t mtype, void *value)
{
  hid_t a;
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  rs_status st = open_attr(r, path, name, &a);
  if (st == RS_OK) {
    hid_t type = H5Aget_type(a), space = H5Aget_space(a);
    H5T_class_t cls = type >= 0 ? H5Tget_class(type) : H5T_NO_CLASS;
    hssize_t npts = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
    size_t size = type >= 0 ? H5Tget_size(type) : 0;
    if ((cls != H5T_FLOAT && cls != H5T_INTEGER) || npts != 1 || size == 0 || size > 8)
      st = RS_ERROR(RS_ERR_INPUT, "%s: attribute '%s' of '%s' is not a single number", r->path,
                    name, h5path(path));
    else if (H5Aread(a, mtype, value) < 0)
      st = RS_ERROR(RS_ERR_INPUT, "%s: cannot read (damaged) attribute '%s' of '%s'", r->path, name,
                    h5path(path));
    if (type >= 0) H5Tclose(type);
    if (space >= 0) H5Sclose(space);
    H5Aclose(a);
  }
  rs_h5_quiet_end(&q);
  return st;
}

rs_status rs_reader_attr_double(const rs_reader *r, const char *path, const char *name,
                                double *value)
{
  return attr_number(r, path, name, H5T_NATIVE_DOUBLE, value);
}

rs_status rs_reader_attr_int64(const rs_reader *r, const char *path, const char *name,
                               long long *value)
{
  return attr_number(r, path, name, H5T_NATIVE_LLONG, value);
}

/* ---- groups --------------------------------------------------------------------------- */

typedef struct name_list {
  char **names;
  size_t n, cap;
  int failed;
} name_list;

static herr_t collect_name(hid_t g, const char *name, const H5L_info_t *info, void *user)
{
  (void)g;
  (void)info;
  name_list *l = user;
  if (l->n == l->cap) {
    size_t cap = l->cap ? 2 * l->cap : 16;
    char **p = realloc(l->names, cap * sizeof *p);
    if (!p) return (l->failed = 1), -1;
    l->names = p;
    l->cap = cap;
  }
  if (!(l->names[l->n] = rsi_reader_dup(name))) return (l->failed = 1), -1;
  ++l->n;
  return 0;
}

/* Whole numbers first, in numeric order; then the rest by strcmp. */
static int is_number(const char *s)
{
  if (!*s) return 0;
  for (; *s; ++s)
    if (!isdigit((unsigned char)*s)) return 0;
  return 1;
}

static int cmp_names(const void *pa, const void *pb)
{
  const char *a = *(const char *const *)pa, *b = *(const char *const *)pb;
  int na = is_number(a), nb = is_number(b);
  if (na != nb) return nb - na;
  if (na) {
    while (*a == '0' && a[1]) ++a;
    while (*b == '0' && b[1]) ++b;
    size_t la = strlen(a), lb = strlen(b);
    if (la != lb) return la < lb ? -1 : 1;
  }
  return strcmp(a, b);
}

rs_status rs_reader_children(const rs_reader *r, const char *path, char ***names, size_t *n)
{
  const char *p = h5path(path);
  name_list l = {0};
  *names = NULL;
  *n = 0;
  rs_status st = RS_OK;
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  hid_t g = -1;
  H5O_info_t info;
  int there = rsi_reader_exists_quiet(r->file, p);
  if (there < 0)
    st = rs_h5_walk_error(&r->bounds, p, there);
  else if (!there || H5Oget_info_by_name(r->file, p, &info, H5P_DEFAULT) < 0 ||
           info.type != H5O_TYPE_GROUP || (g = H5Gopen2(r->file, p, H5P_DEFAULT)) < 0)
    st = RS_ERROR(RS_ERR_INPUT, "%s: no group '%s'", r->path, p);
  else if (H5Literate(g, H5_INDEX_NAME, H5_ITER_INC, NULL, collect_name, &l) < 0)
    st = l.failed ? RS_ERROR(RS_ERR_MEMORY, "out of memory listing '%s'", p)
                  : RS_ERROR(RS_ERR_INPUT, "%s: cannot list group '%s' (damaged)", r->path, p);
  if (g >= 0) H5Gclose(g);
  rs_h5_quiet_end(&q);
  if (st != RS_OK) {
    rs_reader_free_strings(&l.names, l.n);
    return st;
  }
  if (l.n > 1) qsort(l.names, l.n, sizeof *l.names, cmp_names);
  *names = l.names;
  *n = l.n;
  return RS_OK;
}
