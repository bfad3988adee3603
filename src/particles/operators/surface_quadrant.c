/*
 * surface_quadrant.c — free-surface particles by occupied directions
 * (Ma and Zhou 2009; Pan 2022 thesis eqs. 5.32-5.33, Fig. 5.1; doc/theory.md
 * M0-22):
 *
 *   FS_quarter(I) = 1 if N <= 3,  FS_column(I) = 1 if N <= 3,
 *   N = N_east + N_west + N_north + N_south, N_dir = 1 when a neighbour
 *   lies in that quadrant (column);  I is on the surface iff both are 1.
 *
 * The quadrants are the 90-degree sectors centred on the axes (east:
 * |angle| < 45 deg; the thesis's figure is lost, doc M0-22); the columns
 * are the strips of half width `half_width` from I along each axis,
 * clipped by the search circle. A particle inside the water sees all four
 * directions occupied; one on the surface has an empty sector and column
 * above it. A wall particle given a facing direction occupies the sector
 * and column of that direction (the side of the water its wall is on),
 * not those of its position: the floor ahead of a surge's tip then does
 * not fill the tip's eastern sector.
 */
#include <math.h>

#include "particles/neighbour.h"
#include "particles/operators/surface_quadrant.h"

void pop_surface_quadrant(const struct neighbour_list *nl, const double *x,
                          double radius, double half_width,
                          const uint8_t *rows, const uint8_t *counts,
                          const double *facing, uint8_t *flag)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        unsigned sect = 0, col = 0; /* bits: east west north south */
        const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
        const double *rr = neighbour_row_r(nl, i, k0, k1);
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            if (rr[k - k0] >= radius || (counts && !counts[j]))
                continue;
            double dx = x[3 * j] - x[3 * i], dy = x[3 * j + 1] - x[3 * i + 1];
            if (facing && (facing[3 * j] != 0 || facing[3 * j + 1] != 0)) {
                dx = facing[3 * j]; /* a wall: the side it lies on */
                dy = facing[3 * j + 1];
            }
            if (fabs(dx) >= fabs(dy))
                sect |= dx > 0 ? 1u : 2u;
            else
                sect |= dy > 0 ? 4u : 8u;
            if (fabs(dy) < half_width)
                col |= dx > 0 ? 1u : 2u;
            if (fabs(dx) < half_width)
                col |= dy > 0 ? 4u : 8u;
        }
        flag[i] = sect != 15u && col != 15u;
    }
}
