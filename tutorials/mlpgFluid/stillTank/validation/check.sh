#!/bin/bash
# Usage: validation/check.sh [CASE [TIME]]
# The still tank at TIME (default: the latest) against its start: pressure
# L2 error against rho g (1 - y) over the water nodes (0 above the
# surface), the largest node displacement since t = 0 [m], the largest
# speed [m/s], and the free-surface nodes of the last step (log).
set -e
case=${1:-.}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
t=${2:-$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)}
dump() { "$root/bin/vtuInfo" -dump "$case/$1/fluid.vtu" | awk '/^# x/ || (NF > 5 && $1 ~ /^[-0-9.]/)'; }
l2=$(dump "$t" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
    $c["type"] == 0 { pa = 1000 * 9.81 * (1 - $2); if (pa < 0) pa = 0; e = $c["pressure"] - pa
    s += e * e; sa += pa * pa; v = sqrt($c["velocity_0"]^2 + $c["velocity_1"]^2); if (v > vm) vm = v }
    END { printf "%.3g %.3g", sqrt(s / sa), vm }')
# positions only: the start cloud (genParticles) has fewer fields
xy() { dump "$1" | awk '!/^#/ { print $1, $2 }'; }
disp=$(paste <(xy 0) <(xy "$t") | awk '{ d = sqrt(($1 - $3)^2 + ($2 - $4)^2); if (d > m) m = d }
    END { printf "%.3g", m }')
surf=$(grep '^Time' "$case"/log.mlpgFluid 2>/dev/null | tail -1 | awk '{ print $NF }')
echo "t = $t s: pressure L2 $(echo $l2 | cut -d' ' -f1), max speed $(echo $l2 | cut -d' ' -f2) m/s, max displacement $disp m, surface nodes ${surf:-?}"
