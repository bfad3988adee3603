#!/bin/bash
# Usage: validation/cloud.sh CASE N
# The sand cloud of CASE (run N of Pan 2022 Table 1) at every written
# time, by the thesis's definitions (sect. 5.3.3; doc/theory.md S0-10):
# the cloud is the water particles with alpha_s >= 5 % of the current
# largest alpha_s; its front is the lowest of them, Z the descent of the
# front (the bottom of its particle's dl x dl cell) below the sand block's
# bottom (alphaSediment/min in CASE's system/isphSolution), W the cloud's
# width (the span of their x), omega_c =
# dZ/dt (central differences). Also the sediment volume sum alpha_s V
# against its start (conserved) and the double-peak measure of E4-11:
# along x, the largest alpha_s of each particle column; peakL and peakR
# the largest left and right of the centre column x = 0.5 m, dip the
# centre column's over the mean of the two (a double peak: dip < 0.8 with
# both peaks at least 2 dl off the centre; sep = xR - xL).
# Writes validation/series_case<N>.dat with the columns
#   t Z W omega_c alphaMax volume dip sep
# and prints it.
set -e
case=${1:?Usage: validation/cloud.sh CASE N}
n=${2:?Usage: validation/cloud.sh CASE N}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
out="${0%/*}/series_case$n.dat"
dl=$(awk '$1 == "dp" { gsub(/;/, "", $2); print $2 }' "$case/system/particleDict")
yb=$("$root/bin/dictTool" "$case/system/isphSolution" -entry alphaSediment/min | tr -d '();' | awk '{ print $2 }')
times=$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g)
[ -n "$times" ] || { echo "cloud.sh: no time directories in $case" >&2; exit 1; }
for t in $times; do
    [ -f "$case/$t/fluid.vtu" ] || continue
    "$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk -v t="$t" -v dl="$dl" '
        /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; if (!("alpha.sediment" in c)) { skip = 1; exit } next }
        $1 ~ /^[-0-9.]/ && $c["type"] == 0 { m++; x[m] = $1; y[m] = $2; a[m] = $c["alpha.sediment"] + 0
            vol += a[m] * $c["volume"]; if (a[m] > amax) amax = a[m] }
        END { if (skip) exit
              if (!(amax > 0)) { printf "%s nan nan 0 0 nan nan\n", t; exit }
              ymin = 1e9; xmin = 1e9; xmax = -1e9
              for (i = 1; i <= m; i++) {
                  col = int(x[i] / dl + 0.5); if (a[i] > cm[col]) cm[col] = a[i]
                  if (a[i] < 0.05 * amax) continue
                  if (y[i] < ymin) ymin = y[i]; if (x[i] < xmin) xmin = x[i]; if (x[i] > xmax) xmax = x[i] }
              mid = int(0.5 / dl + 0.5)
              for (col in cm) { col += 0
                  if (col < mid - 1 && cm[col] > pl) { pl = cm[col]; xl = col * dl }
                  if (col > mid + 1 && cm[col] > pr) { pr = cm[col]; xr = col * dl } }
              dip = pl + pr > 0 ? cm[mid] / (0.5 * (pl + pr)) : 0
              printf "%s %.6f %.6f %.6e %.10e %.4f %.4f\n", t, ymin - dl / 2, xmax - xmin, amax, vol, dip, xr - xl }'
done | awk -v yb="$yb" '{ n++; t[n] = $1; z[n] = yb - $2; line[n] = $0 }
    END { print "# t Z W omega_c alphaMax volume dip sep   (isphSediment sand dumping; SI units)"
          for (i = 1; i <= n; i++) {
              if (n < 2) w = 0
              else if (i == 1) w = (z[2] - z[1]) / (t[2] - t[1])
              else if (i == n) w = (z[n] - z[n - 1]) / (t[n] - t[n - 1])
              else w = (z[i + 1] - z[i - 1]) / (t[i + 1] - t[i - 1])
              split(line[i], f, " ")
              printf "%s %.5f %.5f %.5f %s %s %s %s\n", t[i], z[i], f[3], w, f[4], f[5], f[6], f[7] } }' > "$out"
cat "$out"
