#!/bin/sh
# hydrostatic.sh CASE [WINDOW [DIR]] — still-water checks of
# doc/theory.md E1-07/E1-08 on the fluid.vtu snapshots of the last WINDOW
# seconds (default 0.2):
#   L2      relative L2 error of the time-averaged fluid pressure (per
#           particle id) against rho g (h - z), h the water depth (the
#           top of the fluid region's box in system/particleDict)
#   umax    largest fluid speed in the window, and the same / sqrt(g h)
#   deepfs  fraction of fluid particles more than 3 dp below the surface
#           flagged as free surface (E1-07 asks < 0.5 %)
# Prints "name value" lines. Needs bin/vtuInfo.
# With DIR (an existing directory), also writes the data of the plot
# (validation/plot.sh in ../hydrostaticTank2D):
#   DIR/pressure.dat  per fluid particle over the window: id, mean height,
#                     mean pressure, rho g (h - mean height) [m, Pa]
#   DIR/speed.dat     per snapshot (all of them): t, largest fluid speed,
#                     the same / sqrt(g h) [s, m/s, -]
set -e
CASE=${1:-.}
WIN=${2:-0.2}
OUT=${3:+$(cd "$3" && pwd)}
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"   # MPSDEM_DIR for a copied case
VTU="$ROOT/bin/vtuInfo"
cd "$CASE"
dim=$(awk '/^dimension/ {gsub(";","",$2); print $2}' constant/particlePatches)
dp=$(awk '/^dp/ {gsub(";","",$2); print $2}' constant/particlePatches)
rho=$(sed 's|//.*||' constant/transportProperties | awk '/^rho/ {gsub(";","",$NF); print $NF}')
g=$(sed 's|//.*||' constant/g | awk '/^value/ {gsub("[();]","",$0); for (i = 2; i <= NF; i++) if ($i != 0) v = $i; print (v < 0 ? -v : v)}')
times=$(ls -d [0-9]* | sort -g)
last=$(echo "$times" | tail -1)
col=$([ "$dim" = 2 ] && echo 2 || echo 3)
# water depth h: the top of the box of the fluid region in
# system/particleDict (the depth the case is built with; a relaxed start,
# mpsFluid -relax, keeps its volume but not its top row), else the highest
# fluid particle of 0/ + dp/2
h=$(sed 's|//.*||' system/particleDict | awk -v c=$col '
    /{/ { depth++ } /}/ { if (--depth < fd) fl = 0 }
    /type[ \t]+fluid[ \t]*;/ { fl = 1; fd = depth }
    fl && /^[ \t]*max[ \t]*\(/ { gsub(/[();]/, " "); print $(c + 1); exit }')
[ -n "$h" ] || h=$("$VTU" -dump 0/fluid.vtu 2>/dev/null | awk -v c=$col -v dp=$dp \
    '!/^#/ && NF > 10 && $4 == 0 { if ($c > m) m = $c } END { print m + dp / 2 }')
for t in $times; do
    [ -n "$OUT" ] || awk -v t=$t -v l=$last -v w=$WIN 'BEGIN { exit !(t >= l - w - 1e-9) }' || continue
    "$VTU" -dump "$t/fluid.vtu" 2>/dev/null | awk -v t=$t '!/^#/ && NF > 10 && $4 == 0 { print t, $0 }'
done | awk -v c=$((col + 1)) -v dp=$dp -v h=$h -v rho=$rho -v g=$g -v d=$dim \
           -v l=$last -v w=$WIN -v out="$OUT" '
{
    u = sqrt($7 * $7 + $8 * $8 + $9 * $9)
    if (out != "") { if (nt == 0 || $1 != tp) { nt++; tt[nt] = $1; tp = $1 }; if (u > ut[nt]) ut[nt] = u }
    if ($1 < l - w - 1e-9) next
    id = $14; n[id]++; ps[id] += $10; zs[id] += $c
    if (u > umax) umax = u
    if ($c < h - 3 * dp) { deep++; if ($16 == 1) deepfs++ }
}
END {
    for (id in n) {
        p = ps[id] / n[id]; z = zs[id] / n[id]; pe = rho * g * (h - z)
        e2 += (p - pe) ^ 2; r2 += pe ^ 2
        if (out != "") printf "%d %.9g %.9g %.9g\n", id, z, p, pe > (out "/pressure.dat")
    }
    for (k = 1; k <= nt; k++)
        printf "%s %.6g %.6g\n", tt[k], ut[k], ut[k] / sqrt(g * h) > (out "/speed.dat")
    printf "depth %.6g\nL2 %.6f\numax %.6g\numax_rel %.6f\ndeepfs %.6f\n",
        h, sqrt(e2 / r2), umax, umax / sqrt(g * h), deep ? deepfs / deep : 0
}'
