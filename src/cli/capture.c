/* See capture.h. */
#include "cli/capture.h"

#include <stdlib.h>
#include <unistd.h>

void cli_capture_begin(cli_capture *c)
{
  c->file = NULL;
  c->saved = -1;
  fflush(stderr);
  FILE *f = tmpfile();
  if (!f) return;
  int saved = dup(STDERR_FILENO);
  if (saved < 0 || dup2(fileno(f), STDERR_FILENO) < 0) {
    if (saved >= 0) close(saved);
    fclose(f);
    return;
  }
  c->file = f;
  c->saved = saved;
}

char *cli_capture_end(cli_capture *c, size_t max)
{
  if (!c->file) return NULL;
  fflush(stderr);
  dup2(c->saved, STDERR_FILENO);
  close(c->saved);
  c->saved = -1;
  char *text = NULL;
  long n = (long)lseek(fileno(c->file), 0, SEEK_END);
  if (n >= 0 && max > 0 && (text = malloc(max))) {
    long from = (size_t)n >= max ? n - (long)(max - 1) : 0;
    size_t got = 0;
    if (fseek(c->file, from, SEEK_SET) == 0) got = fread(text, 1, max - 1, c->file);
    text[got] = '\0';
  }
  fclose(c->file);
  c->file = NULL;
  return text;
}
