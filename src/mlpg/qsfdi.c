/*
 * qsfdi.c — derivatives of MLPG_R by a weighted least-squares fit of the
 * second-order Taylor expansion (QSFDI; Pan 2022 thesis sect. 3.4 names it
 * beside the second-order MLS derivative; doc/theory.md M.7, M0-21):
 *
 *   f_j - f_i ~ a_j . c,   a_j = [dx, dy, dx^2/2, dx dy, dy^2/2]_j / scaled,
 *   c = (sum_j w_j a_j a_j^T)^-1 sum_j w_j a_j (f_j - f_i),
 *   lap f_i = c_xx + c_yy,  df/dx_i = c_x,  df/dy_i = c_y,
 *
 * each = sum_j l_j (f_j - f_i), exact for quadratic f wherever the five
 * moments are independent: the viscous Laplacian, and the one-sided
 * velocity gradient of a wall node for its shear stress (M0-24). The weight
 * is the MLS quartic spline on the radius given (the neighbour list's, so
 * that a corner node finds the five nodes it needs).
 */
#include <math.h>

#include "core/error.h"
#include "mlpg/mlpg.h"

int mlpg_fit2_coeffs(const struct mlpg_cloud *c, int i, const int32_t *cand,
                     int m, double radius, enum mlpg_fit2 op, double *l)
{
    const double *xi = c->x + 3 * i, h = c->dl;
    double M[25] = { 0 }, s[5] = { 0 }, scale = op == MLPG_FIT2_LAPLACIAN
                                                ? h * h : h;
    if (op == MLPG_FIT2_LAPLACIAN)
        s[2] = s[4] = 1;
    else
        s[op == MLPG_FIT2_DX ? 0 : 1] = 1;
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
    if (!mlpg_spd_solve(5, M, s, 1e-12))
        return sim_error(SIM_ERR_NUMERIC,
                         "second-order fit at node %d (%g, %g): fewer than "
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
        l[k] = w * v / scale;
    }
    return SIM_OK;
}
