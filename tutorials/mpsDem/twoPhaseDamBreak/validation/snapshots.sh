#!/usr/bin/env bash
# validation/snapshots.sh [RUN...] — side views (x-z, all y) of finished runs
# of this tutorial at t = 0.1 and 0.15 s, the times of the paper's
# snapshots (Figs. 11-12): water particles (blue) and grains (brown), one
# PNG per run, validation/snapshots_<run>.png. Default: every model*-dp*
# directory. Needs bin/vtuInfo (MPSDEM_DIR for a copied case) and gnuplot.
cd "${0%/*}/.." || exit 1
ROOT="${MPSDEM_DIR:-$(cd ../../.. && pwd)}"
VTU="$ROOT/bin/vtuInfo"
[ -x "$VTU" ] || { echo "snapshots.sh: $VTU not found (set MPSDEM_DIR)" >&2; exit 1; }
command -v gnuplot > /dev/null || { echo "snapshots.sh: gnuplot not found" >&2; exit 1; }
runs=("$@")
[ ${#runs[@]} -eq 0 ] && runs=(model*-dp*/)
runs=("${runs[@]%/}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for r in "${runs[@]}"; do
    plots=()
    for t in 0.1 0.15; do
        [ -f "$r/$t/fluid.vtu" ] && [ -f "$r/$t/dem.vtu" ] || { echo "$r: no $t/fluid.vtu and dem.vtu"; continue 2; }
        # columns: x y z type ... (fluid.vtu); x y z radius ... (dem.vtu)
        "$VTU" -dump "$r/$t/fluid.vtu" 2>/dev/null | awk '!/^#/ && NF > 10 && $4 == 0 { print $1, $3 }' > "$tmp/f$t"
        "$VTU" -dump "$r/$t/dem.vtu" 2>/dev/null | awk '!/^#/ && NF > 10 { print $1, $3 }' > "$tmp/g$t"
        plots+=("set title '$r, t = $t s'; plot '$tmp/f$t' w p pt 7 ps 0.12 lc rgb '#3060c0' t 'water', '$tmp/g$t' w p pt 7 ps 0.12 lc rgb '#8b5a2b' t 'grains'")
    done
    # one x range for both panels: to the farthest particle, and the
    # highest one for z
    read -r xmax zmax < <(cat "$tmp"/f* "$tmp"/g* | awk '$1 > x { x = $1 } $2 > z { z = $2 } END { print 1.05 * x, 1.1 * z }')
    gnuplot <<EOF
set terminal pngcairo size 1200,700 noenhanced
set output 'validation/snapshots_$r.png'
set multiplot layout 2,1
set xlabel 'x [m]'; set ylabel 'z [m]'; set size ratio -1; set key right top
set xrange [0:$xmax]; set yrange [0:$zmax]
${plots[0]}
${plots[1]}
unset multiplot
EOF
    echo "validation/snapshots_$r.png written"
done
