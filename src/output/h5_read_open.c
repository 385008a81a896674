/* Reading reelsim files back, opening them (reelsim/reader.h): from a path or from bytes in
 * memory, the checks of h5_read_check.c first, then whether the file is ours, then its runs
 * (a comparison's from /summary/run, read through h5_read_text.c). HDF5's error printing is
 * off for every call, as in h5_read.c. */
#include "reelsim/reader.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <hdf5.h>

#include "output/h5_read_check.h"
#include "output/h5_read_internal.h"
#include "output/h5_util.h"
#include "util/error.h"

static rs_status add_run(rs_reader *r, const char *base, const char *name)
{
  char **b = realloc(r->base, (size_t)(r->n_runs + 1) * sizeof *b);
  if (b) r->base = b;
  char **m = realloc(r->name, (size_t)(r->n_runs + 1) * sizeof *m);
  if (m) r->name = m;
  if (!b || !m) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  r->base[r->n_runs] = rsi_reader_dup(base);
  r->name[r->n_runs] = rsi_reader_dup(name);
  ++r->n_runs; /* counted even when a copy failed, so close frees what there is */
  if (!r->base[r->n_runs - 1] || !r->name[r->n_runs - 1])
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  return RS_OK;
}

/* The runs of a comparison, in the order of /summary/run (the groups under /runs when a
 * file lacks the summary). */
static rs_status find_runs(rs_reader *r)
{
  char **names = NULL;
  size_t n = 0;
  rs_status st = r->compare && rsi_reader_exists_quiet(r->file, "/summary/run")
                     ? rs_reader_read_strings(r, "/summary/run", &names, &n)
                     : rs_reader_children(r, "/runs", &names, &n);
  for (size_t i = 0; st == RS_OK && i < n; ++i) {
    size_t len = strlen(names[i]) + sizeof "/runs/";
    char *base = malloc(len);
    if (!base) {
      st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
      break;
    }
    snprintf(base, len, "/runs/%s", names[i]);
    int there = rsi_reader_exists_quiet(r->file, base);
    if (there < 0)
      st = rs_h5_walk_error(&r->bounds, base, there);
    else if (!there)
      st = RS_ERROR(RS_ERR_INPUT, "%s: /summary/run names '%s', which is not there", r->path,
                    base);
    else
      st = add_run(r, base, names[i]);
    free(base);
  }
  rs_reader_free_strings(&names, n);
  if (st == RS_OK && r->n_runs == 0)
    st = RS_ERROR(RS_ERR_INPUT, "%s: a comparison file without runs", r->path);
  return st;
}

/* The file is open (r->file): what the checks need, then is it ours, then its runs. */
static rs_status open_opened(rs_reader *r, hsize_t size)
{
  H5F_info2_t info;
  r->bounds.name = r->path;
  r->bounds.file_size = size;
  r->bounds.checksummed = H5Fget_info2(r->file, &info) >= 0 && info.super.version >= 2;
  char *program = NULL;
  rs_status st = rs_reader_attr_string(r, "/", "program", &program);
  int ours = st == RS_OK && strcmp(program, "reelsim") == 0;
  free(program);
  /* there but unreadable: say so rather than "not a reelsim file" */
  if (st != RS_OK && H5Aexists_by_name(r->file, "/", "program", H5P_DEFAULT) != 0) return st;
  if (!ours)
    return RS_ERROR(RS_ERR_INPUT, "'%s' is an HDF5 file but not a reelsim file (no root "
                                  "attribute program = \"reelsim\")", r->path);
  if ((st = rs_h5_check_metadata(&r->bounds, r->file)) != RS_OK) return st;
  int runs = rsi_reader_exists_quiet(r->file, "/runs");
  if (runs < 0) return rs_h5_walk_error(&r->bounds, "/runs", runs);
  r->compare = runs;
  if (r->compare) return find_runs(r);
  /* a run file's one run is named after the file */
  const char *base = strrchr(r->path, '/');
  base = base ? base + 1 : r->path;
  const char *dot = strrchr(base, '.');
  size_t len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
  char *stem = malloc(len + 1);
  if (!stem) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  memcpy(stem, base, len);
  stem[len] = '\0';
  st = add_run(r, "", stem);
  free(stem);
  return st;
}

static rs_status open_file(rs_reader *r)
{
  struct stat sb;
  if (stat(r->path, &sb) != 0)
    return RS_ERROR(RS_ERR_INPUT, "cannot open '%s': %s", r->path, strerror(errno));
  if (S_ISDIR(sb.st_mode)) return RS_ERROR(RS_ERR_INPUT, "'%s' is a directory", r->path);
  htri_t is = H5Fis_hdf5(r->path);
  if (is < 0) return RS_ERROR(RS_ERR_INPUT, "cannot open '%s'", r->path);
  if (is == 0) return RS_ERROR(RS_ERR_INPUT, "'%s' is not an HDF5 file", r->path);
  r->file = H5Fopen(r->path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (r->file < 0) {
    char detail[512];
    rs_h5_error_detail(detail, sizeof detail);
    return RS_ERROR(RS_ERR_INPUT, "cannot open HDF5 file '%s' (damaged?): %s", r->path, detail);
  }
  return open_opened(r, (hsize_t)sb.st_size);
}

static rs_status open_image(rs_reader *r, const void *image, size_t size)
{
  static unsigned long counter;
  char label[64], detail[512];
  /* the name only labels the in-memory file, unique among open files */
  snprintf(label, sizeof label, "reelsim-image-%lu", ++counter);
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl < 0 || H5Pset_fapl_core(fapl, 1 << 16, 0) < 0 ||
      H5Pset_file_image(fapl, (void *)image, size) < 0) {
    if (fapl >= 0) H5Pclose(fapl);
    return RS_ERROR(RS_ERR_IO, "cannot set up an in-memory HDF5 file");
  }
  r->file = H5Fopen(label, H5F_ACC_RDONLY, fapl);
  H5Pclose(fapl);
  if (r->file < 0) {
    rs_h5_error_detail(detail, sizeof detail);
    return RS_ERROR(RS_ERR_INPUT, "cannot open HDF5 file '%s' (damaged?): %s", r->path, detail);
  }
  return open_opened(r, size);
}

/* Opens from the file `path` (image NULL) or from the bytes of image. */
static rs_status reader_open(const char *path, const void *image, size_t size, rs_reader **out)
{
  *out = NULL;
  if (!path || !path[0]) return RS_ERROR(RS_ERR_INPUT, "no file name given");
  rs_reader *r = calloc(1, sizeof *r);
  if (!r || !(r->path = rsi_reader_dup(path))) {
    free(r);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory opening '%s'", path);
  }
  r->file = -1;
  rs_h5_quiet q;
  rs_h5_quiet_begin(&q);
  rs_status st = image ? open_image(r, image, size) : open_file(r);
  rs_h5_quiet_end(&q);
  if (st != RS_OK) rs_reader_close(&r);
  *out = r;
  return st;
}

rs_status rs_reader_open(const char *path, rs_reader **out)
{
  return reader_open(path, NULL, 0, out);
}

rs_status rs_reader_open_image(const void *image, size_t size, const char *name,
                               rs_reader **out)
{
  if (!image || size == 0) {
    *out = NULL;
    return RS_ERROR(RS_ERR_INPUT, "%s: an empty file", name ? name : "(image)");
  }
  return reader_open(name, image, size, out);
}
