#!/bin/sh
# compare.sh CASE — squareColumn against the Yeh & Petroff measurements
# (the repository's data/yeh_petroff_column: force digitised by PySPH from
# Raad & Bidoae 2005 Fig. 18, a second digitisation by ANUGA, velocity from
# Fig. 17) and Stoker's wet-bed bore. Prints one line per number:
#   boreSpeed    least-squares slope of the water front (fluid > 0.03 m up)
#                while it is between x = 0.5 and 0.85 m [m/s]; Stoker 1.889
#   arrival      first time the front's leading particle centre reaches the
#                column face less dp/2 (x >= 0.895) [s]; Stoker 0.265
#   Fpeak_sim/_exp  first force peak on the column, max over 0.2-0.8 s
#                [N] and its time [s]
#   rmsF         RMS of simulated - measured force over 0-3 s at the
#                simulated samples (PySPH points, time-sorted, interpolated)
#   Fmin_sim/_exp  most negative force over 1.25-2.0 s (the reverse force);
#                Fmin_sim_smoothed: of its 0.05 s running mean
#   Upeak_sim/_exp, rmsU  velocity at the probe: the measured trace starts
#                at the bore's arrival, so both are aligned on the first
#                time u > 0.5 m/s; peak (max over the first 0.3 s) and RMS
#                over the first 1.3 s after arrival
#   span         simulated times covered
# and writes CASE/validation/series.dat: t Fx_fluid P1 Fx_solids H1
# waterFront sedimentFront (NaN for the grains' columns: clear water), and
# CASE/validation/velocity.dat: t Ux at the velocity probe, both at the
# samples of H1 and the front (every 5 steps); validation/plot.gp plots
# them.
set -e
CASE=${1:-.}
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"   # MPSDEM_DIR for a copied case
DATA="$ROOT/data/yeh_petroff_column"
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
# restarted runs: bin/tools/foJoin keeps the later run's rows
join_fo() { "$ROOT/bin/tools/foJoin" "$CASE/postProcessing/$1" "$2"; }
join_fo load forces.dat > "$TMP/F"; join_fo P1 probes.dat > "$TMP/P"
join_fo velocity probes.dat > "$TMP/U"; join_fo H1 waveGauges.dat > "$TMP/H"
join_fo waterFront front.dat > "$TMP/X"
for f in F P U H X; do [ -s "$TMP/$f" ] || { echo "compare.sh: no $f output in $CASE/postProcessing" >&2; exit 1; }; done
sort -t, -k1,1g "$DATA/yeh_petroff_force_pysph.csv" | grep -v '^t_s' > "$TMP/Fexp"
grep -v '^t_s' "$DATA/yeh_petroff_velocity_pysph.csv" | sort -t, -k1,1g > "$TMP/Uexp"

# series.dat at the front/H1 samples; force and P1 are written every step
mkdir -p "$CASE/validation"
awk 'FILENAME == ARGV[1] { F[$1] = $2; next } FILENAME == ARGV[2] { P[$1] = $2; next }
     FILENAME == ARGV[3] { H[$1] = $2; next }
     BEGIN { print "# t Fx_fluid P1 Fx_solids H1 waterFront sedimentFront  (SI; NaN: not in this case)" }
     ($1 in H) { printf "%s %s %s NaN %s %s NaN\n", $1, ($1 in F) ? F[$1] : "NaN", ($1 in P) ? P[$1] : "NaN", H[$1], $2 }' \
    "$TMP/F" "$TMP/P" "$TMP/H" "$TMP/X" > "$CASE/validation/series.dat"
awk 'FILENAME == ARGV[1] { H[$1] = 1; next }
     BEGIN { print "# t Ux  (probe velocity at (0.814, 0.305, 0.026) m [m/s])" }
     ($1 in H) { print $1, $2 }' "$TMP/H" "$TMP/U" > "$CASE/validation/velocity.dat"

awk '$2 >= 0.5 && $2 <= 0.85 { n++; st += $1; sx += $2; stt += $1 * $1; stx += $1 * $2 }
     $2 >= 0.895 && !a { a = $1 }
     END { if (n < 3) print "boreSpeed none (the front has not crossed 0.5-0.85 m)"
           else printf "boreSpeed %.3f (%d samples; Stoker 1.889)\n", (n * stx - st * sx) / (n * stt - st * st), n
           if (a) printf "arrival %.4f (Stoker 0.265)\n", a; else print "arrival none (the front never reached x = 0.895)" }' "$TMP/X"

# interpolate the measured series (time-sorted csv) at the simulated times
interp='function load(f,   l, a) { while ((getline l < f) > 0) { split(l, a, ","); m++; te[m] = a[1]; ve[m] = a[2] } }
        function at(T) { while (j < m - 1 && te[j + 1] < T) j++; if (j < 1) j = 1
                         return ve[j] + (T - te[j]) / (te[j + 1] - te[j]) * (ve[j + 1] - ve[j]) }'
awk -v EXP="$TMP/Fexp" "$interp"'
     BEGIN { load(EXP); ms = me = -1e30; ns = ne = 1e30
             for (k = 1; k <= m; k++) { if (te[k] >= 0.2 && te[k] <= 0.8 && ve[k] > me) { me = ve[k]; tme = te[k] }
                                        if (te[k] >= 1.25 && te[k] <= 2 && ve[k] < ne) { ne = ve[k]; tne = te[k] } } }
     $1 > 3 { next }
     { if (!n++) t0 = $1; t1 = $1; e = $2 - at($1); e2 += e * e
       if ($1 >= 0.2 && $1 <= 0.8 && $2 > ms) { ms = $2; tms = $1 }
       if ($1 >= 1.25 && $1 <= 2 && $2 < ns) { ns = $2; tns = $1 }
       if ($1 >= 1.2 && $1 <= 2.05) { q++; tq[q] = $1; fq[q] = $2 } }
     END { if (ms > -1e30) printf "Fpeak_sim %.2f %.4f\n", ms, tms; else print "Fpeak_sim none (no sample in 0.2-0.8 s)"
           printf "Fpeak_exp %.2f %.4f\n", me, tme
           printf "rmsF %.2f (%d samples)\n", sqrt(e2 / n), n
           if (ns < 1e30) printf "Fmin_sim %.2f %.4f\n", ns, tns
           for (a = 1; a <= q; a++) if (tq[a] >= 1.25 && tq[a] <= 2) {
               c = sum = 0; for (b = 1; b <= q; b++) if (tq[b] >= tq[a] - 0.025 && tq[b] <= tq[a] + 0.025) { c++; sum += fq[b] }
               if (!sm || sum / c < sv) { sm = 1; sv = sum / c; tsv = tq[a] } }
           if (sm) printf "Fmin_sim_smoothed %.2f %.4f (0.05 s running mean)\n", sv, tsv
           printf "Fmin_exp %.2f %.4f\n", ne, tne
           printf "span %.4g %.4g%s\n", t0, t1, t1 < 2.999 ? " (shorter than 0-3 s: the run ended early)" : "" }' "$TMP/F"

awk -v EXP="$TMP/Uexp" "$interp"'
     BEGIN { load(EXP); me = -1e30; for (k = 1; k <= m; k++) if (te[k] <= 0.3 && ve[k] > me) me = ve[k] }
     $2 != "nan" && $2 > 0.5 && a == "" { a = $1 }
     a != "" && $1 - a <= 1.3 && $2 != "nan" { T = $1 - a; n++; e = $2 - at(T); e2 += e * e
                                              if (T <= 0.3 && $2 > ms) ms = $2 }
     END { if (!n) { print "Upeak_sim none (the bore never reached the probe)"; exit }
           printf "Uarrival_sim %.4f\nUpeak_sim %.3f\nUpeak_exp %.3f\nrmsU %.3f (%d samples over %.3g s)\n",
                  a, ms, me, sqrt(e2 / n), n, 1.3 }' "$TMP/U"
