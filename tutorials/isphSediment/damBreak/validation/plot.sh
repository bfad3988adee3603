#!/bin/bash
# Usage: validation/plot.sh [CASE]
# validation/damBreak.png: the committed validation/front_dl<dl>.dat (each
# resolution's front.dat of compare.sh) against Martin & Moyce (1952);
# with CASE, also validation/snapshots.png: CASE's particles at t = 0.1,
# 0.2, 0.3, 0.4 s coloured by pressure.
cd "${0%/*}" || exit 1
root=${MPSDEM_DIR:-$(cd ../../../.. && pwd)}
data="$root/data/martin_moyce_1952"
zplot="'$data/martin_moyce_1952_surge_front_n2-2_a2.25in.csv' every ::1 u 1:2 w p pt 7 ps 1.2 lc rgb 'black' t 'Martin and Moyce 1952'"
hplot="'$data/martin_moyce_1952_column_height_n2-2_a2.25in.csv' every ::1 u 1:2 w p pt 7 ps 1.2 lc rgb 'black' t 'Martin and Moyce 1952'"
for f in $(ls front_dl*.dat | sort -t l -k2 -g -r); do
    d=${f#front_dl}; d=${d%.dat}
    zplot="$zplot, '$f' u 2:3 w l lw 2 t 'dl = $d m'"
    hplot="$hplot, '$f' u 4:5 w l lw 2 t 'dl = $d m'"
done
gnuplot <<GP
set terminal pngcairo size 1100,450
set output 'damBreak.png'
set datafile separator whitespace
set multiplot layout 1,2 title 'Dam break, n^2 = 2, a = 0.2 m (isphSediment, no sediment)'
set grid; set key top left
set xlabel 'T = t (2g/a)^{1/2}'; set ylabel 'Z = x/a'; set xrange [0:4]; set yrange [1:6]
set datafile separator ' ,'
plot $zplot
set key top right
set xlabel 'tau = t (g/a)^{1/2}'; set ylabel 'H = h/(2a)'; set xrange [0:3]; set yrange [0:1.1]
plot $hplot
unset multiplot
GP
echo "wrote validation/damBreak.png"
[ -n "$1" ] || exit 0
case=$(cd "$OLDPWD" && cd "$1" && pwd)
for t in 0.1 0.2 0.3 0.4; do
    "$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        $1 ~ /^[-0-9.]/ && $c["type"] < 2 { print $1, $2, $c["pressure"], $c["type"] }' > "snap_$t.tmp"
done
gnuplot <<GP
set terminal pngcairo size 1100,650
set output 'snapshots.png'
set multiplot layout 2,2
set size ratio -1; set xrange [-0.02:1.62]; set yrange [-0.02:0.62]; unset key
set cbrange [0:4000]; set cblabel 'p [Pa]'
do for [t in '0.1 0.2 0.3 0.4'] {
    set title sprintf('t = %s s', t)
    plot 'snap_'.t.'.tmp' u 1:2:3 w p pt 7 ps 0.3 lc palette
}
unset multiplot
GP
rm -f snap_*.tmp
echo "wrote validation/snapshots.png"
