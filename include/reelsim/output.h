/* HDF5 output of a wound reel (serial HDF5 1.10). See docs/output.md for the layout. */
#ifndef REELSIM_OUTPUT_H
#define REELSIM_OUTPUT_H

#include <stddef.h>
#include <stdint.h>

#include "reelsim/reel.h"
#include "reelsim/scene.h"
#include "reelsim/status.h"
#include "reelsim/storage.h"

#include "reelsim/export.h"
RS_BEGIN_DECLS

/* Writes the result to `path`: first to a temporary name beside it, renamed onto
 * `path` only when complete, so a failed run never leaves a file that looks whole. */
rs_status rs_output_write(const char *path, const rs_scene *scene, const rs_reel_result *res);
/* The same with the storage stages (rs_storage_run) under /storage (docs/output.md);
 * storage NULL: exactly rs_output_write. */
rs_status rs_output_write_stored(const char *path, const rs_scene *scene,
                                 const rs_reel_result *res, const rs_storage_result *storage);
/* The same with the defect report the caller already has (rs_scene_assess_defects, or
 * rs_defects_assess with rs_defect_limits_from_problem of the scene's problem) written
 * under /defects instead of assessing the reel again (O(N x modes) on a long reel);
 * defects NULL: exactly rs_output_write_stored. */
rs_status rs_output_write_assessed(const char *path, const rs_scene *scene,
                                   const rs_reel_result *res, const rs_storage_result *storage,
                                   const rs_defect_report *defects);

/* CSV export (docs/output.md): writes DIR/<name>-profile.csv (layer, radius_m, sigma_r_Pa,
 * sigma_theta_Pa, pressure_Pa, wound_on_tension_N_per_m) and DIR/<name>-wot.csv (radius_m,
 * web_tension_N_per_m, nip_load_N_per_m, wound_on_tension_N_per_m): a header line, one row
 * per layer, each number the shortest that reads back as the same double; and when the result has history stages, DIR/<name>-history.csv (stage,
 * layers_wound, roll_radius_m, layer, radius_m, sigma_r_Pa, sigma_theta_Pa: one row per
 * wound layer per stage). Each file goes to a temporary that is renamed into place only
 * when all are complete. DIR must be an existing, writable directory (RS_ERR_INPUT). */
rs_status rs_output_write_csv(const char *dir, const char *name, const rs_reel_result *res);
/* The same, and with a storage result (rs_storage_run; NULL: exactly rs_output_write_csv)
 * also DIR/<name>-storage.csv (stage, hours, temperature_C, humidity_pct, core_pressure_Pa,
 * layer, radius_m, sigma_r_Pa, sigma_theta_Pa, pressure_Pa: one row per layer per stage,
 * stage 0 the wound roll). Numbers in the CSV files are the shortest form that reads back
 * as the same double. */
rs_status rs_output_write_csv_stored(const char *dir, const char *name, const rs_reel_result *res,
                                     const rs_storage_result *storage);
/* The check rs_output_write_csv starts with, for callers that want it before winding. */
rs_status rs_output_check_csv_dir(const char *dir);
/* DIR/<name>-<which>.csv into buf (RS_ERR_INPUT when it does not fit). */
rs_status rs_output_csv_path(const char *dir, const char *name, const char *which, char *buf,
                             size_t size);

/* v in the shortest decimal form that reads back as the same double, as reelsim's CSV
 * files write numbers ("0.07622", "150"); buf of at least 32 bytes. Returns buf. */
const char *rs_output_shortest(char *buf, double v);

/* The check every writer starts with, for callers that want it before a long run:
 * RS_ERR_IO naming `path` when its directory is missing, not a directory or not
 * writable, or `path` is a directory or a device. */
rs_status rs_output_check_target(const char *path);

/* Writes `size` bytes to `path` the way every reelsim output is written: to a new
 * temporary "<path>.tmp.<pid>.<n>" beside it (O_EXCL | O_NOFOLLOW, so never through a
 * planted symlink), flushed to disk (fsync) and renamed onto `path`; the temporaries a
 * killed reelsim left beside `path` are removed first (docs/robustness.md). RS_ERR_IO
 * naming the file and the system's reason; `path` untouched on failure. For the
 * applications' own files (optimize's scene and history). */
rs_status rs_output_write_file(const char *path, const void *data, size_t size);

/* An application's own HDF5 file written as every reelsim file is: built in memory in the
 * newest format HDF5 writes (checksummed metadata; docs/output.md, "Checksums and
 * checks"), filled by `fill(file, user)` (file: the HDF5 file identifier, an hid_t; fill
 * returns 0, or non-zero to abandon the file), then written through
 * rs_output_write_file. RS_ERR_IO naming `path` when the file cannot be built or fill
 * fails; `path` untouched on failure. */
rs_status rs_output_write_h5(const char *path, int (*fill)(int64_t file, void *user), void *user);

/* One run of a comparison (`reelsim compare`): a scene and what winding it gave. */
typedef struct rs_output_run {
  const rs_scene *scene;
  const rs_reel_result *result;
} rs_output_run;

/* Writes n >= 1 runs to one file, staged like rs_output_write (docs/output.md, "Comparison
 * files"): run i's layout (what rs_output_write puts on the root) under
 * /runs/<rs_output_run_name(i, n)>, and /summary with the key figures of every run, in
 * order. */
rs_status rs_output_write_compare(const char *path, int n, const rs_output_run *runs);
/* The same with each run's storage stages (storage[i], rs_storage_run, or NULL: none) under
 * /runs/<name>/storage as in a run file, and run i named names[i] when names is not NULL
 * (a variant's name: the group "<i+1>-<name>") instead of by its scene file. The
 * /summary gains the storage_* figures (NaN for a run without stages) when a run has them.
 * storage NULL and names NULL: exactly rs_output_write_compare. */
rs_status rs_output_write_compare_stored(const char *path, int n, const rs_output_run *runs,
                                         const rs_storage_result *const *storage,
                                         const char *const *names);

/* The group name of run i (0-based) of n: "<i+1>-<scene file name without directory and
 * extension>", the number zero-padded to the width of n ("01-rider" .. "12-taper") so
 * that the groups sort in run order. */
void rs_output_run_name(int i, int n, const char *scene_path, char *buf, size_t size);

/* A parameter sweep (`reelsim sweep`; docs/output.md, "Sweep files"): R runs of one scene
 * at K scene keys' values, and F figures of each run. */
typedef struct rs_output_profile {
  int n;                    /* layers (0: none, a failed run) */
  const double *radius;     /* m, outer radius of each layer */
  const double *sigma_r;    /* Pa */
  const double *sigma_theta;/* Pa */
} rs_output_profile;

typedef struct rs_output_sweep {
  const char *scene_path;         /* the scene swept (attribute scene_file) */
  const char *scene_text;         /* its resolved text with the --set overrides, or NULL */
  const char *sample;             /* "grid" or "lhs:R" (attribute sample) */
  long long seed;                 /* the Latin hypercube's seed (attribute seed; 0 for grid) */
  int n_keys;                     /* K >= 1 */
  const char *const *keys;        /* /sweep/parameters */
  const int *n_words;             /* per key: the words of a word-valued key, 0 for numbers */
  const char *const *const *words;/* per key: its words (NULL for a numeric key) */
  int n_runs;                     /* R >= 1 */
  const double *values;           /* R x K, row-major: the value, or the index of a word */
  int n_figures;                  /* F */
  const char *const *figure_names;/* /sweep/figures/<name> */
  const char *const *figure_units;
  const char *const *figure_help;
  const double *figures;          /* F x R, row-major (NaN where a run failed) */
  const rs_output_profile *profiles; /* R profiles (/sweep/profiles/<i>), or NULL */
} rs_output_sweep;

/* Writes the sweep to one HDF5 file, staged like rs_output_write: /sweep/parameters (K
 * strings), /sweep/values (R x K doubles; a word-valued key's column holds the index of the
 * word, and the attribute "words:<key>" of /sweep/values lists the words, comma-separated),
 * /sweep/figures/<name> (R doubles each, with units and description), and with profiles
 * /sweep/profiles/<i>/{radius, sigma_r, sigma_theta} for run i (0-based). */
rs_status rs_output_write_sweep(const char *path, const rs_output_sweep *sw);

/* The same as CSV, staged likewise: a header line (the keys, then the figures), one row
 * per run; numbers in their shortest round-trip form, a word-valued key as its word, a NaN figure as an empty field. */
rs_status rs_output_write_sweep_csv(const char *path, const rs_output_sweep *sw);

RS_END_DECLS
#endif
