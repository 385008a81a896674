/* Nip profiles, when a run has <run>/nip/profiles/<i>/ (the contact model's output):
 * x (m, nodes), pressure (Pa, on x), shear_upper and shear_lower (Pa, roll and drum side,
 * on x_shear when the file has it, else on x), slip_upper and slip_lower (nonzero where
 * the sheet slips, on the shears' points). One figure per profile: the pressure above,
 * the shears below with the stick zones shaded (roll side in the upper half of the
 * panel, drum side in the lower). Whatever a profile lacks is left out. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot_internal.h"
#include "util/error.h"

typedef struct profile {
  size_t nx, ns;
  double *x, *p, *xs, *up, *lo, *slip_up, *slip_lo;
  size_t n_up, n_lo, n_xs, n_slip_up, n_slip_lo;
} profile;

static void profile_free(profile *f)
{
  free(f->x);
  free(f->p);
  free(f->xs);
  free(f->up);
  free(f->lo);
  free(f->slip_up);
  free(f->slip_lo);
  memset(f, 0, sizeof *f);
}

/* Reads group/name into *v when it exists (else *v = NULL, *n = 0). */
static rs_status read_opt(plot_ctx *c, const char *group, const char *name, double **v,
                          size_t *n)
{
  char path[PLOT_PATH];
  rsi_plot_at(path, "%s/%s", group, name);
  *v = NULL;
  *n = 0;
  return rs_reader_exists(c->rd, path) ? rs_reader_read_1d(c->rd, path, v, n) : RS_OK;
}

static void scale(double *v, size_t n, double s)
{
  for (size_t i = 0; v && i < n; ++i) v[i] *= s;
}

/* Stick runs of `slip` (0 = stick) over points cx[0..n-1] as bands; each point owns the
 * span to the midpoints with its neighbours. */
static rs_status stick_bands(plot_ctx *c, const double *cx, const double *slip, size_t n,
                             double y0, double y1, const char *color, int *any)
{
  double *b0 = malloc((n ? n : 1) * sizeof *b0), *b1 = malloc((n ? n : 1) * sizeof *b1);
  if (!b0 || !b1) {
    free(b0);
    free(b1);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  size_t k = 0;
  for (size_t i = 0; i < n; ++i) {
    if (slip[i] != 0.0) continue;
    double left = i > 0 ? 0.5 * (cx[i - 1] + cx[i])
                  : n > 1 ? cx[0] - 0.5 * (cx[1] - cx[0])
                          : cx[0];
    double right = i + 1 < n ? 0.5 * (cx[i] + cx[i + 1])
                   : n > 1   ? cx[i] + 0.5 * (cx[i] - cx[i - 1])
                             : cx[i];
    if (i > 0 && k > 0 && slip[i - 1] == 0.0) {
      b1[k - 1] = right; /* the stick run goes on */
    } else {
      b0[k] = left;
      b1[k] = right;
      ++k;
    }
  }
  rsi_plot_bands(c, b0, b1, k, y0, y1, color);
  *any = k > 0;
  free(b0);
  free(b1);
  return RS_OK;
}

static rs_status profile_figure(plot_ctx *c, const run_data *d, const char *group,
                                const char *label, const char *file_what)
{
  profile f = {0};
  rs_status st = read_opt(c, group, "x", &f.x, &f.nx);
  size_t np = 0;
  if (st == RS_OK) st = read_opt(c, group, "pressure", &f.p, &np);
  if (st == RS_OK) st = read_opt(c, group, "x_shear", &f.xs, &f.n_xs);
  if (st == RS_OK) st = read_opt(c, group, "shear_upper", &f.up, &f.n_up);
  if (st == RS_OK) st = read_opt(c, group, "shear_lower", &f.lo, &f.n_lo);
  if (st == RS_OK) st = read_opt(c, group, "slip_upper", &f.slip_up, &f.n_slip_up);
  if (st == RS_OK) st = read_opt(c, group, "slip_lower", &f.slip_lo, &f.n_slip_lo);
  if (st != RS_OK || !f.x || !f.p || np != f.nx) { /* nothing to draw without x and p */
    profile_free(&f);
    return st;
  }
  /* the shears' points: x_shear (element midpoints) if it matches, else the nodes */
  const double *sx = NULL;
  size_t ns = f.n_up ? f.n_up : f.n_lo;
  if (f.xs && f.n_xs == ns) sx = f.xs;
  else if (ns == f.nx) sx = f.x;
  scale(f.x, f.nx, 1e3);
  scale(f.xs, f.n_xs, 1e3);
  scale(f.p, f.nx, 1e-3);
  scale(f.up, f.n_up, 1e-3);
  scale(f.lo, f.n_lo, 1e-3);

  char head[600], sub[256];
  double r;
  /* the radius is optional: a miss records an error that is not one, cleared here, before
   * anything whose failure must be reported */
  if (rs_reader_attr_double(c->rd, group, "roll_radius", &r) == RS_OK ||
      rs_reader_attr_double(c->rd, group, "radius", &r) == RS_OK)
    snprintf(sub, sizeof sub, "nip profile %s at roll radius %.1f mm", label, r * 1e3);
  else {
    rs_error_clear();
    snprintf(sub, sizeof sub, "nip profile %s", label);
  }
  snprintf(head, sizeof head, "%s\n%s", d->title, sub);
  char *out = rsi_plot_path(c, file_what);
  if (!out) st = RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (st == RS_OK) st = rs_gp_figure(&c->gp, out);
  free(out);
  if (st == RS_OK) {
    rs_gp_printf(&c->gp, "set multiplot layout %d,1 title ", sx ? 2 : 1);
    rs_gp_string(&c->gp, head);
    /* the legends beside the frames, and the same margins so both panels share x */
    rs_gp_printf(&c->gp, "\nset grid\nset key outside right top\nset lmargin 10\nset rmargin 34\n"
                         "set xlabel 'position across the nip x (mm)'\n"
                         "set ylabel 'contact pressure p (kPa)'\n");
    st = rsi_plot_curve(c, f.x, f.p, f.nx, "with lines linewidth 2.5 linecolor rgb '#1f77b4'",
                    "pressure", NULL);
    rs_gp_plot_end(&c->gp);
  }
  if (st == RS_OK && sx) {
    int stick_up = 0, stick_lo = 0;
    rs_gp_printf(&c->gp, "set ylabel 'shear traction τ (kPa)'\nset xzeroaxis linetype -1\n");
    if (f.slip_up && f.n_slip_up == ns)
      st = stick_bands(c, sx, f.slip_up, ns, 0.5, 1.0, "#d62728", &stick_up);
    if (st == RS_OK && f.slip_lo && f.n_slip_lo == ns)
      st = stick_bands(c, sx, f.slip_lo, ns, 0.0, 0.5, "#2ca02c", &stick_lo);
    if (st == RS_OK && f.up && f.n_up == ns)
      st = rsi_plot_curve(c, sx, f.up, ns, "with lines linewidth 2 linecolor rgb '#d62728'",
                      "τ+ sheet on the roll", NULL);
    if (st == RS_OK && f.lo && f.n_lo == ns)
      st = rsi_plot_curve(c, sx, f.lo, ns, "with lines linewidth 2 linecolor rgb '#2ca02c'",
                      "τ− sheet on the drum / rider", NULL);
    if (st == RS_OK && stick_up) rsi_plot_band_key(c, "#d62728", "stick, roll side (upper half)");
    if (st == RS_OK && stick_lo) rsi_plot_band_key(c, "#2ca02c", "stick, drum side (lower half)");
    if (st == RS_OK && c->gp.n_terms == 0) rsi_plot_empty(c, "no shear data");
    rs_gp_plot_end(&c->gp);
  }
  rs_gp_printf(&c->gp, "unset multiplot\n");
  profile_free(&f);
  return st;
}

rs_status rsi_plot_nip_figures(plot_ctx *c, const run_data *d, int prefix_run)
{
  char group[PLOT_PATH];
  rsi_plot_at(group, "%s/nip/profiles", d->base);
  if (!rs_reader_exists(c->rd, group)) return RS_OK;
  char **names = NULL;
  size_t n = 0;
  rs_status st = rs_reader_children(c->rd, group, &names, &n);
  for (size_t i = 0; st == RS_OK && i < n; ++i) {
    char sub[PLOT_PATH], what[PLOT_PATH];
    rsi_plot_at(sub, "%s/%s", group, names[i]);
    if (prefix_run) rsi_plot_at(what, "%s-nip-%s", d->name, names[i]);
    else rsi_plot_at(what, "nip-%s", names[i]);
    st = profile_figure(c, d, sub, names[i], what);
  }
  rs_reader_free_strings(&names, n);
  return st;
}
