/*
 * kernel_zhang2014.c — the MPS kernel of Zhang, Wan and Hino (2014), used by
 * MLParticle-SJTU and by Xie et al. (2025) eq. (6) (doc/theory.md A.3):
 *
 *     w(r) = r_e / (0.85 r + 0.15 r_e) - 1      0 <= r < r_e
 *     w(r) = 0                                  r >= r_e
 *
 * w(0) = 1/0.15 - 1 = 5.667: finite, so that two particles that come very
 * close do not produce an unbounded repulsion (the reason for the kernel).
 * w(r_e) = 0, continuous. Lattice constants: doc/theory.md E1-01/E1-02.
 *
 * Reference: Y.X. Zhang, D.C. Wan, T. Hino (2014), Comparative study of MPS
 * method and level-set method for sloshing flows, J. Hydrodyn. 26, 577-585.
 */
#include "mps/kernel/kernel.h"

static double w_zhang(double r, double re)
{
    return r < re ? re / (0.85 * r + 0.15 * re) - 1.0 : 0.0;
}

/* The same values as w_zhang, computed for every entry and selected
 * without a branch, so that the loop vectorises: a list holds the pairs
 * of the largest r_e, and whether r < r_e of a smaller one is unpredictable
 * (this loop took 9 % of the coupled dam break's MPS time with a branch
 * and scalar divisions). */
static void weights_zhang(const double *r, int64_t n, double re, double *w)
{
#pragma omp simd
    for (int64_t k = 0; k < n; k++) {
        double v = re / (0.85 * r[k] + 0.15 * re) - 1.0;
        w[k] = r[k] < re ? v : 0.0;
    }
}

const struct mps_kernel_ops mps_kernel_zhang2014 = {
    .name = "zhang2014",
    .reference = "Zhang, Wan & Hino 2014; Xie et al. 2025 eq. 6",
    .w = w_zhang,
    .weights = weights_zhang,
    .finite_at_zero = 1,
};
