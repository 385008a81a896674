#!/usr/bin/env bash
# How the whole reel's time and memory grow with the number of layers (issue 17): the
# cases/pet-rider.yaml reel (contact nip, torque taper) wound to 0.68 m with its caliper
# chosen for N layers, N = 10^4 .. 10^5, no history. Prints N, wall s, solver s, peak KB,
# CVODE steps, core pressure, and the fitted exponent of time ~ N^p; writes the table to
# $2 for docs/img/film_scale.gp.
#   bench/film_scale.sh BUILD_DIR [table.dat]
set -euo pipefail
build=${1:?usage: film_scale.sh BUILD_DIR [table.dat]}
out=${2:-/dev/null}
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '# layers wall_s solver_s peak_kb cvode_steps core_pressure_pa\n' | tee "$out"
for n in 10000 20000 40000 70000 100633; do
  cal=$(awk -v n="$n" 'BEGIN { printf "%.10e", (0.68 - 0.0762) / n }')
  /usr/bin/time -f '%e %M' -o "$tmp/time" "$build/reelsim" run "$here/cases/pet-rider.yaml" \
    --set material.caliper="$cal" --set winding.final_radius=0.68 \
    --set output.history_every=0 -o "$tmp/out.h5" --json >"$tmp/run.json"
  read -r wall kb <"$tmp/time"
  /usr/bin/python3 - "$tmp/run.json" "$wall" "$kb" <<'PY' | tee -a "$out"
import json, sys
j = json.load(open(sys.argv[1]))
print(j["layers"], sys.argv[2], "%.3f" % j["solver_seconds"], sys.argv[3], j["cvode_steps"],
      "%.9e" % j["core_pressure"])
PY
done
/usr/bin/python3 - "$out" <<'PY'
import math, sys
rows = [l.split() for l in open(sys.argv[1]) if not l.startswith("#")]
x = [math.log(float(r[0])) for r in rows]
y = [math.log(float(r[2])) for r in rows]
if len(rows) >= 2:
    mx, my = sum(x) / len(x), sum(y) / len(y)
    p = sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)
    print("solver time ~ N^%.2f (least squares over %d sizes, %s to %s layers)"
          % (p, len(rows), rows[0][0], rows[-1][0]))
PY
