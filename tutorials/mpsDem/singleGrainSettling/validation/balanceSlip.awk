# balanceSlip.awk — the slip speed |u - v| at which the drag of the
# ergunWenYu law (Model B) balances the submerged weight of the grain,
#   F^d(slip)/eps_k = (rho_s - rho_f) V g,
# glass bead d = 2.7 mm, rho_s = 2500, water rho_f = 1000, mu = 1e-3 [SI];
# solved by bisection on [0, 2] m/s.
#   awk -v e=EPS -f validation/balanceSlip.awk     prints the slip [m/s]
# (eps_k = 1: the single-sphere terminal speed 0.343 m/s, Re = 926)
function slip(e,  lo, hi, s, Re, cds, K, i) {
    lo = 0; hi = 2
    for (i = 0; i < 100; i++) {
        s = (lo + hi) / 2; Re = e * 1000 * 0.0027 * s / 1e-3
        cds = Re > 1000 ? 0.44 * s : 24e-3 * (1 + 0.15 * Re^0.687) / (e * 1000 * 0.0027)
        K = 0.75 * cds * 1000 * e^-1.65 / 0.0027
        if (K * s / e > 1500 * 9.81) hi = s; else lo = s
    }
    return s
}
BEGIN { if (e == "") { print "balanceSlip.awk: set -v e=EPS" > "/dev/stderr"; exit 1 }
        printf "%.6f\n", slip(e) }
