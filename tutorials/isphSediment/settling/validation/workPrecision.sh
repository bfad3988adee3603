#!/bin/bash
# Usage: validation/workPrecision.sh [DL...]
#        validation/workPrecision.sh -plot     (the plot of the committed table)
# Work against precision of the settling test (issue: the L2 error of
# alpha_s at 5 s against the wall time): each DL (default 0.05 0.02 0.01
# 0.005 m) with dt = 1e-3 s (the thesis's) and 5e-4 s, run one after the
# other in wp/dl<DL>_dt<dt>/ on the threads OMP_NUM_THREADS allows; the
# error is validation/profile.sh's L2 against (5.50). Prints the table,
# writes validation/workPrecision.dat (columns dl dt L2 Linf wall
# particles steps: the water particles) and, with gnuplot, validation/workPrecision.png.
. "${MPSDEM_DIR:-${0%/*}/../../../..}/bin/tools/RunFunctions" 2>/dev/null || {
    echo "${0##*/}: bin/tools/RunFunctions not found: set MPSDEM_DIR to the mpsdem directory" >&2; exit 1; }
cd "${0%/*}/.." || exit 1
out=validation/workPrecision.dat
if [ "${1:-}" != -plot ]; then
dls=${*:-0.05 0.02 0.01 0.005}
{
    echo "# dl dt L2 Linf wall particles steps  (isphSediment settling, t = 5 s; wall [s] with OMP_NUM_THREADS=${OMP_NUM_THREADS:-all}, load $(cut -d' ' -f1 /proc/loadavg) at the start)"
    for dl in $dls; do
        for dt in 1e-3 5e-4; do
            d=wp/dl${dl}_dt$dt
            rm -rf "$d"; mkdir -p "$d"; cp -r constant system "$d"/
            sed -i "s/^dp .*/dp           $dl;/" "$d/system/particleDict"
            dictTool -case "$d" system/controlDict -set "deltaT=$dt" > /dev/null || exit 1
            (cd "$d" && runApplication genParticles > /dev/null) || exit 1
            t0=$(date +%s.%N)
            (cd "$d" && runApplication isphSediment > /dev/null) || exit 1
            t1=$(date +%s.%N)
            r=$(validation/profile.sh "$d" 5 "$dl" "$d/profile.dat" | awk '/^Linf/ { print $6, $2 }')
            np=$(vtuInfo -dump "$d/0/fluid.vtu" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next } $1 ~ /^[-0-9.]/ && $c["type"] == 0 { n++ } END { print n }')
            echo "$dl $dt $r $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }') ${np:-nan} $(awk -v t="$dt" 'BEGIN { printf "%d", 5 / t + 0.5 }')"
        done
    done
} > "$out"
fi
column -t "$out"
command -v gnuplot > /dev/null || exit 0
gnuplot <<EOF
set terminal pngcairo size 700,500
set output 'validation/workPrecision.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'L2 error of alpha_s at 5 s (relative)'
set title 'isphSediment settling: work against precision'
set key bottom left
# rows alternate: dt = 1e-3, 5e-4 for each dl
plot '$out' every 2 using 5:3 with linespoints pt 7 title 'dt = 1e-3 s', \
     '' every 2::1 using 5:3 with linespoints pt 5 title 'dt = 5e-4 s', \
     '' using 5:3:(sprintf('%g', \$1)) with labels offset 1.5,0.5 notitle
EOF
