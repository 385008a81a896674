/* A gnuplot session: private directory, script, spawn, staging; see gnuplot.h. */
#include "plot/gnuplot.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <spawn.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "util/atomic_file.h"
#include "util/error.h"

extern char **environ;

static char *join(const char *dir, const char *name)
{
  size_t n = strlen(dir) + strlen(name) + 2;
  char *p = malloc(n);
  if (p) snprintf(p, n, "%s/%s", dir, name);
  return p;
}

rs_status rs_gp_begin(rs_gp *gp, int width, int height)
{
  memset(gp, 0, sizeof *gp);
  gp->width = width > 0 ? width : 1000;
  gp->height = height > 0 ? height : 650;
  const char *tmp = getenv("TMPDIR");
  if (!tmp || tmp[0] != '/') tmp = "/tmp";
  gp->dir = join(tmp, "reelsim-plot-XXXXXX");
  if (!gp->dir) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (!mkdtemp(gp->dir)) {
    rs_status st = RS_ERROR(RS_ERR_IO, "cannot make a temporary directory '%s': %s", gp->dir,
                            strerror(errno));
    free(gp->dir);
    gp->dir = NULL;
    return st;
  }
  if (!(gp->script = join(gp->dir, "plot.gp")))
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  if (!(gp->out = fopen(gp->script, "w")))
    return RS_ERROR(RS_ERR_IO, "cannot write '%s': %s", gp->script, strerror(errno));
  /* pngcairo antialiases and knows UTF-8; gnuplot-nox has it, a minimal build may not */
  rs_gp_printf(gp,
               "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
               "  set terminal pngcairo size %d,%d noenhanced font 'DejaVu Sans,11'\n"
               "} else {\n"
               "  set terminal png size %d,%d noenhanced\n"
               "}\n",
               gp->width, gp->height, gp->width, gp->height);
  return RS_OK;
}

/* Removes the files in the private directory (gnuplot writes nothing else), then it. */
static void remove_dir(const char *dir)
{
  DIR *d = opendir(dir);
  if (d) {
    struct dirent *e;
    while ((e = readdir(d))) {
      if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
      char *p = join(dir, e->d_name);
      if (p) unlink(p);
      free(p);
    }
    closedir(d);
  }
  rmdir(dir);
}

void rs_gp_end(rs_gp *gp)
{
  if (gp->out) fclose(gp->out);
  if (gp->dir) remove_dir(gp->dir);
  for (int i = 0; i < gp->n_png; ++i) free(gp->final[i]);
  free(gp->final);
  free(gp->script);
  free(gp->dir);
  memset(gp, 0, sizeof *gp);
}

void rs_gp_printf(rs_gp *gp, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  if (gp->out) vfprintf(gp->out, fmt, ap);
  va_end(ap);
}

void rs_gp_string(rs_gp *gp, const char *s)
{
  if (!gp->out) return;
  /* gnuplot performs `command` and @macro substitution inside double-quoted strings but
   * nothing at all inside single-quoted ones, where '' is the only escape. A newline cannot
   * stand in one, so it is joined as 'a'."\n".'b', a constant string expression. */
  fputc('\'', gp->out);
  for (const unsigned char *p = (const unsigned char *)(s ? s : ""); *p; ++p) {
    if (*p == '\n') fputs("'.\"\\n\".'", gp->out);
    else if (*p == '\'') fputs("''", gp->out);
    else fputc(*p < 0x20 || *p == 0x7f ? ' ' : *p, gp->out);
  }
  fputc('\'', gp->out);
}

rs_status rs_gp_data(rs_gp *gp, int ncols, const double *const *cols, size_t n, char **name,
                     size_t *rows)
{
  char base[32];
  snprintf(base, sizeof base, "d%d.dat", gp->n_data++);
  *name = join(gp->dir, base);
  if (!*name) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  FILE *f = fopen(*name, "w");
  if (!f) return RS_ERROR(RS_ERR_IO, "cannot write '%s': %s", *name, strerror(errno));
  size_t written = 0;
  for (size_t i = 0; i < n; ++i) {
    int ok = 1;
    for (int c = 0; c < ncols; ++c) ok = ok && isfinite(cols[c][i]);
    if (!ok) continue;
    for (int c = 0; c < ncols; ++c) fprintf(f, c ? " %.10g" : "%.10g", cols[c][i]);
    fputc('\n', f);
    ++written;
  }
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return RS_ERROR(RS_ERR_IO, "cannot write '%s': %s", *name, strerror(errno));
  if (rows) *rows = written;
  return RS_OK;
}

static char *png_name(const rs_gp *gp, int i)
{
  char base[32];
  snprintf(base, sizeof base, "p%d.png", i);
  return join(gp->dir, base);
}

rs_status rs_gp_figure(rs_gp *gp, const char *final_path)
{
  char **f = realloc(gp->final, (size_t)(gp->n_png + 1) * sizeof *f);
  if (!f) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  gp->final = f;
  char *png = png_name(gp, gp->n_png);
  if (!png || !(f[gp->n_png] = strdup(final_path))) {
    free(png);
    return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  }
  ++gp->n_png;
  /* reset keeps the terminal; encoding is set again for old gnuplots that reset it */
  rs_gp_printf(gp, "\nreset\nset encoding utf8\nset output ");
  rs_gp_string(gp, png);
  rs_gp_printf(gp, "\n");
  free(png);
  gp->n_terms = 0;
  return RS_OK;
}

void rs_gp_plot_item(rs_gp *gp)
{
  rs_gp_printf(gp, gp->n_terms++ ? ", \\\n     " : "plot ");
}

void rs_gp_plot_end(rs_gp *gp)
{
  rs_gp_printf(gp, "\n");
  gp->n_terms = 0;
}

/* The last lines of gnuplot's messages, where it says what went wrong. */
static void log_tail(const char *path, char *buf, size_t size)
{
  buf[0] = '\0';
  FILE *f = fopen(path, "r");
  if (!f) return;
  char line[512], last[3][512] = {"", "", ""};
  int k = 0;
  while (fgets(line, sizeof line, f)) {
    line[strcspn(line, "\n")] = '\0';
    if (!line[0] || strspn(line, " ^") == strlen(line)) continue;
    snprintf(last[k++ % 3], sizeof last[0], "%s", line);
  }
  fclose(f);
  for (int i = k > 3 ? k - 3 : 0; i < k; ++i) {
    size_t used = strlen(buf);
    snprintf(buf + used, size - used, "%s%s", used ? " | " : "", last[i % 3]);
  }
}

static rs_status spawn_wait(rs_gp *gp, const char *program, const char *log)
{
  posix_spawn_file_actions_t fa;
  pid_t pid;
  char *argv[] = {(char *)program, gp->script, NULL};
  if (posix_spawn_file_actions_init(&fa) != 0) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  int err = posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  if (!err) err = posix_spawn_file_actions_addopen(&fa, 1, log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
  if (!err) err = posix_spawn_file_actions_adddup2(&fa, 1, 2);
  if (!err) err = posix_spawnp(&pid, program, &fa, NULL, argv, environ);
  posix_spawn_file_actions_destroy(&fa);
  if (err == ENOENT)
    return RS_ERROR(RS_ERR_IO, "%s not found (apt-get install gnuplot-nox)", program);
  if (err) return RS_ERROR(RS_ERR_IO, "cannot start %s: %s", program, strerror(err));
  int status;
  /* waitpid is interrupted only by a signal the program catches (the CLI's SIGINT, SIGTERM,
   * SIGHUP, SIGQUIT): gnuplot is stopped too, and the session fails and cleans up. */
  int stopped = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return RS_ERROR(RS_ERR_IO, "waiting for %s: %s", program, strerror(errno));
    if (!stopped++) kill(pid, SIGTERM);
  }
  if (stopped) return RS_ERROR(RS_ERR_INTERRUPTED, "plotting interrupted (%s stopped)", program);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return RS_OK;
  char tail[1024];
  log_tail(log, tail, sizeof tail);
  if (WIFSIGNALED(status))
    return RS_ERROR(RS_ERR_IO, "%s was killed by signal %d%s%s", program, WTERMSIG(status),
                    tail[0] ? ": " : "", tail);
  return RS_ERROR(RS_ERR_IO, "%s failed (exit status %d)%s%s", program, WEXITSTATUS(status),
                  tail[0] ? ": " : "", tail);
}

/* Copies a finished PNG onto its final name, whole or not at all. */
static rs_status stage_png(const char *png, const char *final_path)
{
  FILE *f = fopen(png, "rb");
  if (!f) return RS_ERROR(RS_ERR_IO, "gnuplot wrote no plot for '%s'", final_path);
  size_t cap = 1 << 16, n = 0, got;
  char *buf = malloc(cap);
  while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
    n += got;
    if (n == cap) {
      char *b = realloc(buf, cap *= 2);
      if (!b) free(buf);
      buf = b;
    }
  }
  int bad = ferror(f);
  fclose(f);
  rs_status st = RS_OK;
  if (!buf) st = RS_ERROR(RS_ERR_MEMORY, "out of memory for the plot '%s'", final_path);
  else if (bad) st = RS_ERROR(RS_ERR_IO, "cannot read gnuplot's plot for '%s'", final_path);
  else if (n == 0) st = RS_ERROR(RS_ERR_IO, "gnuplot wrote an empty plot for '%s'", final_path);
  else st = rs_atomic_file_write(final_path, buf, n);
  free(buf);
  return st;
}

rs_status rs_gp_run(rs_gp *gp, const char *program)
{
  if (!program || !program[0]) program = "gnuplot";
  rs_gp_printf(gp, "\nunset output\n");
  int bad = ferror(gp->out);
  int closed = fclose(gp->out);
  gp->out = NULL;
  if (bad || closed != 0)
    return RS_ERROR(RS_ERR_IO, "cannot write the gnuplot script '%s'", gp->script);
  char *log = join(gp->dir, "gnuplot.log");
  if (!log) return RS_ERROR(RS_ERR_MEMORY, "out of memory");
  rs_status st = spawn_wait(gp, program, log);
  free(log);
  for (int i = 0; st == RS_OK && i < gp->n_png; ++i) {
    char *png = png_name(gp, i);
    st = png ? stage_png(png, gp->final[i]) : RS_ERROR(RS_ERR_MEMORY, "out of memory");
    free(png);
  }
  return st;
}
