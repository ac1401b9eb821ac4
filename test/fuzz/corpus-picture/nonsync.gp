# gnuplot script written by whirl sfd nonsync; redraw: gnuplot nonsync.gp
set terminal pngcairo size 1100,750 enhanced font 'Sans,12'
set output 'nonsync.png'
$sync0 << EOD
0.01 3.0002961e-05
0.85808634 0.48551827
1.2828833 0.73084665
1.8587577 0.78564361





























1.7318801 0.52742078
4.8549075 0.31847032
9.8548787 0.3054073

7.5584954 0.91633653
7.0955296 0.91134809






































EOD
$ns0 << EOD



























9.5696776 0.93778497 0.39797705 0.29514843

EOD
$sync1 << EOD



















































































1.7380609 0.71255181






























































































































7.1041029 0.91062042

EOD
$ns1 << EOD
10 0.92435583 0.23747212 0.28824124
8.5908998 0.92493723 0.31640527 0.29716687




























EOD
$lp << EOD
0 -1 -1 -1
EOD
set title 'nonsynchronous response (rotating-frame cycle): {/Symbol l} = 0.0503, {/Symbol d} = 0.3, {/Symbol z} = 0'
set xlabel 'dimensionless speed {/Symbol W}'
set ylabel 'eccentricity {/Symbol e}'
set xrange [8.09007:10]
set yrange [0:1]
set grid
set key outside right top box
plot $sync0 using 1:2 with lines lw 2 lc rgb '#1f4e9c' title 'circular orbits, stable', \
     $sync1 using 1:2 with lines dt 2 lw 2 lc rgb '#1f4e9c' title 'circular orbits, unstable', \
     $ns0 using 1:2 with lines lw 2.5 lc rgb '#d62728' title 'nonsync {/Symbol e}_{max}, stable', \
     $ns0 using 1:3 with lines lw 2.5 lc rgb '#ff7f0e' title 'nonsync {/Symbol e}_{min}, stable', \
     $ns1 using 1:2 with lines dt 2 lw 2 lc rgb '#d62728' title 'nonsync {/Symbol e}_{max}, unstable', \
     $ns1 using 1:3 with lines dt 2 lw 2 lc rgb '#ff7f0e' title 'nonsync {/Symbol e}_{min}, unstable', \
     $lp using 1:2 with points pt 7 ps 1.6 lc rgb '#2ca02c' title 'LP of cycles (birth)', \
     $lp using 1:3 with points pt 7 ps 1.6 lc rgb '#2ca02c' notitle
