#!/bin/bash
# Usage: validation/wake.sh [CASE [TIME]]
# Recirculation length behind the cylinder at TIME (default: the latest):
# u on the row of nodes through the cylinder's centre (the mean of its
# wall nodes, patch 1), past its rear x_c + R; the first sign change of u
# from negative to positive (after the first negative u), interpolated
# linearly; L_wake/D = (x0 - x_c - R)/D with R = 0.02 m. The last line is
# "wake L/D".
set -e
case=${1:-.}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
t=${2:-$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)}
"$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk -v t="$t" '
    /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
    NF > 5 && $1 ~ /^[-0-9.]/ { n++; x[n] = $1; y[n] = $2; ty[n] = $c["type"]; u[n] = $c["velocity_0"]
        if ($c["type"] == 1 && $c["patch"] == 1) { sx += $1; sy += $2; nc++ } }
    END {
        if (!nc) { print "wake.sh: no cylinder nodes (patch 1)" > "/dev/stderr"; exit 1 }
        xc = sx / nc; yc = sy / nc; R = 0.02
        for (k = 1; k <= n; k++)
            if (ty[k] == 0 && y[k] > yc - 1e-4 && y[k] < yc + 1e-4 && x[k] > xc + R) print x[k], u[k], xc, R
    }' | sort -g | awk -v t="$t" '
    $2 < 0 { neg = 1 }
    neg && !done && $2 >= 0 { x0 = p + (0 - pu) * ($1 - p) / ($2 - pu); L = (x0 - $3 - $4) / (2 * $4)
        printf "t = %s s: u = 0 at x = %.4f m, L_wake/D = %.3f\n", t, x0, L
        printf "wake %.4f\n", L; done = 1 }
    { p = $1; pu = $2 }
    END { if (!neg) { print "t = " t " s: no recirculation"; print "wake 0" }
          else if (!done) print "wake NaN" }'
