# gnuplot script written by whirl run; redraw: gnuplot diagram.gp
set terminal pngcairo size 900,650 enhanced font 'Sans,11'
set output 'diagram.png'
set xrange [-0.7896:20.7996]
set yrange [-0.03808595111:0.9910448088]
set label 'LP 2' at 1.8855796, 0.7797946855 offset 1,0.7 left front noenhanced
set label 'LP 3' at 1.666197717, 0.6203767209 offset 1,0.7 left front noenhanced
set label 'LP 8' at 7.088119629, 0.9109810713 offset 1,-0.8 left front noenhanced
set datafile separator '	'
set key outside bottom center horizontal
set bmargin 5
set grid lc rgb '#dddddd'
set title 'whirl run: examples/discover/sfd-rotating.whirl (model sfd_rotating)' noenhanced
set xlabel 'Omega' noenhanced
set ylabel 'L2-NORM' noenhanced
S = 15
plot 'branches.tsv' using 5:(column(1) == 1 && column(S) == 1 ? column(10) : NaN) with lines lw 2 lc rgb '#1f4e9c' title 'stable', \
     'branches.tsv' using 5:(column(1) == 2 && column(S) == 1 ? column(10) : NaN) with lines lw 2 lc rgb '#1f4e9c' notitle, \
     'branches.tsv' using 5:(column(1) == 3 && column(S) == 1 ? column(10) : NaN) with lines lw 2 lc rgb '#1f4e9c' notitle, \
     'branches.tsv' using 5:(column(1) == 1 && column(S) == 0 ? column(10) : NaN) with lines lw 2 dt 2 lc rgb '#c0392b' title 'unstable', \
     'branches.tsv' using 5:(column(1) == 3 && column(S) == 0 ? column(10) : NaN) with lines lw 2 dt 2 lc rgb '#c0392b' notitle, \
     'branches.tsv' using 5:(strcol(3) ne '-' && strcol(3) ne 'EP' ? column(10) : NaN) with points pt 7 ps 1 lc rgb 'black' notitle
