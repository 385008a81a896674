#!/usr/bin/env bash
# Nip-induced tension against nip load (docs/nip.md, "NIT against load"). Runs
# `reelsim nip --json` on tests/cli/scenes/nip-*.yaml and writes (gnuplot)
#   docs/img/nit_vs_load.png   NIT = T0 - Ti, center winder with a rider and surface
#                              winder, beside the full-slip values mu P and mu P - Ti
#   docs/img/nit_levelling.png NIT / (mu P) against load for four paper stacks
# Usage: scripts/nip_plot.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
B="${1:-build}"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
LOADS="200 300 500 700 1000 1500 2000 3000 4000 6000 8000 12000 16000 25000"
field() { printf '%s' "$1" | sed -E "s/.*\"$2\":([^,]*),.*/\1/"; }
# $1 = output file, $2 = scene, $3 = mu_roll, rest: --set overrides
run() {
  local f="$1" scene="$2" mu="$3"
  shift 3
  for P in $LOADS; do
    j=$("$B/reelsim" nip "tests/cli/scenes/$scene.yaml" --radius 0.15 --set nip.load=$P \
        --set nip.friction.roll=$mu --set nip.nodes=64 "$@" --json 2>/dev/null) || continue
    nit=$(field "$j" NIT)
    printf '%s %s %s\n' "$P" "$nit" "$(awk -v n="$nit" -v m="$mu" -v p="$P" 'BEGIN{print n/(m*p)}')" >> "$f"
  done
}
run "$out/center.dat" nip-center 0.19
run "$out/surface.dat" nip-surface 0.19
run "$out/news.dat" nip-center 0.19
run "$out/news04.dat" nip-center 0.4
run "$out/stiff.dat" nip-center 0.19 --set material.radial.K1=2e4 --set material.radial.K2=30 \
    --set material.E_theta=7e9 --set material.G_rtheta=2e9 --set material.caliper=100e-6
run "$out/shear.dat" nip-center 0.19 --set material.G_rtheta=1e8
gnuplot <<GP
set terminal pngcairo size 820,540 noenhanced
set output 'docs/img/nit_vs_load.png'
set title 'Nip-induced tension (contact model, R = 0.15 m, Ti = 350 N/m, mu roll 0.19, drum 0.35)'
set xlabel 'nip load P (N/m)'
set ylabel 'NIT = T0 - Ti (N/m)'
set key top left
set grid
plot [0:25000] 0.19*x title 'mu P (full slip, center winder; Good, Wu & Fikes 1994)' with lines dt 2 lw 2, \
     0.19*x - 350 title 'mu P - Ti (full slip, surface winder)' with lines dt 3 lw 2, \
     '$out/center.dat' using 1:2 title 'center winder with rider' with linespoints lw 2, \
     '$out/surface.dat' using 1:2 title 'surface winder' with linespoints lw 2
set output 'docs/img/nit_levelling.png'
set title 'NIT / (mu P), center winder with rider: where NIT levels off (docs/nip.md)'
set ylabel 'NIT / (mu_roll P)'
set logscale x
set yrange [0:1.05]
set key bottom left
plot [150:30000] '$out/news.dat' using 1:3 title 'newsprint scene (K1 5 kPa, K2 60, 70 um), mu 0.19' with linespoints lw 2, \
     '$out/news04.dat' using 1:3 title 'same stack, mu 0.4' with linespoints lw 2, \
     '$out/stiff.dat' using 1:3 title 'stiffer stack (K1 20 kPa, K2 30, E_theta 7 GPa, 100 um)' with linespoints lw 2, \
     '$out/shear.dat' using 1:3 title 'newsprint, G_rtheta 0.1 GPa' with linespoints lw 2
GP
for f in center surface news news04 stiff shear; do echo "== $f (P NIT NIT/(mu P))"; cat "$out/$f.dat"; done
echo "wrote docs/img/nit_vs_load.png docs/img/nit_levelling.png"
