#!/bin/bash
# Usage: validation/cp.sh DIR [DIR2]
# Surface pressure coefficient Cp = (p - p_inf)/(rho u_a^2/2) of the
# cylinder's wall nodes (patch 1) on its upper half at DIR's last time,
# against theta, the angle from the front stagnation point [deg]; p_inf is
# the pressure of the centre-row node nearest to 7.5 D upstream of the
# centre; rho = 1000 kg/m^3, u_a = 0.1 m/s. Writes DIR/cp.dat. With DIR2:
# also the largest |Cp(DIR2) - Cp(DIR)| over DIR's angles, DIR2's Cp
# interpolated linearly in theta (E3-15: n = 24 against n = 30).
set -e
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
cp_of() {
    local d=$1 t
    t=$(ls -d "$d"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)
    "$root/bin/vtuInfo" -dump "$d/$t/fluid.vtu" | awk '
        /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        NF > 5 && $1 ~ /^[-0-9.]/ { n++; x[n] = $1; y[n] = $2; ty[n] = $c["type"]; pa[n] = $c["patch"]; p[n] = $c["pressure"]
            if ($c["type"] == 1 && $c["patch"] == 1) { sx += $1; sy += $2; nc++ } }
        END { xc = sx / nc; yc = sy / nc; best = 1e9
              for (k = 1; k <= n; k++) if (ty[k] == 0 && y[k] > yc - 1e-4 && y[k] < yc + 1e-4) {
                  e = x[k] - (xc - 0.3); if (e < 0) e = -e; if (e < best) { best = e; pinf = p[k] } }
              print "# theta[deg] Cp   (upper half; p_inf", pinf, "Pa)"
              for (k = 1; k <= n; k++) if (ty[k] == 1 && pa[k] == 1 && y[k] >= yc - 1e-9) {
                  th = atan2(y[k] - yc, -(x[k] - xc)) * 180 / 3.141592653589793
                  printf "%.4f %.6f\n", th, (p[k] - pinf) / 5 } }' | sort -g -k1 > "$d/cp.dat"
}
cp_of "$1"
echo "$1: $(grep -v '^#' "$1/cp.dat" | wc -l) nodes; front Cp $(awk '!/^#/ { print $2; exit }' "$1/cp.dat"), base Cp $(awk '!/^#/ { c = $2 } END { print c }' "$1/cp.dat")"
[ -n "${2:-}" ] || exit 0
cp_of "$2"
awk 'FNR == NR { if (!/^#/) { m++; a[m] = $1; b[m] = $2 }; next }
     !/^#/ { for (k = 1; k < m && a[k + 1] < $1; k++) ;
             if ($1 < a[1] || $1 > a[m]) next
             f = (a[k + 1] > a[k]) ? ($1 - a[k]) / (a[k + 1] - a[k]) : 0
             d = b[k] + f * (b[k + 1] - b[k]) - $2; if (d < 0) d = -d; if (d > mx) mx = d }
     END { printf "max |Cp(%s) - Cp(%s)| = %.4f\n", ARGV[1], ARGV[2], mx }' "$2/cp.dat" "$1/cp.dat"
