/* CSV export of a wound reel (docs/output.md, "CSV files"): the final profile and the
 * wound-on tension per layer, and the history stages when the result has them, one header
 * line, numbers to 17 significant digits so that
 * reading them back gives the same doubles. Both files are built in memory and staged
 * (util/atomic_file.h): each is whole or absent, never half-written. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "util/atomic_file.h"
#include "reelsim/output.h"

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

static rs_status build_profile(const rs_reel_result *res, csv_text *out)
{
  FILE *f = open_memstream(&out->text, &out->size);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV profile");
  fputs("layer,radius_m,sigma_r_Pa,sigma_theta_Pa,pressure_Pa,wound_on_tension_N_per_m\n", f);
  /* layer 1 is the layer on the core; 0 - x keeps an unloaded layer's pressure +0 */
  for (int j = 0; j < res->n_layers; ++j)
    fprintf(f, "%d,%.17g,%.17g,%.17g,%.17g,%.17g\n", j + 1, res->radius[j], res->sigma_r[j],
            res->sigma_theta[j], 0.0 - res->sigma_r[j], res->wound_on_tension[j]);
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV profile");
  return RS_OK;
}

static rs_status build_wot(const rs_reel_result *res, csv_text *out)
{
  FILE *f = open_memstream(&out->text, &out->size);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV tensions");
  fputs("radius_m,web_tension_N_per_m,nip_load_N_per_m,wound_on_tension_N_per_m\n", f);
  for (int j = 0; j < res->n_layers; ++j)
    fprintf(f, "%.17g,%.17g,%.17g,%.17g\n", res->radius[j], res->web_tension[j], res->nip_load[j],
            res->wound_on_tension[j]);
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
  fputs("stage,layers_wound,roll_radius_m,layer,radius_m,sigma_r_Pa,sigma_theta_Pa\n", f);
  for (int s = 0; s < res->n_stages; ++s) {
    const double *sr = res->stage_sigma_r + (size_t)s * (size_t)res->n_layers;
    const double *st = res->stage_sigma_theta + (size_t)s * (size_t)res->n_layers;
    for (int j = 0; j < res->stage_layers[s] && j < res->n_layers; ++j)
      fprintf(f, "%d,%d,%.17g,%d,%.17g,%.17g,%.17g\n", s + 1, res->stage_layers[s],
              res->stage_radius[s], j + 1, res->radius[j], sr[j], st[j]);
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) return RS_ERROR(RS_ERR_MEMORY, "out of memory for the CSV history");
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
  enum { MAX_FILES = 3 };
  static const char *const which[MAX_FILES] = {"wot", "profile", "history"};
  static rs_status (*const build[MAX_FILES])(const rs_reel_result *, csv_text *) = {
      build_wot, build_profile, build_history};
  char path[MAX_FILES][4096];
  char *tmp[MAX_FILES] = {NULL, NULL, NULL};
  csv_text text[MAX_FILES] = {{NULL, 0}, {NULL, 0}, {NULL, 0}};
  if (!res || !name || !name[0]) return RS_ERROR(RS_ERR_INTERNAL, "no result or no name for CSV");
  const int N_FILES = res->n_stages > 0 ? 3 : 2; /* the history when the result has one */
  rs_status st = rs_output_check_csv_dir(dir);
  for (int i = 0; st == RS_OK && i < N_FILES; ++i) {
    st = rs_output_csv_path(dir, name, which[i], path[i], sizeof path[i]);
    if (st == RS_OK) st = rs_atomic_file_check_target(path[i]);
  }
  for (int i = 0; st == RS_OK && i < N_FILES; ++i)
    st = build[i](res, &text[i]);
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
