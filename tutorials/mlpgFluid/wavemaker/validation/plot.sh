#!/bin/bash
# Usage: validation/plot.sh [CASE]
# After validation/compare.sh CASE 24 and CASE 30: the free surface at
# t = 24 s and 30 s against the linear theory, and the mean water level
# against the piston's displaced volume: validation/wavemaker.png.
cd "${0%/*}/.." || exit 1
case=${1:-.}
for f in eta_24 theory_24 eta_30 theory_30 level; do
    [ -f "$case/$f.dat" ] || { echo "plot.sh: no $case/$f.dat (run validation/compare.sh $case 24, then 30)" >&2; exit 1; }
done
gnuplot <<GP
set terminal pngcairo size 1100,900
set output 'validation/wavemaker.png'
set multiplot layout 3,1
set grid; set key top right
set xlabel 'x [m]'; set ylabel 'eta [m]'; set yrange [-0.03:0.03]
set title 'Piston wavemaker, a = 0.01 m, omega = 4.5415 rad/s, dl = 0.04 m: t = 24 s'
plot '$case/theory_24.dat' w l lc rgb 'black' t 'linear theory (S-10)', \
     '$case/eta_24.dat' w l lc rgb 'red' t 'mlpgFluid (free-surface nodes)'
set title 't = 30 s (the front has reflected at the end wall, x = 30 m, since about 26 s; the theory has no end wall)'
plot '$case/theory_30.dat' w l lc rgb 'black' t 'linear theory (S-10)', \
     '$case/eta_30.dat' w l lc rgb 'red' t 'mlpgFluid'
set title 'Mean water level (E3-17)'; set xlabel 't [s]'; set ylabel 'mean eta [m]'; set autoscale y
plot '$case/level.dat' u 1:2 w lp pt 7 ps 0.6 lc rgb 'red' t 'mean eta of the free-surface nodes', \
     '' u 1:3 w l lc rgb 'black' t 'H S(t)/(L - S(t)): the displaced volume', \
     '' u 1:(\$3 + 0.004) w l dt 2 lc rgb 'gray' t '+- 0.1 dl', '' u 1:(\$3 - 0.004) w l dt 2 lc rgb 'gray' notitle
unset multiplot
GP
echo "wrote validation/wavemaker.png"
