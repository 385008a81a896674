#!/usr/bin/env bash
# The 6054-layer newsprint reel against an independent yardstick solver of the same
# build-up increment problem (issue 17), alternating in one sitting: the machine is shared
# and noisy, so only ratios measured side by side mean anything. The yardstick is not part
# of reelsim; give the path of its source (the project's CI machines keep it in
# ../shared/limit/hakiel_fd.c).
#   bench/vs_yardstick.sh BUILD_DIR HAKIEL_FD_C [rounds] [rtol...]
# Prints each round's wall times and the median ratios (reelsim / yardstick with its
# frozen deep part, `-f 1e-5`, its fastest setting).
set -euo pipefail
build=${1:?usage: vs_yardstick.sh BUILD_DIR HAKIEL_FD_C [rounds] [rtol...]}
src=${2:?usage: vs_yardstick.sh BUILD_DIR HAKIEL_FD_C [rounds] [rtol...]}
rounds=${3:-5}
shift $(( $# < 3 ? $# : 3 ))
rtols=("$@")
[ ${#rtols[@]} -gt 0 ] || rtols=(1e-3 5e-4)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
gcc -O2 -march=native -std=c11 -o "$tmp/hakiel_fd" "$src" -lm
for ((i = 0; i < rounds; ++i)); do
  line="yardstick $("$tmp/hakiel_fd" -N 6054 -k 1 -T 8 -t 4 -f 1e-5 | sed -n 's/.*wall \([0-9.]*\).*/\1/p')"
  for r in "${rtols[@]}"; do
    line="$line rtol=$r $("$build/bench/bench_roll" 6054 "$r" | tail -n 1 | awk '{print $2}')"
  done
  echo "$line" | tee -a "$tmp/rows"
done
/usr/bin/python3 - "$tmp/rows" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
y = [float(r[1]) for r in rows]
for k in range(2, len(rows[0]), 2):
    t = [float(r[k + 1]) for r in rows]
    ratios = [a / b for a, b in zip(t, y)]
    print("%s: median %.4f s, yardstick %.4f s, ratio %.2f (%.2f - %.2f)"
          % (rows[0][k], statistics.median(t), statistics.median(y), statistics.median(ratios),
             min(ratios), max(ratios)))
PY
