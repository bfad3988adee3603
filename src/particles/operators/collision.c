/*
 * collision.c — the collision model of Lee et al. (2011); collision.h.
 */
#include "particles/neighbour.h"
#include "particles/operators/collision.h"

void pop_collision(const struct neighbour_list *nl, const double *x,
                   const int32_t *type, const double *rho, double rc,
                   double e, double *u, double *du)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        double d[3] = { 0, 0, 0 };
        if (type[i] == 0) {
            const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
            const double *rr = neighbour_row_r(nl, i, k0, k1);
            for (int64_t k = k0; k < k1; k++) {
                double r = rr[k - k0];
                if (r >= rc || r == 0)
                    continue;
                int j = nl->j[k];
                double n[3], vn = 0;
                for (int q = 0; q < 3; q++) {
                    n[q] = (x[3 * j + q] - x[3 * i + q]) / r;
                    vn += (u[3 * i + q] - u[3 * j + q]) * n[q];
                }
                if (vn <= 0)
                    continue;
                double f = type[j] != 0 ? 1 + e
                         : rho ? (1 + e) * rho[j] / (rho[i] + rho[j])
                         : 0.5 * (1 + e);
                for (int q = 0; q < 3; q++)
                    d[q] -= f * vn * n[q];
            }
        }
        for (int q = 0; q < 3; q++)
            du[3 * i + q] = d[q];
    }
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++)
        if (type[i] == 0)
            for (int q = 0; q < 3; q++)
                u[3 * i + q] += du[3 * i + q];
}
