/*
 * wall_improved.c — the improved weak formulation for wall nodes (Pan
 * 2022 thesis sect. 4.2, eqs. 4.13-4.20, 4.23-4.24; doc/theory.md M.4):
 * the wall node keeps the Rankine-source row over the fluid side of its
 * disc, and the Neumann condition (S-2) enters through the straight sides
 * of the sector, where it cancels the flux of u*:
 *
 *   (angle/2pi) p(x_K) - (1/2pi) int_arc p dtheta
 *       = -(rho/dt) D_K - sum_s (R/2pi) ((rho/dt) n_s.u*_K - g_s)
 *
 * using int_s phi dS = -R/2pi on each side (S-6) with the data constant
 * along the short side. For a flow g_s = (rho/dt) n_s.(u*_K - U) and the
 * side terms reduce to (R/2pi)(rho/dt) n_s.U (4.19; the sign is doc
 * M0-05). Fluid nodes use the same row and right-hand side with no sides.
 */
#include <math.h>

#include "core/error.h"
#include "mlpg/mlpg.h"

#define TWO_PI 6.283185307179586

static int improved_row(const struct mlpg_cloud *c, int i,
                        const int32_t *cand, int m, double *coef,
                        double *work)
{
    return mlpg_row_rankine(c, i, cand, m, coef, work);
}

static double side_terms(const struct mlpg_cloud *c, int i, double rho_dt,
                         double D, const double ustar_i[3], int nseg,
                         const double n[2][2], const double g[2],
                         double kappa)
{
    double b = -rho_dt * D;
    for (int s = 0; s < nseg; s++)
        b -= c->R[i] / TWO_PI
           * (rho_dt * (n[s][0] * ustar_i[0] + n[s][1] * ustar_i[1])
              - kappa * g[s]);
    return b;
}

static double improved_rhs(const struct mlpg_cloud *c, int i, double rho_dt,
                           double D, const double ustar_i[3], int nseg,
                           const double n[2][2], const double g[2])
{
    return side_terms(c, i, rho_dt, D, ustar_i, nseg, n, g, 1);
}

/* The 2-point Gauss rule on a piece of angle d carries a linear mode of p
 * as kappa = d cos(d/(2 sqrt 3)) / (2 sin(d/2)) of itself (0.99845 on a
 * quarter): the half-arc mean of p = p_K + R g_n sin(theta) comes out as
 * 0.99845 (R/pi) g_n. Scaling the Neumann data by the same kappa makes
 * the row exact for linear p (doc M0-20). */
static double consistent_rhs(const struct mlpg_cloud *c, int i,
                             double rho_dt, double D,
                             const double ustar_i[3], int nseg,
                             const double n[2][2], const double g[2])
{
    double t0, angle, ns[2][2];
    int ns_;
    mlpg_sector(c, i, &t0, &angle, &ns_, ns);
    double d = angle / (mlpg_domain_points(c, i) - 1); /* a piece's angle */
    double kappa = d * cos(d / (2 * sqrt(3.0))) / (2 * sin(d / 2));
    return side_terms(c, i, rho_dt, D, ustar_i, nseg, n, g, kappa);
}

const struct mlpg_wall_ops mlpg_wall_improved = {
    .name = "improved",
    .reference = "Pan 2022 thesis sect. 4.2, eqs. 4.13-4.20",
    .row = improved_row,
    .rhs = improved_rhs,
};

const struct mlpg_wall_ops mlpg_wall_consistent = {
    .name = "improvedConsistent",
    .reference = "Pan 2022 thesis sect. 4.2 with doc/theory.md M0-20",
    .row = improved_row,
    .rhs = consistent_rhs,
};
