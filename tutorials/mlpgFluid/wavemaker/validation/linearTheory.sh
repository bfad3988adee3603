#!/bin/bash
# Usage: validation/linearTheory.sh T [XMAX [DX]]
# The linear transient free surface of a piston wavemaker started from
# rest, x(t) = a (1 - cos(omega t)), in water of depth H (doc/theory.md
# M.9, S-10; semi-infinite tank, x from the piston):
#
#   eta(x, t) = (2/pi) int_0^inf [tanh(kH)/k] a omega^2
#               (cos(w_k t) - cos(omega t))/(omega^2 - w_k^2) cos(kx) dk,
#   w_k^2 = g k tanh(kH),
#
# by the midpoint rule on 0 < k < 60/H with dk = 0.002/H (the fraction
# tends to t sin(omega t)/(2 omega) where w_k = omega). Prints "x eta" for
# x = 0, DX, ..., XMAX (default 30 m, 0.05 m), with a = 0.01 m, omega =
# 4.5415 rad/s, H = 1 m, g = 9.81 m/s^2 (the tutorial's dictionaries).
# The steady far field it tends to: A sin(kx - omega t + c), A = a 2
# (cosh 2kH - 1)/(sinh 2kH + 2kH) = 0.017464 m, k = 2.1593 1/m.
[ $# -ge 1 ] || { echo "Usage: ${0##*/} T [XMAX [DX]]" >&2; exit 1; }
awk -v t="$1" -v xmax="${2:-30}" -v dx="${3:-0.05}" 'BEGIN {
    a = 0.01; om = 4.5415; H = 1; g = 9.81; pi = 3.141592653589793
    dk = 0.002 / H; n = int(60 / H / dk)
    for (i = 1; i <= n; i++) {
        k = (i - 0.5) * dk; th = (exp(2 * k * H) - 1) / (exp(2 * k * H) + 1)
        w = sqrt(g * k * th); d = om * om - w * w
        f = (d * d > 1e-18) ? (cos(w * t) - cos(om * t)) / d : t * sin(om * t) / (2 * om)
        F[i] = 2 / pi * th / k * a * om * om * f * dk; K[i] = k
    }
    print "# x[m] eta[m]  (linear theory, t = " t " s)"
    for (x = 0; x <= xmax + 1e-9; x += dx) {
        s = 0; for (i = 1; i <= n; i++) s += F[i] * cos(K[i] * x)
        printf "%.4f %.6e\n", x, s
    }
}'
