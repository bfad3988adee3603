#!/usr/bin/env bash
# grainHistory.sh — time, position and velocity of the grain from every
# <time>/dem.vtu (writeFormat ascii), one line per time: t x y vx vy [SI].
cd "${0%/*}/.." || exit 1
for d in $(ls -d [0-9]* | sort -g); do
    [ -f "$d/dem.vtu" ] || continue
    awk -v t="$d" '
        /Name="velocity"/ { getline; vx = $1; vy = $2; next }
        /<Points>/        { getline; getline; x = $1; y = $2 }
        END { printf "%s %s %s %s %s\n", t, x, y, vx, vy }' "$d/dem.vtu"
done
