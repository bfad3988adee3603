#!/bin/sh
# repose.sh RUN [PROFILE] — the deposit of one run of soilSlope (RUN: a
# copy mu<MU>/ made by ../Allrun) at its last snapshot. Prints
#   mu angle_deg runout height umax
# mu from RUN/constant/soilProperties; the surface profile is the highest
# soil particle (n/n0 >= 0.5) of each dp-wide column of x, + dp/2; angle =
# -atan of the least-squares slope of that profile where it lies between
# 20 % and 80 % of the deposit's height (the flank between toe and crest;
# doc/theory.md E5-03 compares it with atan(mu)); runout = the toe, the
# last column holding soil, + dp/2 [m]; height = the highest point of the
# profile [m]; umax = the largest soil speed [m/s] (the deposit at rest:
# small). With PROFILE, writes the profile there (columns x y).
set -e
RUN=${1:?usage: repose.sh RUN [PROFILE]}
PROF=${2:-/dev/null}
case $PROF in /*) ;; *) PROF="$PWD/$PROF" ;; esac
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"
cd "$RUN"
dp=$(awk '/^dp/ {gsub(";","",$2); print $2}' constant/particlePatches)
mu=$(sed 's|//.*||' constant/soilProperties | awk '$1 == "mu" { gsub(";", "", $2); print $2 }')
last=$(ls -d [0-9]* | sort -g | tail -1)
"$ROOT/bin/vtuInfo" -dump "$last/fluid.vtu" 2>/dev/null | awk -v dp="$dp" -v mu="$mu" -v prof="$PROF" '
    /^# x/ { for (i = 2; i <= NF; i++) k[$i] = i - 1; next }
    /^#/ || NF < 5 { next }
    $k["type"] == 0 && $k["phase"] == 1 {
        u = sqrt($k["velocity_0"]^2 + $k["velocity_1"]^2); if (u > um) um = u
        if ($k["numberDensity"] < 0.5) next
        b = int($1 / dp); if (!(b in top) || $2 > top[b]) top[b] = $2; if (b > bmax) bmax = b }
    END {
        for (b = 0; b <= bmax; b++) if (b in top) { y = top[b] + dp / 2; if (y > H) H = y
            printf "%.6f %.6f\n", (b + 0.5) * dp, y > prof }
        for (b = 0; b <= bmax; b++) if (b in top) { y = top[b] + dp / 2
            if (y >= 0.2 * H && y <= 0.8 * H) { x = (b + 0.5) * dp; n++; sx += x; sy += y; sxx += x * x; sxy += x * y } }
        a = n > 1 ? -atan2(n * sxy - sx * sy, n * sxx - sx * sx) * 45 / atan2(1, 1) : 0
        printf "%s %.2f %.4f %.4f %.4f\n", mu, a, (bmax + 1) * dp, H, um }'
