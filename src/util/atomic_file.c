/* Temporary name, target checks and the final rename; see atomic_file.h. */

#include "util/atomic_file.h"
#include "util/error.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <time.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void errno_text(int err, char *buf, size_t len)
{
  if (strerror_r(err, buf, len) != 0) snprintf(buf, len, "errno %d", err);
}

/* The directory part of `path` ("." when there is none), in a malloc'd string. */
static char *dir_of(const char *path)
{
  const char *slash = strrchr(path, '/');
  if (!slash) return strdup(".");
  size_t n = slash == path ? 1 : (size_t)(slash - path);
  char *dir = malloc(n + 1);
  if (!dir) return NULL;
  memcpy(dir, path, n);
  dir[n] = '\0';
  return dir;
}

static rs_status check_dir(const char *path, const char *dir)
{
  struct stat sb;
  char why[256];
  if (stat(dir, &sb) != 0) {
    int err = errno;
    if (err == ENOENT)
      return RS_ERROR(RS_ERR_IO, "cannot create output file '%s' (directory '%s' does not exist)",
                      path, dir);
    if (err == ENOTDIR)
      return RS_ERROR(RS_ERR_IO,
                      "cannot create output file '%s' (a part of '%s' is not a directory)", path,
                      dir);
    errno_text(err, why, sizeof why);
    return RS_ERROR(RS_ERR_IO, "cannot create output file '%s' (directory '%s': %s)", path, dir,
                    why);
  }
  if (!S_ISDIR(sb.st_mode))
    return RS_ERROR(RS_ERR_IO, "cannot create output file '%s' ('%s' is not a directory)", path,
                    dir);
  if (access(dir, W_OK | X_OK) != 0) {
    errno_text(errno, why, sizeof why);
    return RS_ERROR(RS_ERR_IO,
                    "cannot create output file '%s' (directory '%s' is not writable: %s)", path,
                    dir, why);
  }
  return RS_OK;
}

rs_status rs_atomic_file_check_target(const char *path)
{
  struct stat sb;
  char *dir = dir_of(path);
  if (!dir) return RS_ERROR(RS_ERR_MEMORY, "out of memory checking output file '%s'", path);
  rs_status st = check_dir(path, dir);
  free(dir);
  if (st != RS_OK) return st;
  /* stat follows links: a link to /dev/null must not get a regular file renamed onto it
   * (as root that would replace the device node). */
  if (stat(path, &sb) == 0) {
    if (S_ISDIR(sb.st_mode))
      return RS_ERROR(RS_ERR_IO, "cannot write output file '%s': it is a directory", path);
    if (!S_ISREG(sb.st_mode))
      return RS_ERROR(RS_ERR_IO,
                      "cannot write output file '%s': it exists and is not a regular file", path);
  }
  return RS_OK;
}

/* Creates a new temporary beside `path` exclusively (never reusing an existing name,
 * which may be another process's); *fd and *tmp (malloc'd) are the caller's. */
static rs_status create_temp(const char *path, char **tmp, int *fd)
{
  static atomic_ulong counter;
  char why[256];
  size_t len = strlen(path) + 64;
  char *name = malloc(len);
  *tmp = NULL;
  *fd = -1;
  if (!name) return RS_ERROR(RS_ERR_MEMORY, "out of memory naming a temporary for '%s'", path);
  for (int tries = 0; tries < 1000; ++tries) {
    snprintf(name, len, "%s.tmp.%ld.%lu", path, (long)getpid(), atomic_fetch_add(&counter, 1));
    /* O_EXCL never opens an existing name, a planted symlink included (EEXIST: the next
     * number is tried); O_NOFOLLOW says the same to a reader of this line. */
    *fd = open(name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (*fd >= 0) {
      *tmp = name;
      return RS_OK;
    }
    if (errno != EEXIST) break;
  }
  errno_text(errno, why, sizeof why);
  rs_status st = RS_ERROR(RS_ERR_IO, "cannot create output file '%s' (temporary '%s'): %s", path,
                          name, why);
  free(name);
  return st;
}

static int write_all(int fd, const char *p, size_t size)
{
  while (size > 0) {
    ssize_t n = write(fd, p, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return -1;
    }
    p += n;
    size -= (size_t)n;
  }
  return 0;
}

/* Makes the rename itself durable; failing here loses nothing already written. */
static void sync_dir_of(const char *path)
{
  char *dir = dir_of(path);
  if (!dir) return;
  int dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    (void)fsync(dfd);
    close(dfd);
  }
  free(dir);
}

/* Is `name` "<base>.tmp.<pid>.<n>" (both numbers decimal)? Its pid in *pid. */
static int is_our_temp(const char *name, const char *base, long *pid)
{
  size_t nb = strlen(base);
  if (strncmp(name, base, nb) != 0 || strncmp(name + nb, ".tmp.", 5) != 0) return 0;
  const char *p = name + nb + 5;
  char *end;
  errno = 0;
  long v = strtol(p, &end, 10);
  if (end == p || *end != '.' || errno || v <= 0) return 0;
  p = end + 1;
  (void)strtoul(p, &end, 10);
  if (end == p || *end != '\0') return 0;
  *pid = v;
  return 1;
}

void rs_atomic_file_clean_stale(const char *path)
{
  char *dir = dir_of(path);
  const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
  DIR *d = dir && base[0] ? opendir(dir) : NULL;
  if (!d) {
    free(dir);
    return;
  }
  time_t now = time(NULL);
  struct dirent *e;
  while ((e = readdir(d))) {
    long pid;
    if (!is_our_temp(e->d_name, base, &pid) || pid == (long)getpid()) continue;
    /* another process's, as far as this machine can tell, only if that pid is alive */
    if (kill((pid_t)pid, 0) == 0 || errno != ESRCH) continue;
    size_t n = strlen(dir) + strlen(e->d_name) + 2;
    char *full = malloc(n);
    if (!full) break;
    snprintf(full, n, "%s/%s", dir, e->d_name);
    struct stat sb;
    if (lstat(full, &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_uid == geteuid() &&
        now - sb.st_mtime >= RS_ATOMIC_STALE_SECONDS)
      unlink(full);
    free(full);
  }
  closedir(d);
  free(dir);
}

rs_status rs_atomic_file_prepare(const char *path, const void *data, size_t size, char **tmp)
{
  char why[256];
  int fd;
  rs_atomic_file_clean_stale(path);
  rs_status st = create_temp(path, tmp, &fd);
  if (st != RS_OK) return st;
  /* fsync before rename: otherwise a crash soon after can leave the new name on a file
   * whose data never reached the disk. close() can report a late error (NFS). */
  const char *failed = NULL;
  int err = 0;
  if (write_all(fd, data, size) != 0)
    failed = "write";
  else if (fsync(fd) != 0)
    failed = "flush to disk";
  if (failed) err = errno;
  if (close(fd) != 0 && !failed) {
    failed = "close";
    err = errno;
  }
  if (failed) {
    errno_text(err, why, sizeof why);
    st = RS_ERROR(RS_ERR_IO, "cannot %s output file '%s' (temporary '%s'): %s", failed, path,
                  *tmp, why);
    rs_atomic_file_abort(tmp);
  }
  return st;
}

rs_status rs_atomic_file_commit(const char *path, char **tmp)
{
  char why[256];
  rs_status st = RS_OK;
  if (rename(*tmp, path) != 0) {
    errno_text(errno, why, sizeof why);
    st = RS_ERROR(RS_ERR_IO, "cannot rename the temporary onto output file '%s' (temporary '%s'): %s",
                  path, *tmp, why);
    rs_atomic_file_abort(tmp);
    return st;
  }
  sync_dir_of(path);
  free(*tmp);
  *tmp = NULL;
  return st;
}

void rs_atomic_file_abort(char **tmp)
{
  if (!tmp || !*tmp) return;
  unlink(*tmp);
  free(*tmp);
  *tmp = NULL;
}

rs_status rs_atomic_file_write(const char *path, const void *data, size_t size)
{
  char *tmp = NULL;
  rs_status st = rs_atomic_file_prepare(path, data, size, &tmp);
  if (st == RS_OK) st = rs_atomic_file_commit(path, &tmp);
  return st;
}
