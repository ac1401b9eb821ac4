# gnuplot script written by whirl sfd simulate; redraw: gnuplot history.gp
set terminal pngcairo size 1000,800 enhanced font 'Sans,12'
set output 'history.png'
set grid
set title 'SFD rotor, {/Symbol W} = 1.78, {/Symbol l} = 0.0503, {/Symbol d} = 0.3, {/Symbol z} = 0, F_E = 0'
T = 2 * pi / 1.78
stats 'history.tsv' using 1 nooutput
t1 = STATS_max
t0 = t1 - 10 * T > STATS_min ? t1 - 10 * T : STATS_min
set multiplot layout 2,1
set lmargin 10
set rmargin 10
set xlabel '{/Symbol t}'
set ylabel '{/Symbol e} once a period'
set xrange [STATS_min:t1]
set yrange [0:*]
plot 'poincare.tsv' using 2:(sqrt($3**2 + $4**2)) with points pt 7 ps 0.3 lc rgb '#1f4e9c' notitle
set title sprintf('the last %g periods', (t1 - t0) / T)
set xrange [t0:t1]
set yrange [*:*]
set ylabel 'y, z'
set key outside right top
plot 'history.tsv' using 1:2 with lines lw 1.5 lc rgb '#1f4e9c' title 'y', \
     '' using 1:3 with lines lw 1.5 lc rgb '#d62728' title 'z'
unset multiplot
