/*
 * qsfdi.c — the viscous Laplacian of MLPG_R by a weighted least-squares
 * fit of the second-order Taylor expansion (QSFDI; Pan 2022 thesis sect.
 * 3.4 names it beside the second-order MLS derivative; doc/theory.md M.7,
 * M0-21):
 *
 *   f_j - f_i ~ a_j . c,   a_j = [dx, dy, dx^2/2, dx dy, dy^2/2]_j / scaled,
 *   c = (sum_j w_j a_j a_j^T)^-1 sum_j w_j a_j (f_j - f_i),
 *   lap f_i = c_xx + c_yy = sum_j l_j (f_j - f_i),
 *
 * exact for quadratic f wherever the five moments are independent. The
 * weight is the MLS quartic spline on the radius given (the neighbour
 * list's, so that a corner node finds the five nodes it needs).
 */
#include <math.h>

#include "core/error.h"
#include "mlpg/mlpg.h"

/* Solve the SPD n x n system a s = b in place (Cholesky); 0 when a pivot
 * falls below 1e-12 of the largest diagonal. */
static int spd_solve(int n, double *a, double *b)
{
    double dmax = 0;
    for (int k = 0; k < n; k++)
        dmax = fmax(dmax, a[k * n + k]);
    for (int k = 0; k < n; k++) {
        double d = a[k * n + k];
        for (int q = 0; q < k; q++)
            d -= a[k * n + q] * a[k * n + q];
        if (!(d > 1e-12 * dmax))
            return 0;
        d = sqrt(d);
        a[k * n + k] = d;
        for (int r = k + 1; r < n; r++) {
            double s = a[r * n + k];
            for (int q = 0; q < k; q++)
                s -= a[r * n + q] * a[k * n + q];
            a[r * n + k] = s / d;
        }
    }
    for (int k = 0; k < n; k++) {
        for (int q = 0; q < k; q++)
            b[k] -= a[k * n + q] * b[q];
        b[k] /= a[k * n + k];
    }
    for (int k = n - 1; k >= 0; k--) {
        for (int q = k + 1; q < n; q++)
            b[k] -= a[q * n + k] * b[q];
        b[k] /= a[k * n + k];
    }
    return 1;
}

int mlpg_laplacian_coeffs(const struct mlpg_cloud *c, int i,
                          const int32_t *cand, int m, double radius,
                          double *l)
{
    const double *xi = c->x + 3 * i, h = c->dl;
    double M[25] = { 0 }, s[5] = { 0, 0, 1, 0, 1 };
    for (int k = 0; k < m; k++) {
        double dx = (c->x[3 * cand[k]] - xi[0]) / h;
        double dy = (c->x[3 * cand[k] + 1] - xi[1]) / h;
        double w = cand[k] == i ? 0 : mlpg_weight(hypot(dx, dy) * h, radius);
        if (w == 0)
            continue;
        double a[5] = { dx, dy, dx * dx / 2, dx * dy, dy * dy / 2 };
        for (int r = 0; r < 5; r++)
            for (int q = 0; q < 5; q++)
                M[5 * r + q] += w * a[r] * a[q];
    }
    if (!spd_solve(5, M, s))
        return sim_error(SIM_ERR_NUMERIC,
                         "viscous Laplacian at node %d (%g, %g): fewer than "
                         "five independent neighbours within %g m", i, xi[0],
                         xi[1], radius);
    for (int k = 0; k < m; k++) {
        double dx = (c->x[3 * cand[k]] - xi[0]) / h;
        double dy = (c->x[3 * cand[k] + 1] - xi[1]) / h;
        double w = cand[k] == i ? 0 : mlpg_weight(hypot(dx, dy) * h, radius);
        double a[5] = { dx, dy, dx * dx / 2, dx * dy, dy * dy / 2 };
        double v = 0;
        for (int r = 0; r < 5; r++)
            v += a[r] * s[r];
        l[k] = w * v / (h * h);
    }
    return SIM_OK;
}
