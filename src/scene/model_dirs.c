/* The folders of shipped material models (model_dirs.h).
 *
 * An installed libreelsim or reelsim program finds <prefix>/share/reelsim/models from
 * where its own code sits (dladdr1): <prefix>/lib/libreelsim.so or <prefix>/bin/reelsim,
 * plus the configured relative path from that folder to the models. A program run from
 * the build tree uses the source tree's models/ instead, so an edit there is seen at once
 * and an older install never shadows it. */
#define _GNU_SOURCE /* dladdr1 */
#include "scene/model_dirs.h"

#include <dlfcn.h>
#include <limits.h>
#include <link.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Defaults for a build without CMake's definitions: the relative paths of a
 * GNUInstallDirs layout, no build tree. */
#ifndef RS_MODELS_FROM_LIBDIR
#define RS_MODELS_FROM_LIBDIR "../share/reelsim/models"
#endif
#ifndef RS_MODELS_FROM_BINDIR
#define RS_MODELS_FROM_BINDIR "../share/reelsim/models"
#endif
#ifndef RS_INSTALL_MODELS_DIR
#define RS_INSTALL_MODELS_DIR "/usr/local/share/reelsim/models"
#endif

static const char module_anchor = 0; /* an address inside this library or program */

static int add(char dirs[][RS_PATH_MAX], int n, int max, const char *dir)
{
  if (n >= max || !dir || !dir[0] || strlen(dir) >= RS_PATH_MAX) return n;
  for (int i = 0; i < n; ++i)
    if (strcmp(dirs[i], dir) == 0) return n;
  memcpy(dirs[n], dir, strlen(dir) + 1);
  return n + 1;
}

/* The folder of the shared library or program holding this code, resolved; 0 if unknown.
 * In a program (the reelsim program links the library's objects) glibc names it by its
 * argv[0], bare when it was found through PATH: the kernel's /proc/self/exe then. */
static int module_dir(char *out, size_t size)
{
  Dl_info info;
  struct link_map *map = NULL;
  char real[PATH_MAX], exe[PATH_MAX];
  if (!dladdr1(&module_anchor, &info, (void **)&map, RTLD_DL_LINKMAP) || !info.dli_fname)
    return 0;
  const char *name = info.dli_fname;
  if (map && map->l_name && map->l_name[0] == '\0') { /* the main program */
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
      exe[n] = '\0';
      name = exe;
    }
  }
  if (!realpath(name, real)) return 0;
  char *slash = strrchr(real, '/');
  if (!slash) return 0;
  *slash = '\0';
  return snprintf(out, size, "%s", real[0] ? real : "/") < (int)size;
}

#if defined(RS_BUILD_TREE_DIR) && defined(RS_SOURCE_MODELS_DIR)
static int under(const char *path, const char *dir)
{
  size_t n = strlen(dir);
  return n > 0 && strncmp(path, dir, n) == 0 && (path[n] == '/' || path[n] == '\0');
}
#endif

int rsi_ys_model_dirs(char dirs[][RS_PATH_MAX], int max)
{
  int n = 0;
  const char *env = getenv("REELSIM_MODELS");
  if (env && env[0]) n = add(dirs, n, max, env);

  char here[PATH_MAX], path[RS_PATH_MAX];
  int known = module_dir(here, sizeof here);
#if defined(RS_BUILD_TREE_DIR) && defined(RS_SOURCE_MODELS_DIR)
  char build[PATH_MAX];
  if (known && realpath(RS_BUILD_TREE_DIR, build) && under(here, build))
    return add(dirs, n, max, RS_SOURCE_MODELS_DIR);
#endif
  if (known) {
    if (snprintf(path, sizeof path, "%s/%s", here, RS_MODELS_FROM_LIBDIR) < (int)sizeof path)
      n = add(dirs, n, max, path);
    if (snprintf(path, sizeof path, "%s/%s", here, RS_MODELS_FROM_BINDIR) < (int)sizeof path)
      n = add(dirs, n, max, path);
  }
  n = add(dirs, n, max, RS_INSTALL_MODELS_DIR);
#if defined(RS_BUILD_TREE_DIR) && defined(RS_SOURCE_MODELS_DIR)
  if (!known) n = add(dirs, n, max, RS_SOURCE_MODELS_DIR); /* cannot tell: the last resort */
#endif
  return n;
}
