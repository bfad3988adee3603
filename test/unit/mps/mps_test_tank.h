/* mps_test_tank.h — the 2-D tank the MPS and coupling unit tests build in
 * code: fluid nx x ny cells in the x-y plane (particle centres at
 * (i + 1/2) dp), a wall layer and layers - 1 dummy layers on the bottom
 * and sides, side walls ny + headroom particles high, normals from the
 * fluid into the solid, ids 0..n-1. Pressure and velocity stay 0. */
#ifndef MPSDEM_TEST_MPS_TANK_H
#define MPSDEM_TEST_MPS_TANK_H

#include <math.h>

#include "mps/mps.h"

static inline void mps_test_tank2d(struct mps_particles *P, int nx, int ny,
                                   int layers, int headroom, double dp)
{
    int n = 0, cap = (nx + 2 * layers) * (ny + headroom + layers);
    assert_int_equal(mps_particles_alloc(P, cap, 2), 0);
    for (int i = -layers; i < nx + layers; i++)
        for (int j = -layers; j < ny + headroom; j++) {
            int di = i < 0 ? -i : i >= nx ? i - nx + 1 : 0;
            int dj = j < 0 ? -j : 0;
            int depth = di > dj ? di : dj;
            int fluid = depth == 0 && j < ny;
            if (depth == 0 && !fluid)
                continue;
            double *x = P->x + 3 * n;
            x[0] = (i + 0.5) * dp;
            x[1] = (j + 0.5) * dp;
            P->type[n] = fluid ? MPS_FLUID : depth == 1 ? MPS_WALL : MPS_DUMMY;
            P->patch[n] = fluid ? -1 : 0;
            if (!fluid) {
                double nv[2] = { i < 0 ? -1 : i >= nx ? 1 : 0, j < 0 ? -1 : 0 };
                double l = hypot(nv[0], nv[1]);
                P->normal[3 * n] = nv[0] / l;
                P->normal[3 * n + 1] = nv[1] / l;
            }
            P->id[n] = n;
            n++;
        }
    P->n = n;
}

#endif
