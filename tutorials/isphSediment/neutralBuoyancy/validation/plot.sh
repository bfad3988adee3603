#!/bin/bash
# Usage: validation/plot.sh [CASE [TIME]]
# Pressure and alpha_s of every water particle against height at TIME
# (default: the latest), with rho g (1 - y): validation/neutralBuoyancy.png.
cd "${0%/*}/.." || exit 1
case=${1:-.}
root=${MPSDEM_DIR:-$(cd ../../.. && pwd)}
t=${2:-$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)}
"$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
    $1 ~ /^[-0-9.]/ && $c["type"] == 0 { print $2, $c["pressure"], $c["alpha.sediment"] }' > "$case/profile.dat"
gnuplot <<GP
set terminal pngcairo size 1000,450
set output 'validation/neutralBuoyancy.png'
set multiplot layout 1,2 title 'Neutrally buoyant sediment in still water, t = $t s (isphSediment)'
set grid; set key bottom left
set ylabel 'y [m]'; set xlabel 'p [Pa]'
plot '$case/profile.dat' u 2:1 w p pt 7 ps 0.3 t 'water particles', \
     [0:1] '+' u (9800 * (1 - \$1)):1 w l lc rgb 'black' t 'rho g (1 - y)'
set xlabel 'alpha_s'; set key top right; set xtics rotate by -45 format '%.4f'
plot '$case/profile.dat' u 3:1 w p pt 7 ps 0.3 t 'alpha_s'
unset multiplot
GP
echo "wrote validation/neutralBuoyancy.png"
