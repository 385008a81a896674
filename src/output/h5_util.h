/* Small HDF5 writing helpers for the output module (internal, not installed).
 *
 * Every helper returns RS_OK or records RS_ERR_IO naming the object ("/layers/radius")
 * and, when HDF5 gave one, its innermost reason ("No space left on device").
 * Strings are fixed-length UTF-8 (NUL-padded): kept inside the checksummed object header
 * or chunk, where a variable-length string's global heap has no checksum. Numbers are
 * little-endian IEEE doubles and 64-bit integers whatever the host. Every dataset is
 * checksummed (rs_h5_dcpl_checked) and the file uses HDF5's newest format, whose
 * metadata carries checksums (rs_h5_memfile_create); docs/output.md, "Checksums". */
#ifndef RS_OUTPUT_H5_UTIL_H
#define RS_OUTPUT_H5_UTIL_H

#include <stddef.h>

#include <hdf5.h>

#include "reelsim/status.h"

/* Turns off HDF5's printing of its error stack on this thread for the lifetime of
 * the guard, restoring whatever handler the caller had afterwards. */
typedef struct rs_h5_quiet {
  H5E_auto2_t func;
  void *data;
  int saved;
} rs_h5_quiet;
void rs_h5_quiet_begin(rs_h5_quiet *q);
void rs_h5_quiet_end(rs_h5_quiet *q);

/* The innermost message on this thread's HDF5 error stack, or "" when there is none.
 * Call straight after the failing HDF5 call: the next HDF5 call clears the stack. */
void rs_h5_error_detail(char *buf, size_t len);

/* An empty HDF5 file in memory (core driver, nothing on disk); close with H5Fclose. */
rs_status rs_h5_memfile_create(hid_t *file);
/* The bytes of the file so far, ready to write out (*image malloc'd, caller frees). */
rs_status rs_h5_memfile_image(hid_t file, void **image, size_t *size);

rs_status rs_h5_attr_string(hid_t obj, const char *name, const char *value);
rs_status rs_h5_attr_double(hid_t obj, const char *name, double value);
rs_status rs_h5_attr_int64(hid_t obj, const char *name, long long value);

/* Creates group `name` under `loc`; the caller closes *out with H5Gclose. */
rs_status rs_h5_group_create(hid_t loc, const char *name, hid_t *out);

/* Datasets of doubles, each with string attributes `units` and `description`. */
rs_status rs_h5_write_scalar(hid_t loc, const char *name, double value, const char *units,
                             const char *description);
rs_status rs_h5_write_1d(hid_t loc, const char *name, const double *data, size_t n,
                         const char *units, const char *description);

/* The same for 64-bit integers (counts); `units` may be "". */
rs_status rs_h5_write_1d_int64(hid_t loc, const char *name, const long long *data, size_t n,
                               const char *units, const char *description);

/* A rows x cols row-major array as a chunked dataset with the Fletcher-32 checksum,
 * shuffled and deflate-compressed (fill value NaN, both dimensions extendable, so a
 * history can grow stage by stage).
 * `data` may hold NaN (e.g. layers not yet wound); rows or cols may be 0. */
rs_status rs_h5_write_2d_chunked(hid_t loc, const char *name, const double *data, size_t rows,
                                 size_t cols, const char *units, const char *description);
/* The same for a history of stresses (stages x layers): deflated only from
 * RS_H5_DEFLATE_MIN_BYTES of values, below stored as they are (their chunks checksummed). */
rs_status rs_h5_write_2d_history(hid_t loc, const char *name, const double *data, size_t rows,
                                 size_t cols, const char *units, const char *description);

/* The chunk shape rs_h5_write_2d_chunked picks: rows cut into equal pieces of at most
 * 4096 columns, as many rows as make about 256 KiB, the rows cut into equal chunks too (so
 * the last chunks, stored and deflated whole, are not mostly fill), so reading one stage
 * or one layer touches few chunks. */
void rs_h5_chunk_shape(size_t rows, size_t cols, hsize_t chunk[2]);

/* A 1-D dataset of fixed-length UTF-8 strings as wide as the longest (h5py reads bytes),
 * `units` "". */
rs_status rs_h5_write_1d_strings(hid_t loc, const char *name, const char *const *strings,
                                 size_t n, const char *description);

/* Bytes per chunk of a chunked dataset: 256 KiB, HDF5's advice is 10 KiB .. 1 MiB. */
#define RS_H5_CHUNK_BYTES 262144

/* Bytes of values from which a history of stresses is compressed. Deflate keeps ~0.4 of
 * such a history's bytes (the stages' NaN beyond the layers wound compress away, the
 * stresses' low mantissa bytes do not) at ~70 instructions a byte: below 1 MiB it would
 * save under 0.6 MiB a dataset for more time than the rest of the file's writing. (The
 * lanes' arrays, alike across lanes, keep ~0.15 - 0.25: always deflated.) */
#define RS_H5_DEFLATE_MIN_BYTES 1048576

/* New dataset creation properties (close with H5Pclose) for data of shape `space`
 * (rank 0..2) and elements of elem_size bytes: chunked with the Fletcher-32 checksum
 * (whole rows, RS_H5_CHUNK_BYTES per chunk), or compact for a scalar or no values (the
 * data then lives in the object header, which carries its own checksum). Every dataset
 * helper here uses it when given H5P_DEFAULT. RS_ERR_IO (nothing recorded) on failure. */
rs_status rs_h5_dcpl_checked(hid_t space, size_t elem_size, hid_t *dcpl);

#endif
