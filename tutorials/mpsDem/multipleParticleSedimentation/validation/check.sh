#!/usr/bin/env bash
# validation/check.sh [CASE...] — the checks of doc/theory.md E1-16, E1-17 and
# E1-18 on finished runs of this tutorial (default: modelA modelB), from
# their postProcessing/ (function objects of system/controlDict):
#
#   E1-16 (Model B, at the time nearest 0.45 s, or the last if earlier):
#     E_k / max E_k <= 1 %; |total drag| <= 2 % of the submerged weight
#     1.126 N; total buoyancy 0.7507 N; vertical contact load of the grains
#     on the tank = 1.126 N +- 2 % (mean over the last 0.05 s); bottom-centre
#     pressure = rho g (h_fs - z_probe) within 3 % (h_fs: the wave gauge, the
#     probe 2 mm above the floor; means over the last 0.05 s);
#   E1-17: fluid volume constant (largest relative change), surface height;
#   E1-18: E_k(0.45 s) against E_k(0.3 s) (B decreasing; A growing in the
#     paper).
# Prints a table per case and one PASS/FAIL line per check; exits 1 if a
# check fails. Runs in seconds.
cd "${0%/*}/.." || exit 1
cases=("$@"); [ ${#cases[@]} -eq 0 ] && cases=(modelA modelB)
fails=0
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
# series DIR FO FILE: the rows of postProcessing/FO/<start>/FILE of all
# start times (a restarted run opens a new one), in time order
series() {
    local d
    for d in "$1/postProcessing/$2"/*/; do
        cat "$d$3"
    done | awk '!/^#/' | sort -g -k1,1
}
for c in "${cases[@]}"; do
    P="$c/postProcessing"
    [ -d "$P/energy" ] || { echo "FAIL $c: no run (no $P/energy)"; fails=$((fails + 1)); continue; }
    series "$c" energy kineticEnergy.dat > "$T/energy"
    series "$c" forces couplingForces.dat > "$T/forces"
    series "$c" floor wallForces.dat > "$T/floor"
    series "$c" level waveGauges.dat > "$T/level"
    series "$c" bottom probes.dat > "$T/bottom"
    series "$c" volume volume.dat > "$T/volume"
    model=$(sed -n 's/^model *\([AB]\);.*/\1/p' "$c/system/couplingDict")
    tend=$(awk '!/^#/ { t = $1 } END { print t }' "$T/energy")
    t45=$(awk -v e="$tend" 'BEGIN { print (e < 0.45 ? e : 0.45) }')
    # kinetic energy: peak, at 0.3 s and at t45
    read -r kpeak k30 k45 <<< "$(awk -v t=$t45 '!/^#/ { if ($4 > p) p = $4
        if ($1 <= 0.3 + 1e-9) a = $4; if ($1 <= t + 1e-9) b = $4 } END { print p, a, b }' \
        "$T/energy")"
    # drag and pressure-gradient force (B: buoyancy) at t45
    read -r drag pres <<< "$(awk -v t=$t45 '!/^#/ && $1 <= t + 1e-9 {
        d = sqrt($2^2 + $3^2 + $4^2); p = $7 } END { print d, p }' "$T/forces")"
    # last 0.05 s: floor load, surface height, bottom-centre pressure
    floor=$(awk -v e="$tend" '!/^#/ && $1 > e - 0.05 { s += $4; n++ } END { print (n ? s / n : "nan") }' \
        "$T/floor")
    hfs=$(awk -v e="$tend" '!/^#/ && $1 > e - 0.05 { s += $2; n++ } END { print (n ? s / n : "nan") }' \
        "$T/level")
    pb=$(awk -v e="$tend" '!/^#/ && $1 > e - 0.05 { s += $2; n++ } END { print (n ? s / n : "nan") }' \
        "$T/bottom")
    dv=$(awk '!/^#/ { d = $4 < 0 ? -$4 : $4; if (d > m) m = d } END { print m + 0 }' "$T/volume")
    echo "== $c (model $model, run to $tend s)"
    awk -v kp="$kpeak" -v k3="$k30" -v k4="$k45" -v t="$t45" -v dr="$drag" -v pr="$pres" \
        -v fl="$floor" -v h="$hfs" -v pb="$pb" -v dv="$dv" 'BEGIN {
        printf "  E_k peak %.4g J, at 0.3 s %.4g J, at %s s %.4g J (%.3g %% of peak)\n", kp, k3, t, k4, 100 * k4 / kp
        printf "  |drag| %.4g N (%.3g %% of 1.126 N), pressure-gradient/buoyancy %.4f N (0.7507 N)\n", dr, 100 * dr / 1.126, pr
        printf "  grain load on the tank %.4f N (submerged weight 1.126 N), surface h_fs %.4f m\n", -fl, h
        printf "  bottom-centre pressure %.1f Pa, rho g (h_fs - 0.002) = %.1f Pa (%+.2f %%), fluid volume change %.2g\n", pb, 9810 * (h - 0.002), 100 * (pb / (9810 * (h - 0.002)) - 1), dv }'
    check() { # name condition message; the condition sees kp k3 k4 dr pr fl h pb dv
        if awk -v kp="$kpeak" -v k3="$k30" -v k4="$k45" -v dr="$drag" -v pr="$pres" \
               -v fl="$floor" -v h="$hfs" -v pb="$pb" -v dv="$dv" "BEGIN { exit !($2) }"; then
            echo "PASS $c $1"
        else
            echo "FAIL $c $1: $3"; fails=$((fails + 1))
        fi
    }
    check volume "dv < 1e-9" "fluid volume changed by $dv"
    if [ "$model" = B ]; then
        check E1-16_energy "k4 <= 0.01 * kp" "E_k $k45 J > 1 % of $kpeak J"
        check E1-16_drag "dr <= 0.02 * 1.126" "|drag| $drag N"
        check E1-16_buoyancy "(pr - 0.7507)^2 < (0.0005 * 0.7507)^2" "buoyancy $pres N"
        check E1-16_load "(-fl / 1.126 - 1)^2 <= 0.02^2" "load $floor N"
        check E1-16_pressure "(pb / (9810 * (h - 0.002)) - 1)^2 <= 0.03^2" "bottom pressure $pb Pa, h_fs $hfs m"
        check E1-18_B_decreasing "k4 <= k3" "E_k grew from $k30 to $k45 J"
    else
        echo "INFO $c E1-18 (A): E_k(0.3 s) = $k30 J, E_k($t45 s) = $k45 J (the paper's Model A grows)"
    fi
done
exit $((fails > 0))
