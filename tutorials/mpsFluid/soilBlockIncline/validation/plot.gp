# plot.gp — soilBlockIncline: the sliding speed of the block (its
# middle from 0.3 to 0.5 s) against the incline angle, from
# validation/bisect.dat, with atan(mu) = 30 deg (E5-04: at rest below, sliding
# above). Run from the case directory: gnuplot validation/plot.gp
set terminal pngcairo size 800,450 font ",10"
set output "validation/soilBlockIncline.png"
set grid; set key top left
set xlabel "incline angle theta [deg]"; set ylabel "sliding speed of the block [m/s]"
set xrange [0:60]
set arrow from 29.98, graph 0 to 29.98, graph 1 nohead dt 2 lc rgb "red"
set label "atan(0.577) = 30 deg" at 31, graph 0.9 tc rgb "red"
plot "< grep -v '^threshold' validation/bisect.dat | sort -g" u 1:3 w lp pt 7 ps 0.6 t "viscoplastic soil (mu = 0.577), dp = 5 mm", \
     0.5 * 0.005 / 0.2 w l dt 3 lc rgb "gray" t "at rest below: 0.5 dp in 0.2 s"
