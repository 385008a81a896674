/* The kernel's own record of the process's mappings (/proc/self/smaps), for tests of the
 * huge-page advice (src/util/huge_pages.c, src/cli/heap.c). Linux; elsewhere the readers
 * say there is none. */
#ifndef RS_TESTS_SMAPS_H
#define RS_TESTS_SMAPS_H

#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* 1 when the kernel has transparent huge pages at all (any mode, "never" included). */
static inline int smaps_kernel_has_thp(void)
{
  FILE *f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
  if (!f) return 0;
  fclose(f);
  return 1;
}

/* 1 when the mapping that holds `addr` carries the huge-page advice (VmFlags "hg"), 0 when
 * it does not, -1 when smaps cannot be read. */
static inline int smaps_advised_huge(const void *addr)
{
  FILE *f = fopen("/proc/self/smaps", "r");
  if (!f) return -1;
  char line[512];
  int inside = 0, found = 0;
  const uintptr_t a = (uintptr_t)addr;
  while (fgets(line, sizeof line, f)) {
    unsigned long lo, hi;
    if (sscanf(line, "%lx-%lx ", &lo, &hi) == 2) inside = (a >= lo && a < hi); /* a mapping's head */
    if (inside && strncmp(line, "VmFlags:", 8) == 0) {
      found = strstr(line, " hg") != NULL;
      break;
    }
  }
  fclose(f);
  return found;
}

#endif
