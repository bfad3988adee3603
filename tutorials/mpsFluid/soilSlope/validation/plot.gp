# plot.gp — soilSlope: the deposit profiles of the three friction
# coefficients (validation/profile_mu<MU>.dat from validation/runAll) with
# lines at the angles atan(mu) through the point where each flank crosses
# half the deposit's height. Run from the case directory:
#   gnuplot validation/plot.gp  ->  validation/soilSlope.png
set terminal pngcairo size 1200,420 font ",10"
set output "validation/soilSlope.png"
set grid; set key top right
set xlabel "x [m]"; set ylabel "y [m]"
set size ratio -1
set xrange [0:0.7]; set yrange [0:0.15]
# x where the profile first falls below half of its highest point
half(f) = system("awk '{ x[NR] = $1; y[NR] = $2; if ($2 > h) h = $2 } END { for (i = 1; i <= NR; i++) if (y[i] < h / 2) { print x[i]; exit } }' ".f) + 0
line(x, xh, m) = (h = 0.05 + (xh - x) * m, h > 0 && h < 0.1 ? h : 1/0)
f1 = "validation/profile_mu0.3.dat"; f2 = "validation/profile_mu0.577.dat"; f3 = "validation/profile_mu1.dat"
h1 = half(f1); h2 = half(f2); h3 = half(f3)
set samples 500
plot f1 w lp pt 7 ps 0.4 lc 1 t "mu = 0.3", line(x, h1, 0.3) w l dt 2 lw 2 lc 1 t "atan(0.3) = 16.7 deg", \
     f2 w lp pt 7 ps 0.4 lc 2 t "mu = 0.577", line(x, h2, 0.577) w l dt 2 lw 2 lc 2 t "atan(0.577) = 30 deg", \
     f3 w lp pt 7 ps 0.4 lc 3 t "mu = 1", line(x, h3, 1.0) w l dt 2 lw 2 lc 3 t "atan(1) = 45 deg", \
     "< printf '0 0.1\n0.2 0.1\n0.2 0\n'" w l lc rgb "gray" t "column at t = 0"
