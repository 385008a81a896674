#!/usr/bin/env bash
# NIT = T0 - Ti against nip load for center and surface winding, beside mu P
# (Good, Wu & Fikes 1994). Runs `reelsim nip --json` on tests/cli/scenes/nip-*.yaml and
# writes docs/img/nit_vs_load.png (gnuplot). Usage: scripts/nip_plot.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
B="${1:-build}"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for w in center surface; do
  for P in 400 700 1000 1500 2000 3000 4000 6000 8000 12000 16000; do
    j=$("$B/reelsim" nip "tests/cli/scenes/nip-$w.yaml" --radius 0.15 --set nip.load=$P --json 2>/dev/null) || continue
    nit=$(printf '%s' "$j" | sed -E 's/.*"NIT":([^,]*),.*/\1/')
    printf '%s %s\n' "$P" "$nit" >> "$out/$w.dat"
  done
done
gnuplot <<GP
set terminal pngcairo size 800,520 noenhanced
set output 'docs/img/nit_vs_load.png'
set title 'Nip-induced tension NIT = T0 - Ti (contact model, R = 0.15 m, Ti = 350 N/m, mu roll 0.19, drum 0.35)'
set xlabel 'nip load P (N/m)'
set ylabel 'NIT (N/m)'
set key top left
set grid
plot 0.19*x title 'mu P (Good, Wu & Fikes 1994), mu = 0.19' with lines dt 2 lw 2, \
     '$out/center.dat' title 'center winder with rider' with linespoints lw 2, \
     '$out/surface.dat' title 'surface winder' with linespoints lw 2
GP
cat "$out/center.dat" "$out/surface.dat"
echo "wrote docs/img/nit_vs_load.png"
