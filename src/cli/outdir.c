/* See outdir.h. The path is walked one component at a time, as mkdir -p does: "a/b/c"
 * is a, a/b, a/b/c (an absolute path from its first component below /). */
#include "cli/outdir.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/fail.h"

/* The end of the next component of p after position i (the index of the '/' after it, or
 * the length); skips repeated slashes. */
static size_t next_end(const char *p, size_t i)
{
  size_t n = strlen(p);
  while (i < n && p[i] == '/') ++i;
  while (i < n && p[i] != '/') ++i;
  return i;
}

/* Walks the prefixes of dir; make: creates the missing ones. *deepest gets the deepest
 * existing prefix ("." when none of a relative path exists, "/" for an absolute one). */
static int walk(const char *label, const char *dir, int make, char **deepest, char **top)
{
  size_t n = strlen(dir);
  char *p = malloc(n + 1), *best = malloc(n + 2);
  if (!p || !best) {
    free(p);
    free(best);
    return cli_fail(CLI_EXIT_OTHER, "out of memory");
  }
  strcpy(best, dir[0] == '/' ? "/" : ".");
  int code = CLI_EXIT_OK, missing = 0;
  for (size_t end = next_end(dir, 0); end > 0 && code == CLI_EXIT_OK;) {
    memcpy(p, dir, end);
    p[end] = '\0';
    struct stat sb;
    if (!missing && stat(p, &sb) == 0) {
      if (!S_ISDIR(sb.st_mode))
        code = end == n || next_end(dir, end) == end
                   ? cli_fail(CLI_EXIT_USAGE, "%s '%s' is not a directory", label, dir)
                   : cli_fail(CLI_EXIT_USAGE, "%s '%s': '%s' is not a directory", label, dir, p);
      else
        strcpy(best, p);
    } else if (!missing && errno != ENOENT) {
      code = cli_fail(CLI_EXIT_OTHER, "%s '%s': '%s': %s", label, dir, p, strerror(errno));
    } else {
      missing = 1;
      if (make) {
        if (mkdir(p, 0777) != 0 && errno != EEXIST)
          code = cli_fail(CLI_EXIT_OTHER, "%s '%s': cannot make '%s': %s", label, dir, p,
                          strerror(errno));
        else if (top && !*top && !(*top = strdup(p)))
          code = cli_fail(CLI_EXIT_OTHER, "out of memory");
      }
    }
    size_t next = next_end(dir, end);
    end = next == end ? 0 : next;
  }
  free(p);
  if (code == CLI_EXIT_OK && deepest) *deepest = best;
  else free(best);
  return code;
}

int cli_outdir_check(const char *label, const char *dir)
{
  char *deepest = NULL;
  if (!dir || !dir[0]) return cli_fail(CLI_EXIT_USAGE, "%s: no directory given", label);
  int code = walk(label, dir, 0, &deepest, NULL);
  if (code == CLI_EXIT_OK && access(deepest, W_OK | X_OK) != 0)
    code = strcmp(deepest, dir) == 0
               ? cli_fail(CLI_EXIT_OTHER, "%s '%s' is not writable: %s", label, dir, strerror(errno))
               : cli_fail(CLI_EXIT_OTHER, "%s '%s': cannot make it in '%s': %s", label, dir,
                          deepest, strerror(errno));
  free(deepest);
  return code;
}

int cli_outdir_make(const char *label, const char *dir, cli_outdir *made)
{
  made->top = NULL;
  if (!(made->path = strdup(dir))) return cli_fail(CLI_EXIT_OTHER, "out of memory");
  return walk(label, dir, 1, NULL, &made->top);
}

void cli_outdir_undo(cli_outdir *made)
{
  if (made->path && made->top) {
    /* from DIR up to the uppermost directory made; rmdir leaves one that is not empty */
    char *p = made->path;
    size_t top = strlen(made->top);
    for (;;) {
      size_t n = strlen(p);
      while (n > 1 && p[n - 1] == '/') p[--n] = '\0';
      if (rmdir(p) != 0 || n <= top) break;
      char *slash = strrchr(p, '/');
      if (!slash) break;
      *slash = '\0';
    }
  }
  cli_outdir_free(made);
}

void cli_outdir_free(cli_outdir *made)
{
  free(made->path);
  free(made->top);
  made->path = made->top = NULL;
}
