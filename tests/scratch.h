/* Scratch directories for the tests that write files (unit/test_output.c,
 * unit/test_csv.c, and through synthetic.h the reader, compare and plot tests): make one under /tmp, name files in it, count and read what is there,
 * remove it. Needs check.h included first. */
#ifndef RS_TESTS_SCRATCH_H
#define RS_TESTS_SCRATCH_H

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A new directory /tmp/rs_test_<tag>_XXXXXX (malloc'd name); exits 2 if none can be made. */
static inline char *scratch_dir(const char *tag)
{
  char templ[256];
  snprintf(templ, sizeof templ, "/tmp/rs_test_%s_XXXXXX", tag);
  char *d = strdup(templ);
  if (!d || !mkdtemp(d)) {
    fprintf(stderr, "mkdtemp failed: %s\n", strerror(errno));
    exit(2);
  }
  return d;
}

/* dir/name, malloc'd */
static inline char *scratch_join(const char *dir, const char *name)
{
  size_t n = strlen(dir) + strlen(name) + 2;
  char *p = malloc(n);
  snprintf(p, n, "%s/%s", dir, name);
  return p;
}

/* Number of entries in `dir` (without . and ..); prints them so a failure shows them. */
static inline int scratch_count_entries(const char *dir)
{
  DIR *d = opendir(dir);
  if (!d) return -1;
  int n = 0;
  struct dirent *e;
  while ((e = readdir(d))) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    printf("  entry in %s: %s\n", dir, e->d_name);
    ++n;
  }
  closedir(d);
  return n;
}

/* Removes a directory tree (made writable first: some tests make it read-only). */
static inline void scratch_remove_tree(const char *dir)
{
  DIR *d = opendir(dir);
  if (d) {
    struct dirent *e;
    chmod(dir, 0700);
    while ((e = readdir(d))) {
      if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
      char *p = scratch_join(dir, e->d_name);
      struct stat sb;
      if (lstat(p, &sb) == 0 && S_ISDIR(sb.st_mode))
        scratch_remove_tree(p);
      else
        unlink(p);
      free(p);
    }
    closedir(d);
  }
  rmdir(dir);
}

/* The whole file in a malloc'd buffer (NULL if it cannot be read). */
static inline char *scratch_slurp(const char *path, size_t *len)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  size_t cap = 4096, n = 0;
  char *buf = malloc(cap);
  size_t got;
  while ((got = fread(buf + n, 1, cap - n, f)) > 0) {
    n += got;
    if (n == cap) buf = realloc(buf, cap *= 2);
  }
  fclose(f);
  *len = n;
  return buf;
}

#endif
