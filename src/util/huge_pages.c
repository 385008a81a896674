/* Transparent huge pages for large blocks (huge_pages.h). */
#define _DEFAULT_SOURCE /* madvise, MADV_HUGEPAGE (not in ISO C or strict POSIX) */
#include "util/huge_pages.h"

#include <stdint.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

size_t rs_huge_pages_advise(void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const uintptr_t huge = (uintptr_t)2 << 20;
  if (!p || bytes < (size_t)RS_HUGE_PAGES_MIN_BYTES) return 0;
  const uintptr_t begin = ((uintptr_t)p + huge - 1) & ~(huge - 1);
  const uintptr_t end = ((uintptr_t)p + bytes) & ~(huge - 1);
  if (end <= begin || madvise((void *)begin, end - begin, MADV_HUGEPAGE) != 0) return 0;
  return end - begin;
#else
  (void)p;
  (void)bytes;
  return 0;
#endif
}
