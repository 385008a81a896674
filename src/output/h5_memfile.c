/* An HDF5 file built in memory (core driver, no backing store) and taken out as bytes.
 *
 * Why not let HDF5 write the file: in HDF5 1.10 an H5Fclose that fails to write (disk
 * full) leaves a dangling file identifier that crashes the program at exit (fixed only
 * in 1.14.1), and our own write() gives plain errno reasons. The price is memory: the
 * file twice over, briefly, at the end. */

#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

#include "output/h5_util.h"

rs_status rs_h5_memfile_create(hid_t *file)
{
  static atomic_ulong counter;
  char detail[512], label[64];
  /* The name only labels the in-memory file, but must be unique among open files. */
  snprintf(label, sizeof label, "reelsim-in-memory-%lu", atomic_fetch_add(&counter, 1));
  *file = -1;
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl < 0 || H5Pset_fapl_core(fapl, (size_t)1 << 20, 0) < 0) {
    rs_h5_error_detail(detail, sizeof detail);
    if (fapl >= 0) H5Pclose(fapl);
    return RS_ERROR(RS_ERR_IO, "cannot set up an in-memory HDF5 file: %s", detail);
  }
  *file = H5Fcreate(label, H5F_ACC_EXCL, H5P_DEFAULT, fapl);
  if (*file < 0) rs_h5_error_detail(detail, sizeof detail);
  H5Pclose(fapl);
  if (*file < 0) return RS_ERROR(RS_ERR_IO, "cannot create an in-memory HDF5 file: %s", detail);
  return RS_OK;
}

rs_status rs_h5_memfile_image(hid_t file, void **image, size_t *size)
{
  char detail[512];
  ssize_t n = -1;
  *image = NULL;
  *size = 0;
  /* H5Fget_file_image of 1.10 does not flush first: without this the image lacks the
   * metadata still in the cache (and chunks in the chunk cache) and is no valid file. */
  if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0 || (n = H5Fget_file_image(file, NULL, 0)) < 0) {
    rs_h5_error_detail(detail, sizeof detail);
    return RS_ERROR(RS_ERR_IO, "cannot finish the in-memory HDF5 file: %s", detail);
  }
  if (!(*image = malloc(n > 0 ? (size_t)n : 1)))
    return RS_ERROR(RS_ERR_MEMORY, "out of memory for a %zd-byte HDF5 file", n);
  if (H5Fget_file_image(file, *image, (size_t)n) != n) {
    rs_h5_error_detail(detail, sizeof detail);
    free(*image);
    *image = NULL;
    return RS_ERROR(RS_ERR_IO, "cannot copy the in-memory HDF5 file: %s", detail);
  }
  *size = (size_t)n;
  return RS_OK;
}
