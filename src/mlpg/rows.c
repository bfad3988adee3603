/*
 * rows.c — sub-domains and the Rankine-source rows of MLPG_R (doc/theory.md
 * M.2, M.4-M.6; Pan 2022 thesis eqs. 4.10-4.24, 4.27-4.38; Ma 2005).
 *
 * Node i's sub-domain is the sector of radius R_i from theta0 to
 * theta0 + angle (full circle for a fluid node). With the test function
 * phi = ln(r/R)/(2pi) the weak form of lap p = (rho/dt) div u* is
 *
 *   (1/2pi) int_arc p dtheta - (angle/2pi) p_i
 *       = (rho/dt) (1/2pi) int int u*_r dr dtheta
 *         - sum_s int_s phi ((rho/dt) n_s.u* - n_s.grad p) dS        (4.12, 4.19)
 *
 * (4.15 generalised to a sector: the small circle around i gives
 * -angle/2pi p_i; on a straight side grad phi is along the side.) The arc
 * is cut into pieces of at most a quarter, each integrated with two Gauss
 * points (Ma 2005b): for a quarter, 1/8 of the sum of p at the points.
 * The domain integral (S-9) takes u* linear on each piece's triangle
 * between the node and the piece's two arc ends (4.27)-(4.32), with the
 * determinant corrected (doc M0-11) and the u0, v0 terms that (4.38)
 * drops (doc M0-12); it is exact for linear u*.
 */
#include <math.h>

#include "core/error.h"
#include "mlpg/mlpg.h"
#include "particles/neighbour.h"

#define TWO_PI 6.283185307179586

void mlpg_sector(const struct mlpg_cloud *c, int i, double *theta0,
                 double *angle, int *nseg, double n[2][2])
{
    if (c->type[i] != MLPG_WALL) {
        *theta0 = 0;
        *angle = TWO_PI;
        *nseg = 0;
        return;
    }
    const double *nw = c->normal + 3 * i;
    double a = c->sector[i], t0 = atan2(nw[1], nw[0]) - a / 2;
    *theta0 = t0;
    *angle = a;
    *nseg = 2;
    n[0][0] = sin(t0);                /* e(t0 - pi/2)     */
    n[0][1] = -cos(t0);
    n[1][0] = -sin(t0 + a);           /* e(t0 + a + pi/2) */
    n[1][1] = cos(t0 + a);
}

void mlpg_radii(const struct mlpg_cloud *c, double *R)
{
    const struct neighbour_list *nl = c->nl;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < c->n; i++) {
        double r = c->R0;
        if (c->type[i] != MLPG_WALL)
            for (int64_t k = nl->start[i]; k < nl->start[i + 1]; k++) {
                int j = nl->j[k];
                /* straight-wall nodes whose tangent line passes next to
                 * i: the distance to that line is the distance to the wall
                 * (a corner's bisector is no wall line) */
                if (c->type[j] != MLPG_WALL
                    || fabs(c->sector[j] - TWO_PI / 2) > 1e-6)
                    continue;
                const double *nj = c->normal + 3 * j;
                double dx = c->x[3 * i] - c->x[3 * j];
                double dy = c->x[3 * i + 1] - c->x[3 * j + 1];
                double d = nj[0] * dx + nj[1] * dy;
                double t = fabs(-nj[1] * dx + nj[0] * dy);
                if (d > 0 && t <= c->dl)
                    r = fmin(r, 0.95 * d);
            }
        R[i] = r;
    }
}

int mlpg_candidates(const struct mlpg_cloud *c, int i, int32_t *cand)
{
    const struct neighbour_list *nl = c->nl;
    int m = 0;
    if (cand)
        cand[m] = i;
    m++;
    for (int64_t k = nl->start[i]; k < nl->start[i + 1]; k++) {
        int j = nl->j[k];
        if (c->exclude && c->exclude[j])
            continue;
        if (cand)
            cand[m] = j;
        m++;
    }
    return m;
}

/* Pieces of at most a quarter covering the sector. */
static int pieces(double angle)
{
    int np = (int)ceil(angle / (TWO_PI / 4) - 1e-9);
    return np < 1 ? 1 : np;
}

int mlpg_row_rankine(const struct mlpg_cloud *c, int i, const int32_t *cand,
                     int m, double *coef, double *work)
{
    double t0, angle, ns[2][2];
    int nseg;
    mlpg_sector(c, i, &t0, &angle, &nseg, ns);
    const double *xi = c->x + 3 * i, R = c->R[i];
    double *phi = work;
    const int np = pieces(angle);
    const double d = angle / np, g = 0.5 / sqrt(3.0);
    for (int k = 0; k < m; k++)
        coef[k] = 0;
    for (int a = 0; a < np; a++)
        for (int q = 0; q < 2; q++) {
            double th = t0 + d * (a + 0.5 + (q ? g : -g));
            double p[2] = { xi[0] + R * cos(th), xi[1] + R * sin(th) };
            TRY(mlpg_mls(c, cand, m, p, phi));
            for (int k = 0; k < m; k++)
                coef[k] -= d / (2 * TWO_PI) * phi[k];
        }
    if (c->self_nodal) {
        coef[0] += angle / TWO_PI; /* cand[0] = i */
    } else {
        TRY(mlpg_mls(c, cand, m, xi, phi));
        for (int k = 0; k < m; k++)
            coef[k] += angle / TWO_PI * phi[k];
    }
    return SIM_OK;
}

double mlpg_quarter_integral(double R, double th1, double th2,
                             const double u0[2], double cux, double cuy,
                             double cvx, double cvy)
{
    double s1 = sin(th1), c1 = cos(th1), s2 = sin(th2), c2 = cos(th2);
    return R * (u0[0] * (s2 - s1) - u0[1] * (c2 - c1))
         + R / 4 * ((cux + cvy) * (th2 - th1)
                    + (cux - cvy) * (s2 * c2 - s1 * c1)
                    + (cuy + cvx) * (s2 * s2 - s1 * s1));
}

int mlpg_domain_points(const struct mlpg_cloud *c, int i)
{
    double t0, angle, ns[2][2];
    int nseg;
    mlpg_sector(c, i, &t0, &angle, &nseg, ns);
    return pieces(angle) + 1;
}

int mlpg_domain_weights(const struct mlpg_cloud *c, int i,
                        const int32_t *cand, int m, double *w)
{
    double t0, angle, ns[2][2];
    int nseg;
    mlpg_sector(c, i, &t0, &angle, &nseg, ns);
    const double *xi = c->x + 3 * i, R = c->R[i];
    const int np = pieces(angle);
    for (int a = 0; a <= np; a++) {
        double th = t0 + angle / np * a;
        double p[2] = { xi[0] + R * cos(th), xi[1] + R * sin(th) };
        TRY(mlpg_mls(c, cand, m, p, w + (size_t)a * m));
    }
    return SIM_OK;
}

double mlpg_domain_sum(const struct mlpg_cloud *c, int i, const int32_t *cand,
                       int m, const double *w, const double *ustar)
{
    double t0, angle, ns[2][2];
    int nseg;
    mlpg_sector(c, i, &t0, &angle, &nseg, ns);
    const double R = c->R[i];
    const double u0[2] = { ustar[3 * i], ustar[3 * i + 1] };
    const int np = pieces(angle);
    const double d = angle / np;
    double u[5][2], sum = 0;
    for (int a = 0; a <= np; a++) {  /* MLS values of u* on the arc */
        const double *wa = w + (size_t)a * m;
        u[a][0] = u[a][1] = 0;
        for (int k = 0; k < m; k++) {
            u[a][0] += wa[k] * ustar[3 * cand[k]];
            u[a][1] += wa[k] * ustar[3 * cand[k] + 1];
        }
    }
    for (int a = 0; a < np; a++) {
        double th1 = t0 + d * a, th2 = th1 + d;
        const double *ua = u[a], *ub = u[a + 1];
        /* (4.29)-(4.32) with D = (xa-x0)(yb-y0) - (xb-x0)(ya-y0) */
        double ax = R * cos(th1), ay = R * sin(th1);
        double bx = R * cos(th2), by = R * sin(th2);
        double det = ax * by - bx * ay;
        double cux = R * ((ua[0] - u0[0]) * by - (ub[0] - u0[0]) * ay) / det;
        double cuy = R * ((ub[0] - u0[0]) * ax - (ua[0] - u0[0]) * bx) / det;
        double cvx = R * ((ua[1] - u0[1]) * by - (ub[1] - u0[1]) * ay) / det;
        double cvy = R * ((ub[1] - u0[1]) * ax - (ua[1] - u0[1]) * bx) / det;
        sum += mlpg_quarter_integral(R, th1, th2, u0, cux, cuy, cvx, cvy);
    }
    return sum / TWO_PI;
}

int mlpg_domain_integral(const struct mlpg_cloud *c, int i,
                         const int32_t *cand, int m, const double *ustar,
                         double *work, double *D)
{
    TRY(mlpg_domain_weights(c, i, cand, m, work));
    *D = mlpg_domain_sum(c, i, cand, m, work, ustar);
    return SIM_OK;
}
