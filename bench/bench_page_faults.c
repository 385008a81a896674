/* What a first touch of memory costs: `bench_page_faults [MiB] [rounds]` maps MiB of
 * anonymous memory `rounds` times and writes a byte a 4 KiB page, three ways:
 *   4 KiB    faulted page by page (what malloc's fresh memory costs),
 *   populate mapped with MAP_POPULATE (the pages made in one call),
 *   2 MiB    2 MiB-aligned with madvise(MADV_HUGEPAGE) (transparent huge pages where the
 *            kernel offers them: a fault a 2 MiB page),
 * and prints the process CPU time (user + system) a MiB and a 4 KiB page each way, and the
 * faults counted. Linux only; the program's heap (src/cli/heap.c) takes the third way. */
#define _DEFAULT_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <sys/resource.h>

static double cpu_seconds(long *faults)
{
  struct rusage r;
  getrusage(RUSAGE_SELF, &r);
  *faults = r.ru_minflt;
  return (double)r.ru_utime.tv_sec + 1e-6 * (double)r.ru_utime.tv_usec +
         (double)r.ru_stime.tv_sec + 1e-6 * (double)r.ru_stime.tv_usec;
}

/* one mapping of `bytes` touched a byte a 4 KiB page; 0 when it could not be mapped */
static int touch_once(int way, size_t bytes)
{
  const size_t huge = (size_t)2 << 20, span = way == 2 ? bytes + huge : bytes;
  int flags = MAP_PRIVATE | MAP_ANONYMOUS;
#ifdef MAP_POPULATE
  if (way == 1) flags |= MAP_POPULATE;
#endif
  char *map = mmap(NULL, span, PROT_READ | PROT_WRITE, flags, -1, 0);
  if (map == MAP_FAILED) return 0;
  char *p = map;
  if (way == 2) {
    p = (char *)(((uintptr_t)map + huge - 1) & ~(uintptr_t)(huge - 1));
#ifdef MADV_HUGEPAGE
    (void)madvise(p, bytes, MADV_HUGEPAGE);
#endif
  }
  for (size_t i = 0; i < bytes; i += 4096) p[i] = 1;
  munmap(map, span);
  return 1;
}

int main(int argc, char **argv)
{
  const long mib = argc > 1 ? atol(argv[1]) : 16, rounds = argc > 2 ? atol(argv[2]) : 20;
  if (mib < 1 || rounds < 1 || mib > 4096) {
    fprintf(stderr, "usage: bench_page_faults [MiB 1..4096] [rounds]\n");
    return 2;
  }
  static const char *const name[3] = {"4 KiB", "populate", "2 MiB"};
  const size_t bytes = (size_t)mib << 20;
  printf("%-9s %14s %16s %10s\n", "way", "CPU us / MiB", "CPU us / 4 KiB", "faults");
  for (int way = 0; way < 3; ++way) {
    long f0, f1;
    const double t0 = cpu_seconds(&f0);
    for (long r = 0; r < rounds; ++r)
      if (!touch_once(way, bytes)) {
        fprintf(stderr, "bench_page_faults: could not map %ld MiB\n", mib);
        return 1;
      }
    const double t = cpu_seconds(&f1) - t0, per_mib = 1e6 * t / (double)(rounds * mib);
    printf("%-9s %14.1f %16.3f %10ld\n", name[way], per_mib, per_mib / 256.0, f1 - f0);
  }
  return 0;
}
