/* wet_walls.c — the wall particles in the pressure equation (wet_walls.h). */
#include "particles/operators/wet_walls.h"

#include <math.h>

#include "particles/neighbour.h"

void pop_wet_walls(const struct neighbour_list *nl, const double *x,
                   const int32_t *type, const double *normal,
                   const double g[2], int by_height, double reach, double dl,
                   uint8_t *wet)
{
    const double gn = hypot(g[0], g[1]);
    const double up[2] = { gn > 0 ? -g[0] / gn : 0, gn > 0 ? -g[1] / gn : 0 };
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (type[i] != 1) {
            wet[i] = 1;
            continue;
        }
        const double *ni = normal + 3 * i;
        int height = by_height && gn > 0
                  && -(up[0] * ni[0] + up[1] * ni[1]) > -0.5;
        int w = 0;
        const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
        const double *rr = neighbour_row_r(nl, i, k0, k1);
        for (int64_t k = k0; k < k1 && !w; k++) {
            int j = nl->j[k];
            double h = up[0] * (x[3 * j] - x[3 * i])
                     + up[1] * (x[3 * j + 1] - x[3 * i + 1]);
            w = type[j] == 0 && rr[k - k0] < reach
             && (!height || h >= -0.5 * dl);
        }
        wet[i] = (uint8_t)w;
    }
}
