#!/bin/bash
# Usage: validation/compare.sh [CASE [SHIFT]]
# Surge front Z(T) and residual column height H(tau) of a damBreak run
# against Martin & Moyce (1952), n^2 = 2 (the repository's
# data/martin_moyce_1952, see its README):
#   Z = x/a, T = t sqrt(2 g/a);  H = h/(2a), tau = t sqrt(g/a)
# with a = 0.2 m, g = 9.81 m/s^2, read from every time directory of CASE:
#   x  the leading water particle within 0.35 a of the floor that has at
#      least 7 water neighbours within 2 dl (a spray drop ahead of the
#      surge does not count), + dl/2 (the edge of its cell);
#   h  the highest water particle within 1.5 dl of the back wall, + dl/2.
# The simulation is interpolated linearly at the tabulated T (tau); the
# RMS of the differences is taken over the points inside the simulated
# span. SHIFT (default 0) is added to the simulated T and tau (the
# experiment's release was not instantaneous: the data's README).
# Writes CASE/front.dat (t T Z tau H) and prints "rmsZ value", "nZ n",
# "rmsH value", "nH n".
set -e
case=${1:-.}
shift_t=${2:-0}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
data="$root/data/martin_moyce_1952"
a=0.2
g=9.81
dl=$(awk '$1 == "dp" { gsub(/;/, "", $2); print $2 }' "$case/system/particleDict")
[ -n "$dl" ] || { echo "compare.sh: no dp in $case/system/particleDict" >&2; exit 1; }
out="$case/front.dat"
echo "# t [s]  T = t sqrt(2g/a)  Z = x/a  tau = t sqrt(g/a)  H = h/(2a)   (a = $a m, dl = $dl m)" > "$out"
for d in $(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g); do
    [ "$d" = 0 ] && continue
    "$root/bin/vtuInfo" -dump "$case/$d/fluid.vtu" | awk -v t="$d" -v a=$a -v g=$g -v dl="$dl" '
        /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        $1 !~ /^[-0-9.]/ || $c["type"] != 0 { next }
        { if ($1 < 1.5 * dl && $2 > h) h = $2
          if ($2 < 0.35 * a) { n++; x[n] = $1; y[n] = $2 } }
        END { best = -1
              for (i = 1; i <= n; i++) {
                  if (x[i] <= best) continue
                  m = 0
                  for (j = 1; j <= n && m < 7; j++)
                      if (j != i && (x[i] - x[j])^2 + (y[i] - y[j])^2 < 4 * dl * dl) m++
                  if (m >= 7) best = x[i] }
              printf "%s %.4f %.4f %.4f %.4f\n", t, t * sqrt(2 * g / a), (best + dl / 2) / a,
                     t * sqrt(g / a), (h + dl / 2) / (2 * a) }' >> "$out"
done
rms() { # $1 column of the simulated time, $2 of the value, $3 the data
    awk -F'[ ,]+' -v ct="$1" -v cv="$2" -v sh="$shift_t" '
        FNR == NR { if ($0 !~ /^#/) { n++; t[n] = $ct + sh; v[n] = $cv } next }
        FNR == 1 { next }
        { for (k = 1; k < n; k++) if (t[k] <= $1 && $1 <= t[k + 1]) {
              s = v[k] + (v[k + 1] - v[k]) * ($1 - t[k]) / (t[k + 1] - t[k])
              e2 += (s - $2)^2; m++; break } }
        END { printf "%.4f %d\n", m ? sqrt(e2 / m) : -1, m }' "$out" "$3"
}
set -- $(rms 2 3 "$data/martin_moyce_1952_surge_front_n2-2_a2.25in.csv") \
       $(rms 4 5 "$data/martin_moyce_1952_column_height_n2-2_a2.25in.csv")
printf "rmsZ %s\nnZ %s\nrmsH %s\nnH %s\n" "$1" "$2" "$3" "$4"
