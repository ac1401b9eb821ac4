# gnuplot script written by whirl sfd response; redraw: gnuplot response.gp
set terminal pngcairo size 1100,750 enhanced font 'Sans,12'
set output 'response.png'
$stable << EOD
0.01 3.0002961e-05
0.85808634 0.48551827
1.2828833 0.73084665
1.8587577 0.78564361

1.756091 0.51266563
5.2548982 0.3159523
10.254878 0.30507157
15.254878 0.30274417

15.30303 0.94543601
10.306593 0.9314871
7.4716754 0.91560282
7.0928718 0.91126725


EOD
$unstable << EOD
1.8855796 0.77979469
1.673538 0.65133325


7.2006069 0.91049468
11.985821 0.92706771
16.984658 0.93789639

EOD
$special << EOD
0 -1
EOD
set arrow from 1.666197717, graph 0 to 1.666197717, graph 1 nohead dt 2 lw 1.5 lc rgb '#d62728'
set arrow from 1.8855796, graph 0 to 1.8855796, graph 1 nohead dt 2 lw 1.5 lc rgb '#d62728'
set arrow from 7.088119629, graph 0 to 7.088119629, graph 1 nohead dt 2 lw 1.5 lc rgb '#d62728'
set tmargin 5
set label 'A' at 0.8330988584, graph 1.035 center font 'Sans,14' tc rgb '#d62728'
set label 'B' at 1.775888658, graph 1.035 center font 'Sans,14' tc rgb '#d62728'
set label 'C' at 4.486849614, graph 1.035 center font 'Sans,14' tc rgb '#d62728'
set label 'D' at 13.54405981, graph 1.035 center font 'Sans,14' tc rgb '#d62728'
set title 'SFD rigid rotor, circular orbits: {/Symbol l} = 0.0503, {/Symbol d} = 0.3, {/Symbol z} = 0, F_E = 0' offset 0,1.2
set xlabel 'dimensionless speed {/Symbol W}'
set ylabel 'relative eccentricity {/Symbol e}'
set xrange [0:20]
set yrange [0:1]
set grid
set key outside right top box
plot $stable using 1:2 with lines lw 2.5 lc rgb '#1f4e9c' title 'stable', \
     $unstable using 1:2 with lines dt 2 lw 2.5 lc rgb '#1f4e9c' title 'unstable', \
     $special using 1:2 with points pt 7 ps 1.6 lc rgb '#2ca02c' title 'LP (saddle-node)'
