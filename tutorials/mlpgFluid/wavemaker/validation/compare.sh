#!/bin/bash
# Usage: validation/compare.sh [CASE [T]]
# The free surface of CASE at T (default 24 s) against the linear theory
# (validation/linearTheory.sh, doc/theory.md M.9 and E3-16):
#   amplitude   (max - min)/2 of eta over 5 <= x <= 20 m, run and theory
#   wavelength  mean distance between successive up-crossings of eta = 0
#               over 5 <= x <= 20 m, run and theory
#   phase       the shift s (|s| <= lambda/2) of the theory that fits the
#               run best (least squares over 1 <= x <= 25 m), as a time
#               s/c with c = omega/k (E3-16: < T/10 = 0.138 s)
#   rms         RMS of eta(run) - eta(theory) over 1 <= x <= 25 m
# and E3-17, the mean water level at every written time: the mean of eta
# over the surface nodes (trapezoids) against the level the piston's
# displaced volume raises, H S(t)/(L - S(t)), S = a (1 - cos omega t);
# prints the largest difference (E3-17: < 0.1 dl = 0.004 m).
# eta of the run: the free-surface nodes (type 0, pressureFixed 1) less
# H = 1 m. Writes CASE/eta_<T>.dat (x eta) and CASE/level.dat (t mean
# expected).
set -e
case=${1:-.}
T=${2:-24}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
here=$(cd "${0%/*}" && pwd)
[ -f "$case/$T/fluid.vtu" ] || { echo "compare.sh: no $case/$T/fluid.vtu" >&2; exit 1; }
surface() {
    "$root/bin/vtuInfo" -dump "$case/$1/fluid.vtu" | awk '
        /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        $1 ~ /^[-0-9.]/ && $c["type"] == 0 && $c["pressureFixed"] == 1 { printf "%.6f %.6e\n", $1, $2 - 1 }' | sort -g
}
surface "$T" > "$case/eta_$T.dat"
"$here/linearTheory.sh" "$T" 30 0.01 > "$case/theory_$T.dat"
awk -v om=4.5415 'FNR == NR { if (!/^#/) { n++; xt[n] = $1; et[n] = $2 }; next }
    { m++; xr[m] = $1; er[m] = $2 }
    function th(x,   i, f) { i = int(x / 0.01) + 1; if (i < 1) i = 1; if (i >= n) i = n - 1
                             f = (x - xt[i]) / (xt[i + 1] - xt[i]); return et[i] + f * (et[i + 1] - et[i]) }
    function stats(kind,   j, lo, hi, up, first, last, nu, x0) {
        lo = 1e9; hi = -1e9; nu = 0
        for (j = 1; j <= (kind ? n : m); j++) {
            x = kind ? xt[j] : xr[j]; e = kind ? et[j] : er[j]
            if (x < 5 || x > 20) { pe = e; px = x; continue }
            if (e < lo) lo = e; if (e > hi) hi = e
            if (j > 1 && pe < 0 && e >= 0) { x0 = px + (0 - pe) * (x - px) / (e - pe); if (!nu) first = x0; last = x0; nu++ }
            pe = e; px = x }
        amp[kind] = (hi - lo) / 2; lam[kind] = nu > 1 ? (last - first) / (nu - 1) : 0 }
    END {
        stats(0); stats(1)
        best = 1e30; for (s = -1.5; s <= 1.5; s += 0.005) { q = 0
            for (j = 1; j <= m; j++) if (xr[j] >= 1 && xr[j] <= 25) { d = er[j] - th(xr[j] + s); q += d * d }
            if (q < best) { best = q; bs = s } }
        q = 0; c = 0; for (j = 1; j <= m; j++) if (xr[j] >= 1 && xr[j] <= 25) { d = er[j] - th(xr[j]); q += d * d; c++ }
        k = 2 * 3.141592653589793 / lam[1]
        printf "amplitude %.5f m (theory %.5f m, %+.1f %%)\n", amp[0], amp[1], 100 * (amp[0] / amp[1] - 1)
        printf "wavelength %.4f m (theory %.4f m, %+.2f %%)\n", lam[0], lam[1], 100 * (lam[0] / lam[1] - 1)
        printf "phase %+.3f m = %+.4f s (T/10 = %.4f s)\n", bs, bs / (om / k), 0.1 * 2 * 3.141592653589793 / om
        printf "rms %.5f m over 1-25 m (%d surface nodes)\n", sqrt(q / c), c }' "$case/theory_$T.dat" "$case/eta_$T.dat"
echo "# t[s] mean_eta[m] expected[m]" > "$case/level.dat"
for t in $(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g); do
    surface "$t" | awk -v t="$t" '{ n++; x[n] = $1; y[n] = $2 }
        END { if (n < 2) exit   # the start: no free-surface flags yet
              for (i = 2; i <= n; i++) s += (x[i] - x[i - 1]) * (y[i] + y[i - 1]) / 2
              S = 0.01 * (1 - cos(4.5415 * t)); L = 30
              printf "%s %.6e %.6e\n", t, s / (x[n] - x[1]), S / (L - S) }'
done >> "$case/level.dat"
awk '!/^#/ { d = $2 - $3; if (d < 0) d = -d; if (d > m) { m = d; tm = $1 } }
     END { printf "level: largest |mean eta - H S/(L - S)| %.5f m at t = %s s (0.1 dl = 0.004 m)\n", m, tm }' "$case/level.dat"
