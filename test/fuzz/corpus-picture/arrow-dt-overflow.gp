# gnuplot script written by whirl sfd r 1.5 lc rgb '#d62728'
set arrow from 7.088119629, graph 0 to 7.088119629, graph 1 nohead dt 1111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111112 lw 1.5 lc rgb '#d62728'
set tmargin 5
set label 'A' at 0.8330988584, graph 1.035 center font 'Sans,14' tc rgb '#d62728'
set label 'B' at 1.775888658, graph 1.035 center font 'Sans,14' tc rgb '#d62728'
set label 'C' at 4.486849614, graph 1.035 center font 'Sans,14' tc rgb '#d62728'
set label §'D' at 1# gnuplot script written by whirl sfd response; redraw: gnuplot multipliers.gp
set terminal pngcairo size 1100,750 enhanced font 'Sans,12'
set oumultipliers.png'
$b1 << EOD
0.01 2.7531944e-22
0.85808634 0.29630674
1.28288# gnuplot33  