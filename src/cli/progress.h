/* The progress line of `reelsim run` (progress.c) and its time estimate.
 *
 * The estimate: an increment integrates the roll beneath the new layer, so the cost per
 * layer grows with the layers already wound. Extrapolating the average time per layer
 * (elapsed x remaining / done) is therefore optimistic: with a cost growing linearly in
 * the layers it promises, half-way, a third of the real time left. The estimator fits the
 * cost per layer as c(n) = a + b n, that is the elapsed time as T(n) = a n + b n^2 / 2, by
 * least squares to every (layers, time) sample, and reports the integral of c over the
 * layers still to wind: a (N - n) + b (N^2 - n^2) / 2. A constant cost (b = 0) gives back
 * the plain extrapolation. */
#ifndef RS_CLI_PROGRESS_H
#define RS_CLI_PROGRESS_H

typedef struct cli_eta {
  int total;                      /* N, layers of the reel */
  double s22, s23, s24, s1t, s2t; /* sums of x^2, x^3, x^4, x t, x^2 t with x = n / N */
  int samples;
  int last_n;
  double last_t;
} cli_eta;

void cli_eta_init(cli_eta *e, int total);
/* One sample: n layers done at t seconds after the winding started (n > 0). */
void cli_eta_add(cli_eta *e, int n, double t);
/* Seconds left after the last sample; a negative value when there is no estimate yet
 * (fewer than two distinct samples). */
double cli_eta_left(const cli_eta *e);

/* The progress line on stderr: drawn once the run has taken a second, at most ten times a
 * second, only when `on` (stderr is a terminal and not --quiet). */
typedef struct cli_progress {
  int on, drawn;
  int done, total;
  double r_core, caliper; /* the radius after n layers: r_core + n caliper */
  double t_start, t_last;
  cli_eta eta;
} cli_progress;

void cli_progress_init(cli_progress *p, int on, int total, double r_core, double caliper,
                       double t_start);
/* Called after each increment with the layers done and the clock. */
void cli_progress_update(cli_progress *p, int done, double now);
/* Wipes the line so that messages and the summary start on a clean line. */
void cli_progress_clear(cli_progress *p);

#endif
