#!/bin/bash
# Usage: validation/compare.sh [CASE [T [X0 X1]]]
# The free surface of CASE at T (default 24 s) against the linear theory
# (validation/linearTheory.sh, doc/theory.md M.9 and E3-16), the waves
# fitted over X0 <= x <= X1 (default 5-20 m: developed at 24 s):
#   amplitude   A and wavelength 2 pi/k of the least-squares fit
#   wavelength  eta ~ c + a sin kx + b cos kx over X0 <= x <= X1 (k
#               scanned over 1.5-3 1/m by 0.0005), run and theory: the
#               wave's first harmonic, not its wiggles (c takes a level
#               offset)
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
X0=${3:-5}
X1=${4:-20}
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
awk -v om=4.5415 -v x0="$X0" -v x1="$X1" 'FNR == NR { if (!/^#/) { n++; xt[n] = $1; et[n] = $2 }; next }
    { m++; xr[m] = $1; er[m] = $2 }
    function th(x,   i, f) { i = int(x / 0.01) + 1; if (i < 1) i = 1; if (i >= n) i = n - 1
                             f = (x - xt[i]) / (xt[i + 1] - xt[i]); return et[i] + f * (et[i + 1] - et[i]) }
    function fit(kind,   j, x, e, kk, n3, S, best, q) {
        best = -1
        for (kk = 1.5; kk <= 3; kk += 0.0005) {
            # normal equations of eta ~ c + a sin kx + b cos kx
            split("", S); n3 = 0
            for (j = 1; j <= (kind ? n : m); j++) {
                x = kind ? xt[j] : xr[j]; e = kind ? et[j] : er[j]
                if (x < x0 || x > x1) continue
                sn = sin(kk * x); cs = cos(kk * x); n3++
                S[1] += sn; S[2] += cs; S[3] += sn * sn; S[4] += sn * cs; S[5] += cs * cs
                S[6] += e; S[7] += e * sn; S[8] += e * cs; S[9] += e * e }
            # solve [n3 S1 S2; S1 S3 S4; S2 S4 S5] (c a b) = (S6 S7 S8)
            A11 = n3; A12 = S[1]; A13 = S[2]; A22 = S[3]; A23 = S[4]; A33 = S[5]
            det = A11 * (A22 * A33 - A23 * A23) - A12 * (A12 * A33 - A23 * A13) + A13 * (A12 * A23 - A22 * A13)
            if (det == 0) continue
            c0 = (S[6] * (A22 * A33 - A23 * A23) - A12 * (S[7] * A33 - A23 * S[8]) + A13 * (S[7] * A23 - A22 * S[8])) / det
            a0 = (A11 * (S[7] * A33 - A23 * S[8]) - S[6] * (A12 * A33 - A23 * A13) + A13 * (A12 * S[8] - S[7] * A13)) / det
            b0 = (A11 * (A22 * S[8] - S[7] * A23) - A12 * (A12 * S[8] - S[7] * A13) + S[6] * (A12 * A23 - A22 * A13)) / det
            q = S[9] - c0 * S[6] - a0 * S[7] - b0 * S[8]   # residual sum of squares
            if (best < 0 || q < best) { best = q; amp[kind] = sqrt(a0 * a0 + b0 * b0); lam[kind] = 2 * 3.141592653589793 / kk }
        } }
    END {
        fit(0); fit(1)
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
