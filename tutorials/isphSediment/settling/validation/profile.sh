#!/bin/bash
# Usage: validation/profile.sh CASE [TIME [DL [OUT]]]
# The sediment profile of CASE at TIME (default 5 s): the mean alpha_s
# of each row of water particles (rows by y/DL rounded; DL default 0.01 m)
# against the hindered-settling solution (5.50) of the initial profile
# (5.51) (alpha_s0 = 1e-3 between y = 0.1 and 0.5 m, omega_s = 0.0159 m/s:
#   phi = y + omega_s (1 - f(phi))^1.65 t,  alpha_s(t, y) = f(phi),
# solved per row by fixed-point iteration). Prints the peak position of
# both (E4-06: within DL/2), the largest error relative to alpha_s0
# (E4-06: <= 10 %), the L2 error relative to the solution's, and the
# sediment volume sum alpha_s V against its start (E4-07), and the
# pressure of the water particles against the hydrostatic pressure plus
# the suspended excess (E4-08): p = rho_f g (H - y) + (rho_s - rho_f) g
# int_y^H alpha_s dz, H the top row, the integral over the row means
# (rho_f = 1000, rho_s = 2650, g = 9.8): the L2 error relative to it, and
# the mean pressure of the bottom row of water less rho_f g H against the
# excess there. Writes OUT (default validation/profile_dl<DL>.dat;
# columns x2 alpha, the rows' means).
set -e
case=${1:?Usage: validation/profile.sh CASE [TIME [DL [OUT]]]}
t=${2:-5}
dl=${3:-0.01}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
out=${4:-${0%/*}/profile_dl$dl.dat}
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
# E4-08: the excess below each row is the trapezoid sum of the row means
# from the top row down
"$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk -v dl="$dl" -v prof="$out" '
    BEGIN { while ((getline l < prof) > 0) if (l !~ /^#/) { split(l, w, " "); r = int(w[1] / dl + 0.5); a[r] = w[2]; if (r > top) top = r }
            for (r = top; r >= 0; r--) ex[r] = r == top ? 0 : ex[r + 1] + 0.5 * (a[r] + a[r + 1]) * dl }
    /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
    $1 ~ /^[-0-9.]/ && $c["type"] == 0 { r = int($2 / dl + 0.5); H = top * dl
        pr = 1000 * 9.8 * (H - $2) + 1650 * 9.8 * ex[r]; e = $c["pressure"] - pr; s += e * e; sr += pr * pr
        if (r < bot || !nb) { bot = r; nb = 0; pb = 0 } if (r == bot) { nb++; pb += $c["pressure"] - 1000 * 9.8 * (H - $2) } }
    END { printf "pressure L2 %.3g against the hydrostatic plus the suspended excess; bottom row: p - rho_f g (H - y) %.3f Pa, excess %.3f Pa\n", sqrt(s / sr), pb / nb, 1650 * 9.8 * ex[bot] }'
