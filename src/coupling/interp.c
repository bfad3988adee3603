/*
 * interp.c — Shepard interpolation of MPS fields to grain centres
 * (Xie et al. 2025 eqs. 32-33; doc/theory.md A.7 and A0-14).
 *
 *   phi_k = sum_i phi_i w_s(|r_ki|) / sum_i w_s(|r_ki|)          (32), (33)
 *
 * Shepard's normalisation makes a constant field exact (check E1-11) and
 * keeps eps_k in [eps_min, 1] whatever the particle distribution near a
 * wall or the free surface.
 *
 * Model A needs grad P at the grain centre, which the paper does not
 * define (A0-14). We interpolate the consistent gradient
 *
 *   <grad P>_i = (d/n0) sum_j (P_j - P_i) r_ij w(|r_ij|) / (|r_ij|^2 eps_j)
 *
 * and not the conservative (P_j + P_i) form of eq. (8): the latter is not
 * zero for a constant pressure unless the neighbourhood is symmetric, so a
 * grain near the free surface would feel a spurious force of order P/dp.
 */
#include "coupling/interp.h"

#include <string.h>

#include "coupling/pairs.h"

void coupling_shepard(const struct coupling_pairs *P, int ncomp,
                      const double *f, const uint8_t *mask, const double *def,
                      double *out, double *wsum)
{
#pragma omp parallel for schedule(dynamic, 16)
    for (int k = 0; k < P->ng; k++) {
        double acc[3] = { 0, 0, 0 }, ws = 0;
        for (int64_t e = P->gstart[k]; e < P->gstart[k + 1]; e++) {
            int32_t i = P->gj[e];
            if (mask && !mask[i])
                continue;
            ws += P->gw[e];
            for (int c = 0; c < ncomp; c++)
                acc[c] += P->gw[e] * f[(int64_t)ncomp * i + c];
        }
        for (int c = 0; c < ncomp; c++)
            out[ncomp * k + c] = ws > 0 ? acc[c] / ws : (def ? def[c] : 0.0);
        if (wsum)
            wsum[k] = ws;
    }
}

/* sum w, sum w eps, sum w u (3), sum w gradp (3) of grain k */
static void grain_sums(const struct coupling_pairs *P, int k,
                       const uint8_t *mask, const double *eps,
                       const double *u, const double *gradp_p,
                       double s[COUPLING_SUMS])
{
    for (int c = 0; c < COUPLING_SUMS; c++)
        s[c] = 0;
    for (int64_t e = P->gstart[k]; e < P->gstart[k + 1]; e++) {
        int32_t i = P->gj[e];
        if (mask && !mask[i])
            continue;
        double w = P->gw[e];
        s[0] += w;
        s[1] += w * eps[i];
        for (int c = 0; c < 3; c++)
            s[2 + c] += w * u[3 * (int64_t)i + c];
        if (gradp_p)
            for (int c = 0; c < 3; c++)
                s[5 + c] += w * gradp_p[3 * (int64_t)i + c];
    }
}

static void grain_finish(int k, const double s[COUPLING_SUMS], int with_g,
                         struct coupling_grain_fields *out)
{
    double ws = s[0];
    int wet = ws > 0;
    out->wet[k] = (uint8_t)wet;
    out->eps[k] = wet ? s[1] / ws : 1.0;
    for (int c = 0; c < 3; c++) {
        out->u[3 * k + c] = wet ? s[2 + c] / ws : 0.0;
        if (out->gradp)
            out->gradp[3 * k + c] = wet && with_g ? s[5 + c] / ws : 0.0;
    }
}

void coupling_interp_grains(const struct coupling_pairs *P,
                            const uint8_t *mask, const double *eps,
                            const double *u, const double *gradp_p,
                            struct coupling_grain_fields *out)
{
    int with_g = gradp_p && out->gradp;
#pragma omp parallel for schedule(dynamic, 16)
    for (int k = 0; k < P->ng; k++) {
        double s[COUPLING_SUMS];
        grain_sums(P, k, mask, eps, u, with_g ? gradp_p : NULL, s);
        grain_finish(k, s, with_g, out);
    }
}

void coupling_interp_sums(const struct coupling_pairs *P,
                          const uint8_t *mask, const double *eps,
                          const double *u, const double *gradp_p,
                          double *sums)
{
#pragma omp parallel for schedule(dynamic, 16)
    for (int k = 0; k < P->ng; k++)
        grain_sums(P, k, mask, eps, u, gradp_p, sums + COUPLING_SUMS * k);
}

void coupling_interp_finish(int ng, const double *sums, int with_gradp,
                            struct coupling_grain_fields *out)
{
#pragma omp parallel for schedule(static)
    for (int k = 0; k < ng; k++)
        grain_finish(k, sums + COUPLING_SUMS * k, with_gradp, out);
}

void coupling_gradient_consistent(const struct neighbour_list *nl,
                                  const struct pop_weights *W, int dim,
                                  double n0, const double *x, const double *p,
                                  const double *inv_eps, const uint8_t *rows,
                                  double *out)
{
    const double c0 = dim / n0;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < nl->n; i++) {
        if (rows && !rows[i])
            continue;
        double g[3] = { 0, 0, 0 };
        const int64_t e0 = nl->start[i], e1 = nl->start[i + 1];
        const double *w = pop_weights_of(W, nl, i, e0, e1);
        for (int64_t e = e0; e < e1; e++) {
            int32_t m = nl->j[e];
            if (m == i || w[e - e0] == 0)
                continue;
            double r[3], r2 = 0;
            for (int c = 0; c < 3; c++) {
                r[c] = x[3 * (int64_t)m + c] - x[3 * (int64_t)i + c];
                r2 += r[c] * r[c];
            }
            if (!(r2 > 0))
                continue;   /* coincident particles carry no direction */
            double s = (p[m] - p[i]) * w[e - e0] / r2;
            if (inv_eps)
                s *= inv_eps[m];
            for (int c = 0; c < 3; c++)
                g[c] += s * r[c];
        }
        for (int c = 0; c < 3; c++)
            out[3 * (int64_t)i + c] = c < dim ? c0 * g[c] : 0.0;
    }
}
