/* The reader's checks before it trusts an object; see h5_read_check.h. Callers have
 * HDF5's error printing off. */
#include "output/h5_read_check.h"
#include "util/error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int rs_h5_walk(hid_t file, const char *path)
{
  if (!path || !path[0] || strcmp(path, "/") == 0) return 1;
  size_t len = strlen(path);
  char *buf = malloc(len + 1);
  if (!buf) return RS_H5_LINK_DAMAGED;
  memcpy(buf, path, len + 1);
  int ok = 1;
  for (size_t i = 1; ok == 1 && i <= len; ++i) {
    if (buf[i] != '/' && buf[i] != '\0') continue;
    char c = buf[i];
    buf[i] = '\0';
    H5L_info_t info;
    htri_t there = H5Lexists(file, buf, H5P_DEFAULT);
    if (there < 0) ok = RS_H5_LINK_DAMAGED;
    else if (there == 0) ok = 0;
    else if (H5Lget_info(file, buf, &info, H5P_DEFAULT) < 0) ok = RS_H5_LINK_DAMAGED;
    else if (info.type != H5L_TYPE_HARD) ok = RS_H5_LINK_REFUSED;
    else {
      htri_t obj = H5Oexists_by_name(file, buf, H5P_DEFAULT);
      ok = obj < 0 ? RS_H5_LINK_DAMAGED : obj > 0;
    }
    buf[i] = c;
  }
  free(buf);
  return ok;
}

rs_status rs_h5_walk_error(const rs_h5_bounds *b, const char *path, int walk)
{
  if (walk == RS_H5_LINK_REFUSED)
    return RS_ERROR(RS_ERR_INPUT,
                    "%s: '%s' goes through an external or soft link, which reelsim never "
                    "writes and does not follow",
                    b->name, path);
  return RS_ERROR(RS_ERR_INPUT, "%s: '%s': the file's structure is damaged (unreadable group)",
                  b->name, path);
}

/* 1 when dcpl's pipeline holds filter `id`. */
/* the id of filter i of the dataset's pipeline (H5Z_FILTER_ERROR when it cannot be read) */
static H5Z_filter_t filter_at(hid_t dcpl, int i)
{
  unsigned flags, cd[8], config;
  size_t ncd = 8;
  char name[64];
  return H5Pget_filter2(dcpl, (unsigned)i, &flags, &ncd, cd, sizeof name, name, &config);
}

static int has_filter(hid_t dcpl, H5Z_filter_t id)
{
  int n = H5Pget_nfilters(dcpl);
  for (int i = 0; i < n; ++i)
    if (filter_at(dcpl, i) == id) return 1;
  return 0;
}

/* The first filter of the dataset's pipeline that is not one reelsim writes (HDF5's own
 * shuffle, deflate and Fletcher-32), or -1: any other would have HDF5 look for a filter
 * library on its plugin path to read the values, code a file would choose */
static int foreign_filter(hid_t dcpl)
{
  int n = H5Pget_nfilters(dcpl);
  if (n < 0) return H5Z_FILTER_ERROR;
  for (int i = 0; i < n; ++i) {
    H5Z_filter_t id = filter_at(dcpl, i);
    if (id != H5Z_FILTER_SHUFFLE && id != H5Z_FILTER_DEFLATE && id != H5Z_FILTER_FLETCHER32)
      return id;
  }
  return -1;
}

/* The type checks shared by datasets and attributes: NULL when fine, else why not. */
static const char *type_problem(const rs_h5_bounds *b, hid_t type, int want_strings)
{
  H5T_class_t cls = type >= 0 ? H5Tget_class(type) : H5T_NO_CLASS;
  size_t size = type >= 0 ? H5Tget_size(type) : 0;
  if (want_strings) {
    if (cls != H5T_STRING) return "is not a string";
    htri_t var = H5Tis_variable_str(type);
    if (var < 0) return "has a damaged string type";
    /* a variable-length string lives in the global heap, which has no checksum */
    if (var > 0 && b->checksummed) return "is a variable-length string, which a checksummed "
                                          "reelsim file never holds";
    if (!var && (size == 0 || size > b->file_size)) return "declares a string longer than the file";
    return NULL;
  }
  if (cls != H5T_FLOAT && cls != H5T_INTEGER) return "does not hold numbers";
  if (size == 0 || size > 8) return "holds numbers of an unsupported size";
  return NULL;
}

/* Deflate gives at most about 1032 bytes for one (RFC 1951's longest match per code);
 * the bound allows a little more. */
enum { RS_H5_MAX_RATIO = 1100 };

static rs_status check_storage(const rs_h5_bounds *b, const char *path, hid_t d, hid_t dcpl,
                               size_t elem, hsize_t npoints)
{
  H5D_layout_t layout = H5Pget_layout(dcpl);
  double raw = (double)npoints * (double)elem;
  if (layout == H5D_COMPACT) return RS_OK; /* the values are inside the object header */
  if (layout == H5D_CHUNKED) {
    hsize_t chunk[H5S_MAX_RANK];
    int k = H5Pget_chunk(dcpl, H5S_MAX_RANK, chunk);
    double bytes = (double)elem;
    for (int i = 0; i < k; ++i) bytes *= (double)chunk[i];
    if (k <= 0 || bytes > (double)RS_H5_MAX_CHUNK)
      return RS_ERROR(RS_ERR_INPUT, "%s: '%s' declares chunks of %.3g bytes (at most %zu): "
                      "damaged", b->name, path, bytes, RS_H5_MAX_CHUNK);
    const int foreign = foreign_filter(dcpl);
    if (foreign != -1)
      return RS_ERROR(RS_ERR_INPUT, "%s: '%s' is filtered by HDF5 filter %d, which reelsim never "
                      "writes (no filter library is loaded to read a file): refused", b->name,
                      path, foreign);
    if (b->checksummed && !has_filter(dcpl, H5Z_FILTER_FLETCHER32))
      return RS_ERROR(RS_ERR_INPUT, "%s: '%s' has no Fletcher-32 checksum, which every "
                      "dataset of a checksummed reelsim file has: damaged", b->name, path);
  } else if (layout != H5D_CONTIGUOUS) {
    return RS_ERROR(RS_ERR_INPUT, "%s: '%s' has a storage layout reelsim never writes",
                    b->name, path);
  } else if (b->checksummed) {
    return RS_ERROR(RS_ERR_INPUT, "%s: '%s' is stored without a checksum, which every "
                    "dataset of a checksummed reelsim file has: damaged", b->name, path);
  }
  if (npoints == 0) return RS_OK;
  double stored = (double)H5Dget_storage_size(d);
  int packed = layout == H5D_CHUNKED && has_filter(dcpl, H5Z_FILTER_DEFLATE);
  double can_hold = packed ? stored * RS_H5_MAX_RATIO : stored;
  if (stored > (double)b->file_size || raw > can_hold)
    return RS_ERROR(RS_ERR_INPUT, "%s: '%s' declares %llu values (%.3g bytes) but the file "
                    "stores %.3g bytes of it (file size %llu): damaged or truncated", b->name,
                    path, (unsigned long long)npoints, raw, stored,
                    (unsigned long long)b->file_size);
  return RS_OK;
}

rs_status rs_h5_check_dataset(const rs_h5_bounds *b, const char *path, hid_t d, int want_strings)
{
  hid_t type = H5Dget_type(d), space = H5Dget_space(d), dcpl = H5Dget_create_plist(d);
  hssize_t npoints = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
  const char *why = type_problem(b, type, want_strings);
  size_t elem = type >= 0 ? H5Tget_size(type) : 0;
  if (type >= 0 && want_strings && H5Tis_variable_str(type) > 0) elem = 16; /* hvl_t */
  rs_status st = RS_OK;
  if (why) st = RS_ERROR(RS_ERR_INPUT, "%s: '%s' %s", b->name, path, why);
  else if (npoints < 0 || dcpl < 0)
    st = RS_ERROR(RS_ERR_INPUT, "%s: '%s': cannot read its shape or layout: damaged", b->name,
                  path);
  else st = check_storage(b, path, d, dcpl, elem, (hsize_t)npoints);
  if (dcpl >= 0) H5Pclose(dcpl);
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  return st;
}

rs_status rs_h5_check_attr(const rs_h5_bounds *b, const char *what, hid_t a, int want_strings)
{
  hid_t type = H5Aget_type(a), space = H5Aget_space(a);
  hssize_t npoints = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
  const char *why = type_problem(b, type, want_strings);
  rs_status st = RS_OK;
  if (why) st = RS_ERROR(RS_ERR_INPUT, "%s: %s %s", b->name, what, why);
  else if (npoints != 1)
    st = RS_ERROR(RS_ERR_INPUT, "%s: %s is not a single %s", b->name, what,
                  want_strings ? "string" : "number");
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  return st;
}

/* ---- the whole file's metadata, once, at opening ---------------------------------------- */

typedef struct walk_ctx {
  const rs_h5_bounds *b;
  hid_t file;
  char where[512]; /* the object being looked at, for the message when HDF5 fails */
  rs_status st;
} walk_ctx;

static herr_t check_link(hid_t g, const char *name, const H5L_info_t *info, void *user)
{
  (void)g;
  walk_ctx *w = user;
  snprintf(w->where, sizeof w->where, "/%s", name);
  if (info->type == H5L_TYPE_HARD) return 0;
  w->st = rs_h5_walk_error(w->b, w->where, RS_H5_LINK_REFUSED);
  return -1;
}

/* Reads attribute `name` of the object at w->where whole (its bytes, in the file's own
 * type), after checking its type and size: HDF5 verifies the checksum of whatever holds it. */
static herr_t check_attr(hid_t obj, const char *name, const H5A_info_t *info, void *user)
{
  (void)info;
  walk_ctx *w = user;
  char what[700];
  snprintf(what, sizeof what, "attribute '%s' of '%s'", name, w->where);
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a < 0) {
    w->st = RS_ERROR(RS_ERR_INPUT, "%s: %s: unreadable (damaged)", w->b->name, what);
    return -1;
  }
  hid_t type = H5Aget_type(a), space = H5Aget_space(a);
  H5T_class_t cls = type >= 0 ? H5Tget_class(type) : H5T_NO_CLASS;
  hssize_t npoints = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
  size_t size = type >= 0 ? H5Tget_size(type) : 0;
  int var = cls == H5T_STRING && H5Tis_variable_str(type) > 0;
  double bytes = (double)size * (double)npoints;
  if (npoints < 0 || size == 0 || bytes > (double)w->b->file_size || (var && w->b->checksummed))
    w->st = RS_ERROR(RS_ERR_INPUT, "%s: %s: a type or size reelsim never writes (damaged)",
                     w->b->name, what);
  else if (!var && w->b->checksummed && npoints > 0) {
    void *buf = malloc((size_t)bytes);
    if (!buf) w->st = RS_ERROR(RS_ERR_MEMORY, "out of memory reading %s", what);
    else if (H5Aread(a, type, buf) < 0)
      w->st = RS_ERROR(RS_ERR_INPUT, "%s: %s: unreadable (damaged)", w->b->name, what);
    free(buf);
  }
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  H5Aclose(a);
  return w->st == RS_OK ? 0 : -1;
}

static herr_t check_object(hid_t root, const char *name, const H5O_info_t *info, void *user)
{
  walk_ctx *w = user;
  int root_itself = name[0] == '.' && !name[1];
  snprintf(w->where, sizeof w->where, "/%s", root_itself ? "" : name);
  if (info->num_attrs == 0) return 0;
  hid_t obj = H5Oopen(root, name, H5P_DEFAULT);
  if (obj < 0) {
    w->st = RS_ERROR(RS_ERR_INPUT, "%s: '%s': unreadable object header (damaged)", w->b->name,
                     w->where);
    return -1;
  }
  hsize_t idx = 0;
  herr_t e = H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_NATIVE, &idx, check_attr, w);
  H5Oclose(obj);
  if (e < 0 && w->st == RS_OK)
    w->st = RS_ERROR(RS_ERR_INPUT, "%s: '%s': its attributes are unreadable (damaged)",
                     w->b->name, w->where);
  return e < 0 ? -1 : 0;
}

rs_status rs_h5_check_metadata(const rs_h5_bounds *b, hid_t file)
{
  walk_ctx w = {.b = b, .file = file, .where = "/", .st = RS_OK};
  if (H5Lvisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, check_link, &w) < 0) {
    if (w.st == RS_OK)
      w.st = RS_ERROR(RS_ERR_INPUT, "%s: the groups are unreadable near '%s' (damaged)", b->name,
                      w.where);
    return w.st;
  }
  snprintf(w.where, sizeof w.where, "/");
  if (H5Ovisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, check_object, &w) < 0 && w.st == RS_OK)
    w.st = RS_ERROR(RS_ERR_INPUT, "%s: the objects are unreadable near '%s' (damaged)", b->name,
                    w.where);
  return w.st;
}
