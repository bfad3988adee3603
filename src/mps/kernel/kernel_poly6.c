/*
 * kernel_poly6.c — the polynomial MPS kernel of the soil model (doc/theory.md
 * K.1, eq. (8) of Kim; the "poly6" form of Mueller, Charypar and Gross 2003):
 *
 *     w(r) = (1 - r/r_e)^3 (1 + r/r_e)^3 = (1 - (r/r_e)^2)^3    0 <= r < r_e
 *     w(r) = 0                                                 r >= r_e
 *
 * w(0) = 1, w(r_e) = w'(r_e) = w''(r_e) = 0: smooth where a neighbour enters
 * the support, finite for coincident particles. On the 2-D square lattice
 * with r_e = 2.1 dp: n0 = 2.505337, lambda = 1.264422 dp^2 (doc/theory.md
 * E5-01, test_kernels.c).
 */
#include "mps/kernel/kernel.h"

static double w_poly6(double r, double re)
{
    double q = 1.0 - (r / re) * (r / re);
    return r < re ? q * q * q : 0.0;
}

/* Branch-free like weights_zhang (kernel_zhang2014.c): the same arithmetic
 * as w_poly6, so the two agree bit for bit. */
static void weights_poly6(const double *r, int64_t n, double re, double *w)
{
#pragma omp simd
    for (int64_t k = 0; k < n; k++) {
        double q = 1.0 - (r[k] / re) * (r[k] / re);
        w[k] = r[k] < re ? q * q * q : 0.0;
    }
}

const struct mps_kernel_ops mps_kernel_poly6 = {
    .name = "poly6",
    .reference = "Kim (soil MPS) eq. 8; Mueller, Charypar & Gross 2003",
    .w = w_poly6,
    .weights = weights_poly6,
    .finite_at_zero = 1,
};
