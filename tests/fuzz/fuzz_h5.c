/* libFuzzer target for the HDF5 reader (rs_reader, include/reelsim/reader.h), on files
 * held in memory (rs_reader_open_image: the core driver with the input as its image).
 *
 * The input is an HDF5 file. The reader opens it and the target reads everything the
 * reader can reach, as `plot` and `reelsim.read` would: the attributes of each run, then
 * every dataset under each run's groups (inspected, then read as numbers, a matrix or
 * strings by its kind). The property, for every input: each call returns RS_OK or
 * RS_ERR_INPUT with a non-empty message (any other status, a crash, a leak, a sanitizer
 * report, or more memory than libFuzzer's -rss_limit_mb is a bug). A failure aborts.
 * tests/fuzz/replay.c runs the same function over the kept inputs (h5corpus/) in the
 * normal build. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output/h5_read_check.h" /* rs_reader_open_image */
#include "reelsim/reader.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check(rs_status st, const char *what, const char *path)
{
  if (st == RS_OK) return;
  const char *msg = rs_error_message();
  if (st == RS_ERR_INPUT && msg && msg[0]) return;
  fprintf(stderr, "fuzz_h5: %s '%s': status %s, message '%s', at %s\n", what, path,
          rs_status_name(st), msg ? msg : "(none)", rs_error_where());
  abort();
}

static void read_dataset(const rs_reader *r, const char *path)
{
  rs_reader_kind kind;
  int rank;
  size_t dims[2], n = 0, rows = 0, cols = 0;
  rs_status st = rs_reader_inspect(r, path, &kind, &rank, dims);
  check(st, "inspect", path);
  if (st != RS_OK) return;
  double *v = NULL;
  if (kind == RS_READER_STRING) {
    char **s = NULL;
    check(rs_reader_read_strings(r, path, &s, &n), "read strings", path);
    rs_reader_free_strings(&s, n);
  } else if (rank == 2) {
    check(rs_reader_read_2d(r, path, &v, &rows, &cols), "read 2-D", path);
  } else {
    check(rs_reader_read_1d(r, path, &v, &n), "read 1-D", path);
  }
  rs_reader_free_data(&v);
}

/* Every member of group `path`, down to `depth` levels. */
static void read_group(const rs_reader *r, const char *path, int depth)
{
  char **names = NULL;
  size_t n = 0;
  rs_status st = rs_reader_children(r, path, &names, &n);
  if (st != RS_OK) {
    check(st, "list", path);
    /* not a group: a dataset, then */
    if (depth < 3) read_dataset(r, path);
    return;
  }
  for (size_t i = 0; i < n && i < 64; ++i) {
    size_t len = strlen(path) + strlen(names[i]) + 2;
    char *child = malloc(len);
    if (!child) abort();
    snprintf(child, len, "%s/%s", strcmp(path, "/") == 0 ? "" : path, names[i]);
    if (depth > 0) read_group(r, child, depth - 1);
    free(child);
  }
  rs_reader_free_strings(&names, n);
}

static void read_run(const rs_reader *r, int i)
{
  const char *base = rs_reader_run_base(r, i);
  const char *path = base[0] ? base : "/";
  static const char *const strings[] = {"title", "scene_file", "scene"};
  static const char *const numbers[] = {"layers", "complete", "wall_seconds", "core_pressure"};
  for (size_t k = 0; k < sizeof strings / sizeof *strings; ++k) {
    char *s = NULL;
    rs_status st = rs_reader_attr_string(r, path, strings[k], &s);
    check(st, "attribute", strings[k]);
    rs_reader_free_text(&s);
  }
  for (size_t k = 0; k < sizeof numbers / sizeof *numbers; ++k) {
    double x;
    long long y;
    check(rs_reader_attr_double(r, path, numbers[k], &x), "attribute", numbers[k]);
    check(rs_reader_attr_int64(r, path, numbers[k], &y), "attribute", numbers[k]);
  }
  read_group(r, path, 3);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  rs_reader *r = NULL;
  rs_status st = rs_reader_open_image(data, size, "fuzz.h5", &r);
  check(st, "open", "fuzz.h5");
  if (st == RS_OK && r) {
    int runs = rs_reader_runs(r);
    for (int i = 0; i < runs && i < 16; ++i) read_run(r, i);
    if (rs_reader_is_compare(r)) read_group(r, "/summary", 1);
  } else if (r) {
    fprintf(stderr, "fuzz_h5: a reader handed out on failure\n");
    abort();
  }
  rs_reader_close(&r);
  return 0;
}
