/*
 * couple_output.c — the fluid's reaction -V_i f_A,i of eq. (36) in a
 * coupled run's output (Xie et al. 2025; doc/theory.md A.8), carried
 * through the particle renumbering of mps_step() (couple_output.h).
 */
#include "couplingMps/couple_output.h"

#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "couplingMps/couple_fluid.h"
#include "mps/mps.h"

static int grow(struct couple_output *o, int n)
{
    if (n <= o->cap && o->id)
        return SIM_OK;
    int cap = n > 2 * o->cap ? n : 2 * o->cap;
    SIM_GROW(o->id, cap);
    SIM_GROW(o->F, 3 * cap);
    SIM_GROW(o->out, 3 * cap);
    SIM_GROW(o->key, 2 * cap);
    o->cap = cap;
    return SIM_OK;
}

int couple_output_snapshot(struct couple_output *o,
                           const struct couple_fluid *cf,
                           const struct mps_particles *P)
{
    TRY(grow(o, P->n > 0 ? P->n : 1));
    int m = P->n < cf->pairs.np ? P->n : cf->pairs.np;
    memcpy(o->id, P->id, (size_t)P->n * sizeof *o->id);
    for (int i = 0; i < m; i++) {
        double V = P->phi ? cf->Vp * P->phi[i] : cf->Vp; /* V_i of eq. (36) */
        for (int c = 0; c < 3; c++)
            o->F[3 * i + c] = -V * cf->fA[3 * i + c];
    }
    memset(o->F + 3 * (size_t)m, 0, 3 * (size_t)(P->n - m) * sizeof *o->F);
    o->n = P->n;
    return SIM_OK;
}

static int cmp_key(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

int couple_output_reaction(struct couple_output *o,
                           const struct mps_particles *P, double **out)
{
    TRY(grow(o, P->n > 0 ? P->n : 1));
    *out = o->out;
    if (P->n == o->n && !memcmp(P->id, o->id, (size_t)o->n * sizeof *o->id)) {
        memcpy(o->out, o->F, 3 * (size_t)o->n * sizeof *o->out);
        return SIM_OK;
    }
    /* renumbered since the snapshot: look the ids up (writes only) */
    for (int i = 0; i < o->n; i++) {
        o->key[2 * i] = o->id[i];
        o->key[2 * i + 1] = i;
    }
    qsort(o->key, (size_t)o->n, 2 * sizeof *o->key, cmp_key);
    for (int i = 0; i < P->n; i++) {
        const int64_t *hit = bsearch(&P->id[i], o->key, (size_t)o->n,
                                     2 * sizeof *o->key, cmp_key);
        for (int c = 0; c < 3; c++)
            o->out[3 * i + c] = hit ? o->F[3 * hit[1] + c] : 0.0;
    }
    return SIM_OK;
}

void couple_output_free(struct couple_output *o)
{
    free(o->id); free(o->F); free(o->out); free(o->key);
    memset(o, 0, sizeof *o);
}
