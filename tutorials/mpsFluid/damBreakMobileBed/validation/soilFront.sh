#!/bin/sh
# soilFront.sh RUN — the soil and water fronts of one run of
# damBreakMobileBed (RUN: a directory made by ../Allrun, e.g. solid_1900),
# from its fluid.vtu snapshots, one row per snapshot:
#   t        [s]
#   Xs       soil front: largest x of a soil particle with n/n0 >= 0.5 [m]
#   Hs       height of the soil's leading edge: the highest soil particle
#            within 5 dp behind Xs (+ dp/2) [m] — a blunt ("carpet") front
#            is high, a thin tongue low
#   airborne soil particles with n/n0 < 0.5 (splash: few neighbours; the
#            start, t = 0, has no number density: every particle counts)
#   Xw       water front, as Xs for the water [m]
# Prints "# RUN" and a header line first. Needs bin/vtuInfo (MPSDEM_DIR for
# a copied case).
set -e
RUN=${1:?usage: soilFront.sh RUN}
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"
cd "$RUN"
dp=$(awk '/^dp/ {gsub(";","",$2); print $2}' constant/particlePatches)
echo "# $(basename "$(pwd)"): soil and water fronts (validation/soilFront.sh)"
echo "# t Xs Hs airborne Xw"
for t in $(ls -d [0-9]* | sort -g); do
    "$ROOT/bin/vtuInfo" -dump "$t/fluid.vtu" 2>/dev/null | awk -v t="$t" -v dp="$dp" '
        /^# x/ { for (i = 2; i <= NF; i++) k[$i] = i - 1; next }
        /^#/ || NF < 5 { next }
        $k["type"] == 0 { n++; x[n] = $1; y[n] = $2; nd[n] = t == 0 ? 1 : $k["numberDensity"]
                          s[n] = ("phase" in k) ? $k["phase"] : 0 }
        END {
            xs = -1e9; xw = -1e9
            for (i = 1; i <= n; i++) {
                if (s[i] == 1 && nd[i] < 0.5) air++
                if (nd[i] < 0.5) continue
                if (s[i] == 1 && x[i] > xs) xs = x[i]
                if (s[i] == 0 && x[i] > xw) xw = x[i]
            }
            hs = 0
            for (i = 1; i <= n; i++)
                if (s[i] == 1 && nd[i] >= 0.5 && x[i] > xs - 5 * dp && y[i] + dp / 2 > hs) hs = y[i] + dp / 2
            sx = "nan"; if (xs > -1e9) sx = sprintf("%.5f", xs)
            sw = "nan"; if (xw > -1e9) sw = sprintf("%.5f", xw)
            printf "%s %s %.5f %d %s\n", t, sx, hs, air + 0, sw
        }'
done
