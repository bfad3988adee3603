/*
 * walls.c — partners and extrapolated pressure of wall-layer particles
 * (doc/theory.md A.9; after Koshizuka et al. 1998 and MLParticle-SJTU
 * practice for the partner, Adami, Hu and Adams 2012, J. Comput. Phys.
 * 231, 7057, eq. 27 with a fixed wall for the extrapolation):
 *
 *   partner(i) = argmin_{j wall, |r_ij| < r_c} |r_ij|   (ties: smaller id)
 *   p_w        = sum_f (p_f + rho g.(r_w - r_f)) w_wf / sum_f w_wf
 *
 * The extrapolated field is the hydrostatic one carried across the wall,
 * so that a first-order consistent gradient feels no wall force in still
 * water.
 */
#include "particles/operators/walls.h"

#include <math.h>

#include "particles/neighbour.h"

int pop_wall_partners(const struct neighbour_list *nl, int n,
                      const int32_t *type, int32_t seeker, int32_t target,
                      const int64_t *id, double tol,
                      pop_partner_filter *allow, const void *ctx,
                      int32_t *partner)
{
    int orphans = 0;
    for (int i = 0; i < n; i++) {
        partner[i] = -1;
        if (type[i] != seeker)
            continue;
        double best = INFINITY;
        const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
        const double *rr = neighbour_row_r(nl, i, k0, k1);
        for (int64_t k = k0; k < k1; k++) {
            int j = nl->j[k];
            if (type[j] != target)
                continue;
            if (allow && !allow(ctx, i, j))
                continue;
            double r = rr[k - k0];
            if (r < best - tol
                || (r < best + tol && partner[i] >= 0
                    && id[j] < id[partner[i]])) {
                best = fmin(best, r);
                partner[i] = j;
            }
        }
        orphans += partner[i] < 0;
    }
    for (int pass = 0; pass < 4 && orphans; pass++) {
        orphans = 0;
        for (int i = 0; i < n; i++) {
            if (type[i] != seeker || partner[i] >= 0)
                continue;
            double best = INFINITY;
            const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
            const double *rr = neighbour_row_r(nl, i, k0, k1);
            for (int64_t k = k0; k < k1; k++) {
                int j = nl->j[k];
                if (allow && !allow(ctx, i, j))
                    continue;
                if (type[j] == seeker && partner[j] >= 0
                    && rr[k - k0] < best) {
                    best = rr[k - k0];
                    partner[i] = partner[j];
                }
            }
            orphans += partner[i] < 0;
        }
    }
    return orphans;
}

int pop_wall_extrapolate(const struct neighbour_list *nl,
                         const struct pop_weights *W,
                         const double *x, const double *p,
                         const int32_t *type, int32_t fluid, double rho,
                         const double g[3], int i, double *out)
{
    double sw = 0, sp = 0;
    const int64_t k0 = nl->start[i], k1 = nl->start[i + 1];
    const double *w = pop_weights_of(W, nl, i, k0, k1);
    for (int64_t k = k0; k < k1; k++) {
        int j = nl->j[k];
        double wk = w[k - k0];
        if (wk == 0 || type[j] != fluid)
            continue;
        double pj = p[j];
        for (int q = 0; q < 3; q++)
            pj += rho * g[q] * (x[3 * i + q] - x[3 * j + q]);
        sw += wk;
        sp += wk * pj;
    }
    if (sw == 0)
        return 0;
    *out = sp / sw;
    return 1;
}
