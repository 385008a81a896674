/* The program's heap preparation (src/cli/heap.c, compiled into the test: the CLI is not
 * part of the library): the reserve's 2 MiB-aligned span is marked for transparent huge
 * pages, as the kernel's own record of the mapping (/proc/self/smaps, VmFlags "hg") shows,
 * and blocks allocated afterwards are served from it, from its first huge page on. */
#define _DEFAULT_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "smaps.h"
#include "cli/heap.h"

enum { MIB = 1 << 20 };

/* Under valgrind or a sanitizer the allocator is theirs: the reserve is marked, but the
 * blocks after it come from elsewhere. */
static int allocator_replaced(void)
{
#if defined(__SANITIZE_ADDRESS__)
  return 1;
#else
  const char *pre = getenv("LD_PRELOAD");
  return pre && strstr(pre, "vgpreload") != NULL;
#endif
}

static void marks_reserve(void)
{
  void *first = (void *)1;
  size_t marked = cli_heap_prepare((size_t)8 * MIB, &first);
  CHECK_LOG("bytes marked", marked);
  if (!smaps_kernel_has_thp() || (allocator_replaced() && marked == 0)) { /* ASan refuses mallopt */
    CHECK(marked == 0 && first == NULL);
    return;
  }
  /* 8 MiB hold at least two aligned 2 MiB pages whatever the block's alignment */
  CHECK(marked >= (size_t)4 * MIB && marked <= (size_t)8 * MIB);
  CHECK(marked % (2 * MIB) == 0);
  CHECK(((uintptr_t)first & (2 * MIB - 1)) == 0);
  CHECK(smaps_advised_huge(first) == 1);
}

/* Blocks allocated after the preparation come from the marked span, from its start: the
 * part of the reserve below its first 2 MiB boundary is held. */
static void blocks_from_reserve(void)
{
  void *first = NULL;
  size_t marked = cli_heap_prepare((size_t)CLI_HEAP_RESERVE, &first);
  unsigned char *small = malloc(1000), *b = malloc((size_t)4 * MIB);
  CHECK(small != NULL && b != NULL);
  if (!small || !b) {
    free(small);
    free(b);
    return;
  }
  memset(b, 0xa5, (size_t)4 * MIB);
  CHECK(b[0] == 0xa5 && b[4 * MIB - 1] == 0xa5);
  if (marked > 0 && !allocator_replaced()) {
    const uintptr_t lo = (uintptr_t)first, hi = lo + marked;
    CHECK((uintptr_t)small >= lo - 64 && (uintptr_t)small < lo + 4096);
    CHECK((uintptr_t)b >= lo && (uintptr_t)b + 4 * MIB <= hi);
    CHECK(smaps_advised_huge(b + 2 * MIB) == 1);
  }
  free(small);
  free(b);
}

/* blocks_from_reserve first: run together, it needs the heap as a program finds it */
static const check_case cases[] = {{"blocks_from_reserve", blocks_from_reserve},
                                   {"marks_reserve", marks_reserve}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
