/*
 * wall_original.c — the direct wall scheme MLPG_R used before the thesis
 * (Ma and Zhou 2009; Pan 2022 thesis eqs. 4.25-4.26; doc/theory.md M.5):
 * the wall node's row is the Neumann condition itself,
 *
 *   n_out.grad p(x_K) = (rho/dt) n_out.(u*_K - U)            (S-2)
 *
 * with the SFDI gradient (doc M0-10) and n_out = -normal (the bisector at
 * a corner, doc M0-07). The row is scaled by R/pi, which makes it the
 * improved row's counterpart for linear p (mlpg.h) and leaves the
 * solution unchanged.
 */
#include <math.h>

#include "core/error.h"
#include "mlpg/mlpg.h"

#define PI 3.141592653589793

static int original_row(const struct mlpg_cloud *c, int i,
                        const int32_t *cand, int m, double *coef,
                        double *work)
{
    double (*a)[2] = (double (*)[2])work;
    TRY(mlpg_sfdi(c, i, cand, m, a));
    const double *nw = c->normal + 3 * i, s = c->R[i] / PI;
    double sum = 0;
    for (int k = 0; k < m; k++) {
        coef[k] = -s * (nw[0] * a[k][0] + nw[1] * a[k][1]);
        sum += coef[k];
    }
    coef[0] -= sum; /* cand[0] = i: grad p = sum a_k (p_k - p_i) */
    return SIM_OK;
}

static double original_rhs(const struct mlpg_cloud *c, int i, double rho_dt,
                           double D, const double ustar_i[3], int nseg,
                           const double n[2][2], const double g[2])
{
    (void)rho_dt, (void)D, (void)ustar_i;
    if (nseg != 2)
        return 0;
    /* n_out = (n0 + n1)/|n0 + n1|, so n_out.grad p = (g0 + g1)/|n0 + n1| */
    double sx = n[0][0] + n[1][0], sy = n[0][1] + n[1][1];
    return c->R[i] / PI * (g[0] + g[1]) / sqrt(sx * sx + sy * sy);
}

const struct mlpg_wall_ops mlpg_wall_original = {
    .name = "original",
    .reference = "Ma and Zhou 2009; Pan 2022 thesis eqs. 4.25-4.26",
    .row = original_row,
    .rhs = original_rhs,
};
