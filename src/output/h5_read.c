/* Reading reelsim files back (reelsim/reader.h). HDF5's error printing is off for every
 * call: a missing dataset is an answer here, not a fault, and the messages we record
 * name the file and the path, which HDF5's stack does not. */
#include "reelsim/reader.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <hdf5.h>

#include "output/h5_read_check.h"
#include "output/h5_util.h"
#include "util/error.h"

struct rs_reader {
  char *path;
  hid_t file;
  rs_h5_bounds bounds; /* what the checks of h5_read_check.c know of the file */
  int compare;
  int n_runs;
  char **base; /* "" or "/runs/<name>" */
  char **name;
};

/* "" means the root */
static const char *h5path(const char *path) { return path && path[0] ? path : "/"; }

static char *dup_str(const char *s)
{
  size_t n = strlen(s) + 1;
  char *d = malloc(n);
  if (d) memcpy(d, s, n);
  return d;
}

void rs_reader_free_strings(char ***strings, size_t n)
{
  if (!strings || !*strings) return;
  for (size_t i = 0; i < n; ++i) free((*strings)[i]);
  free(*strings);
  *strings = NULL;
}

void rs_reader_free_data(double **data)
{
  if (!data) return;
  free(*data);
  *data = NULL;
}

void rs_reader_free_text(char **text)
{
  if (!text) return;
  free(*text);
  *text = NULL;
}

void rs_reader_close(rs_reader **rp)
{
  if (!rp || !*rp) return;
  rs_reader *r = *rp;
  if (r->file >= 0) H5Fclose(r->file);
  rs_reader_free_strings(&r->base, (size_t)r->n_runs);
  rs_reader_free_strings(&r->name, (size_t)r->n_runs);
  free(r->path);
  free(r);
  *rp = NULL;
}

const char *rs_reader_path(const rs_reader *r) { return r->path; }
int rs_reader_is_compare(const rs_reader *r) { return r->compare; }
int rs_reader_runs(const rs_reader *r) { return r->n_runs; }
const char *rs_reader_run_base(const rs_reader *r, int i)
{
  return i >= 0 && i < r->n_runs ? r->base[i] : NULL;
}
const char *rs_reader_run_name(const rs_reader *r, int i)
{
  return i >= 0 && i < r->n_runs ? r->name[i] : NULL;
}

/* Exists, walking the path one link at a time (H5Lexists fails on a missing parent):
 * 1, 0, or a negative RS_H5_LINK_* (an external or soft link, a damaged group). */
static int exists_quiet(hid_t file, const char *path) { return rs_h5_walk(file, h5path(path)); }

int rs_reader_exists(const rs_reader *r, const char *path)
{
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  int ok = exists_quiet(r->file, path);
  rs_h5_quiet_end(&q);
  /* a refused link or a damaged group is "there": reading it then says what is wrong,
   * where "absent" would let an optional curve vanish silently */
  return ok != 0;
}

/* ---- datasets ------------------------------------------------------------------------- */

/* Opens dataset `path` and checks its rank is at most max_rank; dims[] filled (1 for a
 * scalar's missing dimensions). */
static rs_status open_dataset(const rs_reader *r, const char *path, int max_rank, hid_t *dset,
                              int *rank, hsize_t dims[2])
{
  *dset = -1;
  int there = exists_quiet(r->file, path);
  if (there < 0) return rs_h5_walk_error(&r->bounds, h5path(path), there);
  if (!there) return RS_ERROR(RS_ERR_INPUT, "%s: no dataset '%s'", r->path, h5path(path));
  H5O_info_t info;
  if (H5Oget_info_by_name(r->file, path, &info, H5P_DEFAULT) < 0)
    return RS_ERROR(RS_ERR_INPUT, "%s: '%s': its object header is damaged", r->path, path);
  hid_t d = info.type == H5O_TYPE_DATASET ? H5Dopen2(r->file, path, H5P_DEFAULT) : -1;
  if (d < 0) return RS_ERROR(RS_ERR_INPUT, "%s: '%s' is not a dataset", r->path, path);
  hid_t space = H5Dget_space(d);
  int k = space >= 0 ? H5Sget_simple_extent_ndims(space) : -1;
  hsize_t dd[H5S_MAX_RANK];
  if (k >= 0 && k <= max_rank) H5Sget_simple_extent_dims(space, dd, NULL);
  if (space >= 0) H5Sclose(space);
  if (k < 0 || k > max_rank) {
    H5Dclose(d);
    if (k < 0) return RS_ERROR(RS_ERR_INPUT, "%s: cannot read the shape of '%s'", r->path, path);
    return RS_ERROR(RS_ERR_INPUT, "%s: '%s' has %d dimensions (expected at most %d)", r->path,
                    path, k, max_rank);
  }
  dims[0] = dims[1] = 1;
  for (int i = 0; i < k; ++i) dims[i] = dd[i];
  *rank = k;
  *dset = d;
  return RS_OK;
}

/* Reads all of an open dataset as doubles into a new array of `count` values. */
static rs_status read_all(const rs_reader *r, const char *path, hid_t d, size_t count,
                          double **data)
{
  rs_status st = rs_h5_check_dataset(&r->bounds, path, d, 0);
  if (st != RS_OK) return st;
  *data = malloc((count ? count : 1) * sizeof **data);
  if (!*data) return RS_ERROR(RS_ERR_MEMORY, "out of memory for %zu values of '%s'", count, path);
  if (count > 0 && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, *data) < 0) {
    char detail[512];
    rs_h5_error_detail(detail, sizeof detail);
    free(*data);
    *data = NULL;
    /* a checksum that does not match, a chunk that does not inflate: the file is damaged */
    return RS_ERROR(RS_ERR_INPUT, "%s: cannot read '%s' (damaged): %s", r->path, path, detail);
  }
  return RS_OK;
}

static rs_status read_nd(const rs_reader *r, const char *path, int max_rank, double **data,
                         int *rank, hsize_t dims[2])
{
  hid_t d;
  *data = NULL;
  dims[0] = dims[1] = 1; /* set by open_dataset on success; -O3 cannot see that */
  rs_status st = open_dataset(r, path, max_rank, &d, rank, dims);
  if (st == RS_OK) {
    st = read_all(r, path, d, (size_t)(dims[0] * dims[1]), data);
    H5Dclose(d);
  }
  return st;
}

rs_status rs_reader_read_1d(const rs_reader *r, const char *path, double **data, size_t *n)
{
  int rank;
  hsize_t dims[2];
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  rs_status st = read_nd(r, path, 1, data, &rank, dims);
  rs_h5_quiet_end(&q);
  *n = st == RS_OK ? (size_t)dims[0] : 0;
  return st;
}

rs_status rs_reader_read_2d(const rs_reader *r, const char *path, double **data, size_t *rows,
                            size_t *cols)
{
  int rank = 0;
  hsize_t dims[2];
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  rs_status st = read_nd(r, path, 2, data, &rank, dims);
  rs_h5_quiet_end(&q);
  if (st == RS_OK && rank != 2) {
    free(*data);
    *data = NULL;
    st = RS_ERROR(RS_ERR_INPUT, "%s: '%s' has %d dimensions (expected 2)", r->path, path, rank);
  }
  *rows = st == RS_OK ? (size_t)dims[0] : 0;
  *cols = st == RS_OK ? (size_t)dims[1] : 0;
  return st;
}

rs_status rs_reader_read_scalar(const rs_reader *r, const char *path, double *value)
{
  double *v = NULL;
  size_t n = 0;
  rs_status st = rs_reader_read_1d(r, path, &v, &n);
  if (st == RS_OK && n != 1)
    st = RS_ERROR(RS_ERR_INPUT, "%s: '%s' holds %zu values (expected one)", r->path, path, n);
  if (st == RS_OK) *value = v[0];
  free(v);
  return st;
}

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
      if (!(out[i] = dup_str(v[i] ? v[i] : ""))) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
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
      if (!(out[i] = dup_str(buf + i * (len + 1)))) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
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
  rs_status st = open_dataset(r, path, 1, &d, &rank, dims);
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
  int there = exists_quiet(r->file, p);
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
  if (!(l->names[l->n] = dup_str(name))) return (l->failed = 1), -1;
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
  int there = exists_quiet(r->file, p);
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

/* ---- opening -------------------------------------------------------------------------- */

static rs_status add_run(rs_reader *r, const char *base, const char *name)
{
  char **b = realloc(r->base, (size_t)(r->n_runs + 1) * sizeof *b);
  if (b) r->base = b;
  char **m = realloc(r->name, (size_t)(r->n_runs + 1) * sizeof *m);
  if (m) r->name = m;
  if (!b || !m) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  r->base[r->n_runs] = dup_str(base);
  r->name[r->n_runs] = dup_str(name);
  ++r->n_runs; /* counted even when a copy failed, so close frees what there is */
  if (!r->base[r->n_runs - 1] || !r->name[r->n_runs - 1])
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  return RS_OK;
}

/* The runs of a comparison, in the order of /summary/run (the groups under /runs when a
 * file lacks the summary). */
static rs_status find_runs(rs_reader *r)
{
  char **names = NULL;
  size_t n = 0;
  rs_status st = r->compare && exists_quiet(r->file, "/summary/run")
                     ? rs_reader_read_strings(r, "/summary/run", &names, &n)
                     : rs_reader_children(r, "/runs", &names, &n);
  for (size_t i = 0; st == RS_OK && i < n; ++i) {
    size_t len = strlen(names[i]) + sizeof "/runs/";
    char *base = malloc(len);
    if (!base) {
      st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
      break;
    }
    snprintf(base, len, "/runs/%s", names[i]);
    int there = exists_quiet(r->file, base);
    if (there < 0)
      st = rs_h5_walk_error(&r->bounds, base, there);
    else if (!there)
      st = RS_ERROR(RS_ERR_INPUT, "%s: /summary/run names '%s', which is not there", r->path,
                    base);
    else
      st = add_run(r, base, names[i]);
    free(base);
  }
  rs_reader_free_strings(&names, n);
  if (st == RS_OK && r->n_runs == 0)
    st = RS_ERROR(RS_ERR_INPUT, "%s: a comparison file without runs", r->path);
  return st;
}

/* The file is open (r->file): what the checks need, then is it ours, then its runs. */
static rs_status open_opened(rs_reader *r, hsize_t size)
{
  H5F_info2_t info;
  r->bounds.name = r->path;
  r->bounds.file_size = size;
  r->bounds.checksummed = H5Fget_info2(r->file, &info) >= 0 && info.super.version >= 2;
  char *program = NULL;
  rs_status st = rs_reader_attr_string(r, "/", "program", &program);
  int ours = st == RS_OK && strcmp(program, "reelsim") == 0;
  free(program);
  /* there but unreadable: say so rather than "not a reelsim file" */
  if (st != RS_OK && H5Aexists_by_name(r->file, "/", "program", H5P_DEFAULT) != 0) return st;
  if (!ours)
    return RS_ERROR(RS_ERR_INPUT, "'%s' is an HDF5 file but not a reelsim file (no root "
                                  "attribute program = \"reelsim\")", r->path);
  if ((st = rs_h5_check_metadata(&r->bounds, r->file)) != RS_OK) return st;
  int runs = exists_quiet(r->file, "/runs");
  if (runs < 0) return rs_h5_walk_error(&r->bounds, "/runs", runs);
  r->compare = runs;
  if (r->compare) return find_runs(r);
  /* a run file's one run is named after the file */
  const char *base = strrchr(r->path, '/');
  base = base ? base + 1 : r->path;
  const char *dot = strrchr(base, '.');
  size_t len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
  char *stem = malloc(len + 1);
  if (!stem) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  memcpy(stem, base, len);
  stem[len] = '\0';
  st = add_run(r, "", stem);
  free(stem);
  return st;
}

static rs_status open_file(rs_reader *r)
{
  struct stat sb;
  if (stat(r->path, &sb) != 0)
    return RS_ERROR(RS_ERR_INPUT, "cannot open '%s': %s", r->path, strerror(errno));
  if (S_ISDIR(sb.st_mode)) return RS_ERROR(RS_ERR_INPUT, "'%s' is a directory", r->path);
  htri_t is = H5Fis_hdf5(r->path);
  if (is < 0) return RS_ERROR(RS_ERR_INPUT, "cannot open '%s'", r->path);
  if (is == 0) return RS_ERROR(RS_ERR_INPUT, "'%s' is not an HDF5 file", r->path);
  r->file = H5Fopen(r->path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (r->file < 0) {
    char detail[512];
    rs_h5_error_detail(detail, sizeof detail);
    return RS_ERROR(RS_ERR_INPUT, "cannot open HDF5 file '%s' (damaged?): %s", r->path, detail);
  }
  return open_opened(r, (hsize_t)sb.st_size);
}

static rs_status open_image(rs_reader *r, const void *image, size_t size)
{
  static unsigned long counter;
  char label[64], detail[512];
  /* the name only labels the in-memory file, unique among open files */
  snprintf(label, sizeof label, "reelsim-image-%lu", ++counter);
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl < 0 || H5Pset_fapl_core(fapl, 1 << 16, 0) < 0 ||
      H5Pset_file_image(fapl, (void *)image, size) < 0) {
    if (fapl >= 0) H5Pclose(fapl);
    return RS_ERROR(RS_ERR_IO, "cannot set up an in-memory HDF5 file");
  }
  r->file = H5Fopen(label, H5F_ACC_RDONLY, fapl);
  H5Pclose(fapl);
  if (r->file < 0) {
    rs_h5_error_detail(detail, sizeof detail);
    return RS_ERROR(RS_ERR_INPUT, "cannot open HDF5 file '%s' (damaged?): %s", r->path, detail);
  }
  return open_opened(r, size);
}

/* Opens from the file `path` (image NULL) or from the bytes of image. */
static rs_status reader_open(const char *path, const void *image, size_t size, rs_reader **out)
{
  *out = NULL;
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no file name given");
  rs_reader *r = calloc(1, sizeof *r);
  if (!r || !(r->path = dup_str(path))) {
    free(r);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory opening '%s'", path);
  }
  r->file = -1;
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  rs_status st = image ? open_image(r, image, size) : open_file(r);
  rs_h5_quiet_end(&q);
  if (st != RS_OK) rs_reader_close(&r);
  *out = r;
  return st;
}

rs_status rs_reader_open(const char *path, rs_reader **out)
{
  return reader_open(path, NULL, 0, out);
}

rs_status rs_reader_open_image(const void *image, size_t size, const char *name,
                               rs_reader **out)
{
  if (!image || size == 0) {
    *out = NULL;
    return RS_ERROR(RS_ERR_INPUT, "%s: an empty file", name ? name : "(image)");
  }
  return reader_open(name, image, size, out);
}

rs_status rs_reader_inspect(const rs_reader *r, const char *path, rs_reader_kind *kind, int *rank,
                            size_t dims[2])
{
  hid_t d;
  int k = 0;
  hsize_t dd[2] = {1, 1};
  *kind = RS_READER_OTHER;
  dims[0] = dims[1] = 1;
  *rank = 0;
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  rs_status st = open_dataset(r, path, 2, &d, &k, dd);
  if (st == RS_OK) {
    hid_t type = H5Dget_type(d);
    switch (type >= 0 ? H5Tget_class(type) : H5T_NO_CLASS) {
    case H5T_FLOAT: *kind = RS_READER_FLOAT; break;
    case H5T_INTEGER: *kind = RS_READER_INTEGER; break;
    case H5T_STRING: *kind = RS_READER_STRING; break;
    default: *kind = RS_READER_OTHER; break;
    }
    if (type >= 0) H5Tclose(type);
    H5Dclose(d);
    *rank = k;
    dims[0] = (size_t)dd[0];
    dims[1] = (size_t)dd[1];
  }
  rs_h5_quiet_end(&q);
  return st;
}
