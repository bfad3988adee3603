#!/bin/bash
# Usage: validation/plot.sh RE [DIR...]
# Centre-line profiles at Re = RE against Ghia et al. (1982): u(y) on
# x = 0.5 and v(x) on y = 0.5 from each DIR's u_Re<RE>.dat / v_Re<RE>.dat
# (validation/compare.sh writes them; default: validation/, the committed
# improved-scheme profiles, and Re<RE>-original/ when present), into
# validation/profiles_Re<RE>.png.
cd "${0%/*}/.." || exit 1
re=${1:?Re}; shift
root=${MPSDEM_DIR:-$(cd ../../.. && pwd)}
dirs=${*:-validation $( [ -d Re$re-original ] && echo Re$re-original)}
c=$(case $re in 100) echo 2;; 400) echo 3;; 1000) echo 4;; 3200) echo 5;; esac)
[ -n "$c" ] || { echo "plot.sh: Ghia gives Re 100, 400, 1000, 3200" >&2; exit 1; }
command -v gnuplot > /dev/null || { echo "plot.sh: gnuplot not found" >&2; exit 1; }
pu=""; pv=""
for d in $dirs; do
    [ -f "$d/u_Re$re.dat" ] || { echo "plot.sh: no $d/u_Re$re.dat" >&2; exit 1; }
    label=$(basename "$d"); label=$([ "$d" = validation ] && echo improved || echo "${label#Re$re-}")
    pu="$pu, '$d/u_Re$re.dat' u 2:1 w l lw 2 t '$label'"
    pv="$pv, '$d/v_Re$re.dat' u 1:2 w l lw 2 t '$label'"
done
gnuplot <<GP
set terminal pngcairo size 1100,500
set output 'validation/profiles_Re$re.png'
set datafile separator whitespace
set multiplot layout 1,2 title 'Lid-driven cavity, Re = $re, dl = 0.01 (mlpgFluid) against Ghia et al. (1982)'
set grid; set key bottom right
set xlabel 'u'; set ylabel 'y'
plot '< tail -n +2 $root/data/ghia_1982_cavity/ghia1982_u_vertical_centerline.csv | tr , " "' u $c:1 w p pt 7 lc rgb 'black' t 'Ghia et al.' $pu
set key top right
set xlabel 'x'; set ylabel 'v'
plot '< tail -n +2 $root/data/ghia_1982_cavity/ghia1982_v_horizontal_centerline.csv | tr , " "' u 1:$c w p pt 7 lc rgb 'black' t 'Ghia et al.' $pv
unset multiplot
GP
echo "wrote validation/profiles_Re$re.png"
