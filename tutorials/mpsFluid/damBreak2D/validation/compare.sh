#!/bin/sh
# compare.sh CASE [SHIFT] — surge front Z(T) and column height H(tau) of a
# damBreak2D run against Martin & Moyce (1952), n^2 = 2, a = 0.05715 m:
#   Z = x/a, T = t sqrt(2 g/a);  H = h/(2a), tau = t sqrt(g/a)
# The simulation is interpolated linearly at the tabulated T (tau); RMS of
# the differences over the points inside the simulated span. x is the
# front function object `surge` (postProcessing/surge/0/front.dat, centre of
# the leading particle) + dp/2, the edge of the fluid; h is the waveGauges
# entry `column` at the back wall (postProcessing/column/0/waveGauges.dat,
# already the surface: top particle + dp/2). SHIFT (default 0) is added to the simulated T, tau
# (the experiment's release is not instantaneous; README of the data).
# Prints "rmsZ value", "rmsH value", "nZ n", "nH n". Data: the repository's
# data/martin_moyce_1952 (see its README).
set -e
CASE=${1:-.}
SHIFT=${2:-0}
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"   # MPSDEM_DIR for a copied case
DATA="$ROOT/data/martin_moyce_1952"
A=0.05715
G=9.81
F="$CASE/postProcessing/surge/0/front.dat"
C="$CASE/postProcessing/column/0/waveGauges.dat"
for f in "$F" "$C" "$CASE/constant/particlePatches"; do
    [ -f "$f" ] || { echo "compare.sh: $f missing" >&2; exit 1; }
done
HALF=$(awk '/^dp/ { gsub(";", "", $2); printf "%.17g", $2 / 2 }' "$CASE/constant/particlePatches")
rms() {   # $1 sim file, $2 data csv, $3 scale of time, $4 scale of value, $5 offset [m]
    awk -F'[ ,]+' -v a=$A -v g=$G -v ts="$3" -v vs="$4" -v off="$5" -v sh=$SHIFT '
    FNR == NR { if ($0 !~ /^#/ && NF >= 2) { n++; t[n] = $1 * sqrt(ts * g / a) + sh; v[n] = ($2 + off) / (vs * a) } next }
    FNR == 1 { next }
    { T = $1; Z = $2
      for (k = 1; k < n; k++) if (t[k] <= T && T <= t[k + 1]) {
          s = v[k] + (v[k + 1] - v[k]) * (T - t[k]) / (t[k + 1] - t[k])
          e2 += (s - Z) ^ 2; m++; break } }
    END { printf "%.4f %d\n", m ? sqrt(e2 / m) : -1, m }' "$1" "$2"
}
set -- $(rms "$F" "$DATA/martin_moyce_1952_surge_front_n2-2_a2.25in.csv" 2 1 "$HALF") \
       $(rms "$C" "$DATA/martin_moyce_1952_column_height_n2-2_a2.25in.csv" 1 2 0)
printf "rmsZ %s\nnZ %s\nrmsH %s\nnH %s\n" "$1" "$2" "$3" "$4"
