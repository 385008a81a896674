/* Reading reelsim HDF5 files back: run files (rs_output_write) and comparison files
 * (rs_output_write_compare). docs/output.md describes the layout.
 *
 * A file holds one or more runs. Run i's datasets live under rs_reader_run_base(r, i):
 * "" for a run file (so its final pressure is "/final/pressure"), "/runs/<name>" for a
 * comparison ("/runs/1-rider/final/pressure"). Paths are absolute HDF5 paths; "" and "/"
 * both mean the root group.
 *
 * Errors: a missing file, a file that is not HDF5, an HDF5 file that reelsim did not
 * write (no root attribute program = "reelsim"), or a dataset that is not there or not
 * of the asked shape are RS_ERR_INPUT naming the file (and the path); HDF5 failures
 * while reading are RS_ERR_IO. HDF5 is not thread-safe in this build: use a reader from
 * one thread at a time. */
#ifndef REELSIM_READER_H
#define REELSIM_READER_H

#include <stddef.h>

#include "reelsim/status.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

typedef struct rs_reader rs_reader;

rs_status rs_reader_open(const char *path, rs_reader **out);
void rs_reader_close(rs_reader **r); /* accepts NULL and *r == NULL */

const char *rs_reader_path(const rs_reader *r);
/* 1 for a comparison file (it has /runs), 0 for a run file. */
int rs_reader_is_compare(const rs_reader *r);
/* Runs in the file (1 for a run file), in run order (/summary/run of a comparison). */
int rs_reader_runs(const rs_reader *r);
/* Group of run i: "" (the root) or "/runs/<name>". */
const char *rs_reader_run_base(const rs_reader *r, int i);
/* Short name of run i: the group name of a comparison run ("1-rider"), or the file name
 * without directory and extension for a run file. */
const char *rs_reader_run_name(const rs_reader *r, int i);

/* 1 when `path` names a dataset or group, 0 when not (also when a parent is missing). */
int rs_reader_exists(const rs_reader *r, const char *path);

/* A 1-D dataset (any numeric type, converted to double; a scalar counts as 1 value).
 * *data is malloc'd (never NULL on success, even for 0 values); the caller frees it
 * (free, or rs_reader_free_data from a language without the C library's free).
 *
 * Every read first checks what it is about to trust (docs/output.md, "Checksums and
 * checks"): only hard links are followed (an external or soft link is refused), the
 * declared size must fit what the file stores before anything is allocated, types and
 * sizes of attributes are checked before they are read, and in a file written with
 * checksums every dataset must carry one, which HDF5 verifies as it reads. A file that
 * fails any of these is RS_ERR_INPUT naming the file and the dataset or attribute. */
rs_status rs_reader_read_1d(const rs_reader *r, const char *path, double **data, size_t *n);
/* Frees what rs_reader_read_1d/_2d returned and sets *data to NULL (NULL accepted). */
void rs_reader_free_data(double **data);

/* What dataset `path` holds, without reading it: its kind, rank (0 for a scalar, 1, 2)
 * and dims (1 for missing dimensions). RS_ERR_INPUT when it is no dataset (or refused,
 * as a read would be) or has more than 2 dimensions. */
typedef enum rs_reader_kind {
  RS_READER_OTHER = 0, /* compound (complex), enum (bool), ...: nothing reelsim writes */
  RS_READER_FLOAT = 1,
  RS_READER_INTEGER = 2,
  RS_READER_STRING = 3
} rs_reader_kind;
rs_status rs_reader_inspect(const rs_reader *r, const char *path, rs_reader_kind *kind, int *rank,
                            size_t dims[2]);

/* A 2-D dataset, row-major, rows x cols doubles. */
rs_status rs_reader_read_2d(const rs_reader *r, const char *path, double **data, size_t *rows,
                            size_t *cols);
/* A scalar dataset (or a 1-D dataset of one value). */
rs_status rs_reader_read_scalar(const rs_reader *r, const char *path, double *value);
/* A 1-D dataset of strings (variable or fixed length); free with rs_reader_free_strings. */
rs_status rs_reader_read_strings(const rs_reader *r, const char *path, char ***strings,
                                 size_t *n);
void rs_reader_free_strings(char ***strings, size_t n);

/* Attribute `name` of the object at `path` (group or dataset). The string is malloc'd.
 * RS_ERR_INPUT when the object or attribute is missing or not of the asked kind. */
rs_status rs_reader_attr_string(const rs_reader *r, const char *path, const char *name,
                                char **value);
/* Frees a string rs_reader_attr_string returned and sets *text to NULL (NULL accepted). */
void rs_reader_free_text(char **text);
rs_status rs_reader_attr_double(const rs_reader *r, const char *path, const char *name,
                                double *value);
rs_status rs_reader_attr_int64(const rs_reader *r, const char *path, const char *name,
                               long long *value);

/* Names of the members of group `path`, sorted so that names that are whole numbers come
 * first in numeric order ("2" before "10"), then the rest alphabetically. Free with
 * rs_reader_free_strings. RS_ERR_INPUT when `path` is not a group. */
rs_status rs_reader_children(const rs_reader *r, const char *path, char ***names, size_t *n);

RS_END_DECLS
#endif
