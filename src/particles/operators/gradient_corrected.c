/*
 * gradient_corrected.c — the corrective-matrix pressure gradient (GC) of
 * Khayyer and Gotoh (2011, J. Comput. Phys. 230, 3093, eqs. 25-27), in the
 * (p_j - p_i) form used by corrected ISPH (Lind et al. 2012, J. Comput.
 * Phys. 231, 1499, eq. 13); MPS: `pressureGradient corrected;` in
 * mpsSchemes, with the fallback normalisation c = d/n0.
 *
 *   <grad p>_i = C_i sum_j (p_j - p_i) r_ij / |r_ij|^2 w_ij / eps_j
 *   C_i        = [ sum_j r_ij (x) r_ij / |r_ij|^2 w_ij / eps_j ]^-1
 *
 * r_ij = r_j - r_i. The matrix makes the operator exact for any linear
 * field on any particle arrangement (first-order consistent), where eq. (8)
 * of Xie et al. (2025) is exact only on a complete symmetric neighbourhood.
 * That matters for still water: with eq. (8) a hydrostatic field gives each
 * particle of a square lattice a net force as soon as the lattice is
 * perturbed, and the (p_i + p_j) pair repulsion makes the square lattice
 * unstable in shear (the growth measured in the 2-D tank: e-folding time
 * 8 ms from t = 0.03 s, see tutorials/mpsFluid/hydrostaticTank2D/README.md).
 * With (p_j - p_i) a uniform pressure exerts no force at all, so nothing
 * keeps particles apart but the PPE density term: pair it with a shifting
 * model or the collision model.
 *
 * Where the moment matrix is (nearly) singular — a particle with neighbours
 * on one line only, or alone — the uncorrected c sum (p_j - p_i) form
 * is used: its reciprocal condition number (smallest / largest eigenvalue,
 * from the 2x2 or 3x3 symmetric matrix) below GC_RCOND.
 */
#include "particles/operators/gradient_corrected.h"

#include <math.h>

#include "particles/neighbour.h"

#define IEPS(j) (inv_eps ? inv_eps[j] : 1.0)

/* Below this ratio of smallest to largest eigenvalue of the moment matrix
 * the correction would amplify noise more than it removes bias. A surface
 * particle of a flat lattice has 0.4 (2-D, r_e = 2.1 dp). */
#define GC_RCOND 0.05

/* Eigenvalues of the symmetric 3x3 matrix m (row-major), ascending
 * (trigonometric solution of the characteristic cubic). */
static void sym3_eigen(const double m[9], double ev[3])
{
    double p1 = m[1] * m[1] + m[2] * m[2] + m[5] * m[5];
    double q = (m[0] + m[4] + m[8]) / 3;
    if (p1 <= 1e-300 * (q * q + 1e-300)) {
        ev[0] = fmin(m[0], fmin(m[4], m[8]));
        ev[2] = fmax(m[0], fmax(m[4], m[8]));
        ev[1] = 3 * q - ev[0] - ev[2];
        return;
    }
    double p2 = (m[0] - q) * (m[0] - q) + (m[4] - q) * (m[4] - q)
              + (m[8] - q) * (m[8] - q) + 2 * p1;
    double p = sqrt(p2 / 6);
    double b[9];
    for (int k = 0; k < 9; k++)
        b[k] = (m[k] - (k % 4 == 0 ? q : 0)) / p;
    double r = (b[0] * (b[4] * b[8] - b[5] * b[7])
              - b[1] * (b[3] * b[8] - b[5] * b[6])
              + b[2] * (b[3] * b[7] - b[4] * b[6])) / 2;
    double phi = r <= -1 ? M_PI / 3 : r >= 1 ? 0 : acos(r) / 3;
    ev[2] = q + 2 * p * cos(phi);
    ev[0] = q + 2 * p * cos(phi + 2 * M_PI / 3);
    ev[1] = 3 * q - ev[0] - ev[2];
}

int pop_moment_solve(int dim, const double m[9], const double v[3],
                     double g[3])
{
    if (dim == 2) {
        double tr = m[0] + m[4], det = m[0] * m[4] - m[1] * m[3];
        double disc = sqrt(fmax(tr * tr / 4 - det, 0));
        double lmin = tr / 2 - disc, lmax = tr / 2 + disc;
        if (!(lmax > 0) || lmin < GC_RCOND * lmax)
            return 0;
        g[0] = (m[4] * v[0] - m[1] * v[1]) / det;
        g[1] = (m[0] * v[1] - m[3] * v[0]) / det;
        g[2] = 0;
        return 1;
    }
    double ev[3];
    sym3_eigen(m, ev);
    if (!(ev[2] > 0) || ev[0] < GC_RCOND * ev[2])
        return 0;
    double c0 = m[4] * m[8] - m[5] * m[7];
    double c1 = m[5] * m[6] - m[3] * m[8],
           c2 = m[3] * m[7] - m[4] * m[6];
    double det = m[0] * c0 + m[1] * c1 + m[2] * c2;
    double inv[9] = {
        c0, m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
        c1, m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
        c2, m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3]
    };
    for (int a = 0; a < 3; a++)
        g[a] = (inv[3 * a] * v[0] + inv[3 * a + 1] * v[1]
                + inv[3 * a + 2] * v[2]) / det;
    return 1;
}

void pop_gradient_corrected(const struct neighbour_list *nl,
                            const struct pop_weights *W,
                            int dim, double c, const double *x,
                            const double *phi, const double *inv_eps,
                            const uint8_t *rows, double *out)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        double v[3] = { 0, 0, 0 }, m[9] = { 0 }, g[3];
        const double *xi = x + 3 * i;
        const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
        const double *rr = neighbour_row_r(nl, i, k0, k1);
        const double *w = pop_weights_row(W, k0, rr, k1 - k0);
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            double r = rr[k - k0], wk = w[k - k0];
            if (wk == 0 || r == 0)
                continue;
            double d[3] = { x[3 * j] - xi[0], x[3 * j + 1] - xi[1],
                            x[3 * j + 2] - xi[2] };
            double a = wk * IEPS(j) / (r * r);
            for (int q = 0; q < 3; q++) {
                v[q] += a * (phi[j] - phi[i]) * d[q];
                for (int s = 0; s < 3; s++)
                    m[3 * q + s] += a * d[q] * d[s];
            }
        }
        if (!pop_moment_solve(dim, m, v, g))
            for (int q = 0; q < 3; q++)
                g[q] = c * v[q];
        for (int q = 0; q < 3; q++)
            out[3 * i + q] = g[q];
    }
}
