/* Cost of rs_output_write and of the chunked 2-D helper at realistic sizes.
 * Prints wall time per write and bytes written; see docs/output.md ("Cost"). */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <hdf5.h>

#include "output/h5_util.h"
#include "reel/result_internal.h"
#include "util/atomic_file.h"
#include "reelsim/output.h"
#include "scene/scene_type.h" /* a scene filled by hand */

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static long file_size(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return -1;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fclose(f);
  return n;
}

int main(int argc, char **argv)
{
  int n = argc > 1 ? atoi(argv[1]) : 100000;
  int stages = argc > 2 ? atoi(argv[2]) : 200;
  const char *path = "/tmp/bench_output.h5";
  static rs_scene scene;
  rs_reel_result r;
  memset(&r, 0, sizeof r);
  snprintf(scene.title, sizeof scene.title, "bench");
  scene.resolved_text = "title: bench\n";
  r.n_layers = n;
  double *buf = malloc(6 * (size_t)n * sizeof *buf);
  r.radius = buf;
  r.wound_on_tension = buf + n;
  r.web_tension = buf + 2 * n;
  r.nip_load = buf + 3 * n;
  r.sigma_r = buf + 4 * n;
  r.sigma_theta = buf + 5 * n;
  for (int i = 0; i < n; ++i) {
    r.radius[i] = 0.04 + 1e-5 * i;
    r.wound_on_tension[i] = 250 + sin(i);
    r.web_tension[i] = 200;
    r.nip_load[i] = 1000;
    r.sigma_r[i] = -1e5 * exp(-i / 1e4);
    r.sigma_theta[i] = 1e6 * cos(i / 1e3);
  }
  const int reps = 5;
  double best = INFINITY;
  for (int k = 0; k < reps; ++k) {
    double t = now();
    if (rs_output_write(path, &scene, &r) != RS_OK) {
      fprintf(stderr, "%s\n", rs_error_message());
      return 1;
    }
    t = now() - t;
    if (t < best) best = t;
  }
  printf("rs_output_write  layers %d: best of %d %.4f s, file %ld bytes\n", n, reps, best,
         file_size(path));

  /* A history S x N with the lower-left triangle wound and NaN elsewhere. */
  size_t S = (size_t)stages, N = (size_t)n;
  double *h = malloc(S * N * sizeof *h);
  for (size_t s = 0; s < S; ++s)
    for (size_t j = 0; j < N; ++j) h[s * N + j] = j <= (s + 1) * N / S ? r.sigma_r[j] * (s + 1) / S : NAN;
  best = INFINITY;
  size_t bytes = 0;
  for (int k = 0; k < reps; ++k) {
    double t = now();
    hid_t f;
    void *img;
    if (rs_h5_memfile_create(&f) != RS_OK ||
        rs_h5_write_2d_chunked(f, "sigma_r", h, S, N, "Pa", "history") != RS_OK ||
        rs_h5_memfile_image(f, &img, &bytes) != RS_OK) {
      fprintf(stderr, "%s\n", rs_error_message());
      return 1;
    }
    H5Fclose(f);
    if (rs_atomic_file_write(path, img, bytes) != RS_OK) return 1;
    free(img);
    t = now() - t;
    if (t < best) best = t;
  }
  printf("2-D chunked      %zu x %zu: best of %d %.4f s, file %zu bytes (raw %zu, ratio %.3f)\n", S,
         N, reps, best, bytes, S * N * sizeof(double), (double)bytes / (S * N * sizeof(double)));
  unlink(path);
  free(h);
  free(buf);
  return 0;
}
