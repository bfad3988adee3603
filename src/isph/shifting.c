/*
 * shifting.c — Fickian particle shifting for isphSediment (`shifting
 * lind2012`; Lind, Xu, Stansby and Rogers 2012, J. Comput. Phys. 231,
 * 1499-1523, eqs. 20-24; doc/theory.md S0-15), after the position update
 * r^(n+1) = r^n + dt u^(n+1):
 *
 *   grad C_a = sum_b V_b grad W_ab                 (concentration gradient)
 *   dr_a     = -A h^2 grad C_a                     (inside the water)
 *   dr_a     = -A h^2 (I - n n) grad C_a           (on or next to the surface)
 *
 * over the water, wall and dummy neighbours (dry ones too: a particle at
 * the waterline is not drawn into the wall above the water); a wall or
 * dummy counts at the particle's own V_a, a mirror of it: with dl^2 the
 * swollen particles of a settled bed (V = m_f/(alpha_f rho_f) > dl^2)
 * were drawn into the floor,
 * n = -grad C/|grad C| the surface normal; capped at 0.1 dl a step. The
 * divergence-only pressure equation of (5.24) keeps div u = 0 but not the
 * spacing: without shifting the particles of a fast flow (a dam break)
 * stretch into lines and clump along the floor until the surface detector
 * finds holes inside the water (the validation README of
 * tutorials/isphSediment/damBreak). Velocities and alpha_s are not
 * re-interpolated: each particle keeps its water and sediment volume, so
 * sum alpha_s V is unchanged.
 */
#include <math.h>

#include "isph/isph_solver.h"
#include "particles/operators/operators.h"

#define MAX_SHIFT 0.1 /* [dl] */

void isph_shift(struct isph_solver *s)
{
    const struct isph_settings *S = &s->S;
    const double reach = S->kernel->support * S->h;
    const double D = S->shift_coeff * S->h * S->h;
    double *dr = s->x0; /* r^n, free once r^(n+1) is set */
#pragma omp parallel for schedule(static)
    for (int a = 0; a < s->n; a++) {
        double G[3] = { 0, 0, 0 }, d[3] = { 0, 0, 0 };
        if (s->type[a] == ISPH_FLUID && s->V[a] > 0) {
            int near = s->fs[a];
            for (int64_t k = s->nl.start[a]; k < s->nl.start[a + 1]; k++) {
                int b = s->nl.j[k];
                if (b == a || (s->type[b] == ISPH_FLUID && !(s->V[b] > 0)))
                    continue;
                /* the list is r*'s: distances at r^(n+1) */
                double r = hypot(s->x[3 * b] - s->x[3 * a],
                                 s->x[3 * b + 1] - s->x[3 * a + 1]);
                if (!(r > 0) || r >= reach)
                    continue;
                double dx[2], gw[2];
                double V = s->type[b] == ISPH_FLUID ? s->V[b] : s->V[a];
                isph_kernel_gradient(&s->cl, a, b, r, dx, gw);
                G[0] += V * gw[0];
                G[1] += V * gw[1];
                near |= s->fs[b];
            }
            pop_fickian_shift(G, G, D, near, MAX_SHIFT * S->dl, d);
        }
        dr[3 * a] = d[0];
        dr[3 * a + 1] = d[1];
    }
    for (int a = 0; a < s->n; a++)
        for (int q = 0; q < 2; q++)
            s->x[3 * a + q] += dr[3 * a + q];
}
