/*
 * smoothing.c — the velocity smoothing of isphSediment (`velocitySmoothing
 * shepard | biharmonic`, `velocitySmoothingRegion all | freeSurface`;
 * doc/theory.md S0-18). Not in the thesis.
 */
#include "isph/isph_solver.h"

/* out = (I - S) f, S f = sum_b V_b W_ab f_b / sum_b V_b W_ab the kernel
 * (Shepard) mean over the water in reach; f's 2 components at stride fs,
 * out's at stride 2; 0 where no water is in reach and for walls. */
static void high_pass(const struct isph_solver *s, const double *f, int fs,
                      double *out)
{
    const double reach = s->S.kernel->support * s->S.h;
#pragma omp parallel for schedule(static)
    for (int a = 0; a < s->n; a++) {
        double m[2] = { 0, 0 }, ws = 0;
        if (s->type[a] == ISPH_FLUID)
            for (int64_t k = s->nl.start[a]; k < s->nl.start[a + 1]; k++) {
                int b = s->nl.j[k];
                double r = s->nl.r[k];
                if (s->type[b] != ISPH_FLUID || !(s->V[b] > 0) || r >= reach)
                    continue;
                double wk = s->V[b] * s->S.kernel->w(r, s->S.h);
                m[0] += wk * f[fs * b];
                m[1] += wk * f[fs * b + 1];
                ws += wk;
            }
        for (int q = 0; q < 2; q++)
            out[2 * a + q] = ws > 0 ? f[fs * a + q] - m[q] / ws : 0;
    }
}

/* velocitySmoothing (S0-18), after the update, for the water and the
 * sediment: shepard u <- u - eps (I - S) u, biharmonic u <- u - eps (I -
 * S)^2 u. Both average a row-to-row checkerboard away, which the
 * corrected divergence of the pressure equation is blind to and which in
 * a suspension grows from the bed and the surface; uniform and linear
 * fields inside the water are kept, still water stays still. shepard
 * damps a wave of length L by about eps (h/L)^2 a step, an artificial
 * viscosity; biharmonic by about eps (h/L)^4, so the eddies of a sinking
 * cloud keep more of their strength. */
void isph_smooth_velocities(struct isph_solver *s)
{
    const double eps = s->S.smoothing_eps;
    double *h1 = s->ustar, *h2 = s->gu; /* free after the update */
    for (int pass = 0; pass < 2; pass++) {
        double *f = pass ? s->us : s->u, *h = h1;
        high_pass(s, f, 3, h1);
        if (s->S.smoothing == ISPH_SMOOTHING_BIHARMONIC) {
            high_pass(s, h1, 2, h2);
            h = h2;
        }
        for (int a = 0; a < s->n; a++)
            if (!s->S.smoothing_surface || s->truncated[a])
                for (int q = 0; q < 2; q++)
                    f[3 * a + q] -= eps * h[2 * a + q];
    }
}

