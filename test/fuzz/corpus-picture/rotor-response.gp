# gnuplot script written by whirl rotor response; redraw: gnuplot response.gp
set terminal pngcairo size 1100,750 enhanced font 'Sans,12'
set output 'response.png'
set title 'unbalance response at node 0: rigid limit of the paper''s rotor (Table 1)' noenhanced
set xlabel 'speed (rev/min)'
set ylabel 'amplitude at node 0 (mm)'
set grid
set key outside right top box
set datafile separator '\t'
plot 'branches.tsv' using 4:($7<0 ? 1e3*$6 : 1/0) with lines lw 1 lc rgb '#777777' title 'stability not computed', \
  'special.tsv' using 4:(strcol(1) eq 'LP' ? 1e3*$6 : 1/0) with points pt 7 ps 1.4 lc rgb 'black' title 'LP'
