#!/bin/sh
# plot.sh [CASE] [WINDOW] [PNG] — picture of the still-water checks of
# doc/theory.md E1-08 for a finished run of hydrostaticTank2D or hydrostaticTank
# (the 3-D case's validation/plot.sh calls this one):
#   (a) time-averaged pressure of each fluid particle over the last WINDOW
#       seconds (default 0.2) against its depth h - y, with rho g (h - y);
#   (b) the same minus rho g (h - y);
#   (c) largest fluid speed / sqrt(g h) of every fluid.vtu snapshot against
#       time, with the E1-08 target 0.01.
# Data from validation/hydrostatic.sh CASE WINDOW DIR (beside this script),
# drawn by validation/plot.gnuplot; the title gives its L2 and max speed.
# CASE defaults to ., PNG to CASE/validation/hydrostatic.png. Needs gnuplot.
set -e
HERE=$(cd "$(dirname "$0")" && pwd)
CASE=${1:-.}
WIN=${2:-0.2}
PNG=${3:-$CASE/validation/hydrostatic.png}
command -v gnuplot > /dev/null || { echo "plot.sh: gnuplot not found" >&2; exit 1; }
[ -f "$CASE/constant/particlePatches" ] || { echo "plot.sh: $CASE is not a finished run (no constant/particlePatches)" >&2; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
out=$("$HERE/hydrostatic.sh" "$CASE" "$WIN" "$TMP")
echo "$out"
val() { echo "$out" | awk -v k="$1" '$1 == k { print $2 }'; }
get() { awk -v k="$1" '$1 == k { gsub(";", "", $2); print $2 }' "$CASE/constant/particlePatches"; }
last=$(cd "$CASE" && ls -d [0-9]* | sort -g | tail -1)
name=$(basename "$(cd "$CASE" && pwd)")
mkdir -p "$(dirname "$PNG")"
gnuplot -e "data = '$TMP'; png = '$PNG'; name = '$name'; dim = $(get dimension); dp = $(get dp)" \
        -e "h = $(val depth); L2 = $(val L2); urel = $(val umax_rel); tend = $last; win = $WIN" \
        "$HERE/plot.gnuplot"
echo "$PNG written"
