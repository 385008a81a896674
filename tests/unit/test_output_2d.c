/* The HDF5 output's chunked 2-D datasets (/history, /storage, /lanes): what
 * rs_h5_write_2d_chunked writes is what the HDF5 C API reads back, bit for bit, NaN
 * included; the layout is chunked, shuffled and deflated (a history from 1 MiB of values,
 * below stored as it is); the dataset grows with NaN in
 * what was never written; and the chunk shape rule on its own. */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>

#include "check.h"
#include "scratch.h"
#include "output/h5_util.h"
#include "util/atomic_file.h"

enum { ROWS = 37, COLS = 5000 }; /* chunks cut both ways: 37 rows, 5000 > 4096 columns */

/* A history-like array: stage s holds values up to column s N / S, NaN beyond; one -0 */
static double *history_like(void)
{
  double *a = malloc((size_t)ROWS * COLS * sizeof *a);
  if (!a) return NULL;
  for (size_t s = 0; s < ROWS; ++s)
    for (size_t j = 0; j < COLS; ++j)
      a[s * COLS + j] =
          j <= s * COLS / ROWS ? -1.0e5 * (double)(s + 1) / (double)(j + 1) : NAN;
  a[3] = -0.0;
  return a;
}

/* Writes `a` as "sigma_r" and an empty (0 x COLS) "empty" the way rs_output_write does
 * (in-memory file, its image, an atomic write) into a scratch file; *dir and the
 * returned path are the caller's (NULL on failure). */
static char *write_file(const double *a, char **dir)
{
  *dir = scratch_dir("output2d");
  char *path = scratch_join(*dir, "h.h5");
  hid_t f;
  void *image = NULL;
  size_t size = 0;
  CHECK(rs_h5_memfile_create(&f) == RS_OK);
  CHECK(rs_h5_write_2d_chunked(f, "sigma_r", a, ROWS, COLS, "Pa", "history of sigma_r") ==
        RS_OK);
  CHECK(rs_h5_write_2d_chunked(f, "empty", NULL, 0, COLS, "Pa", "no stage yet") == RS_OK);
  CHECK(rs_h5_memfile_image(f, &image, &size) == RS_OK);
  H5Fclose(f);
  CHECK(rs_atomic_file_write(path, image, size) == RS_OK);
  CHECK_LOG("file bytes", size);
  free(image);
  return path;
}

static void cleanup(char *path, char *dir)
{
  free(path);
  scratch_remove_tree(dir);
  free(dir);
}

/* Every value comes back with its bits, NaN and -0 included; the units are stored */
static void chunked_2d_values(void)
{
  double *a = history_like(), *b = malloc((size_t)ROWS * COLS * sizeof *b);
  char *dir, *path = a && b ? write_file(a, &dir) : NULL;
  if (!path) goto done;
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT), d = H5Dopen2(f, "sigma_r", H5P_DEFAULT);
  hid_t space = H5Dget_space(d);
  hsize_t dims[2] = {0, 0};
  CHECK(H5Sget_simple_extent_dims(space, dims, NULL) == 2);
  CHECK(dims[0] == ROWS && dims[1] == COLS);
  CHECK(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, b) >= 0);
  size_t bad = 0, nans = 0;
  for (size_t i = 0; i < (size_t)ROWS * COLS; ++i) {
    bad += memcmp(&a[i], &b[i], sizeof a[i]) != 0;
    nans += isnan(b[i]) != 0;
  }
  CHECK(bad == 0);
  CHECK(nans > (size_t)ROWS * COLS / 3);
  CHECK_LOG("NaN entries", nans);
  char units[8] = "";
  hid_t at = H5Aopen(d, "units", H5P_DEFAULT), mt = H5Tcopy(H5T_C_S1);
  H5Tset_size(mt, sizeof units);
  H5Tset_cset(mt, H5T_CSET_UTF8); /* the writer stores UTF-8 strings */
  CHECK(at >= 0 && H5Aread(at, mt, units) >= 0 && strcmp(units, "Pa") == 0);
  H5Tclose(mt);
  H5Aclose(at);
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  cleanup(path, dir);
done:
  free(a);
  free(b);
}

/* 1 when the dataset creation list has the filter */
static int has_filter(hid_t dcpl, H5Z_filter_t filter)
{
  const int nf = H5Pget_nfilters(dcpl);
  for (int i = 0; i < nf; ++i) {
    unsigned flags, cd[8], fc;
    size_t ncd = 8;
    char fname[64];
    if (H5Pget_filter2(dcpl, (unsigned)i, &flags, &ncd, cd, sizeof fname, fname, &fc) == filter)
      return 1;
  }
  return 0;
}

/* Chunked in equal pieces each way, deflated (smaller than the raw values), checksummed */
static void chunked_2d_layout(void)
{
  double *a = history_like();
  char *dir, *path = a ? write_file(a, &dir) : NULL;
  if (!path) goto done;
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT), d = H5Dopen2(f, "sigma_r", H5P_DEFAULT);
  hid_t dcpl = H5Dget_create_plist(d);
  hsize_t chunk[2] = {0, 0};
  CHECK(H5Pget_layout(dcpl) == H5D_CHUNKED);
  CHECK(H5Pget_chunk(dcpl, 2, chunk) == 2);
  /* 5000 columns in 2 of 2500 (not 4096 + a mostly empty one), 37 rows in 3 of 13
   * (32768 values a chunk) */
  CHECK(chunk[0] == 13 && chunk[1] == 2500);
  CHECK_LOG("chunk rows", chunk[0]);
  CHECK_LOG("chunk cols", chunk[1]);
  CHECK(has_filter(dcpl, H5Z_FILTER_SHUFFLE) && has_filter(dcpl, H5Z_FILTER_DEFLATE));
  CHECK(has_filter(dcpl, H5Z_FILTER_FLETCHER32));
  hsize_t stored = H5Dget_storage_size(d);
  CHECK_LOG("compressed bytes / raw bytes", (double)stored / ((double)ROWS * COLS * 8.0));
  CHECK(stored < (hsize_t)ROWS * COLS * sizeof(double));
  H5Pclose(dcpl);
  H5Dclose(d);
  H5Fclose(f);
  cleanup(path, dir);
done:
  free(a);
}

/* A history compressed from RS_H5_DEFLATE_MIN_BYTES of values on: one value short of it
 * stored as it is (its chunks checksummed, its values back bit for bit), at it deflated;
 * any other 2-D dataset (the lanes') deflated whatever its size */
static void deflate_from_min_bytes(void)
{
  const size_t cols = RS_H5_DEFLATE_MIN_BYTES / sizeof(double);
  double *a = malloc(cols * sizeof *a), *b = malloc(cols * sizeof *b);
  hid_t f = -1;
  if (!a || !b || rs_h5_memfile_create(&f) != RS_OK) {
    CHECK(!"set-up");
    goto done;
  }
  for (size_t j = 0; j < cols; ++j) a[j] = -1.0e5 / (double)(j + 1);
  CHECK(rs_h5_write_2d_history(f, "short", a, 1, cols - 1, "Pa", "one value short") == RS_OK);
  CHECK(rs_h5_write_2d_history(f, "at", a, 1, cols, "Pa", "at the bound") == RS_OK);
  CHECK(rs_h5_write_2d_chunked(f, "lanes", a, 1, cols - 1, "Pa", "not a history") == RS_OK);
  for (int k = 0; k < 3; ++k) {
    static const char *const name[3] = {"short", "at", "lanes"};
    hid_t d = H5Dopen2(f, name[k], H5P_DEFAULT), dcpl = H5Dget_create_plist(d);
    const int deflated = k > 0;
    CHECK(has_filter(dcpl, H5Z_FILTER_DEFLATE) == deflated);
    CHECK(has_filter(dcpl, H5Z_FILTER_SHUFFLE) == deflated);
    CHECK(has_filter(dcpl, H5Z_FILTER_FLETCHER32));
    const size_t n = k == 1 ? cols : cols - 1;
    CHECK(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, b) >= 0);
    CHECK(memcmp(a, b, n * sizeof *a) == 0);
    const hsize_t stored = H5Dget_storage_size(d);
    CHECK_LOG(name[k], (double)stored / (double)(n * sizeof(double)));
    if (deflated) CHECK(stored < n * sizeof(double));
    else CHECK(stored >= n * sizeof(double));
    H5Pclose(dcpl);
    H5Dclose(d);
  }
done:
  if (f >= 0) H5Fclose(f);
  free(a);
  free(b);
}

/* Grown by one stage, the new row reads as NaN (the fill value) until written; a dataset
 * of no stages has 0 rows and its columns */
static void chunked_2d_grow(void)
{
  double *a = history_like(), *row = malloc(COLS * sizeof *row);
  char *dir, *path = a && row ? write_file(a, &dir) : NULL;
  if (!path) goto done;
  hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT), d = H5Dopen2(f, "sigma_r", H5P_DEFAULT);
  hsize_t grown[2] = {ROWS + 1, COLS}, dims[2] = {0, 0};
  CHECK(H5Dset_extent(d, grown) >= 0);
  hid_t fs = H5Dget_space(d);
  hsize_t start[2] = {ROWS, 0}, count[2] = {1, COLS};
  H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL);
  hid_t ms = H5Screate_simple(1, &count[1], NULL);
  CHECK(H5Dread(d, H5T_NATIVE_DOUBLE, ms, fs, H5P_DEFAULT, row) >= 0);
  size_t fill_nans = 0;
  for (size_t j = 0; j < COLS; ++j) fill_nans += isnan(row[j]) != 0;
  CHECK(fill_nans == COLS);
  H5Sclose(ms);
  H5Sclose(fs);
  H5Dclose(d);
  d = H5Dopen2(f, "empty", H5P_DEFAULT);
  CHECK(d >= 0);
  hid_t space = H5Dget_space(d);
  CHECK(H5Sget_simple_extent_dims(space, dims, NULL) == 2 && dims[0] == 0 && dims[1] == COLS);
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  cleanup(path, dir);
done:
  free(a);
  free(row);
}

/* The chunk shape rule on its own: a small array is one chunk, an empty one a 1 x 1
 * chunk, a tall one chunks of at most 256 KiB whole rows wide */
static void chunk_shape_rule(void)
{
  hsize_t chunk[2];
  rs_h5_chunk_shape(10, 20, chunk);
  CHECK(chunk[0] == 10 && chunk[1] == 20);
  rs_h5_chunk_shape(0, 0, chunk);
  CHECK(chunk[0] == 1 && chunk[1] == 1);
  rs_h5_chunk_shape(100000, 100, chunk);
  CHECK(chunk[0] * chunk[1] * sizeof(double) <= 256 * 1024 && chunk[1] == 100);
  CHECK_LOG("tall array: chunk rows", chunk[0]);
}

static const check_case cases[] = {
    {"chunked_2d_values", chunked_2d_values},
    {"chunked_2d_layout", chunked_2d_layout},
    {"chunked_2d_grow", chunked_2d_grow},
    {"chunk_shape_rule", chunk_shape_rule},
    {"deflate_from_min_bytes", deflate_from_min_bytes},
};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
