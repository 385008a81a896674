/* The command and option tables (see options.h); the texts follow docs/cli.md. */
#include "cli/options.h"

#include <string.h>

#define SCENE_CMDS (CLI_RUN | CLI_CHECK | CLI_COMPARE | CLI_STUDY | CLI_NIP | CLI_SWEEP | CLI_OPTIMIZE)

const cli_option cli_options[] = {
    {CLI_OPT_OUTPUT, "output", 'o', "FILE", "a file name", CLI_RUN | CLI_CHECK,
     "write the result here (the same as\n"
     "--set output.file=FILE)"},
    {CLI_OPT_OUTPUT, "output", 'o', "FILE", "a file name", CLI_COMPARE,
     "write the comparison here (default compare.h5)"},
    {CLI_OPT_OUTPUT, "output", 'o', "DIR", "a directory", CLI_PLOT,
     "write the PNG files here (default: the current directory;\n"
     "made if missing, as mkdir -p does)"},
    {CLI_OPT_OUTPUT, "output", 'o', "DIR", "a directory", CLI_STUDY,
     "where the files go (default study-<scene name>; made when\n"
     "the runs are done, as mkdir -p does)"},
    {CLI_OPT_OUTPUT, "output", 'o', "FILE", "a file name", CLI_SWEEP,
     "write the sweep here (default sweep.h5)"},
    {CLI_OPT_VARY, "vary", 0, "KEY=LO:HI:N", "KEY=LO:HI:N or KEY=V1,V2,...", CLI_SWEEP,
     "vary scene key KEY over N values evenly spaced from LO\n"
     "to HI, or over a list KEY=V1,V2,... (numbers or words);\n"
     "repeatable: one --vary per key (at least one)"},
    {CLI_OPT_SAMPLE, "sample", 0, "grid|lhs:R", "grid or lhs:R", CLI_SWEEP,
     "grid (default): every combination of the values;\n"
     "lhs:R: R Latin-hypercube samples of the keys' ranges"},
    {CLI_OPT_CSV, "csv", 0, "FILE", "a file name", CLI_SWEEP,
     "also write one CSV row per run (the keys, then the\n"
     "figures) to FILE"},
    {CLI_OPT_THREADS, "threads", 0, "K", "a number of threads", CLI_SWEEP,
     "wind K runs at once, 1 to 256 (default: one per core;\n"
     "under mpirun each rank winds one run at a time)"},
    {CLI_OPT_PROFILES, "profiles", 0, NULL, NULL, CLI_SWEEP,
     "also write every run's final radius, sigma_r and\n"
     "sigma_theta profiles (/sweep/profiles/<i>)"},
    {CLI_OPT_OUTPUT, "output", 'o', "FILE", "a file name", CLI_OPTIMIZE,
     "write the best scene here, as YAML runnable as is\n"
     "(default <scene>-best.yaml)"},
    {CLI_OPT_VARY, "vary", 0, "KEY=LO:HI", "KEY=LO:HI", CLI_OPTIMIZE,
     "search scene value KEY in [LO, HI] (repeatable), e.g.\n"
     "--vary winding.tension=100:600"},
    {CLI_OPT_MINIMIZE, "minimize", 0, "FIGURE", "a figure", CLI_OPTIMIZE,
     "the figure to make least (docs/optimize.md: core_pressure,\n"
     "peak_pressure, ..., misfit, or a varied key)"},
    {CLI_OPT_MAXIMIZE, "maximize", 0, "FIGURE", "a figure", CLI_OPTIMIZE,
     "the figure to make greatest (one of --minimize and\n"
     "--maximize)"},
    {CLI_OPT_SUBJECT_TO, "subject-to", 0, "FIGURE<=X", "FIGURE<=X or FIGURE>=X", CLI_OPTIMIZE,
     "a constraint, FIGURE<=X or FIGURE>=X (repeatable), e.g.\n"
     "--subject-to 'core_pressure<=2e6'"},
    {CLI_OPT_TARGET_PROFILE, "target-profile", 0, "FILE.csv", "a CSV file", CLI_OPTIMIZE,
     "radius (m), pressure (Pa) pairs: the figure misfit is the\n"
     "RMS difference of the final pressure profile from them"},
    {CLI_OPT_HISTORY, "history", 0, "FILE.h5", "a file name", CLI_OPTIMIZE,
     "write every run here (default: the -o name with .h5)"},
    {CLI_OPT_VARIANT, "variant", 0, "'NAME: KEY=VALUE ...'", "'NAME: KEY=VALUE ...'", CLI_COMPARE,
     "a run of the scene before it with these overrides (after\n"
     "--set), named NAME, e.g. --variant 'hyp30: winding.tension.end=84';\n"
     "separate several KEY=VALUE by spaces or ';'; 'NAME:' alone is\n"
     "the scene as it is. A scene followed by variants runs as its\n"
     "variants only (repeatable)"},
    {CLI_OPT_CSV, "csv", 0, "DIR", "a directory", CLI_COMPARE,
     "also write each run's CSV files (as run --csv) to DIR,\n"
     "named by the run (01-taper-profile.csv, ...)"},
    {CLI_OPT_CSV, "csv", 0, "DIR", "a directory", CLI_RUN,
     "also write DIR/<scene>-profile.csv and\n"
     "DIR/<scene>-wot.csv, DIR/<scene>-history.csv when the\n"
     "scene records a history, DIR/<scene>-storage.csv when it\n"
     "has storage stages (DIR made if missing, as mkdir -p does)"},
    {CLI_OPT_RADIUS, "radius", 0, "R", "a roll radius in metres", CLI_NIP,
     "the roll radius (m) at which to solve the nip (required)"},
    {CLI_OPT_SET, "set", 's', "key.path=value", "key.path=value", SCENE_CMDS & ~CLI_COMPARE & ~CLI_STUDY & ~CLI_SWEEP,
     "override one value of the scene before it is checked\n"
     "(repeatable; also --set=key.path=value), e.g.\n"
     "--set winding.tension=300 --set material=pet-film"},
    {CLI_OPT_SET, "set", 's', "key.path=value", "key.path=value", CLI_COMPARE,
     "override one value in every scene (repeatable; also\n"
     "--set=key.path=value)"},
    {CLI_OPT_SET, "set", 's', "key.path=value", "key.path=value", CLI_SWEEP,
     "override one value in every run, before the --vary\n"
     "values (repeatable; also --set=key.path=value)"},
    {CLI_OPT_SET, "set", 's', "key.path=value", "key.path=value", CLI_STUDY,
     "override one value in every run (repeatable; also\n"
     "--set=key.path=value), e.g. a smaller roll for a quicker\n"
     "study"},
    {CLI_OPT_QUICK, "quick", 0, NULL, NULL, CLI_STUDY,
     "fewer levels per knob and a smaller grid (same references)"},
    {CLI_OPT_JOBS, "jobs", 'j', "N", "a number of threads", CLI_STUDY,
     "wind N runs at once, 1 to 64 (default 1: the times are the\n"
     "measurement)"},
    {CLI_OPT_JSON, "json", 0, NULL, NULL, CLI_NIP,
     "print the solution as one JSON object (with the profiles)"},
    {CLI_OPT_JSON, "json", 0, NULL, NULL, CLI_RUN,
     "print the summary as one JSON object on stdout instead of\n"
     "the text (fields: docs/cli.md, \"JSON\")"},
    {CLI_OPT_JSON, "json", 0, NULL, NULL, CLI_COMPARE,
     "print the runs' summaries as one JSON object on stdout\n"
     "instead of the table (fields: docs/cli.md, \"JSON\")"},
    {CLI_OPT_KEEP_PARTIAL, "keep-partial", 0, NULL, NULL, CLI_RUN,
     "when the solver fails or the run is interrupted, still\n"
     "write the layers finished to the output file, marked\n"
     "complete = 0"},
    {CLI_OPT_QUIET, "quiet", 'q', NULL, NULL, CLI_RUN,
     "print nothing but errors (no summary, no progress line)"},
    {CLI_OPT_QUIET, "quiet", 'q', NULL, NULL, CLI_CHECK | CLI_COMPARE | CLI_PLOT | CLI_STUDY | CLI_SWEEP | CLI_OPTIMIZE,
     "print nothing but errors"},
    {CLI_OPT_VERBOSE, "verbose", 'v', NULL, NULL, CLI_EVERY,
     "with an error, also show where in reelsim's code it was\n"
     "found (for a bug report)"},
    {CLI_OPT_HELP, "help", 'h', NULL, NULL, CLI_EVERY, "this help"},
};
const int cli_n_options = (int)(sizeof cli_options / sizeof cli_options[0]);

const cli_command cli_commands[] = {
    {"run", CLI_RUN, "scene file", 0,
     "reelsim run SCENE [-o FILE] [--csv DIR] [--set key.path=value ...] [--quiet]\n"
     "                         [--json] [--keep-partial]",
     "wind the reel a scene file describes, write the result\n"
     "(HDF5) and print a summary",
     "Winds the reel SCENE describes layer by layer, writes the result to an HDF5 file\n"
     "(output.file of the scene, or FILE) and prints a summary: active effects, final\n"
     "radius, layers, core pressure, peak pressure, least hoop stress, wound-on tension\n"
     "range, wall time, and the defect-risk indicators (docs/defects.md).\n",
     "Ctrl-C stops the run after the current step: no file is written, exit status 130\n"
     "(SIGTERM the same, 143).\n"
     "exit status: 0 ok, 2 bad input, 3 the solver failed, 130 interrupted,\n"
     "             143 terminated, 1 other\n"},
    {"check", CLI_CHECK, "scene file", 0, "reelsim check SCENE [-o FILE] [--set key.path=value ...] [--quiet]",
     "load and check a scene; print its active effects and the\n"
     "resolved scene (defaults filled, overrides applied)",
     "Loads and checks SCENE like `run` would, without winding anything: prints the\n"
     "active effects and the resolved scene (material inlined, defaults filled,\n"
     "overrides applied), exactly what `run` would record in its output file.\n",
     "exit status: 0 the scene is good, 2 bad input\n"},
    {"compare", CLI_COMPARE, "scene file", 1,
     "reelsim compare SCENE1 SCENE2 ... [-o FILE] [--set key.path=value ...] [--quiet]\n"
     "                         [--json] [--csv DIR] [SCENE --variant 'NAME: KEY=VALUE ...' ...]",
     "wind several scenes in parallel, print their key figures\n"
     "side by side and write them all to one HDF5 file (compare.h5)",
     "Loads and checks every scene first (bad input in any: exit 2, nothing wound), winds\n"
     "them in parallel (one thread per core), prints a table of their key figures (layers,\n"
     "final radius, core pressure, peak pressure, least hoop stress, wound-on tension\n"
     "range, wall time) and writes all of them to one HDF5 file: /runs/<n>-<scene>/ per\n"
     "scene (the layout of a run file) and /summary (docs/output.md). Scenes with\n"
     "storage stages are stored too: a second table gives the figures after storage.\n"
     "A recipe is a --variant of a scene: its name and the overrides that make it.\n",
     "If a run fails the others still finish and are reported, but no file is written.\n"
     "exit status: 0 ok, 2 bad input in any scene, 3 a run's solver failed,\n"
     "             130 interrupted, 143 terminated, 1 other\n"},
    {"plot", CLI_PLOT, "file", 0, "reelsim plot FILE.h5 [-o DIR] [--quiet]",
     "PNG plots of a run, compare, sweep or study file (needs gnuplot)",
     "Draws PNG plots of a reelsim file with gnuplot into DIR (default: the current\n"
     "directory), named <file name>-<plot>.png: interlayer pressure and hoop stress\n"
     "against radius (with history stages and defect ranges when the file has them,\n"
     "and the roll spinning when it has /final_at_speed), the wound-on tension with the\n"
     "recipe, the air film when the file has /layers/air_film, nip pressure and shear\n"
     "profiles when the file has /nip/profiles; for a compare file the runs overlaid, one plot each; for a\n"
     "sweep file each figure against the parameter varied, or a heat map over the first\n"
     "two varied, and an optimisation's history (/optimize); for a study file (study.h5)\n"
     "the study's picture, <file name>-study.png.\n",
     "exit status: 0 ok, 2 FILE is not a reelsim file or DIR (or a parent of it) is\n"
     "             not a directory, 1 gnuplot missing or failed, other errors\n"},
    {"study", CLI_STUDY, "scene file", 0,
     "reelsim study SCENE [-o DIR] [--set key.path=value ...] [--quick] [--jobs N] [--quiet]",
     "what accuracy costs in time: the scene wound at many\n"
     "numerical settings against a tight reference; a table,\n"
     "study.h5, study.csv and an error-against-time plot with the\n"
     "Pareto front",
     "Winds SCENE at many numerical settings and shows what accuracy costs in time\n"
     "(docs/accuracy.md). First a reference with every knob at its tightest (rtol 1e-9,\n"
     "1 layer per step; with a nip: solved at every layer, 128 contact nodes, 512 series\n"
     "terms) and a tighter second one (rtol 1e-10, 160 nodes, 1024 terms) that measures how\n"
     "far the reference has converged; then the shipped defaults; then one knob at a time\n"
     "(numerics.rtol, numerics.layers_per_step, nip.nodes, nip.terms, nip.T0_rtol,\n"
     "nip.update_every, output.history_every; knobs the scene does not use are skipped)\n"
     "and a small grid. Each run's error against the reference in core pressure, peak\n"
     "pressure, sigma_r and sigma_theta profiles and the final T0, and its time, go\n"
     "into a table, DIR/study.h5, DIR/study.csv and DIR/study.png (error against CPU time,\n"
     "Pareto front, defaults highlighted). The runs use the scene as given plus --set.\n",
     "Ctrl-C or SIGTERM stops the study after the runs in progress: nothing is written\n"
     "and no directory is made (130, 143).\n"
     "exit status: 0 ok, 2 bad input (nothing wound), 3 the reference or default run\n"
     "             failed, 130 interrupted, 143 terminated, 1 other (files, gnuplot)\n"},
    {"nip", CLI_NIP, "scene file", 0,
     "reelsim nip SCENE --radius R [--json] [--set key.path=value ...]",
     "solve the scene's contact nip once at a roll radius:\n"
     "half-width, wound-on tension, stick and slip zones",
     "Solves the scene's contact nip (nip.model: contact) at roll radius R (m): the\n"
     "contact half-width, load, web and wound-on tension T0, peak pressure, the roll's\n"
     "secant modulus, stick and slip zones on both sides (docs/nip.md).\n",
     "exit status: 0 ok, 2 bad input (or a scene without nip.model: contact),\n"
     "             3 the nip could not be solved\n"},
    {"sweep", CLI_SWEEP, "scene file", 0,
     "reelsim sweep SCENE --vary KEY=LO:HI:N [--vary KEY=V1,V2,... ...]\n"
     "                         [--sample grid|lhs:R] [-o FILE] [--csv FILE] [--threads K]\n"
     "                         [--set key.path=value ...] [--profiles] [--quiet]",
     "wind a scene at many values of some of its keys (a grid\n"
     "or a Latin hypercube), in parallel or over MPI ranks, and\n"
     "write every run's figures to one HDF5 file (sweep.h5)",
     "Winds SCENE at every combination of the --vary values (or R Latin-hypercube samples\n"
     "of their ranges), in parallel, and writes one HDF5 file: /sweep/parameters (the\n"
     "keys), /sweep/values (one row per run) and /sweep/figures/ (core_pressure,\n"
     "peak_pressure, min_sigma_theta, final_radius, layers, starring_layers, slip_margin,\n"
     "wall_seconds, status: 0 ok, 2 refused, 3 solver failed; with storage stages the\n"
     "storage_* figures, with lanes ridge_height, max_lane_pressure, slack_lanes)\n"
     "(docs/output.md). Every run's scene is loaded and checked before any is wound.\n"
     "A run that fails is recorded (status, NaN figures) and the others go on. Under\n"
     "mpirun -n P the runs are handed out to the ranks one at a time and rank 0 writes\n"
     "the file (docs/scale.md).\n",
     "Ctrl-C or SIGTERM stops the sweep after the runs in progress: nothing is written\n"
     "(130, 143).\n"
     "exit status: 0 the sweep ran (failed runs are counted in its last line),\n"
     "             2 bad input (nothing wound), 130 interrupted, 143 terminated,\n"
     "             1 other\n"},
    {"optimize", CLI_OPTIMIZE, "scene file", 0,
     "reelsim optimize SCENE --vary KEY=LO:HI ... (--minimize | --maximize) FIGURE\n"
     "                         [--subject-to 'FIGURE<=X' | 'FIGURE>=X' ...]\n"
     "                         [--target-profile FILE.csv] [-o best.yaml] [--history FILE.h5]\n"
     "                         [--set key.path=value ...] [--quiet]",
     "the best recipe within ranges of scene values under\n"
     "constraints on the figures (NLopt COBYLA); the best scene\n"
     "as YAML, every run to HDF5",
     "Searches the scene values given by --vary for the one that minimizes or maximizes a\n"
     "figure of the wound reel (core_pressure, peak_pressure, min_sigma_theta,\n"
     "final_radius, layers, starring_layers, slip_margin, wall_seconds, status, the\n"
     "storage_* figures with storage stages, ridge_height, max_lane_pressure, slack_lanes\n"
     "with lanes, misfit with --target-profile, or a varied key itself) subject to\n"
     "--subject-to constraints: a Latin hypercube of 4 K + 4 runs, then NLopt's COBYLA\n"
     "from the best feasible one (at most 30 K + 30 more runs; docs/optimize.md). A run\n"
     "that fails or is refused counts as infeasible. Prints every run and the best values and figures, writes the best scene\n"
     "(resolved: --set and the values applied) to -o and every run to the history file\n"
     "(/optimize, docs/output.md). Every argument is checked before anything is wound.\n",
     "Ctrl-C or SIGTERM stops after the current run: nothing is written (130, 143).\n"
     "exit status: 0 ok, 2 bad input (nothing wound), 1 no run met the constraints (the\n"
     "             history file is written) or other errors, 130 interrupted,\n"
     "             143 terminated\n"},
};
const int cli_n_commands = (int)(sizeof cli_commands / sizeof cli_commands[0]);

const cli_command *cli_command_find(const char *name)
{
  for (int i = 0; name && i < cli_n_commands; ++i)
    if (strcmp(cli_commands[i].name, name) == 0) return &cli_commands[i];
  return NULL;
}

const cli_option *cli_option_for(cli_opt id, unsigned cmd)
{
  for (int i = 0; i < cli_n_options; ++i)
    if (cli_options[i].id == id && (cli_options[i].cmds & cmd)) return &cli_options[i];
  return NULL;
}
