#!/bin/sh
# compare.sh COPY... — the numbers of each run of columnSediment (the
# copies Hs<H_s>/ that Allrun makes), in the frame of the case (x from the
# wall behind the water, forces positive downstream). For each copy it
# writes validation/series_Hs<H_s>.dat with the columns
#   t Fx_fluid P1 Fx_solids H1 waterFront sedimentFront
# at the samples of H1 and the water front (every 5 steps; force and P1
# are written every step; the grains' columns are interpolated in time,
# NaN without grains), and prints one line per copy:
#   Hs  boreSpeed [m/s] (slope of the water front over x = 0.5-0.85 m;
#       E1-21: within 20 % of Stoker's 1.889 m/s)
#       arrival [s]  (water front at the column face less dp/2, x >= 0.895)
#       Fpeak tF     (largest Fx_fluid over 0.2-1.0 s [N], its time [s])
#       P1peak tP    (largest P1 over 0.2-1.0 s [Pa], its time)
#       Fspeak tS    (largest Fx_solids [N], its time; NaN without grains)
#       Fmin tmin    (most negative Fx_fluid over 1.25-2.0 s: the reverse
#       force on the back face)
#       water1 sed1  (fronts at t = 1 s [m])
#       tend         (last sample: a run that ended early says so)
set -e
[ $# -ge 1 ] || { echo "usage: compare.sh Hs0 Hs0.041 ..." >&2; exit 2; }
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="${MPSDEM_DIR:-$(cd "$HERE/../../../.." && pwd)}"   # MPSDEM_DIR for a copied case
# restarted runs: bin/tools/foJoin keeps the later run's rows
join_fo() { "$ROOT/bin/tools/foJoin" "$1/postProcessing/$2" "$3"; }
printf "%-7s %9s %8s %8s %7s %8s %7s %8s %7s %8s %7s %7s %7s %6s\n" Hs boreSpeed arrival Fpeak tF P1peak tP Fspeak tS Fmin tmin water1 sed1 tend
for c in "$@"; do
    hs=${c##*/}; hs=${hs#Hs}
    tmp="$(mktemp -d)"
    join_fo "$c" load forces.dat > "$tmp/F"; join_fo "$c" P1 probes.dat > "$tmp/P"
    join_fo "$c" H1 waveGauges.dat > "$tmp/H"; join_fo "$c" waterFront front.dat > "$tmp/X"
    join_fo "$c" solidLoad wallForces.dat > "$tmp/S"; join_fo "$c" sedimentFront front.dat > "$tmp/Y"
    [ -s "$tmp/H" ] || { echo "compare.sh: $c has no gauge output" >&2; rm -rf "$tmp"; exit 1; }
    awk -v out="$HERE/series_Hs$hs.dat" '
        function interp(T, q, n, t, v,   k) { if (n == 0 || T < t[1]) return "NaN"
            for (k = pos[q]; k < n && t[k + 1] <= T; k++) ; pos[q] = k
            return k == n ? v[n] : v[k] + (T - t[k]) / (t[k + 1] - t[k]) * (v[k + 1] - v[k]) }
        FILENAME == ARGV[1] { F[$1] = $2; next }
        FILENAME == ARGV[2] { P[$1] = $2; next }
        FILENAME == ARGV[3] { ns++; st[ns] = $1; sv[ns] = $2; next }
        FILENAME == ARGV[4] { ny++; yt[ny] = $1; yv[ny] = $2; next }
        FILENAME == ARGV[5] { X[$1] = $2; next }
        BEGIN { pos[1] = pos[2] = 1; print "# t Fx_fluid P1 Fx_solids H1 waterFront sedimentFront  (SI; NaN: not in this case)" > out }
        { T = $1; f = (T in F) ? F[T] : "NaN"; p = (T in P) ? P[T] : "NaN"
          s = interp(T, 1, ns, st, sv); y = interp(T, 2, ny, yt, yv); x = (T in X) ? X[T] : "NaN"
          printf("%s %s %s %s %s %s %s\n", T, f, p, s, $2, x, y) > out }' \
        "$tmp/F" "$tmp/P" "$tmp/S" "$tmp/Y" "$tmp/X" "$tmp/H"
    rm -rf "$tmp"
    awk -v hs="$hs" '
        /^#/ { next }
        { t = $1 }
        $6 != "NaN" && $6 >= 0.5 && $6 <= 0.85 { n++; a += t; b += $6; aa += t * t; ab += t * $6 }
        $6 != "NaN" && $6 >= 0.895 && !arr { arr = t }
        t >= 0.2 && t <= 1.0 { if ($2 != "NaN" && $2 > fm) { fm = $2; tf = t }
                               if ($3 != "NaN" && $3 > pm) { pm = $3; tp = t } }
        t >= 1.25 && t <= 2.0 && $2 != "NaN" && (!nm++ || $2 < fn) { fn = $2; tn = t }
        $4 != "NaN" && (!hs_s++ || $4 > sm) { sm = $4; ts = t }
        t <= 1 { w1 = $6; s1 = $7 }
        END { printf "%-7s %9s %8s %8.2f %7.3f %8.0f %7.3f %8s %7s %8s %7s %7.3f %7s %6.3g\n", hs,
                     (n > 2 ? sprintf("%.3f", (n * ab - a * b) / (n * aa - a * a)) : "NaN"),
                     arr ? sprintf("%.3f", arr) : "none", fm, tf, pm, tp,
                     hs_s ? sprintf("%.2f", sm) : "NaN", hs_s ? sprintf("%.3f", ts) : "NaN",
                     nm ? sprintf("%.2f", fn) : "NaN", nm ? sprintf("%.3f", tn) : "NaN", w1, s1, t }' \
        "$HERE/series_Hs$hs.dat"
done
