/* Help texts. */
#include <string.h>

#include "cli/cli.h"

static const char general[] =
    "usage: reelsim <command> [options]\n"
    "\n"
    "Simulates winding a reel (paper, film) and the stresses wound into it.\n"
    "\n"
    "commands:\n"
    "  run SCENE      wind the reel a scene file describes, write the result (HDF5)\n"
    "                 and print a summary\n"
    "  check SCENE    load and check a scene; print its active effects and the\n"
    "                 resolved scene (defaults filled, overrides applied)\n"
    "  compare SCENE1 SCENE2 ...\n"
    "                 wind several scenes in parallel, print their key figures side\n"
    "                 by side and write them all to one HDF5 file (compare.h5)\n"
    "  plot FILE.h5   PNG plots of a run or compare file (needs gnuplot)\n"
    "  study SCENE    what accuracy costs in time: the scene wound at many numerical\n"
    "                 settings against a tight reference; a table, study.h5, study.csv\n"
    "                 and an error-against-time plot with the Pareto front\n"
    "  help [CMD]     this text, or one command's\n"
    "\n"
    "options:\n"
    "  --version      print the version\n"
    "  -h, --help     help (also after a command: reelsim run --help)\n"
    "\n"
    "exit status: 0 ok, 2 bad input or usage, 3 the solver failed,\n"
    "             130 interrupted (Ctrl-C), 1 anything else\n"
    "Scene files: docs/scenes.md. Command line: docs/cli.md.\n";

static const char set_help[] =
    "  --set key.path=value\n"
    "                 override one value of the scene before it is checked (repeatable);\n"
    "                 e.g. --set winding.tension=300 --set numerics.rtol=1e-8\n"
    "                      --set material=pet-film --set nip.friction.roll=0.25\n";

static const char run_help[] =
    "usage: reelsim run SCENE [-o FILE] [--csv DIR] [--set key.path=value ...] [--quiet]\n"
    "                         [--keep-partial]\n"
    "\n"
    "Winds the reel SCENE describes layer by layer, writes the result to an HDF5 file\n"
    "(output.file of the scene, or FILE) and prints a summary: active effects, final\n"
    "radius, layers, core pressure, peak pressure, least hoop stress, wound-on tension\n"
    "range, wall time, and the defect-risk indicators (docs/defects.md).\n"
    "\n"
    "options:\n"
    "  -o, --output FILE\n"
    "                 write the result here (same as --set output.file=FILE)\n"
    "  --csv DIR      also write DIR/<scene>-profile.csv and DIR/<scene>-wot.csv\n"
    "                 (DIR must exist)\n"
    "%s"
    "  -q, --quiet    print nothing but errors (no summary, no progress bar)\n"
    "  --keep-partial when the solver fails or the run is interrupted, still write the\n"
    "                 layers finished to the output file, marked complete = 0\n"
    "\n"
    "Ctrl-C stops the run after the current step: no file is written, exit status 130\n"
    "(SIGTERM the same, 143).\n"
    "exit status: 0 ok, 2 bad input, 3 the solver failed, 130 interrupted, 1 other\n";

static const char check_help[] =
    "usage: reelsim check SCENE [--set key.path=value ...]\n"
    "\n"
    "Loads and checks SCENE like `run` would, without winding anything: prints the\n"
    "active effects and the resolved scene (material inlined, defaults filled,\n"
    "overrides applied), exactly what `run` would record in its output file.\n"
    "\n"
    "options:\n"
    "%s"
    "\n"
    "exit status: 0 the scene is good, 2 bad input\n";

static const char compare_help[] =
    "usage: reelsim compare SCENE1 SCENE2 ... [-o FILE] [--set key.path=value ...] [--quiet]\n"
    "\n"
    "Loads and checks every scene first (bad input in any: exit 2, nothing wound), winds\n"
    "them in parallel (one thread per core), prints a table of their key figures (layers,\n"
    "final radius, core pressure, peak pressure, least hoop stress, wound-on tension\n"
    "range, wall time) and writes all of them to one HDF5 file: /runs/<n>-<scene>/ per\n"
    "scene (the layout of a run file) and /summary (docs/output.md).\n"
    "\n"
    "options:\n"
    "  -o, --output FILE\n"
    "                 write the comparison here (default compare.h5)\n"
    "%s"
    "                 (applied to every scene)\n"
    "  -q, --quiet    print nothing but errors\n"
    "\n"
    "If a run fails the others still finish and are reported, but no file is written.\n"
    "exit status: 0 ok, 2 bad input in any scene, 3 a run's solver failed,\n"
    "             130 interrupted, 1 other\n";

static const char plot_help[] =
    "usage: reelsim plot FILE.h5 [-o DIR] [--quiet]\n"
    "\n"
    "Draws PNG plots of a reelsim file with gnuplot into DIR (default: the current\n"
    "directory), named <file name>-<plot>.png: interlayer pressure and hoop stress\n"
    "against radius (with history stages and defect ranges when the file has them),\n"
    "the wound-on tension with the recipe, nip pressure and shear profiles when the\n"
    "file has /nip/profiles; for a compare file the runs overlaid, one plot each.\n"
    "\n"
    "options:\n"
    "  -o, --output DIR\n"
    "                 write the PNG files here (must exist)\n"
    "  -q, --quiet    print nothing but errors\n"
    "\n"
    "exit status: 0 ok, 2 FILE is not a reelsim file or DIR is missing,\n"
    "             1 gnuplot missing or failed, other errors\n";

static const char study_help[] =
    "usage: reelsim study SCENE [-o DIR] [--set key.path=value ...] [--quick] [--jobs N] [--quiet]\n"
    "\n"
    "Winds SCENE at many numerical settings and shows what accuracy costs in time\n"
    "(docs/accuracy.md). First a reference with every knob at its tightest (rtol 1e-9,\n"
    "1 layer per step; with a nip: solved at every layer, 96 contact nodes, 512 series\n"
    "terms) and a tighter second one (rtol 1e-10, 128 nodes, 1024 terms) that measures how\n"
    "far the reference has converged; then the shipped defaults; then one knob at a time\n"
    "(numerics.rtol, numerics.layers_per_step, nip.nodes, nip.terms, nip.T0_rtol,\n"
    "nip.update_every, output.history_every; knobs the scene does not use are skipped)\n"
    "and a small grid. Each run's error against the reference in core pressure, peak\n"
    "pressure, sigma_r and sigma_theta profiles and the final T0, and its time, go\n"
    "into a table, DIR/study.h5, DIR/study.csv and DIR/study.png (error against CPU time,\n"
    "Pareto front, defaults highlighted). The runs use the scene as given plus --set.\n"
    "\n"
    "options:\n"
    "  -o, --output DIR\n"
    "                 where the files go (default study-<scene name>; made if missing)\n"
    "%s"
    "                 (applied to every run, e.g. a smaller roll for a quicker study)\n"
    "  --quick        fewer levels per knob and a smaller grid (same references)\n"
    "  -j, --jobs N   wind N runs at once (default 1: the times are the measurement)\n"
    "  -q, --quiet    print nothing but errors\n"
    "\n"
    "exit status: 0 ok, 2 bad input (nothing wound), 3 the reference or default run\n"
    "             failed, 130 interrupted, 1 other (files, gnuplot)\n";

int cli_usage(FILE *out, const char *cmd)
{
  if (!cmd) {
    fputs(general, out);
    return CLI_EXIT_OK;
  }
  if (strcmp(cmd, "run") == 0) {
    fprintf(out, run_help, set_help);
    return CLI_EXIT_OK;
  }
  if (strcmp(cmd, "check") == 0) {
    fprintf(out, check_help, set_help);
    return CLI_EXIT_OK;
  }
  if (strcmp(cmd, "compare") == 0) {
    fprintf(out, compare_help, set_help);
    return CLI_EXIT_OK;
  }
  if (strcmp(cmd, "plot") == 0) {
    fputs(plot_help, out);
    return CLI_EXIT_OK;
  }
  if (strcmp(cmd, "study") == 0) {
    fprintf(out, study_help, set_help);
    return CLI_EXIT_OK;
  }
  if (strcmp(cmd, "help") == 0) {
    fputs(general, out);
    return CLI_EXIT_OK;
  }
  return cli_fail(CLI_EXIT_USAGE,
                  "help: unknown command '%s' (commands: run, check, compare, plot, study, help)", cmd);
}
