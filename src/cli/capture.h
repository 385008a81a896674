/* What a process writes to stderr, kept in an unnamed temporary file instead (reelsim sweep
 * under mpirun: a worker rank's messages go to rank 0, which prints them). */
#ifndef RS_CLI_CAPTURE_H
#define RS_CLI_CAPTURE_H

#include <stdio.h>

typedef struct cli_capture {
  FILE *file; /* the temporary (NULL: nothing is captured) */
  int saved;  /* the stderr descriptor to restore, or -1 */
} cli_capture;

/* From now on stderr goes to a temporary file. When none can be made, stderr stays as it
 * was (c->file NULL). */
void cli_capture_begin(cli_capture *c);
/* stderr back where it was; what was written meanwhile (malloc'd, NUL-terminated, at most
 * `max` bytes: the end is kept when more was written) or NULL when nothing was captured. */
char *cli_capture_end(cli_capture *c, size_t max);

#endif
