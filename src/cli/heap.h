/* The program's heap, prepared once at start: blocks below 4 MiB come from the heap
 * (reused after they are freed, not mapped afresh and faulted page by page again), and
 * the first `reserve` bytes of the heap are marked for transparent huge pages, so a run
 * touches its working memory in 2 MiB pages rather than 4 KiB ones where the kernel
 * offers them (Linux's THP in "always" or "madvise" mode; docs/performance.md, "Page
 * faults"). A process-wide choice: the program makes it, the library never does. */
#ifndef RS_CLI_HEAP_H
#define RS_CLI_HEAP_H

#include <stddef.h>

enum { CLI_HEAP_RESERVE = 30 << 20 }; /* under glibc's largest mmap threshold, 32 MiB */

/* Returns the bytes marked for huge pages (0 where the C library or kernel has no such
 * mark) and, when `first` is not NULL, the first marked address (NULL when none). The
 * marked span is 2 MiB-aligned and lies inside the reserve. Harmless under other
 * allocators: ASan's refuses the thresholds (nothing is marked), valgrind's takes the
 * block from its own heap (marked, then freed). */
size_t cli_heap_prepare(size_t reserve, void **first);

#endif
