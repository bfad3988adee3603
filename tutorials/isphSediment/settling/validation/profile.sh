#!/bin/bash
# Usage: validation/profile.sh CASE [TIME [DL]]
# The sediment profile of CASE at TIME (default 5 s): the mean alpha_s
# of each row of water particles (rows by y/DL rounded; DL default 0.01 m)
# against the hindered-settling solution (5.50) of the initial profile
# (5.51) (alpha_s0 = 1e-3 between y = 0.1 and 0.5 m, omega_s = 0.0159 m/s:
#   phi = y + omega_s (1 - f(phi))^1.65 t,  alpha_s(t, y) = f(phi),
# solved per row by fixed-point iteration). Prints the peak position of
# both (E4-06: within DL/2), the largest error relative to alpha_s0
# (E4-06: <= 10 %), the L2 error relative to the solution's, and the
# sediment volume sum alpha_s V against its start (E4-07). Writes
# validation/profile_dl<DL>.dat (columns x2 alpha, the rows' means).
set -e
case=${1:?Usage: validation/profile.sh CASE [TIME [DL]]}
t=${2:-5}
dl=${3:-0.01}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
out="${0%/*}/profile_dl$dl.dat"
rows() {
    "$root/bin/vtuInfo" -dump "$case/$1/fluid.vtu" | awk -v dl="$dl" '
        /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        $1 ~ /^[-0-9.]/ && $c["type"] == 0 { r = int($2 / dl + 0.5); n[r]++; y[r] += $2; a[r] += $c["alpha.sediment"]
                                               vol += $c["alpha.sediment"] * $c["volume"] }
        END { for (r in n) printf "%.6f %.8e\n", y[r] / n[r], a[r] / n[r]; printf "# volume %.10e\n", vol }'
}
first=$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g | sed -n 2p)
v0=$(rows "$first" | awk '/^# volume/ { print $3 }')
rows "$t" > "$out.tmp"
v1=$(awk '/^# volume/ { print $3 }' "$out.tmp")
{ echo "# x2 alpha  (isphSediment, t = $t s, dl = $dl m: the mean alpha_s of each particle row)"
  grep -v '^#' "$out.tmp" | sort -g; } > "$out"
rm -f "$out.tmp"
awk -v t="$t" -v dl="$dl" -v v0="$v0" -v v1="$v1" -v t0="$first" '
    function f(y) { return (y < 0.1 || y > 0.5) ? 0 : 0.0005 * (1 + cos(2 * 3.141592653589793 * ((y - 0.1) / 0.4 - 0.5))) }
    function exact(y,   p, k) { p = y; for (k = 0; k < 50; k++) p = y + 0.0159 * (1 - f(p))^1.65 * t; return f(p) }
    !/^#/ { a = exact($1); e = $2 - a; if (e < 0) e = -e; if (e > linf) linf = e; s += ($2 - a)^2; sa += a * a
            if ($2 > pn) { pn = $2; yn = $1 } }
    END { for (y = 0; y <= 0.5; y += 0.0001) if (exact(y) > pa) { pa = exact(y); ya = y }
          printf "peak %.4f m at alpha %.3e (solution %.4f m, %.3e): off by %.4f m (dl/2 = %.4f)\n", yn, pn, ya, pa, yn - ya, dl / 2
          printf "Linf %.4f of alpha_s0; L2 %.4f\n", linf / 0.001, sqrt(s / sa)
          printf "volume %.6e at t = %s s, %.6e at %s s: change %+.3f %%\n", v0, t0, v1, t, 100 * (v1 / v0 - 1) }' "$out"
