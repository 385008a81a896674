/* The plot module's shared pieces (internal, defined in figure.c): a run's data in
 * plotting units and the helpers the figures draw with. Units on every axis: radius in
 * mm, pressures and shears in kPa, hoop stress in MPa, tensions and loads in N/m,
 * positions across the nip in mm. */
#ifndef RS_PLOT_INTERNAL_H
#define RS_PLOT_INTERNAL_H

#include <stddef.h>

#include "plot/gnuplot.h"
#include "reelsim/reader.h"

typedef struct plot_ctx {
  rs_reader *rd;
  rs_gp gp;
  const char *dir;
  char stem[256];
} plot_ctx;

/* One run's final state, converted to plotting units. */
typedef struct run_data {
  const char *base;   /* the run's group ("" or /runs/<name>) */
  const char *name;   /* the run's short name */
  char *title;        /* the scene's title (the name if the file has none) */
  size_t n;           /* layers */
  double *r_mm;       /* outer radius of each layer */
  double *p_kpa;      /* interlayer pressure -sigma_r */
  double *hoop_mpa;   /* sigma_theta */
  double *t0, *web, *nip; /* N/m */
  double core_kpa;    /* core pressure */
  double core_r_mm;   /* core radius, r_1 - t (NaN with fewer than two layers) */
  /* optional (NULL when the file has none): the winding-at-speed effects */
  double *spin_p_kpa, *spin_hoop_mpa; /* /final_at_speed: the roll spinning */
  double *air_um, *air0_um;           /* /layers/air_film, /layers/air_film_entrained (um) */
} run_data;

rs_status rsi_plot_run_read(const plot_ctx *c, int i, run_data *d);
/* plot_storage.c: <stem>-storage-pressure.png, -storage-hoop.png (by stage) and
 * -storage-core.png (core pressure against storage time) when the run has /storage. */
rs_status rsi_plot_storage_figures(plot_ctx *c, const run_data *d);
void rsi_plot_run_free(run_data *d);
/* plot_lanes.c: <stem>-lanes-pressure.png (the pressure map, width x radius),
 * -lanes-profile.png (the final radius across the width, each lane's core pressure) and
 * -lanes-tension.png (the lanes' web tension against radius) when the run has /lanes. */
rs_status rsi_plot_lanes_figures(plot_ctx *c, const run_data *d);

enum { PLOT_PATH = 4096 };

/* printf into buf (PLOT_PATH bytes) for HDF5 paths; returns buf. A path that does not fit
 * is cut, and then names nothing in the file. */
const char *rsi_plot_at(char *buf, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* "<dir>/<stem>-<what>.png" into a malloc'd string. */
char *rsi_plot_path(const plot_ctx *c, const char *what);

/* A colour of the qualitative palette used for runs and curves ("#1f77b4", ...). */
const char *rsi_plot_color(int i);

/* Writes the columns to a data file and adds `plot '<file>' using 1:2 ...` with the given
 * style and title as one item of the plot command. Nothing (and no item) when no row is
 * finite; returns the rows written in *rows (may be NULL). */
rs_status rsi_plot_curve(plot_ctx *c, const double *x, const double *y, size_t n,
                     const char *style, const char *title, size_t *rows);

/* A line y = value across the plot, dashed, as one plot item. */
void rsi_plot_hline(plot_ctx *c, double value, const char *color, const char *title);

/* Shaded bands from x0[k] to x1[k] over the fraction [y0, y1] of the plot's height
 * (set object, drawn behind the curves); call before the plot command. */
void rsi_plot_bands(plot_ctx *c, const double *x0, const double *x1, size_t n, double y0,
                double y1, const char *color);
/* A legend entry for bands of that colour (one plot item). */
void rsi_plot_band_key(plot_ctx *c, const char *color, const char *title);

/* An empty frame saying why (one plot item): for a figure with no data at all. */
void rsi_plot_empty(plot_ctx *c, const char *why);

/* Title line 1 and 2 as a gnuplot "set title". */
void rsi_plot_title(plot_ctx *c, const char *line1, const char *line2);

#endif
