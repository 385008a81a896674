/* The program's heap backed by transparent huge pages where the kernel offers them
 * (heap.h). glibc and Linux only; elsewhere nothing is changed. */
#define _DEFAULT_SOURCE /* madvise, MADV_HUGEPAGE (not in ISO C or strict POSIX) */
#include "cli/heap.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GLIBC__) && defined(__linux__)
#include <malloc.h>
#include <sys/mman.h>
#endif

#if defined(__GLIBC__) && defined(__linux__) && defined(MADV_HUGEPAGE)
static void *heap_spacer; /* held for the process's life (below) */

/* glibc asked to fill freed and new blocks (MALLOC_PERTURB_, or the tunable): it would
 * write the whole reserve, page by page, before the advice */
static int perturbed(void)
{
  const char *p = getenv("MALLOC_PERTURB_"), *t = getenv("GLIBC_TUNABLES");
  return (p && *p && strcmp(p, "0") != 0) || (t && strstr(t, "perturb"));
}
#endif

size_t cli_heap_prepare(size_t reserve, void **first)
{
  if (first) *first = NULL;
#if defined(__GLIBC__) && defined(__linux__) && defined(MADV_HUGEPAGE)
  const uintptr_t huge = (uintptr_t)2 << 20;
  /* The reserve as one block from the heap (a block under the mmap threshold, 32 MiB while
   * it is taken), its 2 MiB pages marked before anything touches them (a 2 MiB span with a
   * page touched at 4 KiB stays at 4 KiB: malloc writes only the block's two ends), then
   * freed to the heap's top, which is kept while under 64 MiB (not handed back, marks and
   * all): later blocks are carved from it while it has room. Once it has not, blocks from
   * 4 MiB are mapped on their own (a long roll's arrays: handed back whole when freed).
   * Both thresholds fixed, where glibc would slide them. */
  if (reserve >= (size_t)32 << 20 || perturbed() || !mallopt(M_TRIM_THRESHOLD, 64 << 20) ||
      !mallopt(M_MMAP_THRESHOLD, 32 << 20))
    return 0;
  free(heap_spacer); /* a second preparation: the first's spacer back to the top */
  heap_spacer = NULL;
  void *p = malloc(reserve);
  size_t marked = 0;
  if (p) {
    const uintptr_t at = (uintptr_t)p; /* the reserve's address, compared after its free */
    const uintptr_t begin = (at + huge - 1) & ~(huge - 1), end = (at + reserve) & ~(huge - 1);
    if (end > begin && madvise((void *)begin, end - begin, MADV_HUGEPAGE) == 0) {
      marked = end - begin;
      if (first) *first = (void *)begin;
    }
    free(p);
    /* the part below the first 2 MiB boundary held, untouched but for its ends, so that
     * the run's blocks start on a huge page rather than in up to 2 MiB of 4 KiB ones (the
     * heap's start is randomised): glibc serves it from the same place, the freed top */
    if (marked && begin - at > 64) {
      heap_spacer = malloc(begin - at - 64);
      if (heap_spacer && (uintptr_t)heap_spacer != at) { /* not where the reserve was */
        free(heap_spacer);
        heap_spacer = NULL;
      }
    }
  }
  (void)mallopt(M_MMAP_THRESHOLD, 4 << 20);
  return marked;
#else
  (void)reserve;
  return 0;
#endif
}
