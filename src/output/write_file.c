/* rs_output_write_file: the atomic writer (util/atomic_file.h) for the applications. */
#include "reelsim/output.h"

#include "util/atomic_file.h"

rs_status rs_output_write_file(const char *path, const void *data, size_t size)
{
  if (!path || (!data && size > 0))
    return RS_ERROR(RS_ERR_INPUT, "rs_output_write_file: no path or no data");
  rs_status st = rs_atomic_file_check_target(path);
  if (st == RS_OK) st = rs_atomic_file_write(path, data, size);
  return st;
}
