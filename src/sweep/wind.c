/* sweep_wind: over MPI ranks when mpirun started more than one, else over threads. Its own
 * file, above both ways, so that neither calls the other (the layer check's call graph). */
#include "sweep/sweep.h"

rs_status sweep_wind(const sweep_spec *spec, sweep_result *out)
{
  if (sweep_mpi_size() > 1) return sweep_mpi_wind(spec, out);
  return sweep_wind_threads(spec, out);
}
