# The million-layer film: time and peak memory against layers, log-log (docs/performance.md,
# "The million-layer film"):
#   bench/film_million.sh build film.dat
#   gnuplot -e "data='film.dat'" docs/img/film_million.gp
# and, with before='old.dat' (the same bench of another build, run alternately), that
# build's CPU time beside it (the figure: the build at commit c7a59ac)
# Columns of film.dat: layers wall_s solver_s cpu_s peak_kb cvode_steps core_pressure_pa.
if (!exists("data")) data = 'film.dat'
set terminal pngcairo size 900,560 font ",11"
set output 'docs/img/film_million.png'
set logscale xy
set xrange [7e3:1.4e6]
set samples 200
set xlabel 'layers N (cases/pet-jumbo.yaml: 1.5 um PET cut to r_c + N t; 949,200 layers whole)'
set ylabel 'time (s)'
set y2label 'peak resident memory (MB)'
set logscale y2
set ytics nomirror
set y2tics
set key top left box opaque
set grid
set title 'cases/pet-jumbo.yaml, reelsim run (scripts/setup.sh build): CPU time and peak memory'
stats data using 1:4 nooutput
n0 = STATS_min_x
t0 = STATS_min_y
f(x) = t0 * (x / n0) ** 1.1
set label 1 'target 12 s' at first 949200, first 12 right offset -1, 0.6 tc rgb 'red'
set label 2 'target 300 MB' at first 949200, second 300 right offset -1, 0.6 tc rgb 'dark-green'
extra = exists("before") ? sprintf(", '%s' using 1:4 with linespoints pt 6 lw 1 dt 3 lc rgb 'blue' title 'CPU time, the build at c7a59ac'", before) : ""
plot data using 1:4 with linespoints pt 7 lw 2 lc rgb 'blue' title 'process CPU time (s, left)', \
     f(x) with lines dt 2 lc rgb 'gray' title 'N^{1.1} from the first point (target slope)', \
     '+' every ::0::0 using (949200):(12) with points pt 6 ps 2 lc rgb 'red' title 'target at 949,200 layers: 12 s', \
     data using 1:($5 / 1024) axes x1y2 with linespoints pt 9 lw 2 lc rgb 'dark-green' title 'peak resident memory (MB, right)', \
     '+' every ::0::0 using (949200):(300) axes x1y2 with points pt 8 ps 2 lc rgb 'dark-green' title 'target: 300 MB' @extra
