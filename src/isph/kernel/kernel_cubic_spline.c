/*
 * kernel_cubic_spline.c — the cubic B-spline kernel in 2-D (Pan 2022
 * thesis eq. 3.28 with its normalisation; doc/theory.md S0-01):
 *
 *   W(q) = 15/(7 pi h^2) (2/3 - q^2 + q^3/2)     0 <= q < 1
 *        = 15/(7 pi h^2) (2 - q)^3/6              1 <= q < 2,   q = r/h.
 *
 * The thesis prints it without the constant.
 */
#include <math.h>

#include "isph/isph.h"

static double w(double r, double h)
{
    double q = r / h, a = 15 / (7 * M_PI * h * h);
    if (q >= 2)
        return 0;
    if (q >= 1)
        return a * (2 - q) * (2 - q) * (2 - q) / 6;
    return a * (2.0 / 3 - q * q + q * q * q / 2);
}

static double dw(double r, double h)
{
    double q = r / h, a = 15 / (7 * M_PI * h * h * h);
    if (q >= 2)
        return 0;
    if (q >= 1)
        return -a * (2 - q) * (2 - q) / 2;
    return a * (-2 * q + 1.5 * q * q);
}

const struct isph_kernel isph_cubic_spline = {
    .name = "cubicSpline",
    .reference = "Pan 2022 eq. 3.28 (2-D constant 15/(7 pi h^2))",
    .support = 2, .w = w, .dw = dw,
};
