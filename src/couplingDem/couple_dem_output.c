/*
 * couple_dem_output.c — the grains' slip u_k - v_k written in a coupled
 * demSolid run's dem.vtu (Xie et al. 2025 eqs. 25, 32-35; doc/theory.md
 * A.7; the fields are listed in couple_dem.h).
 */
#include "couplingDem/couple_dem.h"

#include "dem/dem.h"

int couple_dem_output(struct couple_dem *cd, const struct dem *d)
{
    if (cd->n != d->n || !cd->slip)
        return 0;
    for (size_t k = 0; k < d->n; k++)
        for (int c = 0; c < 3; c++)
            cd->slip[3 * k + c] = cd->wet[k]
                ? cd->uf[3 * k + c] - d->v[3 * k + c] : 0.0;
    return 1;
}
