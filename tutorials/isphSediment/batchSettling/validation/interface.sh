#!/bin/bash
# Usage: validation/interface.sh CASE [T0 [T1]]
# Batch settling (doc/theory.md E4-09): at every written time of CASE the
# height of the clear-water interface and the mean sediment and water
# velocities of the bulk of the suspension; then the interface's descent
# velocity (least squares over T0 <= t <= T1, default 1 s to the end)
# against the model-consistent hindered velocity
#   |u_s| = alpha_f w,  gamma(alpha_f, w) w = alpha_f (rho_s - rho_f) g
# of the drag law the solver uses (Ergun for alpha_f <= 0.8, Wen-Yu with
# the Schiller-Naumann C_D above; src/coupling/drag): a uniform suspension
# in a closed tank settles at it, its water rising at alpha_s w.
# The interface height is y_i = y_m + sum alpha_s V / (alpha_s0 B) over
# the water particles above mid-depth y_m = H/2 (B the tank's water
# width): the top of a suspension of alpha_s0 holding the sediment above
# y_m. It moves at the sediment's velocity through y_m however diffuse the
# interface is, and it is the interface itself while the suspension
# between y_m and the interface is uniform. The bulk is the particles
# with y in [0.3 H, 0.6 H] and alpha_s within 10 % of alpha_s0.
# Writes validation/series_alpha<alpha_s0>.dat with the columns
#   t interface top us_bulk uf_bulk
# and prints it and the comparison.
set -e
case=${1:?Usage: validation/interface.sh CASE [T0 [T1]]}
t0=${2:-1}; t1=${3:-1e9}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
dt="$root/bin/dictTool"
value() { "$dt" "$case/$1" -entry "$2" | awk '{ print $NF }' | tr -d ';'; }
dl=$(awk '$1 == "dp" { gsub(/;/, "", $2); print $2 }' "$case/system/particleDict")
a0=$(value system/isphSolution alphaSediment/value)
rhos=$(value constant/sedimentProperties rho)
d=$(value constant/sedimentProperties d)
rhof=$(value constant/transportProperties rho)
nu=$(value constant/transportProperties nu)
g=$("$dt" "$case/constant/g" -entry value | tr -d '();' | awk '{ print -$2 }')
out="${0%/*}/series_alpha$a0.dat"
model=$(awk -v a0="$a0" -v rs="$rhos" -v rf="$rhof" -v nu="$nu" -v d="$d" -v g="$g" '
    function gam(af, w,   re, cdw) {
        if (af <= 0.8) return 150 * (1 - af) / af * nu * rf / (d * d) + 1.75 * rf * w / d
        re = af * d * w / nu
        cdw = re > 1000 ? 0.44 * w : 24 * nu * rf * (1 + 0.15 * re ^ 0.687) / (af * rf * d)
        return 0.75 * cdw * rf * af ^ -1.65 / d }
    BEGIN { af = 1 - a0; w = 0.01; for (i = 0; i < 200; i++) w = af * (rs - rf) * g / gam(af, w)
            printf "%.6f %.6f", af * w, w }')
set -- $model; vmodel=$1; wmodel=$2
times=$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g)
[ -n "$times" ] || { echo "interface.sh: no time directories in $case" >&2; exit 1; }
{
echo "# t interface top us_bulk uf_bulk   (isphSediment batch settling, alpha_s0 = $a0, dl = $dl m; SI units)"
echo "# model: |u_s| = alpha_f w = $vmodel m/s, slip w = $wmodel m/s"
for t in $times; do
    [ -f "$case/$t/fluid.vtu" ] || continue
    [ "$t" = 0 ] && continue
    "$root/bin/vtuInfo" -dump "$case/$t/fluid.vtu" | awk -v t="$t" -v dl="$dl" -v a0="$a0" '
        /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; if (!("alpha.sediment" in c)) { skip = 1; exit } next }
        $1 ~ /^[-0-9.]/ && $c["type"] == 0 { m++; Y[m] = $2; A[m] = $c["alpha.sediment"] + 0; V[m] = $c["volume"] + 0
            US[m] = $c["U.sediment_1"]; UF[m] = $c["velocity_1"]; if ($2 > top) top = $2 }
        END { if (skip) exit
              ym = top / 2
              for (i = 1; i <= m; i++) {
                  # smoothed steps over 2 dl: a row crossing y_m counts gradually
                  s1 = (Y[i] - ym) / (2 * dl) + 0.5; s1 = s1 < 0 ? 0 : s1 > 1 ? 1 : s1
                  s0 = (Y[i] - ym + 0.1 * top) / (2 * dl) + 0.5; s0 = s0 < 0 ? 0 : s0 > 1 ? 1 : s0
                  sv += s1 * A[i] * V[i]; vb += (s0 - s1) * V[i]
                  if (Y[i] > 0.3 * top && Y[i] < 0.6 * top && A[i] > 0.9 * a0 && A[i] < 1.1 * a0) { nb++; us += US[i]; uf += UF[i] } }
              printf "%s %.6f %.6f %.6f %.6f\n", t, ym + sv / (a0 * vb / (0.1 * top)), top, nb ? us / nb : 0, nb ? uf / nb : 0 }'
done
} > "$out"
cat "$out"
awk -v t0="$t0" -v t1="$t1" -v a0="$a0" -v vm="$vmodel" -v wm="$wmodel" '
    /^#/ { next }
    $1 >= t0 && $1 <= t1 { n++; sx += $1; sy += $2; sxx += $1 * $1; sxy += $1 * $2; us += $4; uf += $5; last = $1 }
    END { if (n < 2) { print "interface.sh: fewer than two times in [" t0 ", " t1 "] s" > "/dev/stderr"; exit 1 }
          v = -(n * sxy - sx * sy) / (n * sxx - sx * sx)
          printf "alpha_s0 %s: interface descent %.5f m/s over %s-%s s; model-consistent alpha_f w = %.5f m/s (slip w %.5f): error %+.1f %%\n", a0, v, t0, last, vm, wm, 100 * (v - vm) / vm
          printf "alpha_s0 %s: bulk u_s %.5f, u_f %.5f m/s (model %.5f, %.5f)\n", a0, us / n, uf / n, -vm, a0 * wm }' "$out"
