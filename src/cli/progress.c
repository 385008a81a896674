/* The progress line and its time estimate (progress.h). */
#include "cli/progress.h"

#include <stdio.h>

void cli_eta_init(cli_eta *e, int total)
{
  *e = (cli_eta){.total = total > 0 ? total : 1};
}

void cli_eta_add(cli_eta *e, int n, double t)
{
  if (n <= 0 || n == e->last_n) return;
  double x = (double)n / e->total, x2 = x * x;
  e->s22 += x2;
  e->s23 += x2 * x;
  e->s24 += x2 * x2;
  e->s1t += x * t;
  e->s2t += x2 * t;
  e->samples++;
  e->last_n = n;
  e->last_t = t;
}

/* T(x) = A x + B x^2 (x = n/N; A = a N, B = b N^2 / 2): the normal equations
 *   [s22 s23] [A]   [s1t]
 *   [s23 s24] [B] = [s2t],  and the time left T(1) - T(x_last). */
double cli_eta_left(const cli_eta *e)
{
  if (e->samples < 2) return -1.0;
  double x = (double)e->last_n / e->total;
  double det = e->s22 * e->s24 - e->s23 * e->s23;
  double linear = e->last_t * (1.0 - x) / x; /* the plain extrapolation */
  if (!(det > 1e-12 * e->s22 * e->s24)) return linear;
  double A = (e->s1t * e->s24 - e->s2t * e->s23) / det;
  double B = (e->s22 * e->s2t - e->s23 * e->s1t) / det;
  /* a cost per layer that would turn negative before the end is noise, not a trend */
  if (A + 2.0 * B < 0.0 || A < 0.0) return linear;
  double left = A * (1.0 - x) + B * (1.0 - x * x);
  return left > 0.0 ? left : 0.0;
}

void cli_progress_init(cli_progress *p, int on, int total, double r_core, double caliper,
                       double t_start)
{
  *p = (cli_progress){.on = on, .total = total, .r_core = r_core, .caliper = caliper,
                      .t_start = t_start};
  cli_eta_init(&p->eta, total);
}

static void draw(cli_progress *p, double now)
{
  double elapsed = now - p->t_start, left = cli_eta_left(&p->eta);
  int pct = p->total > 0 ? (int)(100.0 * p->done / p->total) : 100;
  char eta[48] = "";
  if (left >= 0.0) snprintf(eta, sizeof eta, ", about %.0f s left", left);
  /* \033[K: the line may be shorter than the one before */
  fprintf(stderr, "\rreelsim: layer %d of %d (%d%%), r = %.1f mm, %.0f s%s\033[K", p->done,
          p->total, pct, (p->r_core + p->done * p->caliper) * 1e3, elapsed, eta);
  fflush(stderr);
  p->drawn = 1;
}

void cli_progress_update(cli_progress *p, int done, double now)
{
  p->done = done;
  if (!p->on) return;
  cli_eta_add(&p->eta, done, now - p->t_start);
  if (now - p->t_start >= 1.0 && now - p->t_last >= 0.1) {
    draw(p, now);
    p->t_last = now;
  }
}

void cli_progress_clear(cli_progress *p)
{
  if (!p->drawn) return;
  fputs("\r\033[K", stderr);
  fflush(stderr);
  p->drawn = 0;
}
