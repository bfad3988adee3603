#!/bin/sh
# compare.sh COPY... — the numbers of each run of obstacleSediment (the
# copies Hs<H_s>/ that Allrun makes), in the paper's frame (x_paper =
# 3.22 - x: distance from the reservoir end wall; forces positive
# downstream, i.e. towards the box). For each copy it writes
# validation/series_Hs<H_s>.dat with the columns
#   t Fx_fluid P1 Fx_solids H1 waterFront sedimentFront
# at the samples of the fluid's gauges (every 5 steps; P1 is written every
# step; the grains' columns are interpolated in time, NaN without grains),
# and prints one line per copy:
#   Hs  arrival [s]  (water front at the box face less dp/2, x_paper >=
#       2.3955 - 0.02; E1-22: no earlier than 0.251 s)
#       vmax [m/s]   (largest front speed over 0.05 s windows before the
#       arrival; E1-22: below the Ritter bound 4.646 m/s)
#       Fpeak tF     (largest Fx_fluid over 0.3-1.5 s [N], its time [s])
#       P1peak tP    (largest P1 over 0.3-1.5 s [Pa], its time)
#       Fspeak tS    (largest Fx_solids [N], its time; NaN without grains)
#       P1slope      (least-squares slope of P1 over 3.5-4.5 s [Pa/s]; the
#       paper: P1 decreases there in every case)
#       P1late       (the same over 4.5-6 s; NaN for a run that stops
#       before)
#       water1 sed1  (fronts at t = 1 s [m])
#       tend         (last sample: a run that ended early says so)
set -e
[ $# -ge 1 ] || { echo "usage: compare.sh Hs0 Hs0.071 ..." >&2; exit 2; }
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="${MPSDEM_DIR:-$(cd "$HERE/../../../.." && pwd)}"   # MPSDEM_DIR for a copied case
# restarted runs: bin/tools/foJoin keeps the later run's rows
join_fo() { "$ROOT/bin/tools/foJoin" "$1/postProcessing/$2" "$3"; }
printf "%-8s %8s %7s %9s %7s %9s %7s %9s %7s %10s %9s %7s %7s %6s\n" Hs arrival vmax Fpeak tF P1peak tP Fspeak tS P1slope P1late water1 sed1 tend
for c in "$@"; do
    hs=${c##*/}; hs=${hs#Hs}
    tmp="$(mktemp -d)"
    join_fo "$c" load forces.dat > "$tmp/F"; join_fo "$c" pressure probes.dat > "$tmp/P"
    join_fo "$c" heights waveGauges.dat > "$tmp/H"; join_fo "$c" waterFront front.dat > "$tmp/X"
    join_fo "$c" solidLoad wallForces.dat > "$tmp/S"; join_fo "$c" sedimentFront front.dat > "$tmp/Y"
    [ -s "$tmp/H" ] || { echo "compare.sh: $c has no gauge output" >&2; rm -rf "$tmp"; exit 1; }
    awk -v out="$HERE/series_Hs$hs.dat" '
        function interp(T, q, n, t, v,   k) { if (n == 0 || T < t[1]) return "NaN"
            for (k = pos[q]; k < n && t[k + 1] <= T; k++) ; pos[q] = k
            return k == n ? v[n] : v[k] + (T - t[k]) / (t[k + 1] - t[k]) * (v[k + 1] - v[k]) }
        FILENAME == ARGV[1] { F[$1] = -$2; next }
        FILENAME == ARGV[2] { P[$1] = $2; next }
        FILENAME == ARGV[3] { ns++; st[ns] = $1; sv[ns] = -$2; next }
        FILENAME == ARGV[4] { ny++; yt[ny] = $1; yv[ny] = 3.22 + $2; next }
        FILENAME == ARGV[5] { X[$1] = $2; next }  # already 3.22 - x (origin, direction)
        BEGIN { pos[1] = pos[2] = 1; print "# t Fx_fluid P1 Fx_solids H1 waterFront sedimentFront  (SI, paper frame; NaN: not in this case)" > out }
        { T = $1; f = (T in F) ? F[T] : "NaN"; p = (T in P) ? P[T] : "NaN"
          s = interp(T, 1, ns, st, sv); y = interp(T, 2, ny, yt, yv); x = (T in X) ? X[T] : "NaN"
          printf("%s %s %s %s %s %s %s\n", T, f, p, s, $2, x, y) > out }' \
        "$tmp/F" "$tmp/P" "$tmp/S" "$tmp/Y" "$tmp/X" "$tmp/H"
    rm -rf "$tmp"
    awk -v hs="$hs" '
        /^#/ { next }
        { t = $1 }
        $6 != "NaN" && !arr { if (n && t - t0 >= 0.05) { v = ($6 - x0) / (t - t0); if (v > vmax) vmax = v; t0 = t; x0 = $6 }
                              if (!n++) { t0 = t; x0 = $6 }
                              if ($6 >= 2.3955 - 0.02) arr = t }
        t >= 0.3 && t <= 1.5 { if ($2 != "NaN" && $2 > fm) { fm = $2; tf = t }
                               if ($3 != "NaN" && $3 > pm) { pm = $3; tp = t } }
        $4 != "NaN" && (!hs_s++ || $4 > sm) { sm = $4; ts = t }
        t >= 3.5 && t <= 4.5 && $3 != "NaN" { m++; a += t; b += $3; aa += t * t; ab += t * $3 }
        t >= 4.5 && t <= 6 && $3 != "NaN" { m2++; a2 += t; b2 += $3; aa2 += t * t; ab2 += t * $3 }
        t <= 1 { w1 = $6; s1 = $7 }
        END { printf "%-8s %8s %7.3f %9.1f %7.3f %9.0f %7.3f %9s %7s %10s %9s %7.3f %7s %6.3g\n", hs,
                     arr ? sprintf("%.3f", arr) : "none", vmax, fm, tf, pm, tp,
                     hs_s ? sprintf("%.1f", sm) : "NaN", hs_s ? sprintf("%.3f", ts) : "NaN",
                     (m > 2 ? sprintf("%.0f", (m * ab - a * b) / (m * aa - a * a)) : "NaN"),
                     (m2 > 2 && t >= 5.99 ? sprintf("%.0f", (m2 * ab2 - a2 * b2) / (m2 * aa2 - a2 * a2)) : "NaN"), w1, s1, t }' \
        "$HERE/series_Hs$hs.dat"
done
