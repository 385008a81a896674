/* HDF5 writing helpers; see h5_util.h. Each helper closes everything it opened on
 * every path, so a failed write leaks no HDF5 identifiers. */
#include "output/h5_util.h"
#include "util/error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void rs_h5_quiet_begin(rs_h5_quiet *q)
{
  q->saved = H5Eget_auto2(H5E_DEFAULT, &q->func, &q->data) >= 0;
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

void rs_h5_quiet_end(rs_h5_quiet *q)
{
  if (q->saved) H5Eset_auto2(H5E_DEFAULT, q->func, q->data);
}

enum { RS_H5_DETAIL_LEN = 512 };

static herr_t innermost_cb(unsigned n, const H5E_error2_t *err, void *client)
{
  (void)n;
  /* Walking downward, the last entry is the deepest: the one that says why. */
  if (err->desc) snprintf((char *)client, RS_H5_DETAIL_LEN, "%s", err->desc);
  return 0;
}

void rs_h5_error_detail(char *buf, size_t len)
{
  char deep[RS_H5_DETAIL_LEN] = "";
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, innermost_cb, deep);
  /* A system call failure carries "..., error message = 'No space left on device', ...":
   * that part is what a user can act on; the rest is file offsets. */
  const char *key = "error message = '";
  const char *p = strstr(deep, key);
  if (p) {
    p += strlen(key);
    const char *q = strchr(p, '\'');
    int m = q ? (int)(q - p) : (int)strlen(p);
    snprintf(buf, len, "%.*s", m, p);
  } else {
    snprintf(buf, len, "%s", deep);
  }
}

/* Records the failure of `what` on object `name` under `loc`, reading HDF5's reason
 * before any other HDF5 call clears it. */
static rs_status h5_fail(const char *func, int line, hid_t loc, const char *name,
                         const char *what)
{
  char detail[512], where[1024] = "";
  rs_h5_error_detail(detail, sizeof detail);
  if (H5Iget_name(loc, where, sizeof where) <= 0) where[0] = '\0';
  size_t w = strlen(where);
  if (w > 0 && where[w - 1] == '/') where[--w] = '\0';
  return rs_error_set(RS_ERR_IO, func, __FILE__, line, "cannot %s '%s/%s'%s%s", what, where,
                      name, detail[0] ? ": " : "", detail);
}
#define H5_FAIL(loc, name, what) h5_fail(__func__, __LINE__, (loc), (name), (what))

/* Writes a scalar attribute of file type `ftype` from memory of type `mtype`. */
static rs_status attr_scalar(hid_t obj, const char *name, hid_t ftype, hid_t mtype,
                             const void *value)
{
  rs_status st = RS_OK;
  hid_t space = -1, attr = -1;
  if ((space = H5Screate(H5S_SCALAR)) < 0 ||
      (attr = H5Acreate2(obj, name, ftype, space, H5P_DEFAULT, H5P_DEFAULT)) < 0 ||
      H5Awrite(attr, mtype, value) < 0)
    st = H5_FAIL(obj, name, "write attribute");
  if (attr >= 0) H5Aclose(attr);
  if (space >= 0) H5Sclose(space);
  return st;
}

/* A fixed-length UTF-8 string type of `len` bytes (at least 1), padded with NULs. */
static hid_t fixed_string_type(size_t len)
{
  hid_t type = H5Tcopy(H5T_C_S1);
  if (type >= 0 && (H5Tset_size(type, len ? len : 1) < 0 || H5Tset_cset(type, H5T_CSET_UTF8) < 0 ||
                    H5Tset_strpad(type, H5T_STR_NULLPAD) < 0)) {
    H5Tclose(type);
    type = -1;
  }
  return type;
}

rs_status rs_h5_attr_string(hid_t obj, const char *name, const char *value)
{
  const char *v = value ? value : "";
  hid_t type = fixed_string_type(strlen(v));
  if (type < 0) return H5_FAIL(obj, name, "make the string type for attribute");
  rs_status st = attr_scalar(obj, name, type, type, v); /* "" has the one NUL byte of size 1 */
  H5Tclose(type);
  return st;
}

rs_status rs_h5_attr_double(hid_t obj, const char *name, double value)
{
  return attr_scalar(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

rs_status rs_h5_attr_int64(hid_t obj, const char *name, long long value)
{
  return attr_scalar(obj, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, &value);
}

rs_status rs_h5_group_create(hid_t loc, const char *name, hid_t *out)
{
  *out = H5Gcreate2(loc, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  return *out < 0 ? H5_FAIL(loc, name, "create group") : RS_OK;
}

/* Creates and fills one dataset (file type ftype, memory type mtype) and gives it units
 * and description. */
static rs_status write_typed(hid_t loc, const char *name, hid_t ftype, hid_t mtype, hid_t space,
                             hid_t dcpl, const void *data, const char *units,
                             const char *description)
{
  rs_status st = RS_OK;
  hid_t own = -1;
  if (dcpl == H5P_DEFAULT) {
    if (rs_h5_dcpl_checked(space, H5Tget_size(ftype), &own) != RS_OK)
      return H5_FAIL(loc, name, "set up the checksummed layout for");
    dcpl = own;
  }
  hid_t dset = H5Dcreate2(loc, name, ftype, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  if (own >= 0) H5Pclose(own);
  if (dset < 0) return H5_FAIL(loc, name, "create dataset");
  if (H5Sget_simple_extent_npoints(space) > 0 &&
      H5Dwrite(dset, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    st = H5_FAIL(loc, name, "write dataset");
  if (st == RS_OK) st = rs_h5_attr_string(dset, "units", units);
  if (st == RS_OK) st = rs_h5_attr_string(dset, "description", description);
  if (H5Dclose(dset) < 0 && st == RS_OK) st = H5_FAIL(loc, name, "close dataset");
  return st;
}

static rs_status write_doubles(hid_t loc, const char *name, hid_t space, hid_t dcpl,
                               const double *data, const char *units, const char *description)
{
  return write_typed(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space, dcpl, data, units,
                     description);
}

rs_status rs_h5_write_scalar(hid_t loc, const char *name, double value, const char *units,
                             const char *description)
{
  hid_t space = H5Screate(H5S_SCALAR);
  if (space < 0) return H5_FAIL(loc, name, "make the dataspace for");
  rs_status st = write_doubles(loc, name, space, H5P_DEFAULT, &value, units, description);
  H5Sclose(space);
  return st;
}

rs_status rs_h5_write_1d(hid_t loc, const char *name, const double *data, size_t n,
                         const char *units, const char *description)
{
  hsize_t dims[1] = {n};
  hid_t space = H5Screate_simple(1, dims, NULL);
  if (space < 0) return H5_FAIL(loc, name, "make the dataspace for");
  rs_status st = write_doubles(loc, name, space, H5P_DEFAULT, data, units, description);
  H5Sclose(space);
  return st;
}

rs_status rs_h5_write_1d_int64(hid_t loc, const char *name, const long long *data, size_t n,
                               const char *units, const char *description)
{
  hsize_t dims[1] = {n};
  hid_t space = H5Screate_simple(1, dims, NULL);
  if (space < 0) return H5_FAIL(loc, name, "make the dataspace for");
  rs_status st = write_typed(loc, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, space, H5P_DEFAULT, data,
                             units, description);
  H5Sclose(space);
  return st;
}

void rs_h5_chunk_shape(size_t rows, size_t cols, hsize_t chunk[2])
{
  const size_t target = RS_H5_CHUNK_BYTES / sizeof(double); /* HDF5 advises 10 KiB .. 1 MiB */
  /* as many chunks as each dimension needs, of equal size, so that the last ones, stored
   * (and deflated) whole, are not mostly fill: 13 x 6054 stresses took 2 x 2 chunks of
   * 8 x 4096 (1.7x the data), now 2 x 2 of 7 x 3027 (1.08x) */
  size_t nc = (cols + 4095) / 4096;
  size_t c = nc ? (cols + nc - 1) / nc : 1;
  size_t r = target / c;
  if (r > rows) r = rows;
  if (r == 0) r = 1;
  size_t nr = (rows + r - 1) / r;
  if (nr > 0) r = (rows + nr - 1) / nr;
  chunk[0] = r ? r : 1;
  chunk[1] = c;
}

static rs_status write_2d(hid_t loc, const char *name, const double *data, size_t rows,
                          size_t cols, const char *units, const char *description,
                          double deflate_min_bytes)
{
  rs_status st = RS_OK;
  hsize_t dims[2] = {rows, cols}, maxdims[2] = {H5S_UNLIMITED, H5S_UNLIMITED}, chunk[2];
  const double fill = NAN;
  hid_t space = -1, dcpl = -1;
  rs_h5_chunk_shape(rows, cols, chunk);
  if ((space = H5Screate_simple(2, dims, maxdims)) < 0 ||
      (dcpl = H5Pcreate(H5P_DATASET_CREATE)) < 0 || H5Pset_chunk(dcpl, 2, chunk) < 0 ||
      H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &fill) < 0) {
    st = H5_FAIL(loc, name, "set up the chunked layout for");
  } else if ((double)rows * (double)cols * sizeof(double) >= deflate_min_bytes &&
             H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
    /* Shuffle groups the bytes of the doubles by significance: deflate then finds the
     * repeated exponents. Without zlib the data is still written, just uncompressed.
     * Level 1: a stress history's bytes within 1 % of level 4's for a third of the time. */
    if (H5Pset_shuffle(dcpl) < 0 || H5Pset_deflate(dcpl, 1) < 0)
      st = H5_FAIL(loc, name, "set up compression for");
  }
  /* last in the pipeline: the checksum covers the bytes as stored */
  if (st == RS_OK && H5Pset_fletcher32(dcpl) < 0) st = H5_FAIL(loc, name, "set up the checksum for");
  if (st == RS_OK) st = write_doubles(loc, name, space, dcpl, data, units, description);
  if (dcpl >= 0) H5Pclose(dcpl);
  if (space >= 0) H5Sclose(space);
  return st;
}

rs_status rs_h5_write_2d_chunked(hid_t loc, const char *name, const double *data, size_t rows,
                                 size_t cols, const char *units, const char *description)
{
  return write_2d(loc, name, data, rows, cols, units, description, 0.0);
}

rs_status rs_h5_write_2d_history(hid_t loc, const char *name, const double *data, size_t rows,
                                 size_t cols, const char *units, const char *description)
{
  return write_2d(loc, name, data, rows, cols, units, description, RS_H5_DEFLATE_MIN_BYTES);
}

rs_status rs_h5_write_1d_strings(hid_t loc, const char *name, const char *const *strings,
                                 size_t n, const char *description)
{
  hsize_t dims[1] = {n};
  size_t width = 1;
  for (size_t i = 0; i < n; ++i) {
    size_t len = strings[i] ? strlen(strings[i]) : 0;
    if (len > width) width = len;
  }
  char *packed = calloc(n ? n : 1, width);
  if (!packed) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the strings of '%s'", name);
  for (size_t i = 0; i < n; ++i)
    if (strings[i]) memcpy(packed + i * width, strings[i], strlen(strings[i]));
  hid_t type = fixed_string_type(width), space = -1;
  rs_status st = RS_OK;
  if (type < 0 || (space = H5Screate_simple(1, dims, NULL)) < 0)
    st = H5_FAIL(loc, name, "make the string type or dataspace for");
  if (st == RS_OK)
    st = write_typed(loc, name, type, type, space, H5P_DEFAULT, packed, "", description);
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  free(packed);
  return st;
}

rs_status rs_h5_dcpl_checked(hid_t space, size_t elem_size, hid_t *dcpl)
{
  hsize_t dims[H5S_MAX_RANK];
  int rank = H5Sget_simple_extent_ndims(space);
  hssize_t npoints = H5Sget_simple_extent_npoints(space);
  *dcpl = H5Pcreate(H5P_DATASET_CREATE);
  if (*dcpl < 0 || rank < 0 || npoints < 0 || rank > 2) goto fail;
  if (rank == 0 || npoints == 0) {
    /* nothing to chunk: the value (or the bare shape) lives in the object header */
    if (H5Pset_layout(*dcpl, H5D_COMPACT) < 0) goto fail;
    return RS_OK;
  }
  H5Sget_simple_extent_dims(space, dims, NULL);
  hsize_t chunk[2];
  if (rank == 1) {
    /* as many chunks as the size needs, of equal length: the last one, stored whole, is
     * then not mostly padding (100 000 values: 4 x 25 000, not 4 x 32 768) */
    hsize_t per = (hsize_t)RS_H5_CHUNK_BYTES / (elem_size ? elem_size : 1);
    if (per == 0) per = 1;
    hsize_t count = (dims[0] + per - 1) / per;
    chunk[0] = (dims[0] + count - 1) / count;
  } else {
    rs_h5_chunk_shape((size_t)dims[0], (size_t)dims[1], chunk);
  }
  if (H5Pset_chunk(*dcpl, rank, chunk) < 0 || H5Pset_fletcher32(*dcpl) < 0) goto fail;
  return RS_OK;
fail:
  if (*dcpl >= 0) H5Pclose(*dcpl);
  *dcpl = -1;
  return RS_ERR_IO;
}
