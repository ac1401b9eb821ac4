# gnuplot script written by whirl sfd response; redraw: gnuplot multipliers.gp
set terminal pngcairo size 1100,750 enhanced font 'Sans,12'
set output 'multipliers.png'
$b1 << EOD
0.01 2.7531944e-22
0.85808634 0.29630674
1.2828833 0.10039029
1.8587577 0.76177543
1.7380609 1.5089417
1.7318801 0.4988067
4.8549075 0.86994015
9.8548787 0.93522159
14.854878 0.9567237
19.854877 0.96748806
EOD
$b2 << EOD
20 0.24745843
15.103101 0.22156652
10.106897 0.18634981
7.4273558 0.59960653
7.0919527 0.95408341
7.119278 1.1360308
11.386111 3.0799124
16.384736 4.2609452
EOD
set title 'largest Floquet multiplier modulus of the synchronous orbits'
set xlabel 'dimensionless speed {/Symbol W}'
set ylabel 'max |{/Symbol r}|'
set xrange [0:20]
set logscale y
set yrange [0.001:*]
set grid
set key outside right top box
set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 2 lw 1.5 lc rgb '#d62728'
plot $b1 using 1:2 with lines lw 2 title 'branch 1', $b2 using 1:2 with lines lw 2 title 'branch 2'
