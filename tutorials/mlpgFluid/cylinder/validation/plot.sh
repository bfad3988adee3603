#!/bin/bash
# Usage: validation/plot.sh DIR...
# u/u_a along the row of nodes through the cylinder's centre (the mean of
# its wall nodes, patch 1) at each DIR's
# last time (the steady wake), x measured from the cylinder's centre in
# diameters: validation/wake.png.
[ $# -gt 0 ] || set -- "${0%/*}"/../Re*
dirs=()
for d in "$@"; do dirs+=("$(cd "$d" && pwd)") || exit 1; done
cd "${0%/*}/.." || exit 1
root=${MPSDEM_DIR:-$(cd ../../.. && pwd)}
cmd=""
for d in "${dirs[@]}"; do
    t=$(ls -d "$d"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)
    "$root/bin/vtuInfo" -dump "$d/$t/fluid.vtu" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        NF > 5 && $1 ~ /^[-0-9.]/ { n++; x[n] = $1; y[n] = $2; ty[n] = $c["type"]; u[n] = $c["velocity_0"]
            if ($c["type"] == 1 && $c["patch"] == 1) { sx += $1; sy += $2; nc++ } }
        END { xc = sx / nc; yc = sy / nc
              for (k = 1; k <= n; k++) if (ty[k] == 0 && y[k] > yc - 1e-4 && y[k] < yc + 1e-4) print (x[k] - xc) / 0.04, u[k] / 0.1 }' \
        | sort -g | awk 'p < 0 && $1 > 0 { print "" } { print; p = $1 }' > "$d/centreline.dat"
    cmd="$cmd${cmd:+, }'$d/centreline.dat' w l lw 2 t '$(basename "$d")'"
done
gnuplot <<GP
set terminal pngcairo size 800,500
set output 'validation/wake.png'
set grid; set key bottom right
set xrange [-3:10]
set xlabel '(x - x_c)/D'; set ylabel 'u/u_a on the centre line'
set title 'Flow past a cylinder (mlpgFluid, 24 nodes on the cylinder): steady wakes'
plot $cmd, 0 lc rgb 'black' notitle
GP
echo "wrote validation/wake.png"
