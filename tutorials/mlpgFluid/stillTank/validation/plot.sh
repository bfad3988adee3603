#!/bin/bash
# Usage: validation/plot.sh [CASE [TIME]]
# Pressure of every node against height at TIME (default: the latest)
# beside rho g (1 - y): validation/stillTank.png.
cd "${0%/*}/.." || exit 1
case=${1:-.}
root=${MPSDEM_DIR:-$(cd ../../.. && pwd)}
t=${2:-$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)}
"$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
    NF > 5 && $1 ~ /^[-0-9.]/ { print $2, $c["pressure"], $c["type"] }' > "$case/pressure.dat"
gnuplot <<GP
set terminal pngcairo size 700,500
set output 'validation/stillTank.png'
set grid; set key top right
set xlabel 'p [Pa]'; set ylabel 'y [m]'
set title 'Still tank, t = $t s (mlpgFluid, improvedConsistent, free surface)'
plot '$case/pressure.dat' u (\$3 == 0 ? \$2 : 1/0):1 w p pt 7 ps 0.5 t 'water nodes', \
     '' u (\$3 == 1 ? \$2 : 1/0):1 w p pt 6 ps 0.8 t 'wall nodes', \
     [0:1] '+' u (9810 * (1 - \$1)):1 w l lc rgb 'black' t 'rho g (1 - y)'
GP
echo "wrote validation/stillTank.png"
