/*
 * reaction.c — time-averaged drag and its reaction on the fluid
 * (Xie et al. 2025 eq. 36; doc/theory.md A.7, A.8 "MSS", A.10 steps 4 and 6).
 *
 *   F_bar^d_k = (1/N_sub) sum_{s=1}^{N_sub} F^d_k(s)
 *   f_A,i     = (1/V_i) sum_k F_bar^d_k w_s(|r_ki|) / sum_j w_s(|r_kj|)  (36)
 *
 * with V_i = phi_i V_p, phi_i the particle's fluid volume fraction (1
 * unless genParticles gave volume fractions, grainVolume scale).
 *
 * The DEM side evaluates drag at every sub-step with its own current
 * velocity (stable for light grains); the fluid feels the average, which
 * is the impulse the grains received over the fluid step divided by dt, so
 * momentum is exchanged exactly over the step.
 *
 * Each grain's share is normalised by its own weight sum W_k, hence
 *   sum_i V_i f_A,i = sum_k F_bar_k sum_i w_ki / W_k = sum_k F_bar_k
 * to round-off (check E1-13). The sum over grains is done per particle
 * with the particle-major pair rows (a gather: no atomics, reproducible),
 * after one pass per grain that forms c_k = F_bar_k / W_k.
 */
#include "coupling/reaction.h"

#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "coupling/pairs.h"

int coupling_drag_mean_init(struct coupling_drag_mean *m, int n)
{
    if (n < 0)
        return sim_error(SIM_ERR_INPUT, "drag mean: negative grain count");
    if (n > m->cap || !m->sum) {
        double *s = sim_realloc(m->sum, (3 * (size_t)n + 3) * sizeof *s);
        if (!s)
            return SIM_ERR_NOMEM;
        m->sum = s;
        m->cap = n;
    }
    m->n = n;
    coupling_drag_mean_reset(m);
    return SIM_OK;
}

void coupling_drag_mean_reset(struct coupling_drag_mean *m)
{
    memset(m->sum, 0, 3 * (size_t)m->n * sizeof *m->sum);
    m->count = 0;
}

void coupling_drag_mean_add(struct coupling_drag_mean *m, const double *F)
{
    for (int e = 0; e < 3 * m->n; e++)
        m->sum[e] += F[e];
    m->count++;
}

int coupling_drag_mean_get(const struct coupling_drag_mean *m, double *mean)
{
    if (m->count <= 0)
        return sim_error(SIM_ERR_INPUT, "drag mean: no sub-step accumulated");
    const double inv = 1.0 / (double)m->count;
    for (int e = 0; e < 3 * m->n; e++)
        mean[e] = m->sum[e] * inv;
    return SIM_OK;
}

void coupling_drag_mean_free(struct coupling_drag_mean *m)
{
    free(m->sum);
    memset(m, 0, sizeof *m);
}

/* Weight sum of grain k over the particles that take a share. */
static double grain_weight(const struct coupling_pairs *P, int k,
                           const uint8_t *mask)
{
    double W = 0;
    for (int64_t e = P->gstart[k]; e < P->gstart[k + 1]; e++)
        if (!mask || mask[P->gj[e]])
            W += P->gw[e];
    return W;
}

void coupling_reaction_weights(const struct coupling_pairs *P,
                               const uint8_t *mask, double *W)
{
#pragma omp parallel for schedule(static)
    for (int k = 0; k < P->ng; k++)
        W[k] = grain_weight(P, k, mask);
}

/* W NULL: each grain's weight sum from the pairs at hand. */
static int reaction(struct coupling_pairs *P, const double *W,
                    const uint8_t *mask, const double *Fbar, double Vp,
                    const double *phi, double *fA, int *n_orphan)
{
    if (!(Vp > 0))
        return sim_error(SIM_ERR_INPUT, "reaction: particle volume %g must "
                         "be > 0", Vp);
    double *c = P->gwork;   /* c_k = F_bar_k / W_k */
    int orphans = 0;
#pragma omp parallel for schedule(static) reduction(+ : orphans)
    for (int k = 0; k < P->ng; k++) {
        double Wk = W ? W[k] : grain_weight(P, k, mask);
        for (int d = 0; d < 3; d++)
            c[3 * k + d] = Wk > 0 ? Fbar[3 * k + d] / Wk : 0.0;
        orphans += !(Wk > 0);
    }
    const double inv_v = 1.0 / Vp;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->np; i++) {
        double s[3] = { 0, 0, 0 };
        if (!mask || mask[i])
            for (int64_t e = P->pstart[i]; e < P->pstart[i + 1]; e++)
                for (int d = 0; d < 3; d++)
                    s[d] += P->pw[e] * c[3 * P->pk[e] + d];
        double iv = phi ? inv_v / phi[i] : inv_v;
        for (int d = 0; d < 3; d++)
            fA[3 * (int64_t)i + d] = s[d] * iv;
    }
    if (n_orphan)
        *n_orphan = orphans;
    return SIM_OK;
}

int coupling_reaction(struct coupling_pairs *P, const uint8_t *mask,
                      const double *Fbar, double Vp, const double *phi,
                      double *fA, int *n_orphan)
{
    return reaction(P, NULL, mask, Fbar, Vp, phi, fA, n_orphan);
}

int coupling_reaction_given(struct coupling_pairs *P, const double *W,
                            const uint8_t *mask, const double *Fbar,
                            double Vp, const double *phi, double *fA,
                            int *n_orphan)
{
    return reaction(P, W, mask, Fbar, Vp, phi, fA, n_orphan);
}
