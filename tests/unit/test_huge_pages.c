/* The huge-page advice for large blocks (src/util/huge_pages.c): the whole 2 MiB pages
 * inside a block of 4 MiB or more are advised, as the kernel's own record of the mapping
 * shows (/proc/self/smaps, VmFlags "hg"), and the block's contents are untouched; a
 * smaller block, or none, is left alone. */
#include <stdint.h>
#include <stdlib.h>

#include "check.h"
#include "smaps.h"
#include "util/huge_pages.h"

enum { MIB = 1 << 20 };

static void advises_large_block(void)
{
  const size_t bytes = (size_t)8 * MIB;
  unsigned char *p = calloc(bytes, 1);
  CHECK(p != NULL);
  if (!p) return;
  const size_t advised = rs_huge_pages_advise(p, bytes);
  CHECK_LOG("bytes advised", advised);
  if (!smaps_kernel_has_thp()) {
    CHECK(advised == 0);
  } else {
    /* 8 MiB hold 3 or 4 aligned 2 MiB pages, whatever the block's alignment */
    CHECK(advised >= (size_t)6 * MIB && advised <= bytes && advised % (2 * MIB) == 0);
    const uintptr_t begin = ((uintptr_t)p + 2 * MIB - 1) & ~(uintptr_t)(2 * MIB - 1);
    CHECK(smaps_advised_huge((void *)begin) == 1);
    CHECK(smaps_advised_huge((void *)(begin + advised - 1)) == 1);
  }
  size_t nonzero = 0;
  for (size_t i = 0; i < bytes; i += 4096) nonzero += p[i] != 0;
  CHECK(nonzero == 0); /* still calloc's zeros */
  p[bytes - 1] = 7;
  CHECK(p[bytes - 1] == 7);
  free(p);
}

static void small_block_left_alone(void)
{
  const size_t bytes = (size_t)RS_HUGE_PAGES_MIN_BYTES - 1;
  unsigned char *p = malloc(bytes);
  CHECK(p != NULL);
  CHECK(rs_huge_pages_advise(p, bytes) == 0);
  CHECK(rs_huge_pages_advise(NULL, (size_t)64 * MIB) == 0);
  free(p);
}

static const check_case cases[] = {{"advises_large_block", advises_large_block},
                                   {"small_block_left_alone", small_block_left_alone}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
