# Solver time against layers, log-log (docs/performance.md, "The film at scale"):
#   bench/film_scale.sh BUILD before.dat (and after.dat, measured back to back), then
#   gnuplot -e "before='before.dat'; after='after.dat'" docs/img/film_scale.gp
set terminal pngcairo size 800,560 font ",11"
set output 'docs/img/film_scale.png'
set logscale xy
set xrange [8e3:1.3e5]
set samples 200
set xlabel 'layers N (cases/pet-rider.yaml to 0.68 m, caliper (0.68 - 0.0762)/N)'
set ylabel 'solver time (s)'
set key top left
set grid
stats after using 1:3 nooutput
n0 = STATS_min_x
t0 = STATS_min_y
f(x) = t0 * (x / n0) ** 1.3
plot before using 1:3 with linespoints pt 7 title 'before (f1c8835: rtol 3e-5, correction by CVODE estimates)', \
     after using 1:3 with linespoints pt 5 title 'now (defect-based correction, rtol 1e-3)', \
     f(x) with lines dt 2 lc rgb 'gray' title 'N^{1.3} from the first point (target slope)', \
     3 with lines dt 3 lc rgb 'red' title 'target at 100,633 layers: 3 s'
