/* Advice to the kernel that a large block of the engine's own be backed by transparent
 * huge pages (2 MiB) where it offers them (Linux's THP in "always" or "madvise" mode): a
 * long roll's arrays, touched a page at a time as the roll grows, then fault once a 2 MiB
 * page instead of once a 4 KiB one. Advice only: the memory, its contents and its owner
 * are unchanged; elsewhere (no THP, not Linux) nothing is done. The same rule as NumPy's
 * for its arrays: from 4 MiB. */
#ifndef RS_UTIL_HUGE_PAGES_H
#define RS_UTIL_HUGE_PAGES_H

#include <stddef.h>

enum { RS_HUGE_PAGES_MIN_BYTES = 4 << 20 };

/* Advises the whole 2 MiB pages inside [p, p + bytes) when bytes >= RS_HUGE_PAGES_MIN_BYTES
 * (those a fresh allocation has not touched yet: malloc writes only its block's ends).
 * Returns the bytes advised (0 when none). */
size_t rs_huge_pages_advise(void *p, size_t bytes);

#endif
