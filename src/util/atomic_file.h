/* Atomic files (base layer, internal): putting a finished file in place. The bytes go to
 * "<path>.tmp.<pid>.<n>" beside the target (created O_EXCL | O_NOFOLLOW: never an existing
 * name or a planted symlink), are flushed to disk (fsync), and the temporary is renamed
 * onto `path`; every failure names the file and gives errno's text. rename() within one directory is atomic on POSIX file systems,
 * so readers see either the old file or the whole new one, never a part. */
#ifndef RS_UTIL_ATOMIC_FILE_H
#define RS_UTIL_ATOMIC_FILE_H

#include <stddef.h>

#include "reelsim/status.h"

/* Checks, before any work, what users most often get wrong: the directory of `path`
 * is missing, not a directory or not writable, or `path` itself is a directory or a
 * device. Records RS_ERR_IO with a message naming the path. */
rs_status rs_atomic_file_check_target(const char *path);

/* Writes `size` bytes to a new temporary beside `path` and renames it onto `path`.
 * On failure the temporary is removed and an existing file at `path` is untouched;
 * the error (RS_ERR_IO) names the path and gives the system's reason. */
rs_status rs_atomic_file_write(const char *path, const void *data, size_t size);

/* The same in two steps, for several files that should appear together: prepare writes
 * the bytes to a flushed temporary beside `path` (*tmp, malloc'd); commit renames it onto
 * `path` and frees *tmp; abort removes the temporary and frees *tmp (NULL is fine).
 * Preparing every file before committing any keeps a failure from leaving a mix. */
rs_status rs_atomic_file_prepare(const char *path, const void *data, size_t size, char **tmp);
rs_status rs_atomic_file_commit(const char *path, char **tmp);
void rs_atomic_file_abort(char **tmp);

/* Stale temporaries: before a temporary for `path` is made, every "<path>.tmp.<pid>.<n>"
 * beside it that is a regular file owned by this user, whose pid is not a live process on
 * this machine (kill(pid, 0) fails with ESRCH) and that has not been modified for
 * RS_ATOMIC_STALE_SECONDS (a writer on another machine sharing the folder keeps its file
 * fresh) is removed: what a killed reelsim (SIGKILL, a power cut) left. Best effort. */
#define RS_ATOMIC_STALE_SECONDS 600
void rs_atomic_file_clean_stale(const char *path);

#endif
