#!/bin/sh
# plot.sh — the pictures of E5-07 from the runs of validation/runAll:
#   fronts.png     soil front, height of the soil's leading edge and
#                  airborne soil particles against time, four runs
#                  (validation/fronts_<run>.dat)
#   snapshots.png  water and soil of the solid and the liquid model
#                  (1900 kg/m^3) at 0.25, 0.5 and 1 s
# Needs gnuplot and bin/vtuInfo (MPSDEM_DIR for a copied case).
set -e
cd "$(dirname "$0")/.."
ROOT="${MPSDEM_DIR:-$(cd ../../.. && pwd)}"
command -v gnuplot > /dev/null || { echo "plot.sh: gnuplot not found" >&2; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
for r in solid_1900 liquid_1900; do
    for t in 0.25 0.5 1; do
        "$ROOT/bin/vtuInfo" -dump "$r/$t/fluid.vtu" 2>/dev/null | awk '
            /^# x/ { for (i = 2; i <= NF; i++) k[$i] = i - 1; next } /^#/ || NF < 5 { next }
            { print $1, $2, $k["type"] == 0 ? $k["phase"] : 2 }' > "$TMP/${r}_$t.dat"
    done
done
gnuplot <<GP
set terminal pngcairo size 1200,420 font ",10"
set output "validation/fronts.png"
set multiplot layout 1,3
set grid; set key top left; set xlabel "t [s]"
r1 = "validation/fronts_solid_1900.dat"; r2 = "validation/fronts_liquid_1900.dat"
r3 = "validation/fronts_solid_900.dat"; r4 = "validation/fronts_liquid_900.dat"
set ylabel "soil front X_s [m]"
plot r1 u 1:2 w lp pt 7 ps 0.4 t "solid 1900", r2 u 1:2 w lp pt 5 ps 0.4 t "liquid 1900", \
     r3 u 1:2 w lp pt 6 ps 0.4 t "solid 900", r4 u 1:2 w lp pt 4 ps 0.4 t "liquid 900"
set ylabel "height of the soil's leading edge [m]"
plot r1 u 1:3 w lp pt 7 ps 0.4 t "solid 1900", r2 u 1:3 w lp pt 5 ps 0.4 t "liquid 1900", \
     r3 u 1:3 w lp pt 6 ps 0.4 t "solid 900", r4 u 1:3 w lp pt 4 ps 0.4 t "liquid 900"
set ylabel "airborne soil particles (n/n0 < 0.5)"
plot r1 u 1:4 w lp pt 7 ps 0.4 t "solid 1900", r2 u 1:4 w lp pt 5 ps 0.4 t "liquid 1900", \
     r3 u 1:4 w lp pt 6 ps 0.4 t "solid 900", r4 u 1:4 w lp pt 4 ps 0.4 t "liquid 900"
unset multiplot
set terminal pngcairo size 1500,560 font ",10" noenhanced
set output "validation/snapshots.png"
set multiplot layout 2,3
unset grid; set size ratio -1; set xrange [0:1.2]; set yrange [0:0.5]; unset key
set xlabel "x [m]"; set ylabel "y [m]"
do for [r in "solid_1900 liquid_1900"] {
    do for [t in "0.25 0.5 1"] {
        set title sprintf("%s, t = %s s", r, t)
        plot "$TMP/".r."_".t.".dat" u 1:(\$3 == 0 ? \$2 : 1/0) w p pt 7 ps 0.25 lc rgb "#3070d0", \
             "" u 1:(\$3 == 1 ? \$2 : 1/0) w p pt 7 ps 0.25 lc rgb "#a0522d", \
             "" u 1:(\$3 == 2 ? \$2 : 1/0) w p pt 7 ps 0.15 lc rgb "gray"
    }
}
unset multiplot
GP
echo "wrote validation/fronts.png validation/snapshots.png"
