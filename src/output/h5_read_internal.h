/* The reader's handle and what its files share (h5_read.c: the handle, numbers;
 * h5_read_text.c: strings, attributes, groups; h5_read_open.c: opening, which reads through
 * the other two). Internal, not installed. */
#ifndef RS_OUTPUT_H5_READ_INTERNAL_H
#define RS_OUTPUT_H5_READ_INTERNAL_H

#include <hdf5.h>

#include "output/h5_read_check.h"
#include "reelsim/reader.h"

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
static inline const char *h5path(const char *path) { return path && path[0] ? path : "/"; }

/* A malloc'd copy of s, or NULL */
char *rsi_reader_dup(const char *s);
/* Exists, walking the path one link at a time (H5Lexists fails on a missing parent):
 * 1, 0, or a negative RS_H5_LINK_* (an external or soft link, a damaged group). */
int rsi_reader_exists_quiet(hid_t file, const char *path);
/* Opens dataset `path` and checks its rank is at most max_rank; dims[] filled (1 for a
 * scalar's missing dimensions). */
rs_status rsi_reader_open_dataset(const rs_reader *r, const char *path, int max_rank,
                                  hid_t *dset, int *rank, hsize_t dims[2]);

#endif
