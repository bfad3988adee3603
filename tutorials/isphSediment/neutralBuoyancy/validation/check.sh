#!/bin/bash
# Usage: validation/check.sh [CASE [TIME]]
# E4-04 at TIME (default: the latest written): the pressure of the water
# particles against rho g (H - y) (rho = 1000 kg/m^3, g = 9.8 m/s^2, H =
# 1 m; L2 relative), the largest particle displacement since t = 0 [m and
# dl], the largest |alpha_s - alpha_s0| with alpha_s0 from CASE's
# system/isphSolution (alphaSediment value + gradient.(x - origin), taken
# at the particle's start position), over all water particles and over
# those off the free surface, the largest speed [m/s], and the sum of
# the water particles' volumes V (5.34) against the 1 m^2 of water (E4-03;
# the wall particles stand on the walls, so the water particles' cells
# leave out a strip of dl/2 along each side wall: 1 - dl expected).
set -e
case=${1:-.}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
t=${2:-$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)}
dict="$root/bin/dictTool"
get() { "$dict" "$case/system/isphSolution" -entry "alphaSediment/$1" | tr -d '();' ; }
a0=$(get value); grad=$(get gradient); orig=$(get origin)
dl=$(awk '$1 == "dp" { gsub(/;/, "", $2); print $2 }' "$case/system/particleDict")
dump() { "$root/bin/vtuInfo" -dump "$case/$1/fluid.vtu" | awk '/^# x/ || $1 ~ /^[-0-9.]/'; }
hdr=$(dump "$t" | grep -m1 '^# x')
paste -d' ' <(dump 0 | awk '!/^#/ { print $1, $2 }') <(dump "$t" | grep -v '^#') | awk -v hdr="$hdr" -v a0="$a0" -v g="$grad" -v o="$orig" -v dl="$dl" -v t="$t" '
    BEGIN { n = split(hdr, h, " "); for (k = 2; k <= n; k++) c[h[k]] = k + 1   # after the 2 start columns
            split(g, G, " "); split(o, O, " ") }
    { if ($c["type"] != 0) next
      pa = 1000 * 9.8 * (1 - $4); if (pa < 0) pa = 0; e = $c["pressure"] - pa; s += e * e; sa += pa * pa
      d = sqrt(($3 - $1)^2 + ($4 - $2)^2); if (d > dm) dm = d
      al = a0 + G[1] * ($1 - O[1]) + G[2] * ($2 - O[2]); if (al < 0) al = 0
      ea = $c["alpha.sediment"] - al; if (ea < 0) ea = -ea; if (ea > am) am = ea
      if (!$c["freeSurface"] && ea > ai) ai = ea
      v = sqrt($c["velocity_0"]^2 + $c["velocity_1"]^2); if (v > vm) vm = v; vol += $c["volume"] }
    END { printf "t = %s s: pressure L2 %.3g, displacement %.3g m (%.3g dl), |alpha_s - alpha_s0| %.3g (off the surface %.3g), speed %.3g m/s, sum V %.6f m^2\n", t, sqrt(s / sa), dm, dm / dl, am, ai, vm, vol }'
