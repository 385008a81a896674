/* A file's name without its folder and its last extension (internal). */
#ifndef RS_UTIL_PATH_STEM_H
#define RS_UTIL_PATH_STEM_H

#include <stdio.h>
#include <string.h>

/* "cases/newsprint-rider.yaml" -> "newsprint-rider" (a leading dot is kept: ".hidden"),
 * into out[size], truncated to fit */
static inline void rs_path_stem(const char *path, char *out, size_t size)
{
  const char *base = strrchr(path, '/');
  base = base ? base + 1 : path;
  const char *dot = strrchr(base, '.');
  size_t n = dot && dot != base ? (size_t)(dot - base) : strlen(base);
  snprintf(out, size, "%.*s", (int)n, base);
}

#endif
