/*
 * mls.c — first-order moving least squares and the SFDI gradient of
 * MLPG_R (doc/theory.md M.3, M.7).
 *
 *   p(x) ~ sum_j Phi_j(x) p_j,     Phi_j(x) = Psi^T(x) A^-1(x) w_j(x) Psi(x_j)   (3.17)
 *   A(x) = sum_j w_j(x) Psi(x_j) Psi^T(x_j),   Psi = [1, x, y]                   (3.19)
 *
 * With the basis shifted to the evaluation point and scaled by dl,
 * Psi(x_j) = [1, (x_j - x)/dl, (y_j - y)/dl] and Psi(x) = e_0, so that
 * Phi_j = w_j c . Psi(x_j) with A c = e_0: one 3x3 solve per point.
 * The weight is the quartic spline of doc M0-02 on the support radius
 * 1.85 dl (Pan 2022 sect. 3.3).
 *
 * SFDI (Ma 2008): grad p_i = M^-1 sum_j w_j (p_j - p_i) dx_j with
 * M = sum_j w_j dx_j dx_j^T, dx_j = x_j - x_i: a weighted least-squares fit
 * of the first-order Taylor expansion, exact for linear p.
 */
#include <math.h>

#include "core/error.h"
#include "mlpg/mlpg.h"
#include "particles/operators/gradient_corrected.h"

double mlpg_weight(double r, double rs)
{
    double s = r / rs;
    if (s >= 1)
        return 0;
    double s2 = s * s;
    return 1 - 6 * s2 + 8 * s2 * s - 3 * s2 * s2;
}

int mlpg_spd_solve(int n, double *a, double *b, double rtol)
{
    double dmax = 0;
    for (int k = 0; k < n; k++)
        dmax = fmax(dmax, a[k * n + k]);
    for (int k = 0; k < n; k++) {
        double d = a[k * n + k];
        for (int q = 0; q < k; q++)
            d -= a[k * n + q] * a[k * n + q];
        if (!(d > rtol * dmax))
            return 0;
        d = sqrt(d);
        a[k * n + k] = d;
        for (int r = k + 1; r < n; r++) {
            double t = a[r * n + k];
            for (int q = 0; q < k; q++)
                t -= a[r * n + q] * a[k * n + q];
            a[r * n + k] = t / d;
        }
    }
    for (int k = 0; k < n; k++) {       /* L y = b */
        for (int q = 0; q < k; q++)
            b[k] -= a[k * n + q] * b[q];
        b[k] /= a[k * n + k];
    }
    for (int k = n - 1; k >= 0; k--) {  /* L^T x = y */
        for (int q = k + 1; q < n; q++)
            b[k] -= a[q * n + k] * b[q];
        b[k] /= a[k * n + k];
    }
    return 1;
}

int mlpg_mls(const struct mlpg_cloud *c, const int32_t *cand, int m,
             const double p[2], double *phi)
{
    double a[9] = { 0 };
    for (int k = 0; k < m; k++) {
        const double *xj = c->x + 3 * cand[k];
        double dx = xj[0] - p[0], dy = xj[1] - p[1];
        double w = mlpg_weight(sqrt(dx * dx + dy * dy), c->rs);
        phi[k] = w;
        if (w == 0)
            continue;
        double b[3] = { 1, dx / c->dl, dy / c->dl };
        for (int r = 0; r < 3; r++)
            for (int s = 0; s < 3; s++)
                a[3 * r + s] += w * b[r] * b[s];
    }
    double cc[3] = { 1, 0, 0 }; /* A c = e_0 */
    if (!mlpg_spd_solve(3, a, cc, 1e-10))
        return sim_error(SIM_ERR_NUMERIC,
                         "MLS at (%g, %g): fewer than three non-collinear "
                         "nodes within the support radius %g m",
                         p[0], p[1], c->rs);
    for (int k = 0; k < m; k++) {
        if (phi[k] == 0)
            continue;
        const double *xj = c->x + 3 * cand[k];
        phi[k] *= cc[0] + cc[1] * (xj[0] - p[0]) / c->dl
                + cc[2] * (xj[1] - p[1]) / c->dl;
    }
    return SIM_OK;
}

int mlpg_sfdi(const struct mlpg_cloud *c, int i, const int32_t *cand, int m,
              double (*a)[2])
{
    const double *xi = c->x + 3 * i;
    double M[9] = { 0 };
    for (int k = 0; k < m; k++) {
        double dx = c->x[3 * cand[k]] - xi[0];
        double dy = c->x[3 * cand[k] + 1] - xi[1];
        double r = sqrt(dx * dx + dy * dy);
        double w = cand[k] == i ? 0 : mlpg_weight(r, c->rs);
        a[k][0] = w * dx;
        a[k][1] = w * dy;
        M[0] += w * dx * dx;
        M[1] += w * dx * dy;
        M[4] += w * dy * dy;
    }
    M[3] = M[1];
    for (int k = 0; k < m; k++) {
        double g[3];
        if (!pop_moment_solve(2, M, (double[]){ a[k][0], a[k][1], 0 }, g))
            return sim_error(SIM_ERR_NUMERIC,
                             "SFDI gradient at node %d (%g, %g): its "
                             "neighbours within %g m do not span the plane",
                             i, xi[0], xi[1], c->rs);
        a[k][0] = g[0];
        a[k][1] = g[1];
    }
    return SIM_OK;
}
