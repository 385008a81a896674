# Lumped increments before and after (docs/accuracy.md): run from the top folder after
#   ./build/bench/bench_lumping 6054 1e-6 lumping.dat
# as   gnuplot -e "data='lumping.dat'" docs/img/lumping.gp
if (!exists("data")) data = 'lumping.dat'
set terminal pngcairo size 1200,520 noenhanced font 'DejaVu Sans,11'
set output 'docs/img/lumping.png'
set multiplot layout 1,2 title "Lumped increments on the 6054-layer newsprint reel (Pfeiffer, rtol 1e-6): core-pressure error against layer-by-layer Hakiel"
set logscale xy
set grid
set key bottom right
set ylabel 'relative error of the core pressure'
set format y '%.0e'
set xlabel 'numerics.layers_per_step m'
set xrange [1.5:150]
set yrange [5e-4:2]
plot data index 0 using 2:5 with linespoints pointtype 7 linewidth 2 linecolor rgb '#d62728' title 'first scheme (frozen modulus, load at the block top)', \
     data index 1 using 2:5 with linespoints pointtype 5 linewidth 2 linecolor rgb '#1f77b4' title 'corrected (own radius, predictor-corrector)', \
     1e-3*(x-1) with lines dashtype 2 linecolor rgb '#666666' title '1e-3 (m - 1)'
set xlabel 'CPU time of the winding (s); layer by layer: 2.57 s, error 0'
set xrange [0.1:4]
set logscale x
plot data index 0 using 3:5 with linespoints pointtype 7 linewidth 2 linecolor rgb '#d62728' title 'first scheme', \
     data index 1 using 3:5 with linespoints pointtype 5 linewidth 2 linecolor rgb '#1f77b4' title 'corrected', \
     data index 1 using 3:5:(sprintf("m=%d", $2)) with labels offset 1.2,0.6 font ',9' notitle
unset multiplot
