#!/bin/bash
# Usage: validation/shedding.sh DIR [TSTART]
# Periodic shedding behind the cylinder (E3-14) from DIR's function
# objects over t >= TSTART (default: the second half of the run), on the
# whole lift periods in that window:
#   St    f D/u_a, f from the up-crossings of the lift about its mean
#   C_D   mean drag / (rho u_a^2 D/2); C_Dv its viscous part
#   C_L'  lift amplitude (max - min)/2 / (rho u_a^2 D/2)
#   C_pb  mean (p_base - p_inf) / (rho u_a^2/2): base (rear point) against
#         the centre-line node 7.5 D upstream
# rho = 1000 kg/m^3, u_a = 0.1 m/s, D = 0.04 m (per unit width: q D =
# 0.2 N/m). Plots C_D and C_L against t: validation/shedding.png. Reference (E3-14): St ~ 0.165, C_D ~ 1.33, C_pb ~ -0.7 at
# Re 100 (unbounded flow; the channel's blockage D/h = 6.7 % raises them).
set -e
dir=${1:?Usage: validation/shedding.sh DIR [TSTART]}
join() { for d in $(ls "$dir/postProcessing/$1" | sort -g); do grep -v '^#' "$dir/postProcessing/$1/$d/$2"; done; }
F=$(mktemp); P=$(mktemp); trap 'rm -f "$F" "$P"' EXIT
join load forces.dat > "$F"
paste -d' ' <(join pInf probes.dat) <(join base probes.dat) > "$P"
[ -s "$F" ] || { echo "shedding.sh: no forces in $dir/postProcessing/load" >&2; exit 1; }
awk -v t0="${2:-}" 'FNR == NR { n++; t[n] = $1; fx[n] = $2; fy[n] = $3; fv[n] = $5; next }
     { m++; tp[m] = $1; dp[m] = $4 - $2 }
     END {
        if (t0 == "") t0 = t[n] / 2
        for (i = 1; i <= n; i++) if (t[i] >= t0) { c++; mean += fy[i] }
        if (c < 10) { print "shedding.sh: fewer than 10 samples after t = " t0 > "/dev/stderr"; exit 1 }
        mean /= c
        for (i = 2; i <= n; i++) if (t[i] >= t0 && fy[i - 1] < mean && fy[i] >= mean) {
            tc = t[i - 1] + (mean - fy[i - 1]) * (t[i] - t[i - 1]) / (fy[i] - fy[i - 1])
            if (!nu) first = tc; last = tc; nu++ }
        if (nu < 3) { printf "no shedding after t = %g s: %d lift up-crossings (lift %g N/m at the end)\n", t0, nu, fy[n]; exit 0 }
        f = (nu - 1) / (last - first); q = 0.2
        lo = 1e30; hi = -1e30
        for (i = 1; i <= n; i++) if (t[i] >= first && t[i] <= last) { k++; cd += fx[i]; cv += fv[i]
            if (fy[i] < lo) lo = fy[i]; if (fy[i] > hi) hi = fy[i] }
        for (i = 1; i <= m; i++) if (tp[i] >= first && tp[i] <= last) { kp++; cp += dp[i] }
        printf "St %.4f (f %.4f Hz over %d periods, %.2f-%.2f s)\n", f * 0.04 / 0.1, f, nu - 1, first, last
        printf "C_D %.4f (viscous %.4f)\nC_L amplitude %.4f\n", cd / k / q, cv / k / q, (hi - lo) / 2 / q
        if (kp) printf "C_pb %.4f\n", cp / kp / 5 }' "$F" "$P"
awk '{ print $1, $2 / 0.2, $3 / 0.2 }' "$F" > "$dir/coefficients.dat"
cd "${0%/*}/.." || exit 1
gnuplot <<GP
set terminal pngcairo size 900,450
set output 'validation/shedding.png'
set grid; set key bottom right
set xlabel 't [s]'; set ylabel 'C_D, C_L'; set yrange [-0.6:1.6]
set title 'Cylinder at Re 100 (mlpgFluid, 24 nodes on the cylinder)'
plot '$dir/coefficients.dat' u 1:2 w l lc rgb 'red' t 'C_D', '' u 1:3 w l lc rgb 'blue' t 'C_L'
GP
