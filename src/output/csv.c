/* CSV export of a wound reel (docs/output.md, "CSV files"): the final profile and the
 * wound-on tension per layer, and the history stages when the result has them, one header
 * line, numbers in the shortest form that reads back as the same double (util/shortest.h). Both files are built in memory and staged
 * (util/atomic_file.h): each is whole or absent, never half-written. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "reel/result_internal.h"
#include "util/atomic_file.h"
#include "util/shortest.h"
#include "reelsim/output.h"
#include "util/error.h"
#include "storage/storage_result.h"

rs_status rs_output_check_csv_dir(const char *dir)
{
  struct stat sb;
  if (!dir || !dir[0]) return RS_ERROR(RS_ERR_INPUT, "--csv needs a directory");
  if (stat(dir, &sb) != 0) {
    int err = errno;
    return RS_ERROR(RS_ERR_INPUT, "--csv %s: %s", dir,
                    err == ENOENT ? "no such directory (create it first)" : strerror(err));
  }
  if (!S_ISDIR(sb.st_mode)) return RS_ERROR(RS_ERR_INPUT, "--csv %s: not a directory", dir);
  if (access(dir, W_OK | X_OK) != 0)
    return RS_ERROR(RS_ERR_INPUT, "--csv %s: directory is not writable (%s)", dir, strerror(errno));
  return RS_OK;
}

/* Text of one file, built with open_memstream; *text is malloc'd. */
typedef struct csv_text {
  char *text;
  size_t size;
} csv_text;

const char *rs_output_shortest(char *buf, double v)
{
  return rs_shortest(buf, v);
}

/* One number of a row, in its shortest round-trip form, after a comma unless first. */
static void num(FILE *f, double v, int first)
{
  char b[RS_SHORTEST_SIZE];
  fprintf(f, "%s%s", first ? "" : ",", rs_shortest(b, v));
}

static rs_status build_profile(const rs_reel_result *res, csv_text *out)
{
  FILE *f = open_memstream(&out->text, &out->size);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV profile");
  fputs("layer,radius_m,sigma_r_Pa,sigma_theta_Pa,pressure_Pa,wound_on_tension_N_per_m\n", f);
  /* layer 1 is the layer on the core; 0 - x keeps an unloaded layer's pressure +0 */
  for (int j = 0; j < res->n_layers; ++j) {
    fprintf(f, "%d", j + 1);
    num(f, res->radius[j], 0);
    num(f, res->sigma_r[j], 0);
    num(f, res->sigma_theta[j], 0);
    num(f, 0.0 - res->sigma_r[j], 0);
    num(f, res->wound_on_tension[j], 0);
    fputc('\n', f);
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV profile");
  return RS_OK;
}

static rs_status build_wot(const rs_reel_result *res, csv_text *out)
{
  FILE *f = open_memstream(&out->text, &out->size);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV tensions");
  fputs("radius_m,web_tension_N_per_m,nip_load_N_per_m,wound_on_tension_N_per_m\n", f);
  for (int j = 0; j < res->n_layers; ++j) {
    num(f, res->radius[j], 1);
    num(f, res->web_tension[j], 0);
    num(f, res->nip_load[j], 0);
    num(f, res->wound_on_tension[j], 0);
    fputc('\n', f);
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV tensions");
  return RS_OK;
}

/* Long form, one row per wound layer per stage (the layers not yet wound at a stage, NaN
 * in the arrays, are left out): what a data frame reads without reshaping. */
static rs_status build_history(const rs_reel_result *res, csv_text *out)
{
  FILE *f = open_memstream(&out->text, &out->size);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV history");
  fputs("stage,layers_wound,roll_radius_m,layer,radius_m,sigma_r_Pa,sigma_theta_Pa,pressure_Pa\n", f);
  for (int s = 0; s < res->n_stages; ++s) {
    const double *sr = res->stage_sigma_r + (size_t)s * (size_t)res->n_layers;
    const double *st = res->stage_sigma_theta + (size_t)s * (size_t)res->n_layers;
    for (int j = 0; j < res->stage_layers[s] && j < res->n_layers; ++j) {
      fprintf(f, "%d,%d", s + 1, res->stage_layers[s]);
      num(f, res->stage_radius[s], 0);
      fprintf(f, ",%d", j + 1);
      num(f, res->radius[j], 0);
      num(f, sr[j], 0);
      num(f, st[j], 0);
      num(f, 0.0 - sr[j], 0);
      fputc('\n', f);
    }
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV history");
  return RS_OK;
}

/* The storage stages (docs/storage.md) in long form: one row per layer per stage, stage 0
 * the wound roll. The radius is the wound roll's (the stages change stresses only). */
static rs_status build_storage(const rs_reel_result *res, const rs_storage_result *sr, csv_text *out)
{
  FILE *f = open_memstream(&out->text, &out->size);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV storage stages");
  fputs("stage,hours,temperature_C,humidity_pct,core_pressure_Pa,layer,radius_m,sigma_r_Pa,"
        "sigma_theta_Pa,pressure_Pa\n", f);
  const size_t n = (size_t)sr->n_layers;
  for (int s = 0; s < sr->n_stages; ++s)
    for (size_t j = 0; j < n && j < (size_t)res->n_layers; ++j) {
      double r = sr->sigma_r[(size_t)s * n + j];
      fprintf(f, "%d", s);
      num(f, sr->hours[s], 0);
      num(f, sr->temperature[s], 0);
      num(f, sr->humidity[s], 0);
      num(f, sr->core_pressure[s], 0);
      fprintf(f, ",%zu", j + 1);
      num(f, res->radius[j], 0);
      num(f, r, 0);
      num(f, sr->sigma_theta[(size_t)s * n + j], 0);
      num(f, 0.0 - r, 0);
      fputc('\n', f);
    }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV storage stages");
  return RS_OK;
}

rs_status rs_output_csv_path(const char *dir, const char *name, const char *which, char *buf,
                             size_t size)
{
  int n = snprintf(buf, size, "%s%s%s-%s.csv", dir,
                   dir[0] && dir[strlen(dir) - 1] == '/' ? "" : "/", name, which);
  if (n < 0 || (size_t)n >= size)
    return RS_ERROR(RS_ERR_INPUT, "--csv %s: the file name for '%s' is too long", dir, name);
  return RS_OK;
}

rs_status rs_output_write_csv(const char *dir, const char *name, const rs_reel_result *res)
{
  return rs_output_write_csv_stored(dir, name, res, NULL);
}

rs_status rs_output_write_csv_stored(const char *dir, const char *name, const rs_reel_result *res,
                                     const rs_storage_result *storage)
{
  enum { MAX_FILES = 4 };
  const char *which[MAX_FILES] = {"wot", "profile", "history", "storage"};
  char path[MAX_FILES][4096];
  char *tmp[MAX_FILES] = {NULL, NULL, NULL, NULL};
  csv_text text[MAX_FILES] = {{NULL, 0}, {NULL, 0}, {NULL, 0}, {NULL, 0}};
  if (!res || !name || !name[0]) return RS_ERROR(RS_ERR_INTERNAL, "no result or no name for CSV");
  if (storage && (storage->n_stages < 1 || storage->n_layers != res->n_layers))
    return RS_ERROR(RS_ERR_INTERNAL, "storage result of %d layers for a reel of %d",
                    storage->n_layers, res->n_layers);
  /* the history when the result has one, the storage stages when given */
  int N_FILES = 2;
  if (res->n_stages > 0) ++N_FILES;
  else which[2] = "storage";
  if (storage) ++N_FILES;
  rs_status st = rs_output_check_csv_dir(dir);
  for (int i = 0; st == RS_OK && i < N_FILES; ++i) {
    st = rs_output_csv_path(dir, name, which[i], path[i], sizeof path[i]);
    if (st == RS_OK) st = rs_atomic_file_check_target(path[i]);
  }
  for (int i = 0; st == RS_OK && i < N_FILES; ++i) {
    if (which[i][0] == 'w') st = build_wot(res, &text[i]);
    else if (which[i][0] == 'p') st = build_profile(res, &text[i]);
    else if (which[i][0] == 'h') st = build_history(res, &text[i]);
    else st = build_storage(res, storage, &text[i]);
  }
  /* every file to its temporary first, then the renames: a failure before the renames
   * leaves nothing new; only a failing rename (almost never) can leave the first alone */
  for (int i = 0; st == RS_OK && i < N_FILES; ++i)
    st = rs_atomic_file_prepare(path[i], text[i].text, text[i].size, &tmp[i]);
  for (int i = 0; st == RS_OK && i < N_FILES; ++i)
    st = rs_atomic_file_commit(path[i], &tmp[i]);
  for (int i = 0; i < N_FILES; ++i) {
    rs_atomic_file_abort(&tmp[i]);
    free(text[i].text);
  }
  return st;
}
