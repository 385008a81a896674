#!/usr/bin/env bash
# The two-drum winder case (docs/nip.md, "Two-drum winders"): cases/newsprint-two-drum.yaml
# wound with each nip's NIT capped at material.nit_saturation (380 N/m) and without the cap
# (the sum of mu N), written with gnuplot to
#   docs/img/two_drum.png  left: the nips' loads against the roll radius (each drum's from
#                          the statics, by hand here: (W' + Q) / (2 cos theta); the rider's
#                          taper; the total the run records in /layers/nip_load);
#                          middle: wound-on tension, capped and not;
#                          right: the interlayer pressure of the finished roll, both.
# Usage: scripts/two_drum_plot.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
B="$(cd "${1:-build}" && pwd)"
SCENE="$PWD/cases/newsprint-two-drum.yaml"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
(cd "$out" && "$B/reelsim" run "$SCENE" -q -o capped.h5 --csv capped > /dev/null &&
   "$B/reelsim" run "$SCENE" -q -o free.h5 --csv free --set material.nit_saturation=null > /dev/null)
# hand statics at each layer: rho 640, g 9.80665, r_c 0.0762, R_d 0.5, c 1.05, rider 1500 -> 300
awk -F, 'NR > 1 { R = $1; rc = 0.0762; W = 640 * 9.80665 * 3.141592653589793 * (R*R - rc*rc);
                  Q = 1500 + (300 - 1500) * (R - rc) / (0.5 - rc); s = 0.525 / (R + 0.5);
                  N = (W + Q) / (2 * sqrt(1 - s*s)); print R, N, Q, $3, W }' \
    "$out/capped/newsprint-two-drum-wot.csv" > "$out/loads.dat"
gnuplot <<GP
set terminal pngcairo size 1500,480 noenhanced
set output 'docs/img/two_drum.png'
set multiplot layout 1,3 title 'cases/newsprint-two-drum.yaml: drums 1 m, centres 1.05 m apart, rider 1500 -> 300 N/m, Ti 350 N/m, mu 0.19 on every nip'
set grid
set datafile separator whitespace
set xlabel 'roll radius R (mm)'
set ylabel 'load (N/m)'
set key top left Left reverse opaque box
plot [] [0:8500] '$out/loads.dat' using (\$1*1e3):2 title 'each drum (statics by hand)' with lines lw 2, \
     '' using (\$1*1e3):3 title 'rider' with lines lw 2, \
     '' using (\$1*1e3):5 title 'roll weight W' with lines dt 2 lw 2, \
     '' using (\$1*1e3):4 title 'total (/layers/nip_load)' with lines dt 4 lw 2 lc rgb 'black'
set datafile separator ','
set ylabel 'wound-on tension T0 (N/m)'
set key bottom right
plot [] [0:1700] '$out/free/newsprint-two-drum-wot.csv' using (\$1*1e3):4 title 'no cap: Ti + sum mu N' with lines lw 2, \
     '$out/capped/newsprint-two-drum-wot.csv' using (\$1*1e3):4 title 'each nip capped at 380 N/m' with lines lw 2, \
     '' using (\$1*1e3):2 title 'web tension Ti' with lines dt 2 lw 2 lc rgb 'black'
set ylabel 'interlayer pressure (MPa)'
set key top right
plot '$out/free/newsprint-two-drum-profile.csv' using (\$2*1e3):(\$5/1e6) title 'no cap' with lines lw 2, \
     '$out/capped/newsprint-two-drum-profile.csv' using (\$2*1e3):(\$5/1e6) title 'capped at 380 N/m' with lines lw 2
unset multiplot
GP
echo "wrote docs/img/two_drum.png"
