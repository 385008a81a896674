/* rs_output_write_file: the atomic writer (util/atomic_file.h) for the applications. */
#include "reelsim/output.h"

#include <stdlib.h>

#include "output/h5_util.h"
#include "util/atomic_file.h"
#include "util/error.h"

rs_status rs_output_write_file(const char *path, const void *data, size_t size)
{
  if (!path || (!data && size > 0))
    return RS_ERROR(RS_ERR_INPUT, "rs_output_write_file: no path or no data");
  rs_status st = rs_atomic_file_check_target(path);
  if (st == RS_OK) st = rs_atomic_file_write(path, data, size);
  return st;
}

/* hid_t is int64_t from HDF5 1.10 on; the public header spells it so to stay free of
 * hdf5.h. */
_Static_assert(sizeof(hid_t) == sizeof(int64_t), "hid_t is a 64-bit integer");

rs_status rs_output_write_h5(const char *path, int (*fill)(int64_t file, void *user), void *user)
{
  if (!path || !fill) return RS_ERROR(RS_ERR_INPUT, "rs_output_write_h5: no path or no fill");
  hid_t file = -1;
  rs_status st = rs_h5_memfile_create(&file);
  if (st != RS_OK) return st;
  void *image = NULL;
  size_t size = 0;
  H5E_auto2_t func;
  void *data;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  if (fill((int64_t)file, user) != 0)
    st = RS_ERROR(RS_ERR_IO, "%s: cannot build the HDF5 file", path);
  else
    st = rs_h5_memfile_image(file, &image, &size);
  if (H5Fclose(file) < 0 && st == RS_OK)
    st = RS_ERROR(RS_ERR_IO, "%s: cannot close the in-memory HDF5 file", path);
  H5Eset_auto2(H5E_DEFAULT, func, data);
  if (st == RS_OK) st = rs_output_write_file(path, image, size);
  free(image);
  return st;
}
