/* What the reader (h5_read.c) checks before it trusts an object of a file: links, the
 * declared sizes against the file's size, types, and that a file written with checksums
 * has one on every dataset it reads. Internal to the output module; docs/output.md,
 * "Checksums and checks". */
#ifndef RS_OUTPUT_H5_READ_CHECK_H
#define RS_OUTPUT_H5_READ_CHECK_H

#include <stddef.h>

#include <hdf5.h>

#include "reelsim/reader.h"
#include "reelsim/status.h"

/* What the checks need to know of the open file. */
typedef struct rs_h5_bounds {
  const char *name;  /* the file, for messages */
  hsize_t file_size; /* bytes */
  int checksummed;   /* superblock version >= 2: the format whose metadata has checksums */
} rs_h5_bounds;

/* Walks `path` one link at a time: 1 when it names an object reached through hard links
 * only, 0 when a link is missing, RS_H5_LINK_REFUSED when a link on the way is external
 * or soft (never followed), RS_H5_LINK_DAMAGED when HDF5 could not read a group on the
 * way (its checksum failed, for one). */
enum { RS_H5_LINK_REFUSED = -1, RS_H5_LINK_DAMAGED = -2 };
int rs_h5_walk(hid_t file, const char *path);

/* The RS_ERR_INPUT for a walk's negative answer on `path`. */
rs_status rs_h5_walk_error(const rs_h5_bounds *b, const char *path, int walk);

/* Before reading dataset d (at `path`) whole: it holds numbers (want_strings 0: integer
 * or floating point of at most 8 bytes) or fixed-length strings (1; variable-length
 * ones only in a file without checksums), its declared size fits what the file stores
 * (at most the file's size stored, a compression ratio deflate can reach), its chunks are
 * at most RS_H5_MAX_CHUNK bytes, and in a checksummed file it is compact or carries
 * Fletcher-32. RS_ERR_INPUT naming the file and the dataset otherwise. */
#define RS_H5_MAX_CHUNK ((size_t)64 << 20)
rs_status rs_h5_check_dataset(const rs_h5_bounds *b, const char *path, hid_t d, int want_strings);

/* Before reading attribute a (described by `what`): one value (scalar, or one point), of
 * strings (want_strings 1: fixed-length of at most the file's size; variable-length only
 * in a file without checksums) or numbers (integer or floating point of at most 8 bytes). */
rs_status rs_h5_check_attr(const rs_h5_bounds *b, const char *what, hid_t a, int want_strings);

/* Once, at opening: every link of the file is hard (no external or soft link anywhere),
 * every object header and attribute can be read (in a checksummed file each attribute is
 * read whole, so HDF5 verifies the checksum of whatever holds it), of a type and size
 * reelsim writes. The data of datasets is verified as it is read. RS_ERR_INPUT naming the
 * object otherwise. */
rs_status rs_h5_check_metadata(const rs_h5_bounds *b, hid_t file);

/* rs_reader_open for the bytes of an HDF5 file in memory (the fuzzer's entry; `name`
 * stands for the file in messages and names the one run of a run file). */
rs_status rs_reader_open_image(const void *image, size_t size, const char *name,
                               rs_reader **out);

#endif
