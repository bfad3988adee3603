/*
 * drag_none.c — no drag: F^d_k = 0. For one-way tests (grains that only
 * feel buoyancy or the pressure gradient) and for switching the exchange
 * off without editing the rest of couplingDict.
 */
#include "coupling/drag/drag.h"

static double coeff(const struct drag_fluid *f, double eps, double slip,
                    double d)
{
    (void)f;
    (void)eps;
    (void)slip;
    (void)d;
    return 0.0;
}

static void force_all(const struct drag_fluid *f, int n, const double *eps,
                      const double *d, const double *V, const double *u,
                      const double *v, double *F)
{
    (void)f;
    (void)eps;
    (void)d;
    (void)V;
    (void)u;
    (void)v;
    for (int k = 0; k < 3 * n; k++)
        F[k] = 0.0;
}

const struct drag_ops drag_none = {
    .name = "none",
    .reference = "",
    .validity = "any",
    .coeff = coeff,
    .force_all = force_all,
    .jump_eps = 0.0,
};
