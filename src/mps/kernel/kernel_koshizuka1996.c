/*
 * kernel_koshizuka1996.c — the original MPS kernel of Koshizuka and Oka
 * (1996), eq. (3) there (doc/theory.md B.1):
 *
 *     w(r) = r_e / r - 1      0 < r < r_e
 *     w(r) = 0                r >= r_e
 *
 * Singular at r = 0: two coincident particles give an infinite weight. We
 * return a large finite value (r clamped to 1e-6 r_e) rather than inf so
 * that a collision shows up as a large number density, not a NaN.
 *
 * Reference: S. Koshizuka, Y. Oka (1996), Moving-particle semi-implicit
 * method for fragmentation of incompressible fluid, Nucl. Sci. Eng. 123,
 * 421-434, eq. (3).
 */
#include "mps/kernel/kernel.h"

static double w_koshizuka(double r, double re)
{
    if (r >= re)
        return 0.0;
    double rr = r > 1e-6 * re ? r : 1e-6 * re;
    return re / rr - 1.0;
}

/* w_koshizuka without branches, so that the loop vectorises (as
 * kernel_zhang2014.c). */
static void weights_koshizuka(const double *r, int64_t n, double re,
                              double *w)
{
    const double rmin = 1e-6 * re;
#pragma omp simd
    for (int64_t k = 0; k < n; k++) {
        double rr = r[k] > rmin ? r[k] : rmin;
        double v = re / rr - 1.0;
        w[k] = r[k] < re ? v : 0.0;
    }
}

const struct mps_kernel_ops mps_kernel_koshizuka1996 = {
    .name = "koshizuka1996",
    .reference = "Koshizuka & Oka 1996 eq. 3",
    .w = w_koshizuka,
    .weights = weights_koshizuka,
    .finite_at_zero = 0,
};
