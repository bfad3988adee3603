/*
 * wall_stress.c — what the fluid exerts on the wall nodes of an MLPG
 * cloud (doc/theory.md M0-24), for the force on a body (the function
 * object `forces`; drag and lift of the cylinder, E3-14):
 *
 *   F = sum over wall nodes i of  A_i (p_i n_i + t_i),
 *   t_i = mu (grad u + grad u^T)_i . n_f,i,
 *
 * n_i the unit normal into the solid, n_f = -n_i into the fluid, mu = rho
 * nu. The velocity gradient is the one-sided second-order fit of qsfdi.c
 * over the node's row candidates (wall nodes carry the wall's velocity):
 * a first-order fit would see the boundary layer's curvature as a
 * gradient error of O(dl). A_i is the length of the polygon through the
 * midpoints of the chords to the node's two nearest wall nodes of its
 * patch on either side, |(perp c+ + perp c-)/2|: dl on a straight wall,
 * the chord's cosine share on a curve, dl/sqrt(2) at a right-angled
 * corner (its two half-lengths at right angles); a node with one such
 * neighbour (the end of a patch) stands for half its chord.
 */
#include <math.h>

#include "core/error.h"
#include "mlpg/mlpg_solver.h"

/* A_i of wall node i (above). */
static double wall_area(const struct mlpg_solver *s, int i)
{
    const struct neighbour_list *nl = &s->nl;
    const double *xi = s->x + 3 * i, *ni = s->normal + 3 * i;
    double t[2] = { ni[1], -ni[0] }, best[2] = { HUGE_VAL, HUGE_VAL };
    int near[2] = { -1, -1 };
    for (int64_t e = nl->start[i]; e < nl->start[i + 1]; e++) {
        int j = nl->j[e];
        if (j == i || s->type[j] != MLPG_WALL || s->patch[j] != s->patch[i])
            continue;
        double along = (s->x[3 * j] - xi[0]) * t[0]
                     + (s->x[3 * j + 1] - xi[1]) * t[1];
        int side = along > 0;
        if (along != 0 && nl->r[e] < best[side]) {
            best[side] = nl->r[e];
            near[side] = j;
        }
    }
    if (near[0] < 0 && near[1] < 0)
        return s->S.dl;
    double a[2] = { 0, 0 };
    for (int side = 0; side < 2; side++) {
        if (near[side] < 0)
            continue;
        double c[2] = { s->x[3 * near[side]] - xi[0],
                        s->x[3 * near[side] + 1] - xi[1] };
        double perp[2] = { c[1], -c[0] };
        double sign = perp[0] * ni[0] + perp[1] * ni[1] < 0 ? -0.5 : 0.5;
        a[0] += sign * perp[0];
        a[1] += sign * perp[1];
    }
    return hypot(a[0], a[1]);
}

void mlpg_wall_stress(struct mlpg_solver *s)
{
    const double mu = s->S.rho * s->S.nu;
    if (!s->coef_start) /* before the first step: no rows yet */
        return;
#pragma omp parallel for schedule(dynamic, 64)
    for (int i = 0; i < s->n; i++) {
        double *t = s->traction + 3 * i;
        t[0] = t[1] = t[2] = 0;
        s->wall_area[i] = 0;
        if (s->type[i] != MLPG_WALL || (s->exclude && s->exclude[i]))
            continue;
        s->wall_area[i] = wall_area(s, i);
        int64_t e = s->coef_start[i];
        int m = (int)(s->coef_start[i + 1] - e);
        const int32_t *cand = s->cand + e;
        double l[2][m > 0 ? m : 1], g[2][2] = { { 0 } };
        int bad = 0;
        for (int d = 0; d < 2 && !bad; d++)
            bad = mlpg_fit2_coeffs(&s->c, i, cand, m, s->nl.rc,
                                   d ? MLPG_FIT2_DY : MLPG_FIT2_DX, l[d]);
        if (bad) { /* neighbours on its own line (M0-23): no stress */
            sim_error_clear();
            continue;
        }
        for (int k = 0; k < m; k++)
            for (int c = 0; c < 2; c++)
                for (int d = 0; d < 2; d++) /* g[c][d] = d u_c / d x_d */
                    g[c][d] += l[d][k] * (s->u[3 * cand[k] + c]
                                          - s->u[3 * i + c]);
        const double nf[2] = { -s->normal[3 * i], -s->normal[3 * i + 1] };
        for (int c = 0; c < 2; c++)
            t[c] = mu * ((g[c][0] + g[0][c]) * nf[0]
                         + (g[c][1] + g[1][c]) * nf[1]);
    }
}
