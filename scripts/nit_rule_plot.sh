#!/usr/bin/env bash
# Nip-induced tension of the shipped newsprint model against the measured rule NIT ~ mu N
# (docs/nip.md, "NIT = mu N"; the test tests/validation/test_nit_rule.c checks the same
# numbers). Runs `reelsim nip --json` on tests/validation/scenes/nit-newsprint-rider.yaml
# (center winder, undriven steel rider, mu 0.19) and writes with gnuplot
#   docs/img/nit_mu_n.png  left: NIT against N up to 3 kN/m beside mu N;
#                          right: NIT / (mu N) against N (log) up to 25 kN/m
# for the model's G_rtheta (50 MPa) at R = 0.15 and 0.4 m, and a shear-soft stack
# (G_rtheta 2 MPa, about E_r under the nip: the contact nip's former default).
# Usage: scripts/nit_rule_plot.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
B="${1:-build}"
SCENE=tests/validation/scenes/nit-newsprint-rider.yaml
MU=0.19
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
LOADS="100 200 400 600 800 1000 1500 2000 3000 5000 8000 12000 16000 25000"
# $1 = output file, $2 = roll radius (m), rest: --set overrides
run() {
  local f="$1" R="$2"
  shift 2
  for P in $LOADS; do
    j=$("$B/reelsim" nip "$SCENE" --radius "$R" --set nip.load=$P "$@" --json)
    nit=$(printf '%s' "$j" | sed -E 's/.*"NIT":([^,]*),.*/\1/')
    printf '%s %s %s\n' "$P" "$nit" "$(awk -v n="$nit" -v m="$MU" -v p="$P" 'BEGIN{print n/(m*p)}')" >> "$f"
  done
}
run "$out/r15.dat" 0.15
run "$out/r40.dat" 0.4
run "$out/soft.dat" 0.15 --set material.G_rtheta=2e6
gnuplot <<GP
set terminal pngcairo size 1100,480 noenhanced
set output 'docs/img/nit_mu_n.png'
set multiplot layout 1,2 title 'Shipped newsprint model, center winder with a steel rider (Ti 350 N/m, mu 0.19): NIT = T0 - Ti'
set grid
set key top left Left reverse opaque box
set xlabel 'nip load N (N/m)'
set ylabel 'NIT (N/m)'
plot [0:3000] [0:700] $MU*x title 'mu N (measured rule, Good, Wu & Fikes 1994)' with lines dt 2 lw 2, \
     0.9*$MU*x title '0.9 mu N' with lines dt 4 lw 2 lc rgb 'dark-gray', \
     '$out/r15.dat' using 1:2 title 'G_rtheta 50 MPa, R 0.15 m' with linespoints lw 2, \
     '$out/r40.dat' using 1:2 title 'G_rtheta 50 MPa, R 0.4 m' with linespoints lw 2, \
     '$out/soft.dat' using 1:2 title 'G_rtheta 2 MPa (~E_r, old default)' with linespoints lw 2
set logscale x
set key bottom left Left reverse opaque box
set ylabel 'NIT / (mu N)'
plot [80:30000] [0:1.05] 1 notitle with lines dt 2 lw 2, 0.9 title '0.9 (test bound)' with lines dt 4 lw 2 lc rgb 'dark-gray', \
     '$out/r15.dat' using 1:3 title 'G 50 MPa, R 0.15 m' with linespoints lw 2, \
     '$out/r40.dat' using 1:3 title 'G 50 MPa, R 0.4 m' with linespoints lw 2, \
     '$out/soft.dat' using 1:3 title 'G 2 MPa (~E_r)' with linespoints lw 2
unset multiplot
GP
for f in r15 r40 soft; do echo "== $f (N NIT NIT/(mu N))"; cat "$out/$f.dat"; done
echo "wrote docs/img/nit_mu_n.png"
