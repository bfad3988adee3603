# plot.gp — soilSlope: the deposit profiles of the three friction
# coefficients (validation/profile_mu<MU>.dat from validation/runAll) with
# lines at the angles atan(mu) from each toe. Run from the case directory:
#   gnuplot validation/plot.gp  ->  validation/soilSlope.png
set terminal pngcairo size 1200,420 font ",10"
set output "validation/soilSlope.png"
set grid; set key top right
set xlabel "x [m]"; set ylabel "y [m]"
set size ratio -1
set xrange [0:1.2]; set yrange [0:0.25]
toe(f) = system("tail -1 ".f." | cut -d' ' -f1") + 0
f1 = "validation/profile_mu0.3.dat"; f2 = "validation/profile_mu0.577.dat"; f3 = "validation/profile_mu1.dat"
t1 = toe(f1); t2 = toe(f2); t3 = toe(f3)
plot f1 w lp pt 7 ps 0.4 lc 1 t "mu = 0.3", (x < t1 ? (t1 - x) * 0.3 : 1/0) w l dt 2 lc 1 t "atan(0.3) = 16.7 deg from the toe", \
     f2 w lp pt 7 ps 0.4 lc 2 t "mu = 0.577", (x < t2 ? (t2 - x) * 0.577 : 1/0) w l dt 2 lc 2 t "atan(0.577) = 30 deg", \
     f3 w lp pt 7 ps 0.4 lc 3 t "mu = 1", (x < t3 ? (t3 - x) * 1.0 : 1/0) w l dt 2 lc 3 t "atan(1) = 45 deg", \
     "< printf '0 0.2\n0.1 0.2\n0.1 0\n'" w l lc rgb "gray" t "column at t = 0"
