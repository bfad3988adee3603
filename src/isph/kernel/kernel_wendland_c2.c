/*
 * kernel_wendland_c2.c — the Wendland C2 kernel in 2-D (Pan 2022 thesis
 * eq. 3.29 with the 2-D constant; doc/theory.md S0-01, the thesis's D-11):
 *
 *   W(q) = 7/(4 pi h^2) (1 - q/2)^4 (2q + 1),   q = r/h <= 2,
 *   dW/dr = -7/(4 pi h^3) 5 q (1 - q/2)^3.
 *
 * The thesis prints the 3-D constant 21/(16 pi h^3).
 */
#include <math.h>

#include "isph/isph.h"

static double w(double r, double h)
{
    double q = r / h;
    if (q >= 2)
        return 0;
    double a = 1 - q / 2;
    return 7 / (4 * M_PI * h * h) * a * a * a * a * (2 * q + 1);
}

static double dw(double r, double h)
{
    double q = r / h;
    if (q >= 2)
        return 0;
    double a = 1 - q / 2;
    return -7 / (4 * M_PI * h * h * h) * 5 * q * a * a * a;
}

const struct isph_kernel isph_wendland_c2 = {
    .name = "wendlandC2",
    .reference = "Pan 2022 eq. 3.29 (2-D constant 7/(4 pi h^2))",
    .support = 2, .w = w, .dw = dw,
};
