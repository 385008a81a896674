/* sweep.h's MPI functions in a program whose MPI is a module (sweep/mpi_module.h): one
 * process of rank 0 until sweep_mpi_begin, under mpirun, has opened reelsim-mpi.so; then
 * the module's. The module is looked for beside the program (the build tree), then in
 * <libdir>/reelsim relative to it (an installed program: RS_MPI_MODULE_FROM_BINDIR). */
#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "reelsim/clock.h"
#include "sweep/app_error.h"
#include "sweep/mpi_module.h"

#ifndef RS_MPI_MODULE_FROM_BINDIR
#define RS_MPI_MODULE_FROM_BINDIR "../lib/reelsim"
#endif

static const sweep_mpi_ops *ops;

static const sweep_mpi_host host = {SWEEP_MPI_ABI, rs_clock_wall, sweep_result_alloc,
                                    sweep_run_one, sweep_say_failed};

/* Opens `path` and takes its table; 0 and why in why[] if not. */
static int open_module(const char *path, char *why, size_t why_size)
{
  /* RTLD_GLOBAL: Open MPI's own components, which it opens later, look up its symbols */
  void *h = dlopen(path, RTLD_NOW | RTLD_GLOBAL);
  if (!h) {
    snprintf(why, why_size, "%s", dlerror());
    return 0;
  }
  sweep_mpi_entry_fn entry = (sweep_mpi_entry_fn)dlsym(h, SWEEP_MPI_ENTRY); /* POSIX allows it */
  if (entry) ops = entry(&host);
  if (!ops) {
    snprintf(why, why_size, "%s: not this build's MPI module", path);
    dlclose(h);
    return 0;
  }
  return 1; /* kept open to the end: MPI is never unloaded */
}

static int load(void)
{
  char exe[PATH_MAX], path[PATH_MAX + 64], why[PATH_MAX + 256] = "";
  ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) {
    fprintf(stderr, "reelsim: sweep: started by mpirun, but the program cannot find its own "
                    "folder (/proc/self/exe): running as one process\n");
    return 0;
  }
  exe[n] = '\0';
  char *slash = strrchr(exe, '/'); /* an absolute path: there is one */
  if (slash) *slash = '\0';
  snprintf(path, sizeof path, "%s/%s", exe, SWEEP_MPI_FILE);
  if (access(path, F_OK) != 0)
    snprintf(path, sizeof path, "%s/%s/%s", exe, RS_MPI_MODULE_FROM_BINDIR, SWEEP_MPI_FILE);
  if (open_module(path, why, sizeof why)) return 1;
  fprintf(stderr, "reelsim: sweep: started by mpirun, but its MPI module does not load (%s): "
                  "running as one process\n", why);
  return 0;
}

void sweep_mpi_begin(void)
{
  if (!ops && sweep_mpi_launched() && !load()) return;
  if (ops) ops->begin();
}
void sweep_mpi_end(void)
{
  if (ops) ops->end();
}
int sweep_mpi_rank(void) { return ops ? ops->rank() : 0; }
int sweep_mpi_size(void) { return ops ? ops->size() : 1; }
int sweep_mpi_agree(int code) { return ops ? ops->agree(code) : code; }
int sweep_mpi_poll(int local) { return ops ? ops->poll(local) : local; }
void sweep_mpi_notify(int value)
{
  if (ops) ops->notify(value);
}
int sweep_mpi_peer_stop(int *from)
{
  if (ops) return ops->peer_stop(from);
  if (from) *from = -1;
  return 0;
}
void sweep_mpi_settle(void)
{
  if (ops) ops->settle();
}
sweep_agreement sweep_mpi_agree_all(int code, uint64_t digest, const char *text,
                                    int (*caught)(void))
{
  if (ops) return ops->agree_all(code, digest, text, caught);
  return (sweep_agreement){code, caught ? caught() : 0, 0};
}
rs_status sweep_mpi_wind(const sweep_spec *spec, sweep_result *out)
{
  if (ops) return ops->wind(spec, out);
  memset(out, 0, sizeof *out);
  return APP_ERROR(RS_ERR_INTERNAL, "MPI was not started (no mpirun)");
}
