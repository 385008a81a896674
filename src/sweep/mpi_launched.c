/* Launched by mpirun (sweep/mpi_module.h)? Linked into the program and into the module. */
#include <stdlib.h>

#include "sweep/mpi_module.h"

int sweep_mpi_launched(void)
{
  static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE",
                                     "PMI_RANK"};
  for (size_t i = 0; i < sizeof vars / sizeof vars[0]; ++i)
    if (getenv(vars[i])) return 1;
  return 0;
}
