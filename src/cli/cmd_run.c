/* reelsim run: placeholder until the roll engine (rs_reel_wind) and the HDF5 output
 * (rs_output_write) are on main; the real command replaces this file then. */
#include "cli/cli.h"

int cli_run(const cli_args *a)
{
  (void)a;
  return cli_fail(CLI_EXIT_OTHER, "run: not available in this build yet (use check)");
}
