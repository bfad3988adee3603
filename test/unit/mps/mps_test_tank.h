/* mps_test_tank.h — the tanks the MPS and coupling unit tests build in
 * code: fluid n[0] x ... cells (particle centres at (i + 1/2) dp), the last
 * axis vertical (y in 2-D, z in 3-D); a wall layer and layers - 1 dummy
 * layers on the bottom and on every side, side walls n[dim-1] + headroom
 * particles high, normals from the fluid into the solid, ids 0..n-1, in
 * the order of the loops (first axis outermost). Pressure and velocity
 * stay 0. */
#ifndef MPSDEM_TEST_MPS_TANK_H
#define MPSDEM_TEST_MPS_TANK_H

#include <math.h>

#include "mps/mps.h"

static inline void mps_test_tank(struct mps_particles *P, int dim,
                                 const int n[3], int layers, int headroom,
                                 double dp)
{
    const int v = dim - 1;   /* vertical axis */
    int lo[3], hi[3], cap = 1, np = 0, c[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = a < dim ? -layers : 0;
        hi[a] = a < v ? n[a] + layers : a == v ? n[a] + headroom : 1;
        cap *= hi[a] - lo[a];
    }
    assert_int_equal(mps_particles_alloc(P, cap, dim), 0);
    for (c[0] = lo[0]; c[0] < hi[0]; c[0]++)
        for (c[1] = lo[1]; c[1] < hi[1]; c[1]++)
            for (c[2] = lo[2]; c[2] < hi[2]; c[2]++) {
                int depth = 0;
                double nv[3] = { 0, 0, 0 }, l = 0;
                for (int a = 0; a < dim; a++) {
                    int far = a < v && c[a] >= n[a]; /* no lid */
                    int d = c[a] < 0 ? -c[a] : far ? c[a] - n[a] + 1 : 0;
                    depth = d > depth ? d : depth;
                    nv[a] = c[a] < 0 ? -1 : far ? 1 : 0;
                    l += nv[a] * nv[a];
                }
                int fluid = depth == 0 && c[v] < n[v];
                if (depth == 0 && !fluid)
                    continue;
                for (int a = 0; a < 3; a++) {
                    P->x[3 * np + a] = a < dim ? (c[a] + 0.5) * dp : 0.0;
                    if (!fluid)
                        P->normal[3 * np + a] = nv[a] / sqrt(l);
                }
                P->type[np] = fluid ? MPS_FLUID
                            : depth == 1 ? MPS_WALL : MPS_DUMMY;
                P->patch[np] = fluid ? -1 : 0;
                P->id[np] = np;
                np++;
            }
    P->n = np;
}

/* 2-D: fluid nx x ny cells in the x-y plane, gravity along -y. */
static inline void mps_test_tank2d(struct mps_particles *P, int nx, int ny,
                                   int layers, int headroom, double dp)
{
    mps_test_tank(P, 2, (const int[3]){ nx, ny, 1 }, layers, headroom, dp);
}

#endif
