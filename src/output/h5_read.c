/* Reading reelsim files back (reelsim/reader.h): the handle, numeric datasets, what an
 * object is (strings, attributes and groups: h5_read_text.c; opening: h5_read_open.c).
 * HDF5's error printing is off for every call: a missing dataset is an answer here, not a
 * fault, and the messages we record name the file and the path, which HDF5's stack does
 * not. */
#include "reelsim/reader.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>

#include "output/h5_read_check.h"
#include "output/h5_read_internal.h"
#include "output/h5_util.h"
#include "util/error.h"

char *rsi_reader_dup(const char *s)
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

int rsi_reader_exists_quiet(hid_t file, const char *path)
{
  return rs_h5_walk(file, h5path(path));
}

int rs_reader_exists(const rs_reader *r, const char *path)
{
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  int ok = rsi_reader_exists_quiet(r->file, path);
  rs_h5_quiet_end(&q);
  /* a refused link or a damaged group is "there": reading it then says what is wrong,
   * where "absent" would let an optional curve vanish silently */
  return ok != 0;
}

/* ---- datasets ------------------------------------------------------------------------- */

rs_status rsi_reader_open_dataset(const rs_reader *r, const char *path, int max_rank,
                                  hid_t *dset, int *rank, hsize_t dims[2])
{
  *dset = -1;
  int there = rsi_reader_exists_quiet(r->file, path);
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
  rs_status st = rsi_reader_open_dataset(r, path, max_rank, &d, rank, dims);
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
  rs_status st = rsi_reader_open_dataset(r, path, 2, &d, &k, dd);
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
