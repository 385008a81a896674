# Solver time against layers, log-log (docs/performance.md, "Performance at scale"):
#   gnuplot -e "before='film_base.dat'; after='film_new.dat'" docs/img/film_scale.gp
set terminal pngcairo size 800,560 font ",11"
set output 'docs/img/film_scale.png'
set logscale xy
set xlabel 'layers N (cases/pet-rider.yaml to 0.68 m, caliper (0.68 - 0.0762)/N)'
set ylabel 'solver time (s)'
set key top left
set grid
f(x) = 0.571 * (x / 1e4) ** 1.3
plot before using 1:3 with linespoints pt 7 title 'before (issue 17)', \
     after using 1:3 with linespoints pt 5 title 'lazy deep part', \
     [1e4:1.1e5] f(x) with lines dt 2 lc rgb 'gray' title 'N^{1.3} from the first point'
