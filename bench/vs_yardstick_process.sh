#!/usr/bin/env bash
# Whole process against whole process (issue 35): `reelsim run` of the 6054-layer newsprint
# reel at the default accuracy (cases/newsprint-rider.yaml --set numerics.rtol=null -q) and
# of the contact-nip reel (cases/newsprint-surface.yaml -q), each against the independent
# yardstick solver's whole process on the same 6054-layer reel (`hakiel_fd -N 6054 -k 1
# -T 8 -t 4 -f 1e-5`: its fastest setting; it has no nip). Start-up (dynamic loading, the
# scene), winding and the output file are all inside the time, as a user sees it.
# Alternating in one sitting: the machine is shared and noisy, so only ratios measured side
# by side mean anything. The yardstick is not part of reelsim; give the path of its source.
# Further build folders after the rounds are run in the same rounds, alternating with the
# first (a change measured against the build before it, in one sitting).
#   bench/vs_yardstick_process.sh BUILD_DIR HAKIEL_FD_C [rounds [BUILD_DIR2 ...]]
# Prints each round's wall and CPU (user + system) seconds and, per build and reel, the
# median ratios reelsim / yardstick with their range over the rounds.
set -euo pipefail
usage="usage: vs_yardstick_process.sh BUILD_DIR HAKIEL_FD_C [rounds [BUILD_DIR2 ...]]"
builds=("$(cd "${1:?$usage}" && pwd)")
src=${2:?$usage}
rounds=${3:-9}
shift $(($# < 3 ? $# : 3))
for b in "$@"; do builds+=("$(cd "$b" && pwd)"); done
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
gcc -O2 -march=native -std=c11 -o "$tmp/hakiel_fd" "$src" -lm
/usr/bin/python3 - "$here/cases" "$tmp" "$rounds" "${builds[@]}" <<'PY'
import os, resource, statistics, subprocess, sys, time
cases, tmp, rounds, builds = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
out = os.path.join(tmp, "out.h5")
cmds = {"yardstick": [os.path.join(tmp, "hakiel_fd"), "-N", "6054", "-k", "1", "-T", "8", "-t",
                      "4", "-f", "1e-5"]}
for b, build in enumerate(builds):
    reelsim, tag = os.path.join(build, "reelsim"), "" if b == 0 else "@%d" % (b + 1)
    cmds["rider" + tag] = [reelsim, "run", os.path.join(cases, "newsprint-rider.yaml"), "--set",
                           "numerics.rtol=null", "-q", "-o", out]
    cmds["surface" + tag] = [reelsim, "run", os.path.join(cases, "newsprint-surface.yaml"), "-q",
                             "-o", out]
reels = [k for k in cmds if k != "yardstick"]
if len(builds) > 1:
    for b, build in enumerate(builds):
        print("build %d: %s" % (b + 1, build))

def timed(cmd):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=tmp)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)

rows = []
for i in range(rounds):
    row = {}
    half = (len(reels) + 1) // 2
    for name in ["yardstick"] + reels[:half] + ["yardstick2"] + reels[half:]:  # alternating
        row[name] = timed(cmds[name.rstrip("2") if name == "yardstick2" else name])
    rows.append(row)
    print("round %d: " % (i + 1) + "  ".join("%s %.3f s (cpu %.3f)" % (k, *v)
                                           for k, v in row.items()), flush=True)
for reel in reels:
    ref = "yardstick" if reels.index(reel) < (len(reels) + 1) // 2 else "yardstick2"
    for what, k in (("wall", 0), ("cpu", 1)):
        r = [row[reel][k] / row[ref][k] for row in rows if row[ref][k] > 0]
        if not r:
            continue
        print("%-10s %-4s reelsim median %.3f s, yardstick %.3f s, ratio %.2f (%.2f - %.2f, %d rounds)"
              % (reel, what, statistics.median(row[reel][k] for row in rows),
                 statistics.median(row[ref][k] for row in rows), statistics.median(r), min(r),
                 max(r), len(r)))
PY
