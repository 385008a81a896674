/* Runs the scene-loader fuzz target (fuzz_scene.c) over every file of a directory under
 * tests/fuzz/ in the ordinary build, so inputs the fuzzer once crashed on stay fixed:
 *   replay crashes   (reproducers of fixed bugs)     replay corpus   (the seed inputs)
 * A failing input aborts inside the target, naming itself first on stdout; a folder with
 * no inputs fails too. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef RS_FUZZ_DIR
#error "RS_FUZZ_DIR must name tests/fuzz"
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int by_name(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

static int replay_file(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return perror(path), 1;
  size_t cap = 4096, len = 0;
  char *buf = malloc(cap);
  size_t n;
  while (buf && (n = fread(buf + len, 1, cap - len, f)) > 0) {
    len += n;
    if (len == cap) {
      char *b = realloc(buf, cap *= 2);
      if (!b) free(buf);
      buf = b;
    }
  }
  fclose(f);
  if (!buf) return fprintf(stderr, "%s: out of memory\n", path), 1;
  printf("  %s (%zu bytes)\n", path, len);
  fflush(stdout);
  LLVMFuzzerTestOneInput((const uint8_t *)buf, len);
  free(buf);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc != 2 || strchr(argv[1], '/')) {
    fprintf(stderr, "usage: %s corpus|crashes\n", argv[0]);
    return 2;
  }
  char dir[4096], path[8192];
  snprintf(dir, sizeof dir, "%s/%s", RS_FUZZ_DIR, argv[1]);
  DIR *d = opendir(dir);
  if (!d) return perror(dir), 2;
  char **names = NULL;
  size_t count = 0;
  for (struct dirent *e; (e = readdir(d));) {
    if (e->d_name[0] == '.') continue; /* ., .., .gitkeep */
    char **nn = realloc(names, (count + 1) * sizeof *names);
    if (!nn || !(nn[count] = strdup(e->d_name))) return fprintf(stderr, "out of memory\n"), 2;
    names = nn;
    ++count;
  }
  closedir(d);
  if (count > 1) qsort(names, count, sizeof *names, by_name);
  int bad = 0;
  for (size_t i = 0; i < count; ++i) {
    snprintf(path, sizeof path, "%s/%s", dir, names[i]);
    bad |= replay_file(path);
    free(names[i]);
  }
  free(names);
  /* an empty folder would check nothing: a lost corpus must not pass unnoticed */
  if (count == 0) {
    printf("no inputs in %s: FAILED (a replay of nothing checks nothing)\n", dir);
    return 1;
  }
  printf("%zu inputs from %s: %s\n", count, dir, bad ? "FAILED" : "ok");
  return bad;
}
