#!/bin/bash
# Usage: validation/plot.sh [CASE T1 T2 T3 T4]
# validation/sandDumping.png from the committed validation/series_case<N>.dat
# (cloud.sh): the cloud's front velocity omega_c against t and its width W
# against its descent Z, the four cases of Pan 2022 Table 1, with the
# single grains' settling velocities omega_s (Table 1). With CASE (a run
# directory) and four times, also validation/snapshots.png: alpha_s and
# the dynamic pressure p - rho_f g (H - y) (H = 1 m) of CASE's particles at
# those times.
cd "${0%/*}" || exit 1
root=${MPSDEM_DIR:-$(cd ../../../.. && pwd)}
plots=""; wplots=""
ws=(0 0.1260 0.4952 0.1961 0.4952)
for n in 1 2 3 4; do
    f=series_case$n.dat
    [ -f "$f" ] || continue
    plots="$plots${plots:+, }'$f' u 1:4 w lp pt 7 ps 0.5 lc $n t 'case $n', ${ws[$n]} w l dt 2 lc $n notitle"
    wplots="$wplots${wplots:+, }'$f' u 2:3 w lp pt 7 ps 0.5 lc $n t 'case $n'"
done
gnuplot <<GP
set terminal pngcairo size 1100,450
set output 'sandDumping.png'
set multiplot layout 1,2 title 'Sand dumped into still water (isphSediment; dashed: single-grain omega_s)'
set grid; set key top right
set xlabel 't [s]'; set ylabel 'omega_c = dZ/dt [m/s]'; set xrange [0:3]; set yrange [0:0.9]
plot $plots
set key top left
set xlabel 'Z (descent of the front) [m]'; set ylabel 'W (width of the cloud) [m]'; set xrange [0:1]; set yrange [0:0.5]
plot $wplots
unset multiplot
GP
echo "wrote validation/sandDumping.png"
[ $# -ge 5 ] || exit 0
case=$(cd "$OLDPWD" && cd "$1" && pwd); shift
for t in "$@"; do
    "$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        $1 ~ /^[-0-9.]/ && $c["type"] == 0 { print $1, $2, $c["alpha.sediment"], $c["pressure"] - 1000 * 9.8 * (1 - $2) }' > "snap_$t.tmp"
done
gnuplot <<GP
set terminal pngcairo size 1400,700
set output 'snapshots.png'
set multiplot layout 2,4
set size ratio -1; set xrange [0.2:0.8]; set yrange [0.3:1.02]; unset key
set cbrange [0:0.05]; set cblabel 'alpha_s'
do for [t in '$*'] { set title sprintf('alpha_s, t = %s s', t); plot 'snap_'.t.'.tmp' u 1:2:3 w p pt 7 ps 0.35 lc palette }
set cbrange [-40:40]; set cblabel 'p - rho_f g (H - y) [Pa]'; set palette defined (-1 'blue', 0 'white', 1 'red')
do for [t in '$*'] { set title sprintf('dynamic pressure, t = %s s', t); plot 'snap_'.t.'.tmp' u 1:2:4 w p pt 7 ps 0.35 lc palette }
unset multiplot
GP
rm -f snap_*.tmp
echo "wrote validation/snapshots.png"
