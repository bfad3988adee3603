#!/bin/bash
# Usage: validation/wake.sh [CASE [TIME]]
# Recirculation length behind the cylinder at TIME (default: the latest):
# u on the row of nodes through the cylinder's centre (y = 57 dl), x past
# the cylinder's rear (0.52 m); the first sign change of u from negative to
# positive (after the first negative u), interpolated linearly;
# L_wake/D = (x0 - 0.52)/0.04; the last line "wake L/D".
set -e
case=${1:-.}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
t=${2:-$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)}
"$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk '
    /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
    NF > 5 && $1 ~ /^[-0-9.]/ && $c["type"] == 0 && $2 > 0.29826 - 1e-4 && $2 < 0.29826 + 1e-4 && $1 > 0.52 { print $1, $c["velocity_0"] }' \
| sort -g | awk -v t="$t" '
    $2 < 0 { neg = 1 }
    neg && !done && $2 >= 0 { x0 = p + (0 - pu) * ($1 - p) / ($2 - pu)
        printf "t = %s s: u = 0 at x = %.4f m, L_wake/D = %.3f\n", t, x0, (x0 - 0.52) / 0.04
        printf "wake %.4f\n", (x0 - 0.52) / 0.04; done = 1 }
    { p = $1; pu = $2 }
    END { if (!neg) { print "t = " t " s: no recirculation"; print "wake 0" }
          else if (!done) print "wake NaN" }'
