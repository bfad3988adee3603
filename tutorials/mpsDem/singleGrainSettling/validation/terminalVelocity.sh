#!/usr/bin/env bash
# terminalVelocity.sh — E1-14: mean settling speed of the grain after
# t0 (default 0.2 s) against the drag-law balance
#   (rho_s - rho_f) V g = F^d(slip)/eps_k     (ergunWenYu, Model B)
# solved for the slip at eps_k = 1 (single sphere: 0.343 m/s, Re = 926)
# and at eps_k = 0.9883, the porosity the grain itself makes at its centre
# at dp = 4 mm, kernelRadius 2.6 in 2-D (test/unit/coupling/
# test_couple_glue.c prints it). Usage: validation/terminalVelocity.sh [t0]
cd "${0%/*}/.." || exit 1
t0=${1:-0.2}
b1=$(awk -v e=1.0 -f validation/balanceSlip.awk)      # drag law: balanceSlip.awk
b2=$(awk -v e=0.9883 -f validation/balanceSlip.awk)
validation/grainHistory.sh | awk -v t0="$t0" -v b1="$b1" -v b2="$b2" '
$1 >= t0 { s += $5; s2 += $5 * $5; n++ }
END {
    if (n < 2) { print "no data after t0 = " t0; exit 1 }
    m = -s / n; sd = sqrt(s2 / n - m * m)
    printf "grain speed after %s s: mean %.4f m/s, std %.4f m/s (%d samples)\n", t0, m, sd, n
    printf "balance slip at eps_k = 1:      %.4f m/s  (mean speed %+.2f %%)\n", b1, 100 * (m / b1 - 1)
    printf "balance slip at eps_k = 0.9883: %.4f m/s  (mean speed %+.2f %%)\n", b2, 100 * (m / b2 - 1)
}'
# E1-14 as stated: drag balance and slip from the couplingForces function
# object (columns: time, drag xyz, pressure xyz, slip, eps_k, wet)
f=postProcessing/grain/0/couplingForces.dat
[ -f "$f" ] && awk -v t0="$t0" '!/^#/ && $1 >= t0 { n++; s += $3 / $9; sl += $8; e += $9 }
END {
    V = 4 / 3 * 3.14159265358979 * 0.00135^3; W = 1500 * V * 9.81
    printf "mean F^d/eps_k after %s s: %.5e N, submerged weight %.5e N (%+.2f %%)\n", t0, s / n, W, 100 * (s / n / W - 1)
    printf "mean slip |u_k - v_k|: %.4f m/s at mean eps_k %.4f (%d rows)\n", sl / n, e / n, n
}' "$f"
