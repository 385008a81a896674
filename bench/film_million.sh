#!/usr/bin/env bash
# The million-layer film (issue 35): cases/pet-jumbo.yaml (1.5 um PET, Hakiel's polynomial
# stack law, constant-torque taper, aluminium tube core, r 0.0762 -> 1.5 m: 949,200
# layers) wound whole by `reelsim run` as shipped (its output file written), and cut to
# N = 10^4, 3 10^4, 10^5, 3 10^5 layers by its final radius r_c + N t. Prints N, wall s,
# solver s, process CPU s (user + system: on a shared machine the steadier figure), peak
# resident KB, CVODE steps, core pressure and the fitted exponents of time ~ N^p; writes
# the table to $2 for docs/img/film_million.gp.
#   bench/film_million.sh BUILD_DIR [table.dat] [largest N]
set -euo pipefail
usage="usage: film_million.sh BUILD_DIR [table.dat] [largest N]"
build=${1:?$usage}
out=${2:-/dev/null}
largest=${3:-949200}
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '# layers wall_s solver_s cpu_s peak_kb cvode_steps core_pressure_pa\n' | tee "$out"
for n in 10000 30000 100000 300000 949200; do
  [ "$n" -le "$largest" ] || continue
  r=$(awk -v n="$n" 'BEGIN { printf "%.10g", 0.0762 + n * 1.5e-6 }')
  /usr/bin/time -f '%e %U %S %M' -o "$tmp/time" "$build/reelsim" run "$here/cases/pet-jumbo.yaml" \
    --set winding.final_radius="$r" -o "$tmp/out.h5" --json >"$tmp/run.json"
  read -r wall user sys kb <"$tmp/time"
  /usr/bin/python3 - "$tmp/run.json" "$wall" "$user" "$sys" "$kb" <<'PY' | tee -a "$out"
import json, sys
j = json.load(open(sys.argv[1]))
print(j["layers"], sys.argv[2], "%.3f" % j["solver_seconds"],
      "%.2f" % (float(sys.argv[3]) + float(sys.argv[4])), sys.argv[5], j["cvode_steps"],
      "%.9e" % j["core_pressure"])
PY
done
/usr/bin/python3 - "$out" <<'PY'
import math, sys
rows = [l.split() for l in open(sys.argv[1]) if not l.startswith("#")]
x = [math.log(float(r[0])) for r in rows]
for name, col in (("wall", 1), ("solver", 2), ("cpu", 3)):
    y = [math.log(float(r[col])) for r in rows]
    if len(rows) >= 2:
        mx, my = sum(x) / len(x), sum(y) / len(y)
        p = sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)
        print("%s time ~ N^%.2f (least squares over %d sizes, %s to %s layers)"
              % (name, p, len(rows), rows[0][0], rows[-1][0]))
PY
