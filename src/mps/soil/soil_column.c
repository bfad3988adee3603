/*
 * soil_column.c — the weight of the soil stacked above a particle, eq. (13)
 * of Kim's soil model (doc/theory.md K.3, K0-03):
 *
 *   p_h,i = sum_j rho_j g    over the soil particles j with z_j > z_i and a
 *                            horizontal distance |x_j - x_i| < b
 *
 * (z is y in 2-D; in 3-D the horizontal distance is the one in the x-y
 * plane). p_h is a sum of specific weights [N/m^3], so that the friction
 * (11) is a force per unit volume.
 *
 * The column reaches from the particle to the top of the soil, beyond any
 * neighbour list, so the soil particles are binned by their horizontal
 * position in bins of width b: the particles within b of x_i are in the 3
 * (2-D) or 3 x 3 (3-D) bins around x_i's bin. Cost: the particles of
 * those bins, a few columns' worth, per soil particle.
 */
#include <math.h>
#include <stdlib.h>

#include "core/error.h"
#include "mps/soil/soil.h"

struct binned {
    int64_t bx, by;   /* horizontal bin                                   */
    int i;            /* particle                                         */
};

static int cmp_bin(const void *pa, const void *pb)
{
    const struct binned *a = pa, *b = pb;
    if (a->bx != b->bx)
        return a->bx < b->bx ? -1 : 1;
    if (a->by != b->by)
        return a->by < b->by ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

/* First entry of s[0..m) not before bin (bx, by). */
static int lower_bound(const struct binned *s, int m, int64_t bx, int64_t by)
{
    int lo = 0, hi = m;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (s[mid].bx < bx || (s[mid].bx == bx && s[mid].by < by))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

int soil_column_weight(int n, int dim, const double *x, const uint8_t *role,
                       const double *rho, double g, double b, double *p_h)
{
    const int up = dim == 2 ? 1 : 2;
    int m = 0;
    for (int i = 0; i < n; i++) {
        p_h[i] = 0.0;
        m += role[i] == SOIL_SOIL;
    }
    if (m == 0)
        return SIM_OK;
    if (!(b > 0))
        return sim_error(SIM_ERR_INPUT, "soil column half-width %g: must be > 0", b);
    struct binned *s = sim_malloc((size_t)m * sizeof *s);
    if (!s)
        return SIM_ERR_NOMEM;
    m = 0;
    for (int i = 0; i < n; i++)
        if (role[i] == SOIL_SOIL) {
            s[m].bx = (int64_t)floor(x[3 * i] / b);
            s[m].by = dim == 3 ? (int64_t)floor(x[3 * i + 1] / b) : 0;
            s[m].i = i;
            m++;
        }
    qsort(s, (size_t)m, sizeof *s, cmp_bin);
    const int ry = dim == 3 ? 1 : 0;
#pragma omp parallel for schedule(dynamic, 64)
    for (int q = 0; q < m; q++) {
        const int i = s[q].i;
        const double *xi = x + 3 * i;
        double sum = 0.0;
        for (int64_t dx = -1; dx <= 1; dx++)
            for (int64_t dy = -ry; dy <= ry; dy++) {
                int64_t bx = s[q].bx + dx, by = s[q].by + dy;
                for (int k = lower_bound(s, m, bx, by);
                     k < m && s[k].bx == bx && s[k].by == by; k++) {
                    const double *xj = x + 3 * s[k].i;
                    if (!(xj[up] > xi[up]))
                        continue;
                    double h2 = (xj[0] - xi[0]) * (xj[0] - xi[0]);
                    if (dim == 3)
                        h2 += (xj[1] - xi[1]) * (xj[1] - xi[1]);
                    if (h2 < b * b)
                        sum += rho[s[k].i];
                }
            }
        p_h[i] = sum * g;
    }
    free(s);
    return SIM_OK;
}
