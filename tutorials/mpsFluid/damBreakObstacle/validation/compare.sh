#!/bin/sh
# compare.sh CASE — damBreakObstacle against the MARIN measurements
# (the repository's data/kleefsman_spheric2/spheric_test2_marin_exp.csv,
# whose H1 and H3 columns are already relabelled, see the data README):
#   rmsH1..rmsH4  RMS of simulated - measured water height over 0 <= t <= 6 s,
#                 at the simulated sample times (measurements interpolated)
#   spanH         the times the RMS covers: first and last simulated sample
#                 within 0-6 s, and their number (a run that ended early
#                 covers less than 0-6 s: the line says so)
#   P1peak        first pressure peak at P1 (max over 0.3-0.8 s) [Pa] and its
#                 time [s], simulated and measured; spanP1 the simulated
#                 times that window held
set -e
CASE=${1:-.}
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"   # MPSDEM_DIR for a copied case
EXP="$ROOT/data/kleefsman_spheric2/spheric_test2_marin_exp.csv"
# a restarted run writes postProcessing/<name>/<startTime>/: join them in time order
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
# restarted runs: bin/tools/foJoin keeps the later run's rows
join_fo() { "$ROOT/bin/tools/foJoin" "$CASE/postProcessing/$1" "$2"; }
H="$TMP/waveGauges.dat"; P="$TMP/probes.dat"
join_fo heights waveGauges.dat > "$H"; join_fo pressure probes.dat > "$P"
for f in "$EXP" "$H" "$P"; do [ -s "$f" ] || { echo "compare.sh: $f missing or empty" >&2; exit 1; }; done
awk -F'[ ,]+' '
FNR == NR { if (FNR > 1) { n++; t[n] = $1; for (k = 1; k <= 4; k++) h[k, n] = $(9 + k) } next }
/^#/ { next }
{
    T = $1; if (T > 6) next
    while (j < n - 1 && t[j + 1] < T) j++
    if (j < 1) j = 1
    w = (T - t[j]) / (t[j + 1] - t[j])
    for (k = 1; k <= 4; k++) { e = $(k + 1) - (h[k, j] + w * (h[k, j + 1] - h[k, j])); e2[k] += e * e }
    if (!m) t0 = T
    t1 = T; m++
}
END { for (k = 1; k <= 4; k++) printf "rmsH%d %.4f\n", k, sqrt(e2[k] / m); printf "nH %d\n", m
      printf "spanH %.4g %.4g %d%s\n", t0, t1, m, t1 < 5.99 ? " (shorter than 0-6 s: the run ended early)" : "" }' "$EXP" "$H"
awk -F'[ ,]+' 'BEGIN { m = -1e30 } FNR > 1 && $1 >= 0.3 && $1 <= 0.8 && $2 > m { m = $2; tm = $1 } END { printf "P1peak_exp %.1f %.4f\n", m, tm }' "$EXP"
awk 'BEGIN { m = -1e30 } !/^#/ && $1 >= 0.3 && $1 <= 0.8 { if (!n++) t0 = $1; t1 = $1; if ($2 > m) { m = $2; tm = $1 } }
     END { if (!n) { print "compare.sh: no simulated P1 sample within 0.3-0.8 s" > "/dev/stderr"; exit 1 }
           printf "P1peak_sim %.1f %.4f\n", m, tm
           printf "spanP1 %.4g %.4g %d%s\n", t0, t1, n, t1 < 0.799 ? " (shorter than 0.3-0.8 s: the run ended early)" : "" }' "$P"
